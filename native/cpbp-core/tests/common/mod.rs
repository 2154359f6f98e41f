//! Shared by the controller tests: a ride on flat ground, and the scenarios every
//! controller is held to. Every controller rides through the game's `Ride`, asked for a
//! lean directly.

// Each test crate uses its own subset of these helpers.
#![allow(dead_code)]

pub mod pendulum;

use std::sync::Arc;

use cpbp_core::bike::{read_bike_file, BikeParams, DriveInput, Placement};
use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DQuat, DVec3};

pub const FRAMES_PER_SECOND: usize = 30;

/// The game's street bike, as its file has it (scenes/bike/bikes/street_390.tres).
pub fn street_bike() -> BikeParams {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenes/bike/bikes/street_390.tres"
    );
    read_bike_file(std::path::Path::new(file)).unwrap().params
}

/// A simulation on an endless flat plane, the bike at rest facing an arbitrary heading
/// (so nothing is symmetric by accident).
pub fn flat_ride() -> Simulation {
    flat_ride_in(PhysicsModel::Classic)
}

/// `flat_ride` in another physics model.
pub fn flat_ride_in(physics: PhysicsModel) -> Simulation {
    flat_ride_with(SimulationConfig {
        physics,
        ..SimulationConfig::default()
    })
}

/// `flat_ride` with any configuration (another bike, say).
pub fn flat_ride_with(config: SimulationConfig) -> Simulation {
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(0.3),
    };
    Simulation::new(config, Arc::new(Terrain::flat()), spawn)
}

/// A simulation in the game's physics on `pieces` and endless flat ground, the bike at
/// rest `height` m up at the origin, facing +x.
pub fn exact_sim_on(mut pieces: Vec<TerrainPiece>, height: f64) -> Simulation {
    pieces.push(TerrainPiece::flat_ground());
    let config = SimulationConfig {
        physics: PhysicsModel::Exact,
        ..SimulationConfig::default()
    };
    let spawn = Placement {
        position: DVec3::new(0.0, height, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let terrain = Terrain::new(pieces).expect("valid terrain");
    Simulation::new(config, Arc::new(terrain), spawn)
}

/// A `kind` ride of `sim` whose planners plan with 10 trajectories and wait for every
/// plan, so it repeats exactly.
pub fn planned_ride(sim: Simulation, kind: ControllerKind) -> Ride {
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = 10;
    ride.planner.wait = PlanWait::EveryPlan;
    ride
}

/// The frame's pitch now (degrees, nose up).
pub fn pitch(ride: &Ride) -> f64 {
    let sim = ride.sim();
    let nose = sim.bike().frame_rotation(sim.world()) * DVec3::X;
    nose.dot(sim.up()).asin().to_degrees()
}

/// Full throttle towards `kmh`.
pub fn auto_throttle(kmh: f64) -> DriveInput {
    DriveInput {
        throttle: 1.0,
        brake: 0.0,
        max_speed: kmh / 3.6,
    }
}

/// A `kind` ride on flat ground at full throttle towards `kmh`, asking for no lean. The
/// planners plan with N trajectories and the ride waits for every plan, so a ride does
/// not depend on how fast the machine is.
pub fn ride_at(kind: ControllerKind, kmh: f64, particles: usize) -> Ride {
    ride_in(PhysicsModel::Classic, kind, kmh, particles)
}

/// `ride_at` in another physics model.
pub fn ride_in(physics: PhysicsModel, kind: ControllerKind, kmh: f64, particles: usize) -> Ride {
    let mut ride = Ride::new(flat_ride_in(physics), kind);
    ride.planner.planning.trajectories = particles;
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    ride
}

/// The bike's lean (rad, positive right) now.
pub fn lean(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().lean(sim.world(), sim.up())
}

/// Asks for `lean` (rad) from the next step on.
pub fn ask_lean(ride: &mut Ride, lean: f64) {
    ride.set_intent(Intent {
        lean: Some(lean),
        ..*ride.intent()
    });
}

/// Pulls the brake all the way, throttle shut, from the next step on; the rest of what the
/// ride asks (lean, top speed) stays.
pub fn full_brake(ride: &mut Ride) {
    let mut intent = *ride.intent();
    intent.drive = DriveInput {
        throttle: 0.0,
        brake: 1.0,
        max_speed: intent.drive.max_speed,
    };
    ride.set_intent(intent);
}

/// Rides `seconds` asking for `lean` (rad).
pub fn ride(ride: &mut Ride, seconds: f64, lean: f64) {
    ask_lean(ride, lean);
    for _ in 0..(seconds * FRAMES_PER_SECOND as f64).round() as usize {
        ride.step();
    }
}

/// Rides 20 s straight; the bike must stay up and nearly upright.
pub fn assert_rides_straight_for_20_seconds(r: &mut Ride) {
    ride(r, 20.0, 0.0);
    assert_eq!(r.sim().crashed(), None);
    assert!(lean(r).abs() < 10f64.to_radians());
}

/// Rides 3 s straight, then asks for a 15° right lean for 7 s; returns the RMS lean error
/// (degrees) over the last 5 s, once the turn is established.
pub fn rms_lean_error_in_a_15_degree_turn(r: &mut Ride) -> f64 {
    let want = 15f64.to_radians();
    ride(r, 3.0, 0.0);
    ride(r, 2.0, want);
    let mut squares = Vec::new();
    for _ in 0..5 * FRAMES_PER_SECOND {
        r.step();
        squares.push((lean(r) - want).powi(2));
    }
    assert_eq!(r.sim().crashed(), None);
    (squares.iter().sum::<f64>() / squares.len() as f64)
        .sqrt()
        .to_degrees()
}

/// Rides 3 s straight, then asks for ±15°, reversing every 2 s for 12 s (right first);
/// returns the RMS lean error (degrees) over the second second of each gate after the
/// first, once the lean has swung over: how tightly the lean settles (the scenario tool's
/// `reversals`).
pub fn settled_lean_error_in_reversals(r: &mut Ride) -> f64 {
    let want = 15f64.to_radians();
    ride(r, 3.0, 0.0);
    let mut squares = Vec::new();
    for gate in 0..6 {
        let target = if gate % 2 == 0 { want } else { -want };
        ride(r, 1.0, target);
        for _ in 0..FRAMES_PER_SECOND {
            r.step();
            if gate > 0 {
                squares.push((lean(r) - target).powi(2));
            }
        }
    }
    assert_eq!(r.sim().crashed(), None);
    (squares.iter().sum::<f64>() / squares.len() as f64)
        .sqrt()
        .to_degrees()
}

/// Rides 3 s straight, asks for a 15° right lean, and checks the bar first goes left
/// (the counter-steer), then right, within 1.5 s.
pub fn assert_counter_steers_into_a_right_turn(r: &mut Ride) {
    ride(r, 3.0, 0.0);
    ask_lean(r, 15f64.to_radians());
    let angles: Vec<f64> = (0..45)
        .map(|_| {
            r.step();
            assert_eq!(r.sim().crashed(), None);
            r.sim().bike().steering(r.sim().world()).0
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
