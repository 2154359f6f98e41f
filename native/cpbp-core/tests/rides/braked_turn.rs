//! The righting reserve (`FrontBrake::righting_reserve`): a full brake in a 20° turn at
//! 25 km/h, the stick held in the turn as the scenario `brake-turn` does. With the whole
//! brake the sport 600 stopped before it stood up, leaned into the turn with the bar at
//! full lock, and fell onto its foot; braking no harder than leaves the speed a full-lock
//! turn stands the bike up at, it stops upright. And the foot that holds it at the stop: the dirt 125
//! came to rest still leaned and lay down onto a leg stretched along its frame, whose sole
//! swung in under the bike; a leg that hangs plumb holds it (`Feet::plumb_legs`).

use std::path::Path;

use cpbp_core::bike::{read_bike_file, BikeParams};
use cpbp_core::control::TurnIntent;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

use crate::common;

/// A bike a player chooses, by its file's name.
fn game_bike(name: &str) -> BikeParams {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenes/bike/bikes")
        .join(format!("{name}.tres"));
    read_bike_file(&path)
        .unwrap_or_else(|why| panic!("{why}"))
        .params
}

/// How arcade, in a turn to `side` (1 left, −1 right) at 20° and 25 km/h for 5 s and then
/// on the full brake for 5 s, came out of it.
struct BrakedTurn {
    up: bool,
    /// The distance it stopped in (m).
    stopped_in: f64,
    /// The largest lean on the brake (°), from upright either way.
    deepest: f64,
}

fn brake_in_a_turn(bike: &BikeParams, side: f64) -> BrakedTurn {
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
    let (mut stopped_in, mut deepest) = (0.0, 0.0f64);
    for _ in 0..frames {
        ride.step();
        let sim = ride.sim();
        stopped_in += sim.bike().forward_speed(sim.world(), sim.up()) / 30.0;
        deepest = deepest.max(common::lean(&ride).to_degrees().abs());
        if sim.crashed().is_some() {
            return BrakedTurn {
                up: false,
                stopped_in,
                deepest,
            };
        }
    }
    BrakedTurn {
        up: true,
        stopped_in,
        deepest,
    }
}

#[test]
fn with_the_righting_reserve_the_sport_600_stops_upright_from_a_braked_turn() {
    let reserving = game_bike("sport_600");
    let brake = reserving
        .front_brake
        .expect("the sport 600 has a front brake");
    assert!(brake.righting_reserve, "the sport 600 keeps the reserve");
    let mut whole = reserving.clone();
    if let Some(front) = whole.front_brake.as_mut() {
        front.righting_reserve = false;
    }
    for side in [-1.0, 1.0] {
        let reserve = brake_in_a_turn(&reserving, side);
        let all = brake_in_a_turn(&whole, side);
        println!(
            "turning {side}: reserve up {} in {:.2} m, deepest {:.1}°; whole brake up {} in \
             {:.2} m, deepest {:.1}°",
            reserve.up, reserve.stopped_in, reserve.deepest, all.up, all.stopped_in, all.deepest
        );
        assert!(
            reserve.up,
            "fell braking in a turn to {side} with the reserve"
        );
        // What the field is for: with the whole brake at 20° the bike stopped before it
        // stood up and fell (30 of 30 in the scenario, its legs along the frame); on legs
        // that hang plumb it stops in 2.3 m lain 23° onto its foot. With the reserve it
        // stands up as it stops, never leaning past the 20° it braked at, in 5.7 m.
        assert!(
            reserve.deepest < 20.5,
            "leaned {:.1}° with the reserve",
            reserve.deepest
        );
        assert!(
            reserve.stopped_in < 6.0,
            "stopped in {} m",
            reserve.stopped_in
        );
    }
}

#[test]
fn the_dirt_125_stops_from_a_braked_turn_onto_a_leg_that_hangs_plumb() {
    let plumb = game_bike("dirt_125");
    let feet = plumb.feet.expect("the dirt 125 has feet");
    assert!(feet.plumb_legs, "the dirt 125's legs hang plumb");
    let mut along_frame = plumb.clone();
    if let Some(feet) = along_frame.feet.as_mut() {
        feet.plumb_legs = false;
    }
    for side in [-1.0, 1.0] {
        let hanging = brake_in_a_turn(&plumb, side);
        let along = brake_in_a_turn(&along_frame, side);
        println!(
            "turning {side}: plumb legs up {} deepest {:.1}°, along the frame up {} deepest {:.1}°",
            hanging.up, hanging.deepest, along.up, along.deepest
        );
        assert!(hanging.up, "fell braking in a turn to {side} on plumb legs");
        // What the field is for: 30 of 30 braked turns fell on the legs along the frame.
        assert!(
            !along.up,
            "stayed up on legs along the frame turning to {side}"
        );
    }
}
