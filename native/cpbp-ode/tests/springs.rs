//! Spring–dampers on joints: a mass on a vertical slider settles where the spring carries
//! its weight, rings at the spring's frequency with the damper's overshoot, stays stable
//! at long steps, stops hard at the ends of its travel, and a hinge spring works alike.

use cpbp_ode::{DVec3, Mass, Solver, Spring, World};

const G: f64 = 9.81;
/// A motorcycle corner: 100 kg on 18 N/mm, damped at 0.4 of critical (ω = 13.4 rad/s).
const MASS: f64 = 100.0;
const RATE: f64 = 18_000.0;
const ZETA: f64 = 0.4;

fn damping() -> f64 {
    2.0 * ZETA * (RATE * MASS).sqrt()
}

/// A 100 kg block on a vertical slider to the world with the corner's spring, the free
/// position 50 mm above where it is built (a preloaded spring beyond the top of travel).
fn sprung_block(
    solver: Solver,
    travel: (f64, f64),
) -> (World, cpbp_ode::BodyId, cpbp_ode::JointId) {
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    world.set_solver(solver);
    let block = world.add_body(
        Mass::cuboid(MASS, DVec3::new(0.3, 0.3, 0.3)),
        DVec3::new(0.0, 1.0, 0.0),
    );
    let slider = world.add_slider(block, None, DVec3::new(0.0, 1.0, 0.0));
    world.set_spring(
        slider,
        Spring {
            stiffness: RATE,
            damping: damping(),
            free_position: 0.05,
            travel,
        },
    );
    (world, block, slider)
}

/// Positions of the slider, one per step of `dt`, for `seconds`.
fn ride(world: &mut World, joint: cpbp_ode::JointId, dt: f64, seconds: f64) -> Vec<f64> {
    (0..(seconds / dt).round() as usize)
        .map(|_| {
            world.step(dt);
            world.joint_position(joint)
        })
        .collect()
}

#[test]
fn the_spring_carries_the_weight_where_hookes_law_says() {
    for solver in [Solver::Direct, Solver::QuickStep] {
        let (mut world, _, slider) = sprung_block(solver, (-0.2, 0.2));
        let path = ride(&mut world, slider, 1.0 / 120.0, 4.0);
        let settled = *path.last().unwrap();
        let expected = 0.05 - MASS * G / RATE;
        assert!(
            (settled - expected).abs() < 1e-4,
            "{solver:?}: settled at {settled:.5} m, k·x = m·g at {expected:.5}"
        );
    }
}

#[test]
fn it_rings_at_the_springs_frequency_with_the_dampers_overshoot() {
    let dt = 1.0 / 120.0;
    let (mut world, _, slider) = sprung_block(Solver::Direct, (-0.2, 0.2));
    let path = ride(&mut world, slider, dt, 2.0);
    let equilibrium = 0.05 - MASS * G / RATE;
    // Released from 0 at rest: the first trough, its time and depth past equilibrium.
    let (trough, lowest) = path.iter().enumerate().take((0.6 / dt) as usize).fold(
        (0, f64::MAX),
        |(i0, low), (i, &x)| if x < low { (i, x) } else { (i0, low) },
    );
    let omega = (RATE / MASS).sqrt();
    let damped = omega * (1.0 - ZETA * ZETA).sqrt();
    let half_period = std::f64::consts::PI / damped;
    let time = (trough + 1) as f64 * dt;
    assert!(
        (time - half_period).abs() < 0.1 * half_period,
        "trough after {time:.3} s, half a damped period is {half_period:.3} s"
    );
    let overshoot = (equilibrium - lowest) / equilibrium.abs();
    let exact = (-std::f64::consts::PI * ZETA / (1.0 - ZETA * ZETA).sqrt()).exp();
    // The implicit step damps a little more than the damper: h·ω/2 ≈ 0.06 of critical.
    assert!(
        overshoot < exact && overshoot > 0.7 * exact,
        "overshoot {overshoot:.3}, a damper of ζ = {ZETA} gives {exact:.3}"
    );
}

#[test]
fn it_stays_stable_at_a_thirtieth_of_a_second() {
    // h·ω = 0.45 and h·c/m = 0.36: fine implicitly; the point is that nothing blows up.
    let (mut world, block, slider) = sprung_block(Solver::Direct, (-0.2, 0.2));
    let path = ride(&mut world, slider, 1.0 / 30.0, 4.0);
    assert!(path.iter().all(|x| x.is_finite() && x.abs() < 0.2));
    assert!(world.body_linear_velocity(block)[1].abs() < 1e-3);
}

#[test]
fn the_ends_of_travel_are_hard_stops() {
    // The weight sags to −4.5 mm; with the bump stop at −3 mm it comes to rest on it.
    let (mut world, block, slider) = sprung_block(Solver::Direct, (-0.003, 0.01));
    let path = ride(&mut world, slider, 1.0 / 120.0, 2.0);
    let low = path.iter().cloned().fold(f64::MAX, f64::min);
    assert!(low > -0.006, "went {low:.4} m, the bump stop is at −0.003");
    let rest = *path.last().unwrap();
    assert!(
        (rest + 0.003).abs() < 1e-3,
        "rests at {rest:.4} m, on the stop"
    );
    assert!(world.body_linear_velocity(block)[1].abs() < 1e-2);
    // Thrown up at 3 m/s, it tops out at +10 mm: stops are found at the start of a step,
    // so it may pass the end by one step's travel before the stop pulls it back.
    world.set_body_linear_velocity(block, DVec3::new(0.0, 3.0, 0.0));
    let dt = 1.0 / 120.0;
    let path = ride(&mut world, slider, dt, 0.3);
    let high = path.iter().cloned().fold(f64::MIN, f64::max);
    assert!(
        high < 0.01 + 3.0 * dt,
        "went up to {high:.4} m, the top-out stop is at +0.010"
    );
    assert!(path[path.len() - 1] < 0.01, "back inside its travel");
}

#[test]
fn a_hinge_spring_holds_a_lever_where_the_torques_balance() {
    // A 10 kg bob 0.5 m from a pivot about z: gravity's torque m·g·L·cos θ against the
    // spring's k_θ·(θ_free − θ).
    let mut world = World::new(DVec3::new(0.0, -G, 0.0));
    world.set_solver(Solver::Direct);
    let bob = world.add_body(Mass::sphere(10.0, 0.05), DVec3::new(0.5, 1.0, 0.0));
    let pivot = world.add_hinge(
        bob,
        None,
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
    );
    let k = 2_000.0;
    world.set_spring(
        pivot,
        Spring {
            stiffness: k,
            damping: 2.0 * 0.5 * (k * 10.0 * 0.25).sqrt(),
            free_position: 0.0,
            travel: (-0.5, 0.5),
        },
    );
    let path = ride(&mut world, pivot, 1.0 / 120.0, 3.0);
    let sag = -path.last().unwrap();
    let torque_balance = 10.0 * G * 0.5 * sag.cos() - k * sag;
    assert!(
        sag > 0.01 && torque_balance.abs() < 0.05,
        "sagged {sag:.4} rad"
    );
}

#[test]
fn a_restored_world_rings_exactly_as_the_original() {
    // The spring's stops are set from the joint's position before every step, so they
    // need no saving: a snapshot taken mid-swing replays bit for bit, bump stop included.
    let (mut world, _, slider) = sprung_block(Solver::Direct, (-0.003, 0.01));
    ride(&mut world, slider, 1.0 / 120.0, 0.3);
    let snapshot = world.snapshot();
    let first = ride(&mut world, slider, 1.0 / 120.0, 1.0);
    world.restore(&snapshot).unwrap();
    let again = ride(&mut world, slider, 1.0 / 120.0, 1.0);
    assert_eq!(first, again);
}
