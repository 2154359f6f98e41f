//! The rider falls off in a crash and is put back on with the bike: the hand and foot let
//! go so the same bodies tumble, nobody plans for a riderless bike, a lift puts the rider
//! back in the riding pose, and a snapshot carries who is on the bike, so a replica steps
//! exactly as the master does.

use crate::common;

use cpbp_core::bike::Part;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Ride};
use cpbp_core::simulation::Simulation;
use glam::DVec3;

/// Where `part` is relative to `on` (in `on`'s body coordinates).
fn relative(sim: &Simulation, part: Part, on: Part) -> DVec3 {
    let world = sim.world();
    let base = sim.bike().body(on);
    let rotation = world.body_quaternion(base);
    let offset = world.body_position(sim.bike().body(part)) - world.body_position(base);
    rotation.inverse() * offset
}

/// The torso's place on the frame.
fn torso_on_frame(sim: &Simulation) -> DVec3 {
    relative(sim, Part::Torso, Part::Frame)
}

/// A ride knocked over sideways at 15 km/h: steps until it crashes (at most 3 s).
fn knocked_over(kind: ControllerKind) -> Ride {
    let mut ride = common::ride_in(PhysicsModel::Exact, kind, 15.0, 5);
    common::ride(&mut ride, 2.0, 0.0);
    let sideways = ride
        .sim()
        .bike()
        .heading(ride.sim().world(), ride.sim().up())
        .cross(DVec3::Y);
    ride.push(sideways * 400.0);
    for _ in 0..3 * common::FRAMES_PER_SECOND {
        if ride.step().crashed.is_some() {
            return ride;
        }
    }
    panic!("a 400 N·s shove did not knock the bike over");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_rider_falls_off_nobody_plans_and_a_lift_puts_the_rider_back() {
    let mut ride = knocked_over(ControllerKind::COMBINED);
    let seated = {
        let mut fresh = common::ride_in(PhysicsModel::Exact, ControllerKind::ARCADE, 15.0, 1);
        fresh.step();
        torso_on_frame(fresh.sim())
    };
    assert!(!ride.sim().rider_is_on(), "the rider let go");
    let gaps = ride.sim().bike().rider_hold_gaps(ride.sim().world());
    assert!(
        gaps.iter().all(|gap| *gap < 0.01),
        "held until the crash: {gaps:?}"
    );
    for _ in 0..2 * common::FRAMES_PER_SECOND {
        ride.step();
        assert!(ride.plan().is_none(), "nobody plans for a riderless bike");
    }
    let thrown = (torso_on_frame(ride.sim()) - seated).length();
    let [foot, hand] = ride.sim().bike().rider_hold_gaps(ride.sim().world());
    assert!(
        thrown > 0.2 && foot > 0.2 && hand > 0.2,
        "the rider moved {thrown:.2} m from the seat, the foot {foot:.2} m from the peg, \
         the hand {hand:.2} m from the grip"
    );
    ride.lift_upright();
    assert!(ride.sim().rider_is_on(), "back on");
    let back = (torso_on_frame(ride.sim()) - seated).length();
    let gaps = ride.sim().bike().rider_hold_gaps(ride.sim().world());
    assert!(back < 0.02, "in the riding pose again ({back:.3} m off)");
    assert!(
        gaps.iter().all(|gap| *gap < 1e-6),
        "foot and hand held again: {gaps:?}"
    );
    common::ride(&mut ride, 3.0, 0.0);
    assert_eq!(ride.sim().crashed(), None, "rides on after the lift");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with a controller: run in release (tools/test.sh does)"
)]
fn a_replica_of_a_riderless_bike_steps_exactly_as_the_master() {
    let mut ride = knocked_over(ControllerKind::ARCADE);
    let mut replica = ride.sim().replica();
    replica
        .world_mut()
        .restore(&ride.sim().world().snapshot())
        .expect("same shape");
    assert!(!replica.rider_is_on(), "the snapshot says the rider is off");
    for _ in 0..common::FRAMES_PER_SECOND {
        ride.step();
        replica.step();
    }
    assert_eq!(ride.sim().world().snapshot(), replica.world().snapshot());
}

/// Knocked over at 15 km/h, the bike slides on its side and scrapes the road (sparks in
/// the game), where ridden upright nothing of it but the tyres touches.
#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn a_bike_sliding_on_its_side_scrapes_the_road_and_an_upright_one_does_not() {
    let mut upright = common::ride_in(PhysicsModel::Exact, ControllerKind::ARCADE, 15.0, 1);
    common::ride(&mut upright, 2.0, 0.0);
    let (sim, up) = (upright.sim(), upright.sim().up());
    assert!(
        sim.bike().scrapes(sim.world(), up).is_empty(),
        "riding upright"
    );

    let mut ride = knocked_over(ControllerKind::ARCADE);
    let mut fastest = 0.0_f64;
    for _ in 0..common::FRAMES_PER_SECOND {
        ride.step();
        let (sim, up) = (ride.sim(), ride.sim().up());
        for (at, speed) in sim.bike().scrapes(sim.world(), up) {
            assert!(at.y.abs() < 0.05, "a scrape on the road, not at {at}");
            fastest = fastest.max(speed);
        }
    }
    assert!(
        fastest > 1.0,
        "slid on its side at {fastest:.2} m/s at most"
    );
}
