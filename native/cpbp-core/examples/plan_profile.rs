//! Plans over and over for a profiler (docs/benchmarks-history.md,
//! "where a plan's time goes"):
//! `perf record -F 2000 native/target/release/examples/plan_profile [N] [threads] [plans]
//! [physics model] [horizon s] [--bike FILE]`. Combined mode, riding off towards 15 km/h
//! on flat ground, rolling out in the physics model's rollout physics (classic unless
//! named), over the default horizon unless one is given, on the reference bike unless
//! `--bike` names another.

use std::sync::Arc;

use cpbp_core::bike::{take_bike_argument, Controls, DriveInput, Placement, POSE_GAIN};
use cpbp_core::control::{cpbp, Goal, PlanningConfig, PlanningSession};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::DVec3;

fn main() {
    let mut arguments: Vec<String> = std::env::args().skip(1).collect();
    let bike = take_bike_argument(&mut arguments)
        .unwrap_or_else(|why| panic!("{why}"))
        .map(|file| file.params)
        .unwrap_or_default();
    let physics = match arguments.get(3) {
        Some(name) => PhysicsModel::from_name(name).expect("a physics model: classic or exact"),
        None => PhysicsModel::Classic,
    };
    let numbers: Vec<usize> = arguments
        .iter()
        .take(3)
        .map(|a| a.parse().expect("whole numbers: N threads plans"))
        .collect();
    let (n, threads, plans) = match numbers[..] {
        [n, t, p] => (n, t, p),
        [n, t] => (n, t, 60),
        [n] => (n, 2, 60),
        _ => (64, 2, 60),
    };
    let terrain = Arc::new(Terrain::flat());
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        ..Placement::IDENTITY
    };
    let config = SimulationConfig {
        physics,
        bike,
        ..SimulationConfig::default()
    };
    let mut sim = Simulation::new(config, terrain, spawn);
    let drive = DriveInput {
        throttle: 0.6,
        brake: 0.0,
        max_speed: 15.0 / 3.6,
    };
    // One second of riding off, the rider holding the pose, as `make bench` plans.
    let mut controls = Controls::default();
    drive.apply(sim.bike().params().wheel_radius, &mut controls);
    for _ in 0..30 {
        sim.bike().pose_hold(sim.world(), POSE_GAIN, &mut controls);
        sim.set_controls(controls);
        sim.step();
    }
    let mut config = PlanningConfig {
        trajectories: n,
        threads,
        ..PlanningConfig::default()
    }
    .rolling_out_in(physics);
    if let Some(horizon) = arguments.get(4) {
        config.horizon = horizon.parse().expect("a horizon in seconds");
    }
    let mut optimizer = PlanningSession::new(&sim, &cpbp::COMBINED, config);
    let started = std::time::Instant::now();
    for _ in 0..plans {
        optimizer.controls(&sim, &Goal::riding(0.0, drive));
    }
    let ms = started.elapsed().as_secs_f64() * 1000.0 / plans as f64;
    println!("N = {n}, {threads} thread(s): {ms:.1} ms per plan");
}
