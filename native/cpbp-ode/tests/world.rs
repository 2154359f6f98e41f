//! A world steps, collides and moves between threads, through the public API only.

use cpbp_ode::{DVec3, Gyroscopic, Mass, Solver, World};

const G: f64 = 9.81;

#[test]
fn a_dropped_body_falls_half_g_t_squared() {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    let ball = world.add_body(Mass::sphere(1.0, 0.1), DVec3::new(0.0, 10.0, 0.0));
    let dt = 1.0 / 240.0;
    let steps = 240;
    for _ in 0..steps {
        world.step(dt);
    }
    let t = dt * steps as f64;
    let fallen = 10.0 - world.body_position(ball)[1];
    // Semi-implicit Euler overshoots ½gt² by ½g·t·dt; allow that and no more.
    let exact = 0.5 * G * t * t;
    assert!(
        (fallen - exact).abs() <= 0.5 * G * t * dt + 1e-9,
        "fell {fallen}, ½gt² = {exact}"
    );
    assert!((world.body_linear_velocity(ball)[1] + G * t).abs() < 1e-9);
}

#[test]
fn a_sphere_comes_to_rest_on_a_plane_with_either_solver() {
    for solver in [Solver::QuickStep, Solver::Direct] {
        let mut world = World::new(DVec3::new(0.0, -G, 0.0));
        world.set_solver(solver);
        world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
        let ball = world.add_body(Mass::sphere(2.0, 0.25), DVec3::new(0.0, 1.0, 0.0));
        world.add_sphere(0.25, Some(ball));
        for _ in 0..600 {
            world.step(1.0 / 120.0);
        }
        let y = world.body_position(ball)[1];
        assert!(
            (y - 0.25).abs() < 0.01,
            "{solver:?}: sphere rests at {y}, radius 0.25"
        );
        assert!(
            world.body_linear_velocity(ball)[1].abs() < 1e-3,
            "{solver:?}"
        );
    }
}

#[test]
fn a_body_knows_the_slope_it_stands_on_and_a_snapshot_carries_it() {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    // A road falling 15° towards +x; the ball rolls down it.
    let slope = DVec3::new(15f64.to_radians().sin(), 15f64.to_radians().cos(), 0.0);
    world.add_plane(slope, 0.0);
    let ball = world.add_body(Mass::sphere(2.0, 0.25), DVec3::new(0.0, 0.26, 0.0));
    world.add_sphere(0.25, Some(ball));
    assert_eq!(world.body_ground_normal(ball), None, "not stepped yet");
    for _ in 0..10 {
        world.step(1.0 / 120.0);
    }
    let normal = world.body_ground_normal(ball).expect("on the road");
    assert!((normal - slope).length() < 1e-9, "{normal}");
    let saved = world.snapshot();
    world.forget_contacts();
    assert_eq!(world.body_ground_normal(ball), None);
    world.restore(&saved).unwrap();
    assert_eq!(world.body_ground_normal(ball), Some(normal));
}

#[test]
fn many_threads_step_their_own_worlds_with_contacts_at_once() {
    // The rollouts step one world per thread; this must be race-free (no shared
    // threading dispatcher, thread-local collision caches) and give identical results.
    let simulate = || {
        let mut world = World::new(DVec3::new(0.0, -G, 0.0));
        world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
        let ball = world.add_body(Mass::sphere(1.0, 0.2), DVec3::new(0.0, 0.5, 0.0));
        world.add_sphere(0.2, Some(ball));
        world.add_box(DVec3::new(0.5, 0.5, 0.5), None);
        for _ in 0..2000 {
            world.step(1.0 / 240.0);
        }
        world.body_position(ball)
    };
    let reference = simulate();
    let handles: Vec<_> = (0..8).map(|_| std::thread::spawn(simulate)).collect();
    for handle in handles {
        assert_eq!(handle.join().unwrap(), reference);
    }
}

#[test]
fn worlds_can_move_between_threads() {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    let ball = world.add_body(Mass::sphere(1.0, 0.1), DVec3::new(0.0, 0.0, 0.0));
    let world = std::thread::spawn(move || {
        world.step(0.1);
        world
    })
    .join()
    .unwrap();
    assert!(world.body_position(ball)[1] < 0.0);
}

#[test]
fn a_tabulated_inertia_is_taken_and_an_impossible_one_refused() {
    let frame = [[9.2, 0.0, 2.4], [0.0, 11.0, 0.0], [2.4, 0.0, 2.8]];
    assert_eq!(
        Mass::with_inertia(85.0, frame).map(|m| m.total()),
        Some(85.0)
    );
    // Violates the triangle inequality (no rigid body has it).
    let impossible = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 5.0]];
    assert!(Mass::with_inertia(1.0, impossible).is_none());
    let lopsided = [[1.0, 0.2, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    assert!(Mass::with_inertia(1.0, lopsided).is_none(), "not symmetric");
    assert!(Mass::with_inertia(0.0, frame).is_none());
}

#[test]
fn a_gyroscope_precesses_at_the_textbook_rate_with_the_explicit_gyroscopic_term() {
    // A wheel spinning at 40 rad/s about its axle, held by a ball joint on the axle 0.2 m
    // from its centre: gravity's torque turns the axle about the vertical at
    // Ω = m g d / (I_s ω_s). This is the coupling a bicycle's wheels give its frame.
    let (mass, radius, arm, spin) = (2.0, 0.3, 0.2, 40.0);
    let precession = mass * G * arm / (0.5 * mass * radius * radius * spin);
    let seconds = 2.0;
    let turned = |mode: Gyroscopic| {
        let mut world = World::new(DVec3::new(0.0, -G, 0.0));
        let wheel = world.add_body(
            Mass::cylinder(mass, 0, radius, 0.05),
            DVec3::new(arm, 0.0, 0.0),
        );
        world.add_ball(wheel, None, DVec3::ZERO);
        world.set_gyroscopic(wheel, mode);
        world.set_body_angular_velocity(wheel, DVec3::new(spin, precession, 0.0));
        world.set_body_linear_velocity(wheel, DVec3::new(0.0, 0.0, -precession * arm));
        for _ in 0..(seconds * 120.0) as usize {
            world.step(1.0 / 120.0);
        }
        let [x, _, z] = world.body_position(wheel).to_array();
        (-z).atan2(x)
    };
    let expected = precession * seconds;
    let explicit = turned(Gyroscopic::Explicit);
    let implicit = turned(Gyroscopic::Implicit);
    // Measured: explicit −1 %, ODE's implicit term +7 % (it weakens the wheel's coupling).
    let error = |found: f64| (found / expected - 1.0).abs();
    assert!(
        error(explicit) < 0.03,
        "explicit turned {explicit}, expected {expected}"
    );
    assert!(
        error(implicit) > 2.0 * error(explicit),
        "implicit turned {implicit}"
    );
}
