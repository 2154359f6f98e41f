//! The suspension on the ridden bike: it rides at its design sag, and soaks up a drop
//! within its travel, without bouncing the bike off the ground and with a softer jolt to
//! the frame than the same bike rigid.

use crate::common;

use std::sync::Arc;

use cpbp_core::bike::{BikeParams, Part, Placement};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

fn compression(ride: &Ride) -> (f64, f64) {
    let sim = ride.sim();
    sim.bike().suspension_compression(sim.world())
}

#[cfg_attr(
    debug_assertions,
    ignore = "rides for seconds: run in release (tools/test.sh does)"
)]
#[test]
fn the_bike_rides_at_its_design_sag() {
    let s = BikeParams::default()
        .suspension
        .expect("the default bike is sprung");
    let (front_sag, rear_sag) = (s.sag * s.front_travel, s.sag * s.rear_travel);
    let mut ride = common::ride_in(PhysicsModel::Exact, ControllerKind::ARCADE, 15.0, 5);
    for _ in 0..90 {
        ride.step();
    }
    let (front, rear) = compression(&ride);
    assert!(
        (front - front_sag).abs() < 2e-3,
        "fork at {front:.4} m, designed {front_sag}"
    );
    assert!(
        (rear - rear_sag).abs() < 2e-3,
        "rear at {rear:.4} m, designed {rear_sag}"
    );
}

/// A 40 m deck 0.8 m high whose edge is 12 m ahead of the spawn, over flat ground, with
/// `bike` in the game's physics.
fn drop_off(bike: BikeParams) -> Simulation {
    let deck = TerrainPiece {
        source: "deck".into(),
        shape: TerrainShape::Cuboid {
            size: DVec3::new(40.0, 0.8, 10.0),
        },
        placement: Placement {
            position: DVec3::new(-8.0, 0.4, 0.0),
            rotation: DQuat::IDENTITY,
        },
    };
    let ground = TerrainPiece::flat_ground();
    let terrain = Terrain::new(vec![deck, ground]).expect("valid terrain");
    let spawn = Placement {
        position: DVec3::new(0.0, 0.82, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let config = SimulationConfig {
        physics: PhysicsModel::Exact,
        bike,
        ..SimulationConfig::default()
    };
    Simulation::new(config, Arc::new(terrain), spawn)
}

/// What a landing off the deck at 20 km/h did: the deepest compression of each end (m),
/// the steps a wheel spent off the ground after both had touched down, and the hardest
/// jolt of the frame (m/s², the largest change of its vertical speed in one step).
struct Landing {
    deepest: (f64, f64),
    bounced: usize,
    jolt: f64,
}

fn ride_off_the_deck(bike: BikeParams) -> Landing {
    let mut ride = Ride::new(drop_off(bike), ControllerKind::ARCADE);
    ride.set_intent(Intent::cruise(20.0));
    let dt = ride.sim().config().control_dt;
    let mut landing = Landing {
        deepest: (0.0, 0.0),
        bounced: 0,
        jolt: 0.0,
    };
    let (mut landed, mut vertical) = (false, 0.0);
    for _ in 0..150 {
        let events = ride.step();
        assert!(events.crashed.is_none(), "crashed: {:?}", events.crashed);
        let sim = ride.sim();
        let frame = sim
            .world()
            .body_linear_velocity(sim.bike().body(Part::Frame))[1];
        let height = sim.bike().center_of_mass(sim.world()).y;
        let (rear, front) = sim.bike().wheel_contacts(sim.world());
        landed |= height < 1.0 && rear && front;
        if landed {
            let (f, r) = compression(&ride);
            landing.deepest = (landing.deepest.0.max(f), landing.deepest.1.max(r));
            landing.bounced += usize::from(!(rear && front));
            landing.jolt = landing.jolt.max((frame - vertical).abs() / dt);
        }
        vertical = frame;
    }
    assert!(landed, "never came down off the deck");
    landing
}

#[cfg_attr(
    debug_assertions,
    ignore = "rides for seconds: run in release (tools/test.sh does)"
)]
#[test]
fn a_drop_is_soaked_up_within_the_travel_and_the_wheels_stay_down() {
    let travel = BikeParams::default()
        .suspension
        .expect("sprung")
        .front_travel;
    let sprung = ride_off_the_deck(BikeParams::default());
    let rigid = ride_off_the_deck(BikeParams::default().rigid());
    let (front, rear) = sprung.deepest;
    assert!(
        front > 0.06 && rear > 0.06,
        "the landing used the suspension: fork {front:.3} m, rear {rear:.3} m"
    );
    assert!(
        front < travel + 0.01 && rear < travel + 0.01,
        "within travel"
    );
    assert!(
        sprung.bounced <= 3,
        "a wheel left the ground for {} steps",
        sprung.bounced
    );
    // Measured: 49 m/s² against the rigid bike's 76.
    assert!(
        sprung.jolt < 0.75 * rigid.jolt,
        "the frame's hardest jolt: {:.0} m/s² sprung, {:.0} rigid",
        sprung.jolt,
        rigid.jolt
    );
}
