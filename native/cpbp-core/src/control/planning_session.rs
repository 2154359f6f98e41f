//! A planner at work on the bike (thesis §4.3): whichever planner its spec builds (C-PBP
//! alone or combined, predictive sampling, MPPI) plans in rollout worlds cloned from the
//! master, one per trajectory, with the same cost; the arcade controller's memory is kept
//! in step with the master for the planners whose trajectory 1 follows it.

use std::sync::Arc;

use super::arcade::ArcadeController;
use super::bike_rollout::{BikeRollout, CostTolerances, PlanStart, RolloutPolicy, TerminalValue};
use super::learned::{LoadedValue, PolicyNetwork};
use super::plan_result::{PlanPhases, PlanResult};
use super::planner::{BikePlanner, Follows, PlannerSpec};
use super::Goal;
use crate::bike::Controls;
use crate::ode::Solver;
use crate::physics::{PhysicsModel, RolloutStepping};
use crate::settings::{self, SettingValues};
use crate::simulation::Simulation;

#[derive(Clone, Debug, PartialEq)]
pub struct PlanningConfig {
    /// Trajectories (N).
    pub trajectories: usize,
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
    /// Weight of the control priors' cost against the lean cost when choosing the best
    /// trajectory: the 16 planned dimensions add about 48 prior terms per step against one
    /// lean term, and unweighted they decide which trajectory wins.
    pub control_cost_weight: f64,
    pub seed: u64,
    /// Rollout threads (0: one per core).
    pub threads: usize,
    /// The planners' own parameters by name (`PlannerSpec::parameters`): each planner
    /// reads its own, at its default where this holds none.
    pub parameters: SettingValues,
    /// Whether a learned cost-to-go ends the plans: with `value` loaded the planners plan
    /// `value_horizon` and cost the rest of `horizon` with it (`planned`).
    pub terminal_value: bool,
    /// The horizon planned when the cost-to-go ends it (s).
    pub value_horizon: f64,
    /// The learned cost-to-go, or why there is none.
    pub value: LoadedValue,
    /// Planning steps after which a planner that can records its trajectories' states
    /// with what the rest of the horizon cost from them (`PlanResult::value_samples`, a
    /// cost-to-go's training data); empty: none.
    pub record_values_after: Vec<usize>,
}

impl Default for PlanningConfig {
    fn default() -> Self {
        Self {
            trajectories: settings::TRAJECTORIES.default_number() as usize,
            horizon: settings::HORIZON_S.default_number(),
            rollout_stepping: RolloutStepping::uniform(4),
            rollout_solver: Solver::QuickStep,
            tolerances: CostTolerances::default(),
            control_cost_weight: 0.01,
            seed: settings::PLANNER_SEED.default_number() as u64,
            threads: 0,
            parameters: SettingValues::none(),
            terminal_value: settings::TERMINAL_VALUE.default_number() != 0.0,
            value_horizon: settings::VALUE_HORIZON_S.default_number(),
            value: LoadedValue::default(),
            record_values_after: Vec::new(),
        }
    }
}

impl PlanningConfig {
    /// The seconds the planners plan, and the cost-to-go that stands for the rest of the
    /// horizon after them: the value horizon and the rest while the terminal value is on
    /// and its network loaded (and the value horizon the shorter), the whole horizon and
    /// none otherwise.
    pub fn planned(&self) -> (f64, Option<TerminalValue>) {
        match self.value.network() {
            Some(network) if self.terminal_value && self.value_horizon < self.horizon => (
                self.value_horizon,
                Some(TerminalValue {
                    network: Arc::clone(network),
                    remaining_s: self.horizon - self.value_horizon,
                }),
            ),
            _ => (self.horizon, None),
        }
    }

    /// Why the plans are not shortened as asked (the terminal value is on, its network
    /// missing or unusable), as the HUD says it.
    pub fn value_problem(&self) -> Option<&str> {
        self.value.problem().filter(|_| self.terminal_value)
    }

    /// This configuration rolling out as `physics` prescribes (solver and stepping).
    pub fn rolling_out_in(self, physics: PhysicsModel) -> Self {
        Self {
            rollout_solver: physics.rollout_solver(),
            rollout_stepping: physics.rollout_stepping(),
            ..self
        }
    }

    /// Whether `other` plans as this does but for the number of trajectories: a planner
    /// can switch between the two without being built anew.
    pub fn differs_only_in_trajectories(&self, other: &Self) -> bool {
        Self {
            trajectories: other.trajectories,
            ..self.clone()
        } == *other
    }
}

/// The planner, its rollout worlds, and the arcade controller it can lean on.
pub struct PlanningSession {
    pub config: PlanningConfig,
    spec: &'static PlannerSpec,
    planner: Box<dyn BikePlanner>,
    rollouts: Vec<BikeRollout>,
    arcade: ArcadeController,
    /// The network trajectory 1 follows when the spec follows one (`follow`).
    network: Option<Arc<PolicyNetwork>>,
    last: Option<PlanResult>,
}

impl PlanningSession {
    /// The planner `spec` builds, with N rollout worlds like the master of `sim`.
    pub fn new(sim: &Simulation, spec: &'static PlannerSpec, config: PlanningConfig) -> Self {
        let dt = sim.config().control_dt;
        let steps = (config.planned().0 / dt).round().max(1.0) as usize;
        let mut optimizer = Self {
            planner: (spec.build)(&config, steps),
            spec,
            rollouts: Vec::new(),
            arcade: ArcadeController::default(),
            network: None,
            last: None,
            config,
        };
        optimizer.add_rollouts(sim, dt);
        optimizer
    }

    /// Plans with `n` trajectories from the next plan on, keeping the planner's memory;
    /// worlds are added when N grows past every N before (and kept when it shrinks).
    pub fn set_trajectories(&mut self, sim: &Simulation, n: usize) {
        self.config.trajectories = n.max(1);
        self.planner.set_trajectories(self.config.trajectories);
        self.add_rollouts(sim, sim.config().control_dt);
    }

    /// Rollout worlds like the master of `sim` until there is one per trajectory.
    fn add_rollouts(&mut self, sim: &Simulation, step_dt: f64) {
        let config = &self.config;
        let value = config.planned().1;
        while self.rollouts.len() < config.trajectories.max(1) {
            let mut world = sim.new_world();
            world.set_solver(config.rollout_solver);
            self.rollouts.push(BikeRollout {
                world,
                bike: sim.bike().clone(),
                gravity: sim.config().gravity,
                up: sim.up(),
                step_dt,
                stepping: config.rollout_stepping,
                goal: Goal::default(),
                tolerances: config.tolerances,
                policy: None,
                start: PlanStart::default(),
                value: value.clone(),
                fallen: false,
            });
        }
    }

    /// The network the ride hands a planner that follows one (guided mode); with none,
    /// it follows the arcade controller. Planners that follow nothing ignore it.
    pub fn follow(&mut self, network: Option<Arc<PolicyNetwork>>) {
        self.network = network;
    }

    /// Forgets previous plans (after a reset or a lift).
    pub fn reset(&mut self) {
        self.planner.reset();
        self.arcade.reset();
        self.last = None;
    }

    /// Where the last plan's time went.
    pub fn phases(&self) -> PlanPhases {
        self.planner.phases()
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
            plan.trajectories
                .iter()
                .map(|t| self.as_controls(&t.controls))
                .collect()
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
        self.planner.note_applied(controls.values());
    }

    /// The rollouts' stepping for a plan from `sim`'s state towards `goal`: the
    /// configuration's, or the master's own while the bike leans, or is asked to lean, at
    /// least its `planners_exact_from_lean` (asked, so that the turn-in's plans already
    /// predict the deep lean they lead into).
    pub fn rollout_stepping_for(&self, sim: &Simulation, goal: &Goal) -> RolloutStepping {
        let from = sim.bike().params().planners_exact_from_lean;
        let lean = || sim.bike().lean(sim.world(), sim.up()).abs();
        // 90° is "never", not "lying on the ground": a fallen reference bike plans as before.
        if from < std::f64::consts::FRAC_PI_2 && goal.lean.abs().max(lean()) >= from {
            RolloutStepping::uniform(sim.config().substeps)
        } else {
            self.config.rollout_stepping
        }
    }

    /// Plans one control step of `sim` towards the player's `goal`.
    pub fn controls(&mut self, sim: &Simulation, goal: &Goal) -> Controls {
        let start = sim.world().snapshot();
        let stepping = self.rollout_stepping_for(sim, goal);
        for rollout in &mut self.rollouts {
            rollout.goal = *goal;
            rollout.tolerances = self.config.tolerances;
            rollout.stepping = stepping;
        }
        // Combined mode: particle 1 rides with the arcade controller, starting from the
        // master's controller memory (taken before this step updates it); guided mode:
        // with the network (the arcade controller while there is none).
        let followed = match (self.spec.follows, self.network.clone()) {
            (Follows::Nothing, _) => None,
            (Follows::Network, Some(network)) => Some(RolloutPolicy::Network(network)),
            (Follows::Arcade | Follows::Network, _) => Some(RolloutPolicy::Arcade(self.arcade)),
        };
        if let (Some(policy), Some(rollout)) = (followed, self.rollouts.get_mut(1)) {
            rollout.policy = Some(policy);
        }
        // Keep the arcade controller's memory in step with the master.
        self.arcade.controls_of(sim, goal);
        let result = self.planner.plan(&mut self.rollouts, &start);
        let controls = self.rollouts[0].controls_for(&result.control);
        self.last = Some(result);
        controls
    }
}
