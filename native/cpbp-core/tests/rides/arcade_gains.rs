//! Arcade's gains at speed (`BikeParams::arcade_tuned_speed`). The thesis tuned K_p and
//! K_d at 25 km/h; a rider strong enough at the bar to hold 45° at 60 km/h (100 N·m) makes
//! the loop ring at 90 km/h with them, and a full brake from there falls. Shrunk as
//! v₀/v above 25 km/h, the loop is as quiet at 90 as at 25 and the brake stops upright.

use crate::common;

use cpbp_core::bike::BikeParams;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

/// The street bike with 100 N·m at the bar and arcade's gains held to `tuned_kmh`.
fn strong_at_the_bar(tuned_kmh: f64) -> BikeParams {
    BikeParams {
        max_steer_torque: 100.0,
        arcade_tuned_speed: tuned_kmh / 3.6,
        ..common::street_bike()
    }
}

/// Arcade at 90 km/h for 5 s, then the full brake for 8 s: the largest swing of the bar
/// (°) in the last second before the brake, and whether it fell.
fn full_brake_from_90(bike: BikeParams) -> (f64, bool) {
    let sim = common::flat_ride_with(SimulationConfig {
        bike,
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
    ride.set_intent(Intent::cruise(90.0));
    let mut bar = Vec::new();
    for step in 0..13 * common::FRAMES_PER_SECOND {
        if step == 13 * common::FRAMES_PER_SECOND - 8 * common::FRAMES_PER_SECOND {
            let mut brake = Intent::cruise(90.0);
            brake.drive.throttle = 0.0;
            brake.drive.brake = 1.0;
            ride.set_intent(brake);
        }
        ride.step();
        if ride.sim().crashed().is_some() {
            return (f64::NAN, true);
        }
        if (4 * common::FRAMES_PER_SECOND..5 * common::FRAMES_PER_SECOND).contains(&step) {
            bar.push(
                ride.sim()
                    .bike()
                    .steering(ride.sim().world())
                    .0
                    .to_degrees(),
            );
        }
    }
    let swing = bar.iter().fold(0f64, |m, b| m.max(b.abs()));
    (swing, false)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "a 13 s ride: run in release (tools/test.sh does)"
)]
fn with_its_gains_shrunk_above_25_kmh_arcade_brakes_from_90_on_a_strong_bar() {
    let (_, fell) = full_brake_from_90(strong_at_the_bar(0.0));
    assert!(
        fell,
        "the thesis's gains at 90 km/h on a 100 N·m bar held the brake"
    );
    let (swing, fell) = full_brake_from_90(strong_at_the_bar(25.0));
    assert!(!fell, "fell braking from 90 km/h with the gains shrunk");
    assert!(swing < 0.1, "the bar swung {swing:.2}° at 90 km/h");
}
