//! A rewind puts the ride back exactly: ridden on from the moment with the same intents
//! the ride repeats what it did then, bit for bit (the arcade controller's memory kept);
//! the history holds what it was asked and no more, and forgets a respawn's past.

mod common;

use cpbp_core::bike::{DriveInput, Placement, RiderPosition};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, RewindRefusal, Ride};
use cpbp_core::simulation::SimulationConfig;
use glam::{DQuat, DVec3};

/// The intent of step `i`: throttle towards 25 km/h, a turn that swings right and left,
/// the rider's weight moving, the brake in the last stretch.
fn intent_at(i: usize) -> Intent {
    let t = i as f64 / 30.0;
    Intent {
        drive: DriveInput {
            throttle: if t < 6.0 { 0.8 } else { 0.0 },
            brake: if t >= 6.0 { 0.5 } else { 0.0 },
            max_speed: 25.0 / 3.6,
        },
        turn: 0.4 * (t * 0.9).sin(),
        rider: RiderPosition {
            forward: 0.3 * (t * 1.3).sin(),
            right: 0.2 * (t * 0.7).cos(),
        },
        ..Intent::default()
    }
}

fn ride() -> Ride {
    let sim = common::flat_ride_in(PhysicsModel::Exact);
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
    ride.keep_history(10.0);
    ride
}

#[test]
fn ridden_on_from_a_rewind_the_ride_repeats_exactly() {
    let mut ride = ride();
    let mut states = Vec::new();
    for i in 0..240 {
        ride.set_intent(intent_at(i));
        ride.step();
        states.push(ride.sim().world().snapshot());
    }
    // Five seconds back from step 240: the moment before step 90.
    let back = ride.rewind(5.0).expect("eight seconds kept");
    assert!((back - 5.0).abs() < 1e-9, "{back}");
    assert_eq!(ride.steps(), 90);
    assert_eq!(
        ride.sim().world().snapshot(),
        states[89],
        "the state after step 89"
    );
    for (i, state) in states.iter().enumerate().skip(90) {
        ride.set_intent(intent_at(i));
        ride.step();
        assert_eq!(
            &ride.sim().world().snapshot(),
            state,
            "step {i} repeats exactly"
        );
    }
}

#[test]
fn the_history_holds_what_it_was_asked_and_forgets_a_respawns_past() {
    let mut ride = ride();
    assert_eq!(ride.rewind(5.0), Err(RewindRefusal::NothingYet));
    for i in 0..400 {
        ride.set_intent(intent_at(i));
        ride.step();
    }
    assert!(
        (ride.rewindable() - 10.0).abs() < 1e-9,
        "ten seconds kept, no more"
    );
    // What the history holds, for docs/benchmarks.md: the world's snapshot is most of a
    // moment.
    let world = ride.sim().world().snapshot();
    let bytes = std::mem::size_of_val(world.bodies.as_slice())
        + std::mem::size_of_val(world.motors.as_slice())
        + world.touching_static.len()
        + 2 * world.feet_touching.len();
    println!(
        "rewind history: a moment's world {bytes} B ({} bodies, {} joints); 10 s at 30 Hz {:.0} KiB",
        world.bodies.len(),
        world.motors.len(),
        (bytes * 300) as f64 / 1024.0
    );
    let back = ride.rewind(60.0).expect("as far as it goes");
    assert!((back - 10.0).abs() < 1e-9, "{back}");
    assert_eq!(ride.steps(), 100);
    ride.reset_to(Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::IDENTITY,
    });
    assert_eq!(
        ride.rewind(1.0),
        Err(RewindRefusal::NothingYet),
        "not past a respawn"
    );
    let mut untracked = Ride::new(
        common::flat_ride_with(SimulationConfig::default()),
        ControllerKind::ARCADE,
    );
    untracked.step();
    assert_eq!(untracked.rewind(1.0), Err(RewindRefusal::NotKept));
}

#[test]
fn a_planner_plans_afresh_from_a_rewind_and_rides_on() {
    let mut ride = common::planned_ride(
        common::flat_ride_in(PhysicsModel::Exact),
        ControllerKind::COMBINED,
    );
    ride.keep_history(10.0);
    for i in 0..120 {
        ride.set_intent(intent_at(i));
        ride.step();
    }
    let back = ride.rewind(2.0).expect("four seconds kept");
    assert!((back - 2.0).abs() < 1e-9, "{back}");
    assert_eq!(ride.steps(), 60);
    for i in 60..180 {
        ride.set_intent(intent_at(i));
        ride.step();
    }
    assert_eq!(ride.steps(), 180);
    assert_eq!(ride.sim().crashed(), None, "the planner rode on upright");
    assert!(
        ride.rewindable() > 5.0,
        "the ride after the rewind is kept too"
    );
}
