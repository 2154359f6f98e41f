//! The controllers behind the registry: thin adapters from the one controller interface to
//! the arcade controller, manual driving and the planning thread.

use super::controller::{Controller, Intent, PlannerSettings, RideState};
use crate::bike::{manual_controls, Controls};
use crate::control::{AnytimeOptimizer, ArcadeController, HandoverStats, Plan, PlannerSpec};
use crate::simulation::Simulation;

/// The arcade controller (thesis §4.3.2) on the master.
#[derive(Default)]
pub struct ArcadeDriver(ArcadeController);

impl ArcadeDriver {
    pub fn boxed() -> Box<dyn Controller> {
        Box::<Self>::default()
    }
}

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

impl ManualDriver {
    pub fn boxed() -> Box<dyn Controller> {
        Box::new(Self)
    }
}

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

/// A planner on its own thread, handed over at control steps.
pub struct PlannerDriver {
    anytime: AnytimeOptimizer,
}

impl PlannerDriver {
    pub fn new(sim: &Simulation, spec: &'static PlannerSpec, planner: &PlannerSettings) -> Self {
        Self {
            anytime: AnytimeOptimizer::new(sim, spec, planner.wait),
        }
    }
}

impl Controller for PlannerDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        self.anytime.wait = state.planner.wait;
        self.anytime
            .controls(state.sim, &state.goal, &state.planner.optimizer)
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
