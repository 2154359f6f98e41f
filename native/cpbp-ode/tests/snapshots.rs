//! Snapshot/restore must let a rollout branch from any state and reproduce what the
//! original world does, bit for bit, and a world must step the same whatever else its
//! thread steps (each world carries its own QuickStep random sequence).

use cpbp_ode::{DVec3, Mass, World, WorldState};

const DT: f64 = 1.0 / 120.0;

/// A small pile of boxes and spheres tumbling onto a plane and into each other: many
/// contacts, so QuickStep's constraint reordering and the collision order both matter.
fn tumbling_pile() -> World {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
    for i in 0..4 {
        let x = i as f64 * 0.35;
        let cube = world.add_body(
            Mass::cuboid(3.0, DVec3::new(0.4, 0.4, 0.4)),
            DVec3::new(x, 0.5 + 0.45 * i as f64, 0.1 * i as f64),
        );
        world.add_box(DVec3::new(0.4, 0.4, 0.4), Some(cube));
        world.set_body_linear_velocity(cube, DVec3::new(0.5 - 0.3 * i as f64, 0.0, 0.2));
        let ball = world.add_body(
            Mass::sphere(1.5, 0.2),
            DVec3::new(x + 0.1, 1.2 + 0.4 * i as f64, -0.15),
        );
        world.add_sphere(0.2, Some(ball));
    }
    world
}

fn run(world: &mut World, steps: usize) -> Vec<WorldState> {
    (0..steps)
        .map(|_| {
            world.step(DT);
            world.snapshot()
        })
        .collect()
}

/// Lets the pile settle a little, takes a snapshot there, then records what follows.
fn branch_point_and_original(world: &mut World) -> (WorldState, Vec<WorldState>) {
    run(world, 40);
    let branch_point = world.snapshot();
    (branch_point, run(world, 240))
}

#[test]
fn restore_then_steps_repeat_the_original_bit_for_bit() {
    let mut world = tumbling_pile();
    let (branch_point, original) = branch_point_and_original(&mut world);

    world.restore(&branch_point).unwrap();
    let replay = run(&mut world, 240);
    assert_eq!(replay, original);
    assert!(original
        .last()
        .unwrap()
        .bodies
        .iter()
        .all(|b| b.is_finite()));
}

#[test]
fn restoring_into_another_identically_built_world_matches() {
    let (branch_point, original) = branch_point_and_original(&mut tumbling_pile());

    let mut rollout = tumbling_pile();
    run(&mut rollout, 7); // a different history must not matter
    rollout.restore(&branch_point).unwrap();
    assert_eq!(run(&mut rollout, 240), original);
}

#[test]
fn a_restored_world_reports_the_contacts_of_the_state_it_was_given() {
    // What a step is asked before it runs (did this body touch the ground in the last
    // step?) is part of the state: a world restored from elsewhere must not answer from
    // its own history.
    let mut original = tumbling_pile();
    run(&mut original, 120);
    let on_the_ground = original.snapshot();
    let touching: Vec<bool> = (0..8)
        .map(|i| original.body_touches_static(cpbp_ode::BodyId(i)))
        .collect();
    assert!(
        touching.iter().any(|&t| t),
        "the pile has settled onto the plane"
    );

    let mut fresh = tumbling_pile();
    fresh.restore(&on_the_ground).unwrap();
    let restored: Vec<bool> = (0..8)
        .map(|i| fresh.body_touches_static(cpbp_ode::BodyId(i)))
        .collect();
    assert_eq!(restored, touching);
    assert_eq!(fresh.snapshot(), on_the_ground);
}

#[test]
fn rollouts_on_several_threads_match_the_single_threaded_result() {
    let (branch_point, original) = branch_point_and_original(&mut tumbling_pile());

    let handles: Vec<_> = (0..4)
        .map(|_| {
            let start = branch_point.clone();
            std::thread::spawn(move || {
                let mut rollout = tumbling_pile();
                rollout.restore(&start).unwrap();
                run(&mut rollout, 240)
            })
        })
        .collect();
    for handle in handles {
        assert_eq!(handle.join().unwrap(), original);
    }
}

#[test]
fn a_snapshot_of_another_shape_is_refused() {
    let mut small = World::new(DVec3::new(0.0, -9.81, 0.0));
    small.add_body(Mass::sphere(1.0, 0.1), DVec3::new(0.0, 1.0, 0.0));
    let error = small.restore(&tumbling_pile().snapshot()).unwrap_err();
    assert_eq!(error.expected_bodies, 1);
    assert_eq!(error.found_bodies, 8);
}

#[test]
fn worlds_stepped_in_turn_on_one_thread_each_repeat_their_lone_ride() {
    let alone = run(&mut tumbling_pile(), 200);
    let (mut first, mut second) = (tumbling_pile(), tumbling_pile());
    run(&mut second, 13); // a head start, so the two sequences differ
    let interleaved: Vec<WorldState> = (0..200)
        .map(|_| {
            second.step(DT);
            first.step(DT);
            first.snapshot()
        })
        .collect();
    assert_eq!(interleaved, alone);
}
