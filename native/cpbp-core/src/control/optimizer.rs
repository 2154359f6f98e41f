//! The optimizer and combined controllers (thesis §4.3): C-PBP plans in rollout worlds
//! cloned from the master; combined mode warm-starts it with the arcade controller's own
//! rollout (particle 1), optimizer mode without one.

use super::arcade::ArcadeController;
use super::bike_rollout::{bike_priors, BikeRollout, LeanGoal};
use super::cpbp::{PlanResult, Planner, PlannerConfig, RolloutSystem};
use crate::bike::{Controls, DriveInput};
use crate::simulation::Simulation;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OptimizerMode {
    /// C-PBP alone; particle 1 replays the last frame's local refinement.
    Optimizer,
    /// C-PBP warm-started with the arcade controller's trajectory.
    Combined,
}

#[derive(Clone, Debug, PartialEq)]
pub struct OptimizerConfig {
    pub mode: OptimizerMode,
    /// Trajectories (N).
    pub particles: usize,
    /// Planning horizon (s); the thesis used 1.2 s.
    pub horizon: f64,
    /// ODE steps per planning step in the rollouts. The master takes 4; at fewer,
    /// QuickStep's 20 iterations do not converge the rider–handlebar chain, the rollouts
    /// ride a different (less stable) bike and their plans mislead (measured: both modes
    /// fall at 10 km/h with 2).
    pub rollout_substeps: usize,
    /// Lean tolerance s of eq. 4.7 (rad).
    pub lean_tolerance: f64,
    /// Mutation scale of the followed sequences (σm = scale · σ0).
    pub mutation_scale: f64,
    /// Weight of the control priors' cost against the lean cost when choosing the best
    /// trajectory: the 16 planned dimensions add about 48 prior terms per step against one
    /// lean term, and unweighted they decide which trajectory wins.
    pub control_cost_weight: f64,
    pub seed: u64,
    /// Rollout threads (0: one per core).
    pub threads: usize,
}

impl Default for OptimizerConfig {
    fn default() -> Self {
        Self {
            mode: OptimizerMode::Combined,
            particles: 15,
            horizon: 1.2,
            rollout_substeps: 4,
            lean_tolerance: 5f64.to_radians(),
            mutation_scale: 0.2,
            control_cost_weight: 0.01,
            seed: 2015,
            threads: 0,
        }
    }
}

/// The planner, its rollout worlds, and the arcade controller it can lean on.
pub struct BikeOptimizer {
    pub config: OptimizerConfig,
    planner: Planner,
    rollouts: Vec<BikeRollout>,
    arcade_rollout: BikeRollout,
    arcade: ArcadeController,
    last: Option<PlanResult>,
}

impl BikeOptimizer {
    /// Builds N + 1 rollout worlds like the master of `sim`.
    pub fn new(sim: &Simulation, config: OptimizerConfig) -> Self {
        let dt = sim.config().control_dt;
        let steps = (config.horizon / dt).round().max(1.0) as usize;
        let rollout = || BikeRollout {
            world: sim.new_world(),
            bike: sim.bike().clone(),
            up: sim.up(),
            step_dt: dt,
            substeps: config.rollout_substeps.max(1),
            goal: LeanGoal::default(),
            drive: DriveInput::default(),
        };
        let planner_config = PlannerConfig {
            particles: config.particles.max(2),
            steps,
            seed: config.seed,
            threads: config.threads,
            refine: config.mode == OptimizerMode::Optimizer,
            control_cost_weight: config.control_cost_weight,
            ..PlannerConfig::default()
        };
        Self {
            planner: Planner::new(planner_config, bike_priors(config.mutation_scale)),
            rollouts: (0..config.particles.max(2)).map(|_| rollout()).collect(),
            arcade_rollout: rollout(),
            arcade: ArcadeController::default(),
            last: None,
            config,
        }
    }

    /// Forgets previous plans (after a reset or a lift).
    pub fn reset(&mut self) {
        self.planner.reset();
        self.arcade.reset();
        self.last = None;
    }

    /// The last frame's plan (trajectories, costs), for statistics and visualisation.
    pub fn last_plan(&self) -> Option<&PlanResult> {
        self.last.as_ref()
    }

    /// Plans one control step of `sim` towards `desired_lean` with the player's `drive`.
    pub fn controls(
        &mut self,
        sim: &Simulation,
        desired_lean: f64,
        drive: &DriveInput,
    ) -> Controls {
        let start = sim.world().snapshot();
        let goal = LeanGoal {
            lean: desired_lean,
            tolerance: self.config.lean_tolerance,
        };
        for rollout in self
            .rollouts
            .iter_mut()
            .chain(std::iter::once(&mut self.arcade_rollout))
        {
            rollout.goal = goal;
            rollout.drive = *drive;
        }
        let warm = match self.config.mode {
            OptimizerMode::Combined => Some(self.arcade_sequence(&start, desired_lean, drive)),
            OptimizerMode::Optimizer => None,
        };
        // Keep the arcade controller's memory in step with the master.
        let dt = sim.config().control_dt;
        self.arcade
            .controls(sim.bike(), sim.world(), desired_lean, drive, sim.up(), dt);
        let result = self
            .planner
            .plan(&mut self.rollouts, &start, warm.as_deref());
        let controls = self.rollouts[0].controls_for(&result.control);
        self.last = Some(result);
        controls
    }

    /// What the arcade controller would do over the horizon, from the master's state.
    fn arcade_sequence(
        &mut self,
        start: &crate::ode::WorldState,
        lean: f64,
        drive: &DriveInput,
    ) -> Vec<f64> {
        let steps = self.planner.config.steps;
        let mut arcade = self.arcade;
        let rollout = &mut self.arcade_rollout;
        rollout.restore(start);
        let mut sequence = Vec::with_capacity(steps * crate::bike::CONTROL_DIM);
        for k in 0..steps {
            let controls = arcade.controls(
                &rollout.bike,
                &rollout.world,
                lean,
                drive,
                rollout.up,
                rollout.step_dt,
            );
            sequence.extend_from_slice(controls.values());
            if rollout.step(controls.values(), k).is_none() {
                // The rest of the sequence repeats the last control; particle 1 replays
                // it and the planner costs the blow-up like any other.
                let last = controls.values().to_vec();
                while sequence.len() < steps * crate::bike::CONTROL_DIM {
                    sequence.extend_from_slice(&last);
                }
                break;
            }
        }
        sequence
    }
}
