//! A lean that asks for more grip than the tyres have ends in a low-side, named as one:
//! the street bike on a slippery road (μ = 0.4, a wet painted line or gravel) asked for
//! its full 30° at 40 km/h, which needs tan 30° ≈ 0.58, slides its tyres out from under
//! itself and goes down on the side it leaned to. On the street bike's own tyres the same
//! lean holds.

use std::path::Path;

use crate::common;

use cpbp_core::bike::{read_bike_file, BikeParams, Fall};
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

fn street_bike() -> BikeParams {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenes/bike/bikes/street_390.tres"
    );
    read_bike_file(Path::new(file)).unwrap().params
}

/// Arcade on `bike` at 40 km/h, then asked for 30° of right lean for up to 4 s; the
/// crash's description, if it fell.
fn lean_hard(bike: BikeParams) -> Option<(Option<Fall>, String)> {
    let sim = common::flat_ride_with(SimulationConfig {
        bike,
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
    ride.set_intent(Intent::cruise(40.0));
    common::ride(&mut ride, 8.0, 0.0);
    assert_eq!(ride.sim().crashed(), None, "it reached 40 km/h upright");
    ride.set_intent(Intent {
        lean: Some(30f64.to_radians()),
        ..Intent::cruise(40.0)
    });
    for _ in 0..120 {
        ride.step();
        if let Some(crash) = ride.sim().crashed() {
            return Some((crash.fall, crash.describe()));
        }
    }
    None
}

#[test]
fn a_lean_beyond_the_grip_is_a_low_side() {
    let slippery = BikeParams {
        tyre_friction: 0.4,
        ..street_bike()
    };
    let (fall, what) = lean_hard(slippery).expect("on μ = 0.4 a 30° lean falls");
    assert_eq!(fall, Some(Fall::LowSide), "{what}");
    assert!(what.starts_with("low-side"), "{what}");
    assert_eq!(lean_hard(street_bike()), None, "on its own tyres 30° holds");
}
