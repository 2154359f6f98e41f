//! Snapshots of a riding bike, hostile controls, and explosion detection.

use cpbp_core::bike::{index, Bike, BikeParams, Controls, Part, Placement, CONTROL_DIM};
use cpbp_core::ode::{World, WorldState};
use glam::DVec3;

const DT: f64 = 1.0 / 120.0;

fn riding_bike() -> (World, Bike) {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
    let bike = Bike::build(&mut world, &BikeParams::default(), &Placement::IDENTITY);
    (world, bike)
}

/// Throttle on, rider holding the pose, a gentle steering wobble: exercises every motor.
fn ride(world: &mut World, bike: &Bike, from_step: usize, steps: usize) -> Vec<WorldState> {
    let mut controls = Controls::default();
    controls.set(index::REAR_WHEEL, 15.0);
    controls.set(index::FORCE + 1, 0.4);
    (from_step..from_step + steps)
        .map(|i| {
            controls.set(index::STEER, 0.3 * (i as f64 * 0.05).sin());
            bike.pose_hold(world, 5.0, &mut controls);
            bike.apply(world, &controls);
            world.step(DT);
            world.snapshot()
        })
        .collect()
}

#[test]
fn a_restored_riding_bike_repeats_the_master_bit_for_bit() {
    let (mut master, bike) = riding_bike();
    ride(&mut master, &bike, 0, 90);
    let branch_point = master.snapshot();
    let original = ride(&mut master, &bike, 90, 120);

    master.restore(&branch_point).unwrap();
    assert_same_run(&ride(&mut master, &bike, 90, 120), &original, "same world");

    let (mut rollout, _) = riding_bike();
    rollout.restore(&branch_point).unwrap();
    assert_same_run(
        &ride(&mut rollout, &bike, 90, 120),
        &original,
        "another world",
    );
}

/// Bitwise equality, reported as the first step that differs (the states are large).
fn assert_same_run(replay: &[WorldState], original: &[WorldState], what: &str) {
    assert_eq!(replay.len(), original.len());
    if let Some(step) = (0..replay.len()).find(|&i| replay[i] != original[i]) {
        let body = (0..replay[step].bodies.len())
            .find(|&b| replay[step].bodies[b] != original[step].bodies[b]);
        panic!(
            "{what}: replay differs from step {step} on (body {body:?}; motors equal: {})",
            replay[step].motors == original[step].motors
        );
    }
}

/// SplitMix64: a fixed, dependency-free stream of test inputs.
struct TestInputs(u64);

impl TestInputs {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Mostly plausible numbers, often hostile ones: NaN, ±∞, huge, tiny.
    fn control_value(&mut self) -> f64 {
        match self.next() % 10 {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => f64::NEG_INFINITY,
            3 => (self.next() as f64 - u64::MAX as f64 / 2.0) * 1e290,
            4 => f64::MIN_POSITIVE,
            _ => (self.next() % 20_000) as f64 / 1000.0 - 10.0,
        }
    }
}

#[test]
fn ten_thousand_hostile_control_vectors_never_break_the_simulation() {
    let (mut world, bike) = riding_bike();
    let mut inputs = TestInputs(2015);
    let mut changed_total = 0;
    for _ in 0..10_000 {
        let raw: [f64; CONTROL_DIM] = std::array::from_fn(|_| inputs.control_value());
        let (controls, changed) = Controls::sanitized(&raw);
        changed_total += changed;
        assert!(controls.values().iter().all(|v| v.is_finite()));
        bike.apply(&mut world, &controls);
        world.step(DT);
        assert_eq!(
            bike.explosion(&world),
            None,
            "bounded controls must keep the state finite"
        );
        if bike.part_touching_ground(&world).is_some() {
            bike.reset(&mut world, &Placement::IDENTITY);
        }
    }
    assert!(changed_total > 10_000, "the inputs were not hostile enough");
}

#[test]
fn an_exploding_world_is_detected() {
    let (mut world, bike) = riding_bike();
    world.step(DT);
    assert_eq!(bike.explosion(&world), None);
    world.set_body_linear_velocity(bike.body(Part::Torso), DVec3::new(1e9, 0.0, 0.0));
    let report = bike
        .explosion(&world)
        .expect("an absurd speed is an explosion");
    assert!(report.contains("torso"), "{report}");
    world.set_body_linear_velocity(bike.body(Part::Torso), DVec3::new(f64::NAN, 0.0, 0.0));
    assert!(bike.explosion(&world).unwrap().contains("non-finite"));
    bike.reset(&mut world, &Placement::IDENTITY);
    assert_eq!(bike.explosion(&world), None, "a reset recovers");
}
