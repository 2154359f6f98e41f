//! The optimizer and combined controllers (C-PBP, N = 15) on flat ground. Heavy: `make
//! test` runs these in a release build; debug builds skip them.

mod common;

use cpbp_core::bike::Controls;
use cpbp_core::control::{BikeOptimizer, OptimizerConfig, OptimizerMode};
use cpbp_core::simulation::Simulation;

/// A flat ride and the planner in `mode` at `kmh`, as a closure the scenarios drive.
fn planner_at(
    kmh: f64,
    mode: OptimizerMode,
) -> (Simulation, impl FnMut(&Simulation, f64) -> Controls) {
    let sim = common::flat_ride();
    let mut optimizer = BikeOptimizer::new(
        &sim,
        OptimizerConfig {
            mode,
            particles: 15,
            ..OptimizerConfig::default()
        },
    );
    let drive = common::auto_throttle(kmh);
    (sim, move |sim: &Simulation, lean| {
        optimizer.controls(sim, lean, &drive)
    })
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_rides_straight_at_10_15_20_and_25_kmh() {
    for kmh in [10.0, 15.0, 20.0, 25.0] {
        let (mut sim, mut control) = planner_at(kmh, OptimizerMode::Combined);
        common::assert_rides_straight_for_20_seconds(&mut sim, &mut control);
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn optimizer_rides_straight_at_10_15_20_and_25_kmh() {
    for kmh in [10.0, 15.0, 20.0, 25.0] {
        let (mut sim, mut control) = planner_at(kmh, OptimizerMode::Optimizer);
        common::assert_rides_straight_for_20_seconds(&mut sim, &mut control);
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_follows_a_15_degree_lean_within_3_degrees_rms() {
    let (mut sim, mut control) = planner_at(20.0, OptimizerMode::Combined);
    let rms = common::rms_lean_error_in_a_15_degree_turn(&mut sim, &mut control);
    assert!(rms <= 3.0, "RMS lean error {rms:.2}°");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn optimizer_alone_follows_a_15_degree_lean_within_4_degrees_rms() {
    let (mut sim, mut control) = planner_at(20.0, OptimizerMode::Optimizer);
    let rms = common::rms_lean_error_in_a_15_degree_turn(&mut sim, &mut control);
    assert!(rms <= 4.0, "RMS lean error {rms:.2}°");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn counter_steering_emerges_in_combined_and_optimizer_modes() {
    for mode in [OptimizerMode::Combined, OptimizerMode::Optimizer] {
        let (mut sim, mut control) = planner_at(20.0, mode);
        common::assert_counter_steers_into_a_right_turn(&mut sim, &mut control);
    }
}
