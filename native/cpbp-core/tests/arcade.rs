//! The arcade controller (thesis §4.3.2) on flat ground: it keeps the bike up, follows a
//! commanded lean, and counter-steers to start a turn.

mod common;

use cpbp_core::bike::{index, DriveInput};
use cpbp_core::control::{ArcadeController, ArcadeGains};
use cpbp_core::simulation::Simulation;
use glam::DVec3;

const DT: f64 = 1.0 / 30.0;

fn ride(kmh: f64) -> (Simulation, ArcadeController, DriveInput) {
    let drive = DriveInput {
        throttle: 1.0,
        brake: 0.0,
        max_speed: kmh / 3.6,
    };
    (
        common::flat_ride(),
        ArcadeController::new(ArcadeGains::default()),
        drive,
    )
}

/// One control step towards `lean`; returns the steering rate commanded.
fn step(sim: &mut Simulation, arcade: &mut ArcadeController, drive: &DriveInput, lean: f64) -> f64 {
    let controls = arcade.controls(sim.bike(), sim.world(), lean, drive, DVec3::Y, DT);
    sim.set_controls(controls);
    sim.step();
    controls.get(index::STEER)
}

#[test]
fn it_rides_straight_for_20_seconds_at_every_test_speed() {
    for kmh in [10.0, 15.0, 20.0, 25.0] {
        let (mut sim, mut arcade, drive) = ride(kmh);
        for _ in 0..(20.0 / DT) as usize {
            step(&mut sim, &mut arcade, &drive, 0.0);
        }
        assert_eq!(sim.crashed(), None, "{kmh} km/h");
        let speed = sim.bike().forward_speed(sim.world(), DVec3::Y) * 3.6;
        assert!((speed - kmh).abs() < 0.5, "{kmh} km/h: rode at {speed}");
        assert!(
            sim.bike().lean(sim.world(), DVec3::Y).abs() < 5f64.to_radians(),
            "{kmh} km/h"
        );
    }
}

#[test]
fn it_follows_a_commanded_lean_at_20_kmh() {
    let (mut sim, mut arcade, drive) = ride(20.0);
    let want = 15f64.to_radians();
    let mut squares = Vec::new();
    for i in 0..(10.0 / DT) as usize {
        let t = i as f64 * DT;
        step(
            &mut sim,
            &mut arcade,
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
    assert!(rms <= 3.0, "RMS lean error {rms:.2}° in a steady 15° turn");
}

#[test]
fn a_right_turn_starts_with_a_left_counter_steer() {
    let (mut sim, mut arcade, drive) = ride(20.0);
    for _ in 0..(3.0 / DT) as usize {
        step(&mut sim, &mut arcade, &drive, 0.0);
    }
    // Command a right lean and record the steering angle (positive left) as it happens.
    let angles: Vec<f64> = (0..45)
        .map(|_| {
            step(&mut sim, &mut arcade, &drive, 15f64.to_radians());
            sim.bike().steering(sim.world()).0
        })
        .collect();
    common::assert_counter_steers(&angles);
}
