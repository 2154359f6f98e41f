//! A torus tyre rolls up a kerb: ODE reports a mesh edge with the faces' normals, which
//! the tyre must turn into a contact at the edge itself (cpbp-ode's `tyre.rs`).

use cpbp_core::bike::Placement;
use cpbp_core::ode::{Mass, Solver, World};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::DVec3;

/// A 10 kg wheel of 0.30 m (a torus tyre or a plain sphere) rolling at `speed` into a
/// 0.12 m kerb 1 m ahead; where it is after 2 s (x forward, y up).
fn roll_into_a_kerb(speed: f64, tyre: bool) -> DVec3 {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.set_solver(Solver::Direct);
    let corners = [(1.0, 0.0), (1.0, 0.12), (5.0, 0.0), (5.0, 0.12)];
    let points = corners
        .iter()
        .flat_map(|&(x, y)| [DVec3::new(x, y, -2.0), DVec3::new(x, y, 2.0)])
        .collect();
    let kerb = TerrainPiece {
        source: "kerb".into(),
        shape: TerrainShape::Convex { points },
        placement: Placement::IDENTITY,
    };
    let ground = TerrainPiece::flat_ground();
    let wheel = world.add_body(Mass::sphere(10.0, 0.3), DVec3::new(0.0, 0.3, 0.0));
    if tyre {
        world.add_tyre(0.3, 0.06, wheel);
    } else {
        world.add_sphere(0.3, Some(wheel));
    }
    Terrain::new(vec![kerb, ground])
        .expect("valid terrain")
        .add_to(&mut world);
    world.set_body_linear_velocity(wheel, DVec3::new(speed, 0.0, 0.0));
    world.set_body_angular_velocity(wheel, DVec3::new(0.0, 0.0, -speed / 0.3));
    for _ in 0..240 {
        world.step(1.0 / 120.0);
    }
    world.body_position(wheel)
}

#[test]
fn a_tyre_rolls_up_a_kerb_as_a_sphere_does() {
    for speed in [2.0, 4.0] {
        let (tyre, sphere) = (
            roll_into_a_kerb(speed, true),
            roll_into_a_kerb(speed, false),
        );
        assert!(
            (tyre[1] - 0.42).abs() < 0.01 && tyre[0] > 1.2,
            "at {speed} m/s the tyre is at {tyre:?}, not on the kerb (a sphere: {sphere:?})"
        );
    }
}
