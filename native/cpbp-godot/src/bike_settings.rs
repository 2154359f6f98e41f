//! The node's exports as the ride's settings: which controller drives and how the
//! planners plan. GDScript and the inspector may change them at any time; they are read
//! again before every physics tick.

use std::time::Duration;

use cpbp_core::control::{BaselineSettings, CostTolerances, OptimizerConfig, PlanWait};
use cpbp_core::physics::{PhysicsModel, RolloutStepping};
use cpbp_core::ride::PlannerSettings;

use crate::bike_simulation::BikeSimulation;

impl BikeSimulation {
    /// The exports, as the ride's settings: GDScript may change them at any time.
    pub(crate) fn sync_settings(&mut self) {
        let kind = self.controller_kind();
        let defaults = BaselineSettings::default();
        // The built ride's physics: a change of the export waits for the next build.
        let physics = self
            .sim()
            .map_or(PhysicsModel::from(self.physics), |sim| sim.config().physics);
        let mut optimizer = OptimizerConfig {
            particles: self.trajectories.clamp(1, 256) as usize,
            horizon: self.horizon.clamp(0.2, 3.0),
            tolerances: CostTolerances {
                lean: self.lean_tolerance_deg.clamp(1.0, 30.0).to_radians(),
                rider: self.rider_tolerance_cm.clamp(1.0, 20.0) / 100.0,
            },
            threads: self.planning_threads.clamp(0, 64) as usize,
            seed: self.planner_seed as u64,
            baseline: BaselineSettings {
                knots: self.baseline_knots.clamp(2, 36) as usize,
                noise: finite_or(self.baseline_noise, defaults.noise).clamp(0.05, 2.0),
                temperature: finite_or(self.mppi_temperature, defaults.temperature)
                    .clamp(0.001, 1.0),
                steering_only: self.baseline_steering_only,
            },
            ..OptimizerConfig::default()
        }
        .rolling_out_in(physics);
        if self.rollout_substeps > 0 {
            optimizer.rollout_stepping =
                RolloutStepping::uniform(self.rollout_substeps.min(8) as usize);
        }
        let planner = PlannerSettings {
            optimizer,
            wait: if self.wait_for_every_plan {
                PlanWait::EveryPlan
            } else {
                PlanWait::AtMost(Duration::from_secs_f64(
                    self.plan_wait_ms.clamp(0.0, 1000.0) / 1000.0,
                ))
            },
        };
        if let Some(ride) = &mut self.ride {
            ride.set_controller(kind);
            ride.planner = planner;
            ride.wait_for_throttle = self.wait_for_throttle;
        }
    }
}

/// `value`, or `fallback` if it is not a number (an inspector typo, a script's NaN).
fn finite_or(value: f64, fallback: f64) -> f64 {
    if value.is_finite() {
        value
    } else {
        fallback
    }
}
