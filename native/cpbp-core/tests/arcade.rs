//! The arcade controller (thesis §4.3.2) on flat ground: it keeps the bike up, follows a
//! commanded lean, and counter-steers to start a turn.

use std::sync::Arc;

use cpbp_core::bike::{index, DriveInput, Placement};
use cpbp_core::control::{ArcadeController, ArcadeGains};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

const DT: f64 = 1.0 / 30.0;

fn ride(kmh: f64) -> (Simulation, ArcadeController, DriveInput) {
    let plane = TerrainShape::Plane {
        normal: DVec3::Y,
        distance: 0.0,
    };
    let terrain = Terrain::new(vec![TerrainPiece {
        source: "flat".into(),
        shape: plane,
        placement: Placement::IDENTITY,
    }]);
    // Facing an arbitrary heading, so nothing is symmetric by accident.
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(0.3),
    };
    let sim = Simulation::new(
        SimulationConfig::default(),
        Arc::new(terrain.unwrap()),
        spawn,
    );
    let drive = DriveInput {
        throttle: 1.0,
        brake: 0.0,
        max_speed: kmh / 3.6,
    };
    (sim, ArcadeController::new(ArcadeGains::default()), drive)
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
    let first_left = angles.iter().position(|a| *a > 1f64.to_radians());
    let first_right = angles.iter().position(|a| *a < -1f64.to_radians());
    match (first_left, first_right) {
        (Some(left), Some(right)) => {
            assert!(left < right, "left at step {left}, right at step {right}")
        }
        other => panic!("expected the bar left then right, got {other:?} in {angles:?}"),
    }
}
