//! The optimizer and combined controllers (C-PBP, N = 15) on flat ground. Heavy: `make
//! test` runs these in a release build; debug builds skip them.

use crate::common;

use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Ride};

/// A flat ride with the `kind` planner (N = 15) at `kmh`. The straight rides below take
/// the two ends of the protocol's 10–25 km/h: the experiment rides every speed at scale.
fn planner_at(kmh: f64, kind: ControllerKind) -> Ride {
    common::ride_at(kind, kmh, 15)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_rides_straight_at_10_and_25_kmh() {
    for kmh in [10.0, 25.0] {
        common::assert_rides_straight_for_20_seconds(&mut planner_at(
            kmh,
            ControllerKind::COMBINED,
        ));
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn optimizer_rides_straight_at_10_and_25_kmh() {
    for kmh in [10.0, 25.0] {
        common::assert_rides_straight_for_20_seconds(&mut planner_at(
            kmh,
            ControllerKind::OPTIMIZER,
        ));
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_follows_a_15_degree_lean_within_3_degrees_rms() {
    let rms =
        common::rms_lean_error_in_a_15_degree_turn(&mut planner_at(20.0, ControllerKind::COMBINED));
    assert!(rms <= 3.0, "RMS lean error {rms:.2}°");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn optimizer_alone_follows_a_15_degree_lean_within_4_degrees_rms() {
    let rms = common::rms_lean_error_in_a_15_degree_turn(&mut planner_at(
        20.0,
        ControllerKind::OPTIMIZER,
    ));
    assert!(rms <= 4.0, "RMS lean error {rms:.2}°");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn counter_steering_emerges_in_combined_and_optimizer_modes() {
    for kind in [ControllerKind::COMBINED, ControllerKind::OPTIMIZER] {
        common::assert_counter_steers_into_a_right_turn(&mut planner_at(20.0, kind));
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_at_5_settles_into_lean_reversals_as_tightly_as_the_optimizer_at_10() {
    let exact = |kind, n| common::ride_in(PhysicsModel::Exact, kind, 25.0, n);
    let combined = common::settled_lean_error_in_reversals(&mut exact(ControllerKind::COMBINED, 5));
    let optimizer =
        common::settled_lean_error_in_reversals(&mut exact(ControllerKind::OPTIMIZER, 10));
    assert!(
        combined <= optimizer,
        "settled RMS lean error at 25 km/h: combined-5 {combined:.2}°, optimizer-10 {optimizer:.2}°"
    );
}
