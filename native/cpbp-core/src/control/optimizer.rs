//! The planning controllers: the optimizer and combined (thesis §4.3: C-PBP plans in
//! rollout worlds cloned from the master; combined mode warm-starts it with the arcade
//! controller's own rollout, particle 1, optimizer mode without one), and the baselines
//! predictive sampling and MPPI in the same worlds with the same cost.

use super::arcade::ArcadeController;
use super::bike_rollout::{bike_priors, BikeRollout, CostTolerances};
use super::cpbp::{PlanResult, Planner, PlannerConfig, WarmStart};
use super::sampling::{SamplingConfig, SamplingPlanner, SamplingUpdate};
use super::Goal;
use crate::bike::{index, Controls, CONTROL_DIM};
use crate::ode::Solver;
use crate::physics::{PhysicsModel, RolloutStepping};
use crate::simulation::Simulation;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OptimizerMode {
    /// C-PBP alone; particle 1 replays the last frame's local refinement.
    Optimizer,
    /// C-PBP warm-started with the arcade controller's trajectory.
    Combined,
    /// MuJoCo MPC's predictive sampling: the cheapest of a nominal plan and its
    /// perturbations becomes the plan.
    Sampling,
    /// MPPI: the cost-weighted average of the perturbations becomes the plan.
    Mppi,
}

/// What the baseline planners (predictive sampling, MPPI) sample and how widely.
#[derive(Clone, Debug, PartialEq)]
pub struct BaselineSettings {
    /// Knots of a plan over the horizon.
    pub knots: usize,
    /// A knot's perturbation σ as a share of the priors' static σ (steering: 4 rad/s).
    pub noise: f64,
    /// MPPI's temperature, relative to the spread of the totals (median − cheapest).
    pub temperature: f64,
    /// Plan the steering alone, the rider holding the riding pose with the pose PD (the
    /// pose prior's mean), instead of every joint.
    pub steering_only: bool,
}

impl Default for BaselineSettings {
    /// Chosen with `examples/baseline_sweep` (docs/results.md, "Planners side by side"):
    /// sampling every joint falls at walking pace; steering alone with 10 knots, σ = 2 rad/s
    /// and MPPI at temperature 0.01 tracked a 15° turn best.
    fn default() -> Self {
        Self {
            knots: 10,
            noise: 0.5,
            temperature: 0.01,
            steering_only: true,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct OptimizerConfig {
    pub mode: OptimizerMode,
    /// Trajectories (N).
    pub particles: usize,
    /// Planning horizon (s); the thesis used 1.2 s.
    pub horizon: f64,
    /// ODE steps per planning step in the rollouts; `Ride` takes the physics model's
    /// (`PhysicsModel::rollout_stepping`). With QuickStep the master takes 4: at fewer its
    /// 20 iterations do not converge the rider–handlebar chain, the rollouts ride a
    /// different (less stable) bike and their plans mislead (measured: both modes fall at
    /// 10 km/h with 2). The direct solver holds the chain at one step, finer at the start.
    pub rollout_stepping: RolloutStepping,
    /// The rollouts' constraint solver, the physics model's in a `Ride` (see
    /// `fidelity::divergence` before choosing another).
    pub rollout_solver: Solver,
    /// How strictly the cost holds the lean (eq. 4.7's s, rad) and the rider's position (m).
    pub tolerances: CostTolerances,
    /// Mutation scale of the followed sequences (σm = scale · σ0).
    pub mutation_scale: f64,
    /// Weight of the control priors' cost against the lean cost when choosing the best
    /// trajectory: the 16 planned dimensions add about 48 prior terms per step against one
    /// lean term, and unweighted they decide which trajectory wins.
    pub control_cost_weight: f64,
    pub seed: u64,
    /// Rollout threads (0: one per core).
    pub threads: usize,
    /// Settings of the baseline planners (ignored by C-PBP).
    pub baseline: BaselineSettings,
}

impl Default for OptimizerConfig {
    fn default() -> Self {
        Self {
            mode: OptimizerMode::Combined,
            particles: 15,
            horizon: 1.2,
            rollout_stepping: RolloutStepping::uniform(4),
            rollout_solver: Solver::QuickStep,
            tolerances: CostTolerances::default(),
            mutation_scale: 0.2,
            control_cost_weight: 0.01,
            seed: 2015,
            threads: 0,
            baseline: BaselineSettings::default(),
        }
    }
}

impl OptimizerConfig {
    /// This configuration rolling out as `physics` prescribes (solver and stepping).
    pub fn rolling_out_in(self, physics: PhysicsModel) -> Self {
        Self {
            rollout_solver: physics.rollout_solver(),
            rollout_stepping: physics.rollout_stepping(),
            ..self
        }
    }
}

/// How a mode searches: C-PBP, or one of the baselines.
enum Search {
    Cpbp(Planner),
    Sampling(SamplingPlanner),
}

/// The planner, its rollout worlds, and the arcade controller it can lean on.
pub struct BikeOptimizer {
    pub config: OptimizerConfig,
    search: Search,
    rollouts: Vec<BikeRollout>,
    arcade: ArcadeController,
    last: Option<PlanResult>,
}

impl BikeOptimizer {
    /// Builds N + 1 rollout worlds like the master of `sim`.
    pub fn new(sim: &Simulation, config: OptimizerConfig) -> Self {
        let dt = sim.config().control_dt;
        let steps = (config.horizon / dt).round().max(1.0) as usize;
        let rollout = || BikeRollout {
            world: {
                let mut world = sim.new_world();
                world.set_solver(config.rollout_solver);
                world
            },
            bike: sim.bike().clone(),
            gravity: sim.config().gravity,
            up: sim.up(),
            step_dt: dt,
            stepping: config.rollout_stepping,
            goal: Goal::default(),
            tolerances: config.tolerances,
            policy: None,
        };
        Self {
            search: search_for(&config, steps),
            rollouts: (0..config.particles.max(1)).map(|_| rollout()).collect(),
            arcade: ArcadeController::default(),
            last: None,
            config,
        }
    }

    /// Forgets previous plans (after a reset or a lift).
    pub fn reset(&mut self) {
        match &mut self.search {
            Search::Cpbp(planner) => planner.reset(),
            Search::Sampling(planner) => planner.reset(),
        }
        self.arcade.reset();
        self.last = None;
    }

    /// The last frame's plan (trajectories, costs), for statistics and visualisation.
    pub fn last_plan(&self) -> Option<&PlanResult> {
        self.last.as_ref()
    }

    /// The last plan's chosen sequence (the best trajectory's, or MPPI's average) as
    /// controls, one per control step (the first is what `controls` returned), with the
    /// player's throttle and brake.
    pub fn chosen_sequence(&self) -> Vec<Controls> {
        self.last
            .as_ref()
            .map_or_else(Vec::new, |plan| self.as_controls(&plan.chosen))
    }

    /// Every final trajectory of the last plan as controls, as `chosen_sequence` gives the
    /// chosen one (for replaying the plan's rollouts without the planner).
    pub fn sequences(&self) -> Vec<Vec<Controls>> {
        self.last.as_ref().map_or_else(Vec::new, |plan| {
            plan.sequences.iter().map(|s| self.as_controls(s)).collect()
        })
    }

    fn as_controls(&self, sequence: &[f64]) -> Vec<Controls> {
        sequence
            .chunks_exact(crate::bike::CONTROL_DIM)
            .map(|u| self.rollouts[0].controls_for(u))
            .collect()
    }

    /// Tells the planner which controls the master really applied last (when that was
    /// not its own first control: a fallback, or a plan that arrived late).
    pub fn note_applied(&mut self, controls: &Controls) {
        match &mut self.search {
            Search::Cpbp(planner) => planner.note_applied(controls.values()),
            Search::Sampling(planner) => planner.note_applied(controls.values()),
        }
    }

    /// Plans one control step of `sim` towards the player's `goal`.
    pub fn controls(&mut self, sim: &Simulation, goal: &Goal) -> Controls {
        let start = sim.world().snapshot();
        for rollout in &mut self.rollouts {
            rollout.goal = *goal;
            rollout.tolerances = self.config.tolerances;
        }
        // Combined mode: particle 1 rides with the arcade controller, starting from the
        // master's controller memory (taken before this step updates it).
        if let (OptimizerMode::Combined, Some(rollout)) =
            (self.config.mode, self.rollouts.get_mut(1))
        {
            rollout.policy = Some(self.arcade);
        }
        // Keep the arcade controller's memory in step with the master.
        self.arcade.controls_of(sim, goal);
        // Particle 1: combined mode follows the arcade controller live; the optimizer
        // alone replays last frame's refinement.
        let result = match &mut self.search {
            Search::Cpbp(planner) => {
                let warm = match self.config.mode {
                    OptimizerMode::Combined => WarmStart::Policy,
                    _ => WarmStart::Refinement,
                };
                planner.plan(&mut self.rollouts, &start, warm)
            }
            Search::Sampling(planner) => planner.plan(&mut self.rollouts, &start),
        };
        let controls = self.rollouts[0].controls_for(&result.control);
        self.last = Some(result);
        controls
    }
}

/// The search `config.mode` names, planning `steps` steps ahead.
fn search_for(config: &OptimizerConfig, steps: usize) -> Search {
    let priors = bike_priors(config.mutation_scale);
    let update = match config.mode {
        OptimizerMode::Optimizer | OptimizerMode::Combined => {
            let planner_config = PlannerConfig {
                particles: config.particles.max(1),
                steps,
                seed: config.seed,
                threads: config.threads,
                refine: config.mode == OptimizerMode::Optimizer,
                control_cost_weight: config.control_cost_weight,
                ..PlannerConfig::default()
            };
            return Search::Cpbp(Planner::new(planner_config, priors));
        }
        OptimizerMode::Sampling => SamplingUpdate::Best,
        OptimizerMode::Mppi => SamplingUpdate::Weighted {
            temperature: config.baseline.temperature,
        },
    };
    let baseline = &config.baseline;
    let sampled = baseline
        .steering_only
        .then(|| (0..CONTROL_DIM).map(|d| d == index::STEER).collect());
    let sampling_config = SamplingConfig {
        samples: config.particles.max(1),
        steps,
        knots: baseline.knots.max(2),
        noise: baseline.noise,
        update,
        sampled,
        control_cost_weight: config.control_cost_weight,
        seed: config.seed,
        threads: config.threads,
        ..SamplingConfig::default()
    };
    Search::Sampling(SamplingPlanner::new(sampling_config, priors))
}
