//! The righting reserve (`FrontBrake::righting_reserve`): a full brake in a 20° turn at
//! 25 km/h, the stick held in the turn as the scenario `brake-turn` does. With the whole
//! brake the sport 600 stopped before it stood up, leaned into the turn with the bar at
//! full lock, and fell; braking no harder than leaves the speed a full-lock turn stands
//! the bike up at, it stops upright.

use std::path::Path;

use cpbp_core::bike::{read_bike_file, BikeParams};
use cpbp_core::control::TurnIntent;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

use crate::common;

fn sport_600() -> BikeParams {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/bike/bikes/sport_600.tres");
    read_bike_file(&path)
        .unwrap_or_else(|why| panic!("{why}"))
        .params
}

/// Whether arcade, in a turn to `side` (1 left, −1 right) at 20° and 25 km/h for 5 s and
/// then on the full brake for 5 s, is still up, with the distance (m) it stopped in.
fn stays_up_braking_in_a_turn(bike: &BikeParams, side: f64) -> (bool, f64) {
    let sim = common::flat_ride_with(SimulationConfig {
        physics: PhysicsModel::Exact,
        bike: bike.clone(),
        ..SimulationConfig::default()
    });
    let (kmh, lean) = (25.0, 20f64.to_radians());
    let speed = kmh / 3.6;
    let curvature = lean.tan() * sim.config().gravity.length() / (speed * speed);
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
    let turn = Intent {
        lean: None,
        turn: side * curvature / TurnIntent::default().max_curvature,
        ..Intent::cruise(kmh)
    };
    ride.set_intent(turn);
    let frames = 5 * common::FRAMES_PER_SECOND;
    for _ in 0..frames {
        ride.step();
    }
    common::full_brake(&mut ride);
    let mut stopped_in = 0.0;
    for _ in 0..frames {
        ride.step();
        let sim = ride.sim();
        stopped_in += sim.bike().forward_speed(sim.world(), sim.up()) / 30.0;
        if sim.crashed().is_some() {
            return (false, stopped_in);
        }
    }
    (true, stopped_in)
}

#[test]
fn with_the_righting_reserve_the_sport_600_stops_upright_from_a_braked_turn() {
    let reserving = sport_600();
    let brake = reserving
        .front_brake
        .expect("the sport 600 has a front brake");
    assert!(brake.righting_reserve, "the sport 600 keeps the reserve");
    let mut whole = reserving.clone();
    if let Some(front) = whole.front_brake.as_mut() {
        front.righting_reserve = false;
    }
    for side in [-1.0, 1.0] {
        let (up, stopped_in) = stays_up_braking_in_a_turn(&reserving, side);
        let (up_whole, stopped_whole) = stays_up_braking_in_a_turn(&whole, side);
        println!(
            "turning {side}: reserve up {up} in {stopped_in:.2} m, whole brake up {up_whole} \
             in {stopped_whole:.2} m"
        );
        assert!(up, "fell braking in a turn to {side} with the reserve");
        // What the field is for: the whole brake at 20° drops the bike (30 of 30 in the
        // scenario), and the reserve costs some distance (5.7 m from 2.3 m here).
        assert!(
            !up_whole,
            "stayed up with the whole brake turning to {side}"
        );
        assert!(stopped_in < 6.0, "stopped in {stopped_in} m");
    }
}
