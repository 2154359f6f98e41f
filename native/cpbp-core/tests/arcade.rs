//! The arcade controller (thesis §4.3.2) on flat ground: it keeps the bike up, follows a
//! commanded lean, and counter-steers to start a turn.

mod common;

use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Ride};

fn arcade_at(kmh: f64) -> Ride {
    common::ride_at(ControllerKind::ARCADE, kmh, 0)
}

#[test]
fn it_rides_straight_for_20_seconds_at_every_test_speed() {
    for kmh in [10.0, 15.0, 20.0, 25.0] {
        let mut ride = arcade_at(kmh);
        common::assert_rides_straight_for_20_seconds(&mut ride);
        let sim = ride.sim();
        let speed = sim.bike().forward_speed(sim.world(), sim.up()) * 3.6;
        assert!((speed - kmh).abs() < 0.5, "{kmh} km/h: rode at {speed}");
        let lean = common::lean(&ride).abs();
        assert!(lean < 5f64.to_radians(), "{kmh} km/h: leaning {lean} rad");
    }
}

#[test]
fn it_follows_a_commanded_lean_at_20_kmh() {
    let rms = common::rms_lean_error_in_a_15_degree_turn(&mut arcade_at(20.0));
    assert!(rms <= 3.0, "RMS lean error {rms:.2}° in a steady 15° turn");
}

#[test]
fn it_settles_into_fast_lean_reversals_at_25_kmh() {
    // A horizon of 0.8 s at every speed crept the last degrees: 5.5° here.
    let mut ride = common::ride_in(PhysicsModel::Exact, ControllerKind::ARCADE, 25.0, 0);
    let rms = common::settled_lean_error_in_reversals(&mut ride);
    assert!(
        rms <= 2.0,
        "settled RMS lean error {rms:.2}° in ±15° reversals"
    );
}

#[test]
fn a_right_turn_starts_with_a_left_counter_steer() {
    common::assert_counter_steers_into_a_right_turn(&mut arcade_at(20.0));
}

#[test]
fn it_rides_a_bike_file_other_than_the_reference() {
    // The pit bike the game's tests draw, read from its file as the Rust tools read bikes.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/fixtures/bikes/pit_bike.tres");
    let bike = cpbp_core::bike::read_bike_file(&path).unwrap();
    assert_eq!(bike.params.wheelbase, 1.12);
    let config = cpbp_core::simulation::SimulationConfig {
        bike: bike.params,
        ..Default::default()
    };
    let mut ride = Ride::new(common::flat_ride_with(config), ControllerKind::ARCADE);
    ride.set_intent(cpbp_core::ride::Intent::cruise(15.0));
    common::assert_rides_straight_for_20_seconds(&mut ride);
}
