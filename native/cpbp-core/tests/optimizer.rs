//! The optimizer and combined controllers (C-PBP, N = 15) on flat ground. Heavy: `make
//! test` runs these in a release build; debug builds skip them.

mod common;

use cpbp_core::bike::DriveInput;
use cpbp_core::control::{BikeOptimizer, OptimizerConfig, OptimizerMode};
use cpbp_core::simulation::Simulation;
use glam::DVec3;

const FRAMES_PER_SECOND: usize = 30;

fn ride(kmh: f64, mode: OptimizerMode) -> (Simulation, BikeOptimizer, DriveInput) {
    let sim = common::flat_ride();
    let config = OptimizerConfig {
        mode,
        particles: 15,
        ..OptimizerConfig::default()
    };
    let optimizer = BikeOptimizer::new(&sim, config);
    (
        sim,
        optimizer,
        DriveInput {
            throttle: 1.0,
            brake: 0.0,
            max_speed: kmh / 3.6,
        },
    )
}

fn step(sim: &mut Simulation, optimizer: &mut BikeOptimizer, drive: &DriveInput, lean: f64) {
    let controls = optimizer.controls(sim, lean, drive);
    sim.set_controls(controls);
    sim.step();
}

fn rides_straight_for_20_seconds(mode: OptimizerMode, kmh: f64) {
    let (mut sim, mut optimizer, drive) = ride(kmh, mode);
    for _ in 0..20 * FRAMES_PER_SECOND {
        step(&mut sim, &mut optimizer, &drive, 0.0);
    }
    assert_eq!(sim.crashed(), None, "{mode:?} at {kmh} km/h");
    assert!(
        sim.bike().lean(sim.world(), DVec3::Y).abs() < 10f64.to_radians(),
        "{mode:?} at {kmh} km/h"
    );
}

/// Steering angles (positive left) in the 1.5 s after a 15° right lean is asked for.
fn steering_into_a_right_turn(mode: OptimizerMode) -> Vec<f64> {
    let (mut sim, mut optimizer, drive) = ride(20.0, mode);
    for _ in 0..3 * FRAMES_PER_SECOND {
        step(&mut sim, &mut optimizer, &drive, 0.0);
    }
    (0..45)
        .map(|_| {
            step(&mut sim, &mut optimizer, &drive, 15f64.to_radians());
            assert_eq!(sim.crashed(), None);
            sim.bike().steering(sim.world()).0
        })
        .collect()
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_rides_straight_at_15_20_and_25_kmh() {
    for kmh in [15.0, 20.0, 25.0] {
        rides_straight_for_20_seconds(OptimizerMode::Combined, kmh);
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn optimizer_rides_straight_at_15_20_and_25_kmh() {
    for kmh in [15.0, 20.0, 25.0] {
        rides_straight_for_20_seconds(OptimizerMode::Optimizer, kmh);
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn combined_follows_a_15_degree_lean_within_3_degrees_rms() {
    let (mut sim, mut optimizer, drive) = ride(20.0, OptimizerMode::Combined);
    let want = 15f64.to_radians();
    let mut squares = Vec::new();
    for i in 0..10 * FRAMES_PER_SECOND {
        let t = i as f64 / FRAMES_PER_SECOND as f64;
        step(
            &mut sim,
            &mut optimizer,
            &drive,
            if t >= 3.0 { want } else { 0.0 },
        );
        if t >= 5.0 {
            squares.push((sim.bike().lean(sim.world(), DVec3::Y) - want).powi(2));
        }
    }
    let rms = (squares.iter().sum::<f64>() / squares.len() as f64)
        .sqrt()
        .to_degrees();
    assert_eq!(sim.crashed(), None);
    assert!(rms <= 3.0, "RMS lean error {rms:.2}°");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn counter_steering_emerges_in_combined_and_optimizer_modes() {
    common::assert_counter_steers(&steering_into_a_right_turn(OptimizerMode::Combined));
    common::assert_counter_steers(&steering_into_a_right_turn(OptimizerMode::Optimizer));
}
