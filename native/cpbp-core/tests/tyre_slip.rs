//! How fast a tyre slides over the ground: what the game's tyre marks and smoke answer.

use cpbp_core::bike::{Bike, BikeParams, Part, Placement};
use cpbp_core::ode::World;
use glam::DVec3;

const UP: DVec3 = DVec3::Y;

/// The bike in its built pose moving forward (+x) at `speed` as one body, each wheel
/// turning at `spin` times the rate that rolls it at that speed.
fn moving_bike(speed: f64, spin: f64) -> (World, Bike) {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.add_plane(UP, 0.0);
    let params = BikeParams::default();
    let bike = Bike::build(&mut world, &params, &Placement::IDENTITY);
    for part in Part::ALL {
        world.set_body_linear_velocity(bike.body(part), DVec3::X * speed);
    }
    // Axles along +z: a wheel rolls forward turning about −z.
    let rolling = -DVec3::Z * speed / params.wheel_radius;
    for wheel in [Part::RearWheel, Part::FrontWheel] {
        world.set_body_angular_velocity(bike.body(wheel), rolling * spin);
    }
    (world, bike)
}

#[test]
fn a_rolling_tyre_does_not_slide_and_a_locked_one_slides_at_the_bikes_speed() {
    let (world, bike) = moving_bike(8.0, 1.0);
    let (rear, front) = bike.tyre_slip_speeds(&world, UP);
    assert!(
        rear < 0.05 && front < 0.05,
        "rolling: {rear:.3}, {front:.3} m/s"
    );
    let (world, bike) = moving_bike(8.0, 0.0);
    let (rear, front) = bike.tyre_slip_speeds(&world, UP);
    assert!(
        (rear - 8.0).abs() < 0.05 && (front - 8.0).abs() < 0.05,
        "locked: {rear}, {front}"
    );
    let (world, bike) = moving_bike(8.0, 1.5);
    let (rear, _) = bike.tyre_slip_speeds(&world, UP);
    assert!(
        (rear - 4.0).abs() < 0.05,
        "spinning half as fast again: {rear}"
    );
}

#[test]
fn sliding_sideways_is_sliding() {
    let (mut world, bike) = moving_bike(0.0, 0.0);
    for part in Part::ALL {
        world.set_body_linear_velocity(bike.body(part), DVec3::Z * 3.0);
    }
    let (rear, front) = bike.tyre_slip_speeds(&world, UP);
    assert!(
        (rear - 3.0).abs() < 0.05 && (front - 3.0).abs() < 0.05,
        "{rear}, {front}"
    );
}
