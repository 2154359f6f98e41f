//! The arcade controller (thesis §4.3.2) on flat ground: it keeps the bike up, follows a
//! commanded lean, and counter-steers to start a turn.

mod common;

use cpbp_core::bike::Controls;
use cpbp_core::control::ArcadeController;
use cpbp_core::simulation::Simulation;

const DT: f64 = 1.0 / common::FRAMES_PER_SECOND as f64;

/// The arcade controller at `kmh`, as a closure the scenarios drive.
fn arcade_at(kmh: f64) -> impl FnMut(&Simulation, f64) -> Controls {
    let mut arcade = ArcadeController::default();
    let drive = common::auto_throttle(kmh);
    move |sim, lean| arcade.controls(sim.bike(), sim.world(), lean, &drive, sim.up(), DT)
}

#[test]
fn it_rides_straight_for_20_seconds_at_every_test_speed() {
    for kmh in [10.0, 15.0, 20.0, 25.0] {
        let mut sim = common::flat_ride();
        common::assert_rides_straight_for_20_seconds(&mut sim, &mut arcade_at(kmh));
        let speed = sim.bike().forward_speed(sim.world(), sim.up()) * 3.6;
        assert!((speed - kmh).abs() < 0.5, "{kmh} km/h: rode at {speed}");
        let lean = sim.bike().lean(sim.world(), sim.up()).abs();
        assert!(lean < 5f64.to_radians(), "{kmh} km/h: leaning {lean} rad");
    }
}

#[test]
fn it_follows_a_commanded_lean_at_20_kmh() {
    let rms =
        common::rms_lean_error_in_a_15_degree_turn(&mut common::flat_ride(), &mut arcade_at(20.0));
    assert!(rms <= 3.0, "RMS lean error {rms:.2}° in a steady 15° turn");
}

#[test]
fn a_right_turn_starts_with_a_left_counter_steer() {
    common::assert_counter_steers_into_a_right_turn(&mut common::flat_ride(), &mut arcade_at(20.0));
}
