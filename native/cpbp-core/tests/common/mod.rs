//! Shared by the controller tests: a ride on flat ground and the counter-steer check.

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

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

/// Steering angles (positive left) recorded as a right turn begins: the bar must first go
/// left (the counter-steer), then right.
pub fn assert_counter_steers(angles: &[f64]) {
    let first_left = angles.iter().position(|a| *a > 1f64.to_radians());
    let first_right = angles.iter().position(|a| *a < -1f64.to_radians());
    match (first_left, first_right) {
        (Some(left), Some(right)) => {
            assert!(left < right, "left at step {left}, right at step {right}")
        }
        other => panic!("expected the bar left then right, got {other:?} in {angles:?}"),
    }
}
