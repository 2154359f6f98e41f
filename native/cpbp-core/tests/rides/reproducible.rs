//! A ride repeats exactly: the same ride from a new `Simulation` ends in the same state,
//! bit for bit, whatever its thread simulated before or simulates in between. Results,
//! resumed experiments, paired comparisons and replays all lean on this.
//! The planner rides are heavy: `make test` runs this file in a release build.

use crate::common;

use cpbp_core::ode::WorldState;
use cpbp_core::ride::{ControllerKind, Ride};

/// Rides 3 s at `kmh` asking for a 10° right lean after 1 s, from a new simulation, and
/// returns the final state. `between` runs after every control step (other work on the
/// same thread).
fn ride(kind: ControllerKind, kmh: f64, between: &mut impl FnMut()) -> WorldState {
    let mut ride = common::ride_at(kind, kmh, 5);
    ride.planner.planning.threads = 2;
    for step in 0..90 {
        if step == 30 {
            common::ask_lean(&mut ride, 10f64.to_radians());
        }
        ride.step();
        between();
    }
    assert_eq!(ride.late_plans(), 0, "every step waited for its plan");
    ride.sim().world().snapshot()
}

/// Another ride on the calling thread, stepped one control step per call.
fn other_ride() -> impl FnMut() {
    let mut other: Ride = common::ride_at(ControllerKind::ARCADE, 20.0, 0);
    common::ask_lean(&mut other, -0.1);
    move || {
        other.step();
    }
}

/// The ride alone on a new thread, then on a thread that rode something else first and
/// steps another simulation between its steps: both must end in the same state.
fn assert_repeats(kind: ControllerKind) {
    let alone = std::thread::spawn(move || ride(kind, 10.0, &mut || {}))
        .join()
        .unwrap();
    let after_others = std::thread::spawn(move || {
        ride(ControllerKind::ARCADE, 20.0, &mut || {});
        let mut other = other_ride();
        ride(kind, 10.0, &mut other)
    })
    .join()
    .unwrap();
    assert!(
        alone == after_others,
        "{kind:?}: the ride depended on what its thread simulated"
    );
    // And not trivially: another speed ends elsewhere.
    assert!(ride(ControllerKind::ARCADE, 12.0, &mut || {}) != alone);
}

#[test]
fn an_arcade_ride_does_not_depend_on_its_thread() {
    assert_repeats(ControllerKind::ARCADE);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn a_combined_ride_does_not_depend_on_its_thread() {
    assert_repeats(ControllerKind::COMBINED);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn an_optimizer_ride_does_not_depend_on_its_thread() {
    assert_repeats(ControllerKind::OPTIMIZER);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn the_baseline_planners_rides_do_not_depend_on_their_thread() {
    assert_repeats(ControllerKind::SAMPLING);
    assert_repeats(ControllerKind::MPPI);
}
