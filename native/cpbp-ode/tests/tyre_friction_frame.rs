//! Grip the same at every heading: a sled on four round skids (tyres that cannot turn)
//! slides along its own length at headings 0°, 22.5° and 45° to the world's axes. With
//! ODE's own friction directions (world axes on level ground) its pyramid lets the sled
//! at 45° slow √2 times as hard as the one at 0°; with the directions following the tyre
//! (`World::set_tyre_friction_follows_wheel`) it slows at μg at every heading.

use cpbp_ode::{DQuat, DVec3, Mass, SurfaceParams, World};

const G: f64 = 9.81;
const MU: f64 = 0.8;
const SKID_RADIUS: f64 = 0.05;

/// The sled's deceleration (m/s²) sliding at 6 m/s along its length, heading `degrees`
/// from the world's x axis, measured over 0.3 s.
fn deceleration(degrees: f64, follows_wheel: bool) -> f64 {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    world.set_surface(SurfaceParams {
        mu: MU,
        ..SurfaceParams::default()
    });
    world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
    // Low and long, so braking barely moves its load between the skids.
    let height = 0.1;
    let sled = world.add_body(
        Mass::cuboid(50.0, DVec3::new(1.2, 0.1, 0.6)),
        DVec3::new(0.0, height, 0.0),
    );
    let heading = DQuat::from_rotation_y(degrees.to_radians());
    world.set_body_quaternion(sled, heading);
    for (x, z) in [(0.5, 0.25), (0.5, -0.25), (-0.5, 0.25), (-0.5, -0.25)] {
        // A skid is a tyre whose crown is its radius; its "axle" is the sled's z, so it
        // rolls (and here slides) along the sled's x.
        let skid = world.add_tyre(SKID_RADIUS, SKID_RADIUS, sled);
        world.set_geom_offset(
            skid,
            DVec3::new(x, SKID_RADIUS - height, z),
            DQuat::IDENTITY,
        );
        world.set_tyre_friction_follows_wheel(skid, follows_wheel);
    }
    let v0 = 6.0;
    let forward = heading * DVec3::X;
    world.set_body_linear_velocity(sled, forward * v0);
    let (dt, seconds) = (1.0 / 120.0, 0.3);
    for _ in 0..(seconds / dt) as usize {
        world.step(dt);
    }
    (v0 - world.body_linear_velocity(sled).dot(forward)) / seconds
}

#[test]
fn with_friction_along_the_tyre_a_slide_slows_alike_at_every_heading() {
    let expected = MU * G;
    for degrees in [0.0, 22.5, 45.0, 60.0] {
        let measured = deceleration(degrees, true);
        assert!(
            (measured - expected).abs() < 0.02 * expected,
            "heading {degrees}°: {measured:.3} m/s², expected μg = {expected:.3}"
        );
    }
}

#[test]
fn with_odes_own_directions_the_grip_depends_on_heading() {
    // What the bike field `tyre_friction_follows_wheel` is for: left at 0 (the reference
    // bike's), a slide diagonal to the world's axes meets the pyramid's diagonal.
    let along_axis = deceleration(0.0, false);
    let diagonal = deceleration(45.0, false);
    let ratio = diagonal / along_axis;
    assert!(
        (ratio - 2f64.sqrt()).abs() < 0.03,
        "45° / 0°: {ratio:.3}, expected √2 ({along_axis:.3} and {diagonal:.3} m/s²)"
    );
}
