//! The rider's feet (`bike::Feet`): brought to a stop the bike stands on a foot put down,
//! indefinitely, with every controller, and pulls away when the throttle opens.

use crate::common;

use cpbp_core::bike::DriveInput;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};

/// Sets the triggers: `throttle` towards 8 km/h, or the brake.
fn drive(ride: &mut Ride, throttle: bool) {
    let drive = DriveInput {
        throttle: if throttle { 1.0 } else { 0.0 },
        brake: if throttle { 0.0 } else { 1.0 },
        max_speed: 8.0 / 3.6,
    };
    ride.set_intent(Intent {
        drive,
        ..*ride.intent()
    });
}

/// Rides `seconds`, failing on a crash; returns the largest lean (degrees) and in how
/// many steps a foot stood on the ground.
fn ride_for(ride: &mut Ride, seconds: f64) -> (f64, usize) {
    let (mut lean, mut on_a_foot) = (0f64, 0);
    for _ in 0..(seconds * common::FRAMES_PER_SECOND as f64) as usize {
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "{:?} fell", ride.controller());
        lean = lean.max(common::lean(ride).abs().to_degrees());
        let sim = ride.sim();
        let (left, right) = sim.bike().feet_on_ground(sim.world());
        on_a_foot += usize::from(left || right);
    }
    (lean, on_a_foot)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn every_controller_stops_on_a_foot_and_pulls_away() {
    // The foot holds the bike whoever rides it, so arcade (whose steps cost nothing)
    // stands 30 s to show it lasts; the planners stand 10 s, long enough to show they
    // leave the foot be, and the rest would cost make test a minute of planning.
    for (kind, standing) in [
        (ControllerKind::ARCADE, 30.0),
        (ControllerKind::COMBINED, 10.0),
        (ControllerKind::OPTIMIZER, 10.0),
    ] {
        let mut ride = common::ride_in(PhysicsModel::Exact, kind, 8.0, 10);
        ride_for(&mut ride, 3.0);
        drive(&mut ride, false);
        ride_for(&mut ride, 2.0);
        let (lean, on_a_foot) = ride_for(&mut ride, standing);
        assert!(lean < 5.0, "{kind:?} leaned {lean:.1}° standing");
        assert!(on_a_foot > 0, "{kind:?} stood without a foot down");
        // The planners' plans carry the triggers they were made with: the feet come up
        // a step or two after the throttle opens.
        drive(&mut ride, true);
        let (lean_setting_off, _) = ride_for(&mut ride, 1.0);
        let (lean, on_a_foot) = ride_for(&mut ride, 3.0);
        let lean = lean.max(lean_setting_off);
        assert!(lean < 10.0, "{kind:?} leaned {lean:.1}° pulling away");
        assert_eq!(on_a_foot, 0, "{kind:?} rode on with a foot down");
        let sim = ride.sim();
        let kmh = sim.bike().forward_speed(sim.world(), sim.up()) * 3.6;
        assert!(kmh > 7.5, "{kind:?} at {kmh:.1} km/h after 4 s");
    }
}

#[test]
fn a_released_bike_stands_on_a_foot_from_rest() {
    // No controller's help and no crutch: put down at rest, the bike falls onto a foot
    // and stays there.
    let mut ride = Ride::new(
        common::flat_ride_in(PhysicsModel::Exact),
        ControllerKind::MANUAL,
    );
    let (lean, on_a_foot) = ride_for(&mut ride, 10.0);
    assert!(lean < 5.0, "leaned {lean:.1}°");
    assert!(on_a_foot > 100, "a foot down in only {on_a_foot} steps");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn every_controller_rides_at_walking_pace_straight_and_round_the_tightest_turn() {
    // 3.2 km/h, just above where the feet come down; then 5 km/h on the turn stick's
    // tightest circle, 3 m (3.7° of lean). Planners wobble about 10° in the turn.
    let tightest = (5.0f64 / 3.6).powi(2) / (3.0 * 9.81);
    for kind in [
        ControllerKind::ARCADE,
        ControllerKind::COMBINED,
        ControllerKind::OPTIMIZER,
    ] {
        let mut ride = common::ride_in(PhysicsModel::Exact, kind, 3.2, 10);
        common::ride(&mut ride, 3.0, 0.0);
        let (lean, _) = ride_for(&mut ride, 9.0);
        assert!(lean < 5.0, "{kind:?} leaned {lean:.1}° at 3.2 km/h");
        let mut ride = common::ride_in(PhysicsModel::Exact, kind, 5.0, 10);
        common::ride(&mut ride, 3.0, tightest.atan());
        ride_for(&mut ride, 9.0);
    }
}

#[test]
fn standing_on_a_foot_the_rider_holds_the_bar_straight() {
    // A bar left at full lock leans the bike onto the foot (the fork's flop) and sets
    // off steered into the lean: the rider straightens it whatever the controller asks.
    let mut ride = Ride::new(
        common::flat_ride_in(PhysicsModel::Exact),
        ControllerKind::MANUAL,
    );
    let turning = |ride: &mut Ride, throttle: f64| {
        let mut intent = *ride.intent();
        intent.steer_rate = 1.0;
        intent.drive.throttle = throttle;
        intent.drive.max_speed = 5.0 / 3.6;
        ride.set_intent(intent);
    };
    turning(&mut ride, 0.0);
    let bar = |ride: &Ride| {
        ride.sim()
            .bike()
            .steering(ride.sim().world())
            .0
            .to_degrees()
    };
    let mut widest = 0f64;
    for _ in 0..3 * common::FRAMES_PER_SECOND {
        ride.step();
        widest = widest.max(bar(&ride).abs());
    }
    assert!(widest < 2.0, "the bar turned {widest:.1}° with a foot down");
    // Pulling away, the feet come up and the bar is the controller's again.
    turning(&mut ride, 1.0);
    for _ in 0..common::FRAMES_PER_SECOND / 2 {
        ride.step();
    }
    assert!(
        bar(&ride) > 10.0,
        "the bar at {:.1}° riding off",
        bar(&ride)
    );
}
