//! The C-PBP planner balancing an inverted pendulum simulated in ODE: the smallest
//! unstable system with real contacts-free rigid-body dynamics, cloned worlds and motors.

mod common;

use common::pendulum::{Pendulum, DT};
use cpbp_core::control::cpbp::{CpbpConfig, CpbpPlanner, Priors, RolloutSystem, WarmStart};

fn planner() -> CpbpPlanner {
    let priors = Priors::uniform(1, 2.0, 1.0, 0.2, 4.0);
    let config = CpbpConfig {
        particles: 16,
        steps: 24,
        seed: 1,
        ..CpbpConfig::default()
    };
    CpbpPlanner::new(config, priors)
}

#[test]
fn left_alone_the_pendulum_falls() {
    let mut free = Pendulum::new(0.2);
    for _ in 0..60 {
        free.world.set_motor(free.hinge, 0, 0.0, 0.0);
        free.world.step(DT / 2.0);
        free.world.step(DT / 2.0);
    }
    assert!(free.tilt().abs() > 1.0, "tilt {}", free.tilt());
}

#[test]
fn the_planner_brings_it_upright_and_keeps_it_there() {
    let mut master = Pendulum::new(0.3);
    let mut systems: Vec<Pendulum> = (0..16).map(|_| Pendulum::new(0.3)).collect();
    let mut planner = planner();
    let mut tilts = Vec::new();
    for _ in 0..150 {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        let refined = result.refined.as_ref().expect("features given");
        assert!(refined.iter().all(|u| (-4.0..=4.0).contains(u)));
        master.advance(result.control[0]);
        tilts.push(master.tilt());
    }
    let last = &tilts[90..];
    let worst = last.iter().map(|t| t.abs()).fold(0.0, f64::max);
    assert!(worst < 0.05, "worst tilt over the last 2 s: {worst} rad");
}
