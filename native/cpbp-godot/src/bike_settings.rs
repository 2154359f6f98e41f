//! The node's exports as the ride's settings: which controller drives, how the planners
//! plan and what the pedals drive. GDScript and the inspector may change them at any
//! time, in any order; before every physics tick they are read, clamped to the core's
//! limits, and handed to the ride when they differ from what it has.

use std::time::Duration;

use cpbp_core::control::{BaselineSettings, CostTolerances, OptimizerConfig, PlanWait};
use cpbp_core::physics::{PhysicsModel, RolloutStepping};
use cpbp_core::ride::{limits, PlannerSettings, GAME_PLAN_WAIT};

use crate::bike_simulation::BikeSimulation;

impl BikeSimulation {
    /// The exports, as the ride's settings: GDScript may change them at any time.
    pub(crate) fn sync_settings(&mut self) {
        let kind = self.controller_kind();
        let planner = self.planner_settings();
        if let Some(drive) = self.drive().filter(|d| *d != self.intent.drive) {
            self.intent.drive = drive;
            self.apply_intent();
        }
        if let Some(ride) = &mut self.ride {
            if ride.controller() != kind {
                ride.set_controller(kind);
            }
            if ride.planner != planner {
                ride.planner = planner;
            }
            ride.wait_for_throttle = self.wait_for_throttle;
        }
    }

    /// The planners' settings the exports ask for, within the core's limits (a value
    /// that is not a number counts as the default).
    fn planner_settings(&self) -> PlannerSettings {
        let defaults = OptimizerConfig::default();
        let baseline = BaselineSettings::default();
        // The built ride's physics: a change of the export waits for the next build.
        let physics = self
            .sim()
            .map_or(PhysicsModel::from(self.physics), |sim| sim.config().physics);
        let mut optimizer = OptimizerConfig {
            particles: limits::TRAJECTORIES.clamp_count(self.trajectories.into()),
            horizon: limits::HORIZON_S.clamp(self.horizon, defaults.horizon),
            tolerances: CostTolerances {
                lean: limits::LEAN_TOLERANCE_DEG
                    .clamp(
                        self.lean_tolerance_deg,
                        defaults.tolerances.lean.to_degrees(),
                    )
                    .to_radians(),
                rider: limits::RIDER_TOLERANCE_CM
                    .clamp(self.rider_tolerance_cm, defaults.tolerances.rider * 100.0)
                    / 100.0,
            },
            threads: limits::PLANNING_THREADS.clamp_count(self.planning_threads.into()),
            seed: self.planner_seed as u64,
            baseline: BaselineSettings {
                knots: limits::BASELINE_KNOTS.clamp_count(self.baseline_knots.into()),
                noise: limits::BASELINE_NOISE.clamp(self.baseline_noise, baseline.noise),
                temperature: limits::MPPI_TEMPERATURE
                    .clamp(self.mppi_temperature, baseline.temperature),
                steering_only: self.baseline_steering_only,
            },
            policy: crate::policy_model::policy_at(&self.policy_model),
            ..defaults
        }
        .rolling_out_in(physics);
        let rollout_substeps = limits::ROLLOUT_SUBSTEPS.clamp_count(self.rollout_substeps.into());
        if rollout_substeps > 0 {
            optimizer.rollout_stepping = RolloutStepping::uniform(rollout_substeps);
        }
        PlannerSettings {
            optimizer,
            auto_trajectories: self.auto_trajectories,
            wait: if self.wait_for_every_plan {
                PlanWait::EveryPlan
            } else {
                let default_ms = GAME_PLAN_WAIT.as_secs_f64() * 1000.0;
                let wait_ms = limits::PLAN_WAIT_MS.clamp(self.plan_wait_ms, default_ms);
                PlanWait::AtMost(Duration::from_secs_f64(wait_ms / 1000.0))
            },
        }
    }
}
