//! Coulomb friction bounded by the normal force it loads. A cart skids on a locked rear
//! skid while its front wheel rolls freely: the skid's friction pitches the cart forward
//! and takes load off the skid, so the cart slows less than a skid carrying its static
//! load would. The direct solver's own friction bounds come from normal forces solved
//! without friction (the static load); for tyres, ODE patch 04 solves again with the
//! loaded ones.

use cpbp_ode::{DQuat, DVec3, Mass, Solver, SurfaceParams, World};

const G: f64 = 9.81;
const MU: f64 = 1.0;
/// The cart's centre of mass sits HEIGHT above the ground, REAR behind the skid's contact
/// and FRONT ahead of the front wheel's.
const HEIGHT: f64 = 0.7;
const REAR: f64 = 0.7;
const FRONT: f64 = 0.7;
const CART_MASS: f64 = 100.0;
const WHEEL_RADIUS: f64 = 0.3;
const SKID_RADIUS: f64 = 0.05;

/// The cart's deceleration (m/s²) from 5 m/s, measured over 0.3 s.
fn skid_deceleration(solver: Solver) -> f64 {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    world.set_solver(solver);
    world.set_surface(SurfaceParams {
        mu: MU,
        ..SurfaceParams::default()
    });
    world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
    let cart = world.add_body(
        Mass::cuboid(CART_MASS, DVec3::new(1.4, 0.2, 0.3)),
        DVec3::new(0.0, HEIGHT, 0.0),
    );
    // Both contacts are tyres (a skid of round section is a tyre whose crown is its
    // radius): only tyres ask for the loaded bound.
    let skid = world.add_tyre(SKID_RADIUS, SKID_RADIUS, cart);
    world.set_geom_offset(
        skid,
        DVec3::new(-REAR, SKID_RADIUS - HEIGHT, 0.0),
        DQuat::IDENTITY,
    );
    // A light wheel, so the cart's mass and centre are the cart body's.
    let axle = DVec3::new(FRONT, WHEEL_RADIUS, 0.0);
    let wheel = world.add_body(Mass::sphere(0.01, WHEEL_RADIUS), axle);
    world.add_tyre(WHEEL_RADIUS, 0.06, wheel);
    world.add_hinge(cart, Some(wheel), axle, DVec3::new(0.0, 0.0, 1.0));
    let v0 = 5.0;
    world.set_body_linear_velocity(cart, DVec3::new(v0, 0.0, 0.0));
    world.set_body_linear_velocity(wheel, DVec3::new(v0, 0.0, 0.0));
    world.set_body_angular_velocity(wheel, DVec3::new(0.0, 0.0, -v0 / WHEEL_RADIUS));
    let (dt, seconds) = (1.0 / 120.0, 0.3);
    for _ in 0..(seconds / dt) as usize {
        world.step(dt);
    }
    (v0 - world.body_linear_velocity(cart)[0]) / seconds
}

/// Moments about the centre of mass with the skid's friction μN_r at the ground:
/// N_r = m g FRONT / (REAR + FRONT + μ HEIGHT), so a = μ g FRONT / (L + μ HEIGHT).
fn loaded_deceleration() -> f64 {
    MU * G * FRONT / (REAR + FRONT + MU * HEIGHT)
}

#[test]
fn a_skid_brakes_with_the_load_its_friction_leaves_on_it() {
    // Without patch 04 the direct solver brakes at the static load's 4.86 m/s²; the
    // loaded skid gives 3.27. (QuickStep's 20 iterations stop short of either: 2.35.)
    let expected = loaded_deceleration();
    let measured = skid_deceleration(Solver::Direct);
    assert!(
        (measured - expected).abs() < 0.01 * expected,
        "{measured:.3} m/s², expected {expected:.3}"
    );
}
