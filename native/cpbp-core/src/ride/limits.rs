//! The ranges the ride's settings may be set in, by a player, a level designer or a
//! script: the game node's inspector ranges and its clamps of what scripts set both read
//! these, and the experiment's tools get the trajectory count's through the registry's
//! copy (tools/cpbp_experiment/controllers.json). Each name says its unit.

use crate::bike::TOP_SPEED_KMH;

/// An inclusive range of one setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    pub min: f64,
    pub max: f64,
}

impl Limit {
    const fn new(min: f64, max: f64) -> Self {
        Self { min, max }
    }

    /// `value` within the range, or `fallback` (clamped too) if it is not a number.
    pub fn clamp(self, value: f64, fallback: f64) -> f64 {
        let value = if value.is_finite() { value } else { fallback };
        value.clamp(self.min, self.max)
    }

    /// A whole-number setting within the range.
    pub fn clamp_count(self, value: i64) -> usize {
        value.clamp(self.min as i64, self.max as i64) as usize
    }
}

/// Trajectories a planner simulates per control step (N).
pub const TRAJECTORIES: Limit = Limit::new(1.0, 256.0);
/// The trajectories the game's automatic choice moves between (`auto_trajectories`).
pub const AUTO_TRAJECTORIES: Limit = Limit::new(5.0, 64.0);
/// How far ahead the planners plan (s).
pub const HORIZON_S: Limit = Limit::new(0.2, 3.0);
/// Lean error that costs one unit (degrees).
pub const LEAN_TOLERANCE_DEG: Limit = Limit::new(1.0, 30.0);
/// Rider position error that costs one unit at full stick (cm).
pub const RIDER_TOLERANCE_CM: Limit = Limit::new(1.0, 20.0);
/// Longest the game waits at a control step for a plan (ms).
pub const PLAN_WAIT_MS: Limit = Limit::new(0.0, 1000.0);
/// Threads that simulate the trajectories (0: one per core).
pub const PLANNING_THREADS: Limit = Limit::new(0.0, 64.0);
/// ODE steps per planning step in the rollouts (0: the physics model's own).
pub const ROLLOUT_SUBSTEPS: Limit = Limit::new(0.0, 8.0);
/// ODE steps per control step of the master.
pub const SUBSTEPS: Limit = Limit::new(1.0, 16.0);
/// The baseline planners' knots over the horizon.
pub const BASELINE_KNOTS: Limit = Limit::new(2.0, 36.0);
/// The baselines' knot perturbation, as a share of the steering prior's σ.
pub const BASELINE_NOISE: Limit = Limit::new(0.05, 2.0);
/// MPPI's temperature, relative to the spread of its candidates' costs.
pub const MPPI_TEMPERATURE: Limit = Limit::new(0.001, 1.0);
/// Speed full throttle drives towards (km/h).
pub const MAX_SPEED_KMH: Limit = Limit::new(1.0, TOP_SPEED_KMH);
/// Share of the rear motor's torque that full throttle or brake uses.
pub const MOTOR_FORCE: Limit = Limit::new(0.1, 1.0);

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
