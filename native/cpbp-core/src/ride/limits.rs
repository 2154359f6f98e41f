//! The trajectory counts the ride takes, as the settings schema (`crate::settings`) gives
//! them: the tools and the tests read these. Every other setting's range is its schema
//! entry's (`settings::HORIZON_S.limit()`).

use crate::settings::{self, Range};

/// An inclusive range of one setting.
pub type Limit = Range;

/// Trajectories a planner simulates per control step (N).
pub const TRAJECTORIES: Limit = settings::TRAJECTORIES.limit();
/// The trajectories the game's automatic choice moves between (`auto_trajectories`).
pub const AUTO_TRAJECTORIES: Limit = settings::AUTO_TRAJECTORY_RANGE;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamps_into_the_range_and_replaces_what_is_not_a_number() {
        let horizon = settings::HORIZON_S.limit();
        assert_eq!(horizon.clamp(9.0, 1.2), 3.0);
        assert_eq!(horizon.clamp(f64::NAN, 1.2), 1.2);
        assert_eq!(horizon.clamp(f64::NEG_INFINITY, 99.0), 3.0);
        assert_eq!(TRAJECTORIES.clamp_count(-4), 1);
        assert_eq!(TRAJECTORIES.clamp_count(1_000), 256);
    }
}
