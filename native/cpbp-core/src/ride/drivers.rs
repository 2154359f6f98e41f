//! The controllers behind the registry: thin adapters from the one controller interface to
//! the arcade controller, manual driving and the planning thread.

use super::controller::{Controller, Intent, PlannerSettings, RideState};
use crate::bike::{manual_controls, Controls};
use crate::control::{AnytimeOptimizer, ArcadeController, HandoverStats, OptimizerMode, Plan};
use crate::simulation::Simulation;

/// The arcade controller (thesis §4.3.2) on the master.
#[derive(Default)]
pub struct ArcadeDriver(ArcadeController);

impl Controller for ArcadeDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        self.0.controls_of(state.sim, &state.goal)
    }

    fn reset(&mut self) {
        self.0.reset();
    }
}

/// Nobody balances: the bar follows the steering rate input.
pub struct ManualDriver;

impl Controller for ManualDriver {
    fn controls(&mut self, state: &RideState<'_>, intent: &Intent) -> Controls {
        manual_controls(
            state.sim.bike(),
            state.sim.world(),
            &intent.drive,
            intent.steer_rate,
        )
    }

    fn reset(&mut self) {}
}

/// C-PBP on its own thread (optimizer or combined mode), handed over at control steps.
pub struct PlannerDriver {
    mode: OptimizerMode,
    anytime: AnytimeOptimizer,
}

impl PlannerDriver {
    pub fn new(sim: &Simulation, mode: OptimizerMode, planner: &PlannerSettings) -> Self {
        Self {
            mode,
            anytime: AnytimeOptimizer::new(sim, planner.wait),
        }
    }
}

impl Controller for PlannerDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        self.anytime.wait = state.planner.wait;
        let config = crate::control::OptimizerConfig {
            mode: self.mode,
            ..state.planner.optimizer.clone()
        };
        self.anytime.controls(state.sim, &state.goal, &config)
    }

    fn reset(&mut self) {
        self.anytime.reset();
    }

    fn plan(&self) -> Option<&Plan> {
        self.anytime.plan()
    }

    fn handover(&self) -> Option<HandoverStats> {
        Some(self.anytime.stats)
    }

    fn failure(&self) -> Option<&str> {
        self.anytime.failure()
    }

    fn inject_fault(&mut self, message: &str) {
        self.anytime.inject_fault(message);
    }
}
