//! Shared by the controller tests: a ride on flat ground, and the scenarios every
//! controller is held to. A controller is passed in as a closure from the simulation and
//! the desired lean to the controls for the next step.

// Each test crate uses its own subset of these helpers.
#![allow(dead_code)]

use std::sync::Arc;

use cpbp_core::bike::{Controls, DriveInput, Placement};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

pub const FRAMES_PER_SECOND: usize = 30;

/// A simulation on an endless flat plane, the bike at rest facing an arbitrary heading
/// (so nothing is symmetric by accident).
pub fn flat_ride() -> Simulation {
    let plane = TerrainShape::Plane {
        normal: DVec3::Y,
        distance: 0.0,
    };
    let piece = TerrainPiece {
        source: "flat".into(),
        shape: plane,
        placement: Placement::IDENTITY,
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(0.3),
    };
    Simulation::new(
        SimulationConfig::default(),
        Arc::new(Terrain::new(vec![piece]).unwrap()),
        spawn,
    )
}

/// Full throttle towards `kmh`.
pub fn auto_throttle(kmh: f64) -> DriveInput {
    DriveInput {
        throttle: 1.0,
        brake: 0.0,
        max_speed: kmh / 3.6,
    }
}

/// Rides `seconds` asking for `lean` (rad) each step.
pub fn ride(
    sim: &mut Simulation,
    seconds: f64,
    lean: f64,
    control: &mut impl FnMut(&Simulation, f64) -> Controls,
) {
    for _ in 0..(seconds * FRAMES_PER_SECOND as f64).round() as usize {
        let controls = control(sim, lean);
        sim.set_controls(controls);
        sim.step();
    }
}

/// Rides 20 s straight; the bike must stay up and nearly upright.
pub fn assert_rides_straight_for_20_seconds(
    sim: &mut Simulation,
    control: &mut impl FnMut(&Simulation, f64) -> Controls,
) {
    ride(sim, 20.0, 0.0, control);
    assert_eq!(sim.crashed(), None);
    assert!(sim.bike().lean(sim.world(), DVec3::Y).abs() < 10f64.to_radians());
}

/// Rides 3 s straight, then asks for a 15° right lean for 7 s; returns the RMS lean error
/// (degrees) over the last 5 s, once the turn is established.
pub fn rms_lean_error_in_a_15_degree_turn(
    sim: &mut Simulation,
    control: &mut impl FnMut(&Simulation, f64) -> Controls,
) -> f64 {
    let want = 15f64.to_radians();
    ride(sim, 3.0, 0.0, control);
    ride(sim, 2.0, want, control);
    let mut squares = Vec::new();
    for _ in 0..5 * FRAMES_PER_SECOND {
        ride(sim, 1.0 / FRAMES_PER_SECOND as f64, want, control);
        squares.push((sim.bike().lean(sim.world(), DVec3::Y) - want).powi(2));
    }
    assert_eq!(sim.crashed(), None);
    (squares.iter().sum::<f64>() / squares.len() as f64)
        .sqrt()
        .to_degrees()
}

/// Rides 3 s straight, asks for a 15° right lean, and checks the bar first goes left
/// (the counter-steer), then right, within 1.5 s.
pub fn assert_counter_steers_into_a_right_turn(
    sim: &mut Simulation,
    control: &mut impl FnMut(&Simulation, f64) -> Controls,
) {
    ride(sim, 3.0, 0.0, control);
    let angles: Vec<f64> = (0..45)
        .map(|_| {
            ride(
                sim,
                1.0 / FRAMES_PER_SECOND as f64,
                15f64.to_radians(),
                control,
            );
            assert_eq!(sim.crashed(), None);
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
