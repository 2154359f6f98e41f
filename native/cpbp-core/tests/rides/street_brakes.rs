//! The game's street bike (scenes/bike/bikes/street_390.tres) brakes as a road bike with
//! ABS does: a full brake from 60 km/h averages 0.9 g or more from the moment the trigger
//! is pulled, the rear tyre stays on the road, no step of it speeds the bike up, and it
//! ends standing; with the weight forward the same trigger still lifts a stoppie. Without
//! ABS (the players' Pro assist) the same full brake throws the rider over the bar.

use crate::common;

use cpbp_core::bike::{
    index, Controls, CrashCause::Touched, DriveInput, Part, RiderPosition, UPPER,
};
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

/// A `kind` ride of the street bike at `kmh`, planners at N = 5 waiting for every plan.
fn street_ride(kind: ControllerKind, kmh: f64) -> Ride {
    let sim = common::flat_ride_with(SimulationConfig {
        bike: common::street_bike(),
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = 5;
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    common::ride(&mut ride, kmh / 3.6 / 2.0 + 3.0, 0.0);
    ride
}

fn speed(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().forward_speed(sim.world(), sim.up())
}

/// What a full brake did: its mean deceleration (g, v₀²/2d from the trigger), the
/// highest the rear tyre rose off the road (m) and the least a step slowed the bike (g).
struct Stop {
    mean_g: f64,
    rear_lift: f64,
    least_step_g: f64,
}

fn full_brake(ride: &mut Ride) -> Stop {
    let dt = ride.sim().config().control_dt;
    let g = ride.sim().config().gravity.length();
    let start = speed(ride);
    common::full_brake(ride);
    let (mut distance, mut last) = (0.0, start);
    let mut stop = Stop {
        mean_g: 0.0,
        rear_lift: 0.0,
        least_step_g: f64::INFINITY,
    };
    while last > 0.05 {
        ride.step();
        let sim = ride.sim();
        assert_eq!(sim.crashed(), None, "fell braking");
        let v = speed(ride);
        distance += (last + v.max(0.0)) / 2.0 * dt;
        stop.least_step_g = stop.least_step_g.min((last - v) / dt / g);
        // The road is flat at height 0.
        let rear = sim.bike().tyre_contacts(sim.world(), sim.up()).0;
        stop.rear_lift = stop.rear_lift.max(rear.dot(sim.up()));
        last = v;
    }
    stop.mean_g = start * start / (2.0 * distance) / g;
    stop
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn a_full_brake_from_60_averages_09_g_with_the_rear_on_the_road_and_ends_standing() {
    for kind in [ControllerKind::ARCADE, ControllerKind::COMBINED] {
        let mut ride = street_ride(kind, 60.0);
        let stop = full_brake(&mut ride);
        assert!(stop.mean_g >= 0.9, "{kind:?}: {:.3} g", stop.mean_g);
        assert!(
            stop.rear_lift < 0.001,
            "{kind:?}: the rear rose {:.1} mm",
            stop.rear_lift * 1000.0
        );
        assert!(
            stop.least_step_g > 0.0,
            "{kind:?}: a step sped up at {:.2} g",
            stop.least_step_g
        );
        common::ride(&mut ride, 3.0, 0.0);
        assert_eq!(ride.sim().crashed(), None, "{kind:?} fell standing");
        assert!(common::lean(&ride).abs() < 5f64.to_radians());
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_weight_forward_still_lifts_a_stoppie_on_the_street_bike() {
    let mut ride = street_ride(ControllerKind::ARCADE, 20.0);
    ride.set_intent(Intent {
        drive: DriveInput {
            throttle: 0.0,
            brake: 1.0,
            max_speed: 20.0 / 3.6,
        },
        rider: RiderPosition {
            forward: 1.0,
            right: 0.0,
        },
        ..*ride.intent()
    });
    let mut lowest = 0f64;
    for _ in 0..3 * common::FRAMES_PER_SECOND {
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "fell in the stoppie");
        lowest = lowest.min(common::pitch(&ride));
    }
    assert!(lowest < -7.0, "stoppie only {lowest:.1}°");
}

/// The wrists' sideways angles (the larger, rad) after half a second of raw controls that
/// drive the arms' sideways axes to their top rate, from a ride at 30 km/h, with the full
/// brake or without it.
fn wrists_driven_sideways(braking: bool) -> f64 {
    let mut ride = street_ride(ControllerKind::ARCADE, 30.0);
    let radius = ride.sim().bike().params().wheel_radius;
    let mut controls = Controls::default();
    for axis in 1..3 {
        for joint in [index::SHOULDER, index::WRIST] {
            controls.set(joint + axis, UPPER[joint + axis]);
        }
    }
    let brake = if braking { 1.0 } else { 0.0 };
    DriveInput {
        throttle: 0.0,
        brake,
        max_speed: 30.0 / 3.6,
    }
    .apply(radius, &mut controls);
    ride.set_raw_controls(controls);
    for _ in 0..common::FRAMES_PER_SECOND / 2 {
        ride.step();
    }
    let angles = ride.sim().bike().rider_joint_angles(ride.sim().world());
    angles[9].abs().max(angles[10].abs())
}

/// Braking, the street bike's rider holds the arms in the riding pose sideways whatever a
/// planner asks of them: the optimizer's random wrist targets otherwise walked the wrists
/// to their limits over a stop from 90 km/h and the rider's weight 0.2 m to one side,
/// where no steering holds the bike. Off the brake the arms follow what they are asked.
#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn braking_the_rider_holds_the_arms_sideways_whatever_a_planner_asks() {
    let held = wrists_driven_sideways(true).to_degrees();
    let free = wrists_driven_sideways(false).to_degrees();
    assert!(held < 3.0, "braking, the wrists turned {held:.1}°");
    assert!(free > 15.0, "off the brake they follow: only {free:.1}°");
}

#[test]
fn without_abs_a_full_brake_from_60_throws_the_rider_over_the_bar_where_abs_stops_standing() {
    // Arcade balances both (the players' Standard and Pro assists); the same full brake.
    for abs in [true, false] {
        let mut ride = street_ride(ControllerKind::ARCADE, 60.0);
        ride.set_aids(abs, 1.0);
        assert_eq!(ride.sim().config().abs, abs);
        common::full_brake(&mut ride);
        let mut crash = None;
        for _ in 0..90 {
            ride.step();
            crash = crash.or(ride.sim().crashed());
        }
        if abs {
            assert_eq!(crash, None, "with ABS it stops standing");
            assert!(speed(&ride).abs() < 0.1, "and stopped");
        } else {
            // No rear-lift mitigation: the rear rises and the bike goes over its front tyre.
            let crash = crash.expect("without ABS the bike goes over");
            assert_eq!(crash.cause, Touched(Part::Torso), "{crash:?}");
        }
    }
}

#[test]
fn abs_comes_back_on_and_a_lean_share_limits_the_turn() {
    let mut ride = street_ride(ControllerKind::ARCADE, 20.0);
    let full = ride.sim().config().bike.max_lean;
    ride.set_aids(false, 0.75);
    assert!(!ride.sim().config().abs);
    let mut intent = Intent::cruise(20.0);
    intent.lean = Some(2.0);
    ride.set_intent(intent);
    assert!(
        (ride.desired_lean() - 0.75 * full).abs() < 1e-12,
        "held to 3/4 of the lean"
    );
    ride.set_aids(true, 1.0);
    assert!(ride.sim().config().abs, "on again");
    assert_eq!(ride.desired_lean(), full, "the whole lean again, exactly");
    ride.set_aids(true, f64::NAN);
    assert_eq!(
        ride.desired_lean(),
        full,
        "a share that is not a number is the whole"
    );
}
