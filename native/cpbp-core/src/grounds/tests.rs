use glam::{DQuat, DVec3};
use rand::SeedableRng;
use rand_pcg::Pcg64Mcg;

use super::*;
use crate::bike::Placement;
use crate::terrain::{Terrain, TerrainShape};

#[test]
fn the_test_levels_field_is_its_file() {
    let field = LogField::test_level();
    assert_eq!(field.area, [14.0, 22.0]);
    assert_eq!(field.count, 20);
    assert_eq!(field.radius, [0.08, 0.16]);
    assert_eq!(
        field.length,
        LogField::default().length,
        "left at the default"
    );
}

#[test]
fn a_broken_field_file_names_the_key() {
    let head = "[gd_resource type=\"LogFieldDescription\" format=3]\n\n[resource]\n";
    let refused = |body: &str| parse_log_field(&format!("{head}{body}")).unwrap_err();
    assert!(refused("count = many\n").contains("count"));
    assert!(refused("count = 500\n").contains("at most 200"));
    assert!(refused("radius_range = Vector2(0.2, 0.1)\n").contains("radius_range"));
    assert!(refused("area = (1, 2)\n").contains("Vector2"));
    assert!(refused("wobble = 3\n").contains("no wobble"));
    assert!(parse_log_field("[gd_resource type=\"BikeDescription\" format=3]").is_err());
}

#[test]
fn a_seed_lays_the_same_logs_inside_the_field() {
    let field = LogField::test_level();
    let logs = field.layout(1042);
    assert_eq!(logs, field.layout(1042));
    assert_ne!(logs, field.layout(1043));
    assert_eq!(logs.len(), 20);
    for log in &logs {
        assert!((0.08..=0.16).contains(&log.radius) && (1.0..=3.0).contains(&log.length));
        assert!(log.angle.abs() <= 35f64.to_radians() + 1e-9);
        assert!(log.centre[0].abs() <= 7.0 && log.centre[2].abs() <= 11.0);
    }
}

#[test]
fn logs_lie_across_the_way_where_the_field_is_placed() {
    let field = LogField {
        count: 1,
        max_angle_deg: 0.0,
        ..LogField::default()
    };
    let log = field.layout(7)[0];
    // The field turned so its way ahead (−z) is +x, 10 m along x.
    let at = Placement {
        position: DVec3::new(10.0, 0.0, 0.0),
        rotation: DQuat::from_rotation_y(-std::f64::consts::FRAC_PI_2),
    };
    let piece = &field.pieces(7, at)[0];
    let axis = piece.placement.rotation * DVec3::Y;
    assert!(
        axis.x.abs() < 1e-12 && (axis.z.abs() - 1.0).abs() < 1e-12,
        "{axis}"
    );
    let ahead = piece.placement.position.x - 10.0;
    assert!(
        (ahead + f64::from(log.centre[2])).abs() < 1e-6,
        "−z became +x"
    );
    assert!(matches!(piece.shape, TerrainShape::Cylinder { .. }));
    let mut pieces = vec![crate::terrain::TerrainPiece::flat_ground()];
    pieces.extend(LogField::test_level().pieces(3, at));
    assert!(Terrain::new(pieces).is_ok());
}

#[test]
fn rolling_bumps_are_one_ground_as_heights_or_triangles() {
    let bumps = RollingBumps::draw(&mut Pcg64Mcg::seed_from_u64(5), 0.1);
    for (x, z) in [(0.0, 0.0), (3.5, 7.25), (31.0, 2.0)] {
        let h = bumps.height_at(x, z);
        assert!((0.0..=0.1).contains(&h), "{h}");
    }
    let TerrainShape::HeightMap { heights, .. } = bumps.height_map(4, 2.0).shape else {
        panic!("a height map");
    };
    // Row z = 1 (of 5 posts), column x = 2: at (4 m, 2 m).
    assert_eq!(heights[5 + 2], bumps.height_at(4.0, 2.0));
    let TerrainShape::TriMesh { vertices } = bumps.tri_mesh(4, 2.0).shape else {
        panic!("a mesh");
    };
    assert_eq!(vertices.len(), 4 * 4 * 6);
    assert_eq!(
        vertices[0],
        DVec3::new(-4.0, bumps.height_at(-4.0, -4.0), -4.0)
    );
}
