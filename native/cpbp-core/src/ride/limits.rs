//! The ranges the ride's settings may be set in, by a player, a level designer or a
//! script, as the settings schema (`crate::settings`) gives them: the game node's clamps
//! and the tools read these. Each name says its unit.

use crate::settings::{self, Range};

/// An inclusive range of one setting.
pub type Limit = Range;

/// Trajectories a planner simulates per control step (N).
pub const TRAJECTORIES: Limit = settings::TRAJECTORIES.limit();
/// The trajectories the game's automatic choice moves between (`auto_trajectories`).
pub const AUTO_TRAJECTORIES: Limit = settings::AUTO_TRAJECTORY_RANGE;
/// How far ahead the planners plan (s).
pub const HORIZON_S: Limit = settings::HORIZON_S.limit();
/// Lean error that costs one unit (degrees).
pub const LEAN_TOLERANCE_DEG: Limit = settings::LEAN_TOLERANCE_DEG.limit();
/// Rider position error that costs one unit at full stick (cm).
pub const RIDER_TOLERANCE_CM: Limit = settings::RIDER_TOLERANCE_CM.limit();
/// Longest the game waits at a control step for a plan (ms).
pub const PLAN_WAIT_MS: Limit = settings::PLAN_WAIT_MS.limit();
/// Threads that simulate the trajectories (0: one per core).
pub const PLANNING_THREADS: Limit = settings::PLANNING_THREADS.limit();
/// ODE steps per planning step in the rollouts (0: the physics model's own).
pub const ROLLOUT_SUBSTEPS: Limit = settings::ROLLOUT_SUBSTEPS.limit();
/// ODE steps per control step of the master.
pub const SUBSTEPS: Limit = settings::SUBSTEPS.limit();
/// The baseline planners' knots over the horizon.
pub const BASELINE_KNOTS: Limit = settings::BASELINE_KNOTS.limit();
/// The baselines' knot perturbation, as a share of the steering prior's σ.
pub const BASELINE_NOISE: Limit = settings::BASELINE_NOISE.limit();
/// MPPI's temperature, relative to the spread of its candidates' costs.
pub const MPPI_TEMPERATURE: Limit = settings::MPPI_TEMPERATURE.limit();
/// Speed full throttle drives towards (km/h).
pub const MAX_SPEED_KMH: Limit = settings::MAX_SPEED_KMH.limit();
/// Share of the rear motor's torque that full throttle or brake uses.
pub const MOTOR_FORCE: Limit = settings::MOTOR_FORCE.limit();

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamps_into_the_range_and_replaces_what_is_not_a_number() {
        assert_eq!(HORIZON_S.clamp(9.0, 1.2), 3.0);
        assert_eq!(HORIZON_S.clamp(f64::NAN, 1.2), 1.2);
        assert_eq!(HORIZON_S.clamp(f64::NEG_INFINITY, 99.0), 3.0);
        assert_eq!(TRAJECTORIES.clamp_count(-4), 1);
        assert_eq!(TRAJECTORIES.clamp_count(1_000), 256);
    }
}
