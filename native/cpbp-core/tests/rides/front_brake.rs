//! The front brake (`bike::FrontBrake`): the brake trigger stops the bike with both
//! wheels, letting off before the rear lifts; with the rider's weight forward it holds a
//! stoppie, the rear wheel up, and the bike stands on a foot once stopped.

use crate::common;

use cpbp_core::bike::{DriveInput, RiderPosition};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent};

/// From 20 km/h, `brake` with the weight at `forward` for 3 s: the lowest pitch (degrees,
/// nose down negative) and when the bike stopped (s). It must not fall.
fn brake_from_20(kind: ControllerKind, brake: f64, forward: f64) -> (f64, f64) {
    let mut ride = common::ride_in(PhysicsModel::Exact, kind, 20.0, 10);
    common::ride(&mut ride, 3.0, 0.0);
    ride.set_intent(Intent {
        drive: DriveInput {
            throttle: 0.0,
            brake,
            max_speed: 20.0 / 3.6,
        },
        rider: RiderPosition {
            forward,
            right: 0.0,
        },
        ..*ride.intent()
    });
    let (mut lowest, mut stopped) = (0f64, f64::NAN);
    for step in 0..3 * common::FRAMES_PER_SECOND {
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "{kind:?} fell braking");
        lowest = lowest.min(common::pitch(&ride));
        let sim = ride.sim();
        if stopped.is_nan() && sim.bike().forward_speed(sim.world(), sim.up()) < 0.3 {
            stopped = (step + 1) as f64 / common::FRAMES_PER_SECOND as f64;
        }
    }
    (lowest, stopped)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_brake_stops_the_bike_with_the_rear_down_and_a_stoppie_lifts_it() {
    for kind in [ControllerKind::ARCADE, ControllerKind::COMBINED] {
        let (lowest, stopped) = brake_from_20(kind, 0.5, 0.0);
        assert!(
            lowest > -6.0,
            "{kind:?} pitched to {lowest:.1}° at half brake"
        );
        assert!(stopped < 1.5, "{kind:?} took {stopped:.2} s to stop");
        let (lowest, _) = brake_from_20(kind, 1.0, 1.0);
        assert!(lowest < -7.0, "{kind:?} stoppie only {lowest:.1}°");
    }
}
