//! A foot's leg (`World::set_foot_leg`): stretching it moves the sole, so a body resting
//! on a foot is held higher by as much; and whether the foot is down and how far its leg
//! is stretched come back with a snapshot, so a world branched from it stands the same.

use cpbp_ode::{DVec3, FootSurface, GeomId, Mass, World};

const DT: f64 = 1.0 / 240.0;
const SOLE: DVec3 = DVec3::new(0.0, -0.3, 0.0);

/// A 10 kg block held off the ground on one foot below it, its leg pointing down.
fn block_on_a_foot() -> (World, GeomId) {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.add_plane(DVec3::Y, 0.0);
    let block = world.add_body(Mass::sphere(10.0, 0.1), DVec3::new(0.0, 0.5, 0.0));
    let surface = FootSurface {
        mu: 0.8,
        stiffness: 80_000.0,
        damping: 3_000.0,
    };
    let foot = world.add_foot(0.05, block, surface);
    world.set_foot_leg(foot, SOLE, -DVec3::Y);
    world.set_foot_down(foot, true);
    (world, foot)
}

fn settle(world: &mut World, seconds: f64) {
    for _ in 0..(seconds / DT).round() as usize {
        world.step(DT);
    }
}

fn height(world: &World) -> f64 {
    world.body_position(cpbp_ode::BodyId(0)).y
}

#[test]
fn a_stretched_leg_holds_the_body_higher_by_the_stretch() {
    let (mut world, foot) = block_on_a_foot();
    settle(&mut world, 1.0);
    let standing = height(&world);
    // Sole 0.3 below, radius 0.05, sinking ~1.2 mm under 98 N at 80 kN/m.
    assert!((standing - 0.35).abs() < 0.005, "stood at {standing}");
    assert!(world.foot_touches_ground(foot));

    world.set_foot_extension(foot, 0.1);
    settle(&mut world, 1.0);
    let stretched = height(&world) - standing;
    assert!((stretched - 0.1).abs() < 1e-3, "rose {stretched}");
    assert_eq!(world.foot_extension(foot), 0.1);
}

#[test]
fn a_snapshot_carries_the_foot_down_and_its_leg() {
    let (mut world, foot) = block_on_a_foot();
    world.set_foot_extension(foot, 0.08);
    settle(&mut world, 0.5);
    let branch = world.snapshot();
    assert_eq!(branch.feet_down, vec![true]);
    assert_eq!(branch.feet_extension, vec![0.08]);
    settle(&mut world, 0.5);
    let original = world.snapshot();

    // Lifted and retracted since: restoring puts both back, and the steps repeat exactly.
    world.set_foot_down(foot, false);
    world.set_foot_extension(foot, 0.0);
    settle(&mut world, 0.2);
    world.restore(&branch).unwrap();
    assert!(world.is_foot_down(foot));
    assert_eq!(world.foot_extension(foot), 0.08);
    settle(&mut world, 0.5);
    assert_eq!(world.snapshot(), original);
}

#[test]
fn a_leg_turned_moves_its_sole_and_a_snapshot_carries_the_turn() {
    let (mut world, foot) = block_on_a_foot();
    world.set_foot_extension(foot, 0.1);
    assert_eq!(world.foot_sole(foot), Some(SOLE - DVec3::Y * 0.1));
    let slanted = DVec3::new(0.0, -1.0, 1.0);
    world.set_foot_leg_direction(foot, slanted);
    let sole = world.foot_sole(foot).unwrap();
    assert!(
        (sole - (SOLE + slanted.normalize() * 0.1)).length() < 1e-12,
        "{sole}"
    );
    settle(&mut world, 0.3);
    let branch = world.snapshot();
    assert_eq!(
        branch.feet_leg_direction,
        vec![slanted.normalize().to_array()]
    );
    settle(&mut world, 0.3);
    let original = world.snapshot();

    // Turned back since: restoring turns it again, and the steps repeat exactly.
    world.set_foot_leg_direction(foot, -DVec3::Y);
    settle(&mut world, 0.2);
    world.restore(&branch).unwrap();
    assert_eq!(world.foot_leg_direction(foot), Some(slanted.normalize()));
    settle(&mut world, 0.3);
    assert_eq!(world.snapshot(), original);
}
