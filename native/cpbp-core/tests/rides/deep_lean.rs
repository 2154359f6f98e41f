//! Deep leans on the street bike. A lean that asks for more grip than the tyres have ends
//! in a low-side, named as one: on a slippery road (μ = 0.4, a wet painted line or
//! gravel) the full 30° at 40 km/h, which needs tan 30° ≈ 0.58, slides the tyres out from
//! under the bike and it goes down on the side it leaned to; on its own tyres the same
//! lean holds. And 45° at 60 km/h, which the tyres (μ = 1) grip, holds under arcade once
//! the rider turns the bar with 100 N·m (`max_steer_torque`); with the reference's 60 the
//! bar barely moves past 40° and the lean creeps on into a low-side.

use crate::common;

use cpbp_core::bike::{BikeParams, Fall};
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

/// Arcade on `bike` at `kmh`, then asked for `lean_deg` of right lean for 6 s: the mean
/// lean (°) over the last 3 s, or how it fell.
fn lean_hard(bike: BikeParams, kmh: f64, lean_deg: f64) -> Result<f64, (Option<Fall>, String)> {
    let sim = common::flat_ride_with(SimulationConfig {
        bike,
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
    ride.set_intent(Intent::cruise(kmh));
    common::ride(&mut ride, kmh / 3.6 / 2.0 + 4.0, 0.0);
    assert_eq!(ride.sim().crashed(), None, "it reached {kmh} km/h upright");
    ride.set_intent(Intent {
        lean: Some(lean_deg.to_radians()),
        ..Intent::cruise(kmh)
    });
    let mut held = Vec::new();
    for step in 0..180 {
        ride.step();
        let sim = ride.sim();
        if let Some(crash) = sim.crashed() {
            return Err((crash.fall, crash.describe()));
        }
        if step >= 90 {
            held.push(sim.bike().lean(sim.world(), sim.up()).to_degrees());
        }
    }
    Ok(held.iter().sum::<f64>() / held.len() as f64)
}

#[test]
fn a_lean_beyond_the_grip_is_a_low_side() {
    let slippery = BikeParams {
        tyre_friction: 0.4,
        ..common::street_bike()
    };
    let (fall, what) = lean_hard(slippery, 40.0, 30.0).expect_err("on μ = 0.4 30° falls");
    assert_eq!(fall, Some(Fall::LowSide), "{what}");
    assert!(what.starts_with("low-side"), "{what}");
    let lean = lean_hard(common::street_bike(), 40.0, 30.0).expect("on its own tyres 30° holds");
    assert!((lean - 30.0).abs() < 1.0, "held {lean:.1}°");
}

#[test]
fn a_strong_hand_at_the_bar_holds_45_degrees_at_60_kmh() {
    let bike = BikeParams {
        max_lean: 45f64.to_radians(),
        tyre_friction_follows_wheel: true,
        max_steer_torque: 100.0,
        ..common::street_bike()
    };
    let lean = lean_hard(bike.clone(), 60.0, 45.0).expect("with 100 N·m 45° holds");
    assert!((lean - 45.0).abs() < 1.0, "held {lean:.1}°");
    let weak = BikeParams {
        max_steer_torque: 60.0,
        ..bike
    };
    let (fall, what) = lean_hard(weak, 60.0, 45.0).expect_err("with 60 N·m it creeps over");
    assert_eq!(fall, Some(Fall::LowSide), "{what}");
}
