//! `make bench`: prints the performance figures recorded in docs/benchmarks.md.
//! Timings are medians of several runs so one noisy run does not move them.

use std::time::Instant;

use cpbp_core::ode::{Mass, World};

const RUNS: usize = 7;

fn main() {
    let info = cpbp_core::build_info();
    println!(
        "Counter-Steer benchmarks (native {}, {} threads available)",
        info.version,
        threads()
    );
    println!("ODE: {}", info.ode.raw);
    println!();
    println!("{:<52} {:>12}", "figure", "value");
    for bodies in [1, 15] {
        let micros = median(|| step_cost(bodies, 2_000));
        println!(
            "{:<52} {:>9.2} µs",
            format!("ODE QuickStep, {bodies} sphere(s) resting on a plane"),
            micros
        );
    }
    let micros = median(world_creation_cost);
    println!(
        "{:<52} {:>9.2} µs",
        "create + destroy a world with 15 bodies", micros
    );
}

/// Mean µs per step of a world with `bodies` spheres in contact with a plane.
fn step_cost(bodies: usize, steps: usize) -> f64 {
    let mut world = sphere_world(bodies);
    for _ in 0..100 {
        world.step(1.0 / 120.0);
    }
    let start = Instant::now();
    for _ in 0..steps {
        world.step(1.0 / 120.0);
    }
    start.elapsed().as_secs_f64() * 1e6 / steps as f64
}

/// Mean µs to build and drop a 15-body world.
fn world_creation_cost() -> f64 {
    let count = 200;
    let start = Instant::now();
    for _ in 0..count {
        drop(sphere_world(15));
    }
    start.elapsed().as_secs_f64() * 1e6 / count as f64
}

fn sphere_world(bodies: usize) -> World {
    let mut world = World::new([0.0, -9.81, 0.0]);
    world.add_plane([0.0, 1.0, 0.0], 0.0);
    for i in 0..bodies {
        let body = world.add_body(Mass::sphere(10.0, 0.3), [i as f64, 0.3, 0.0]);
        world.add_sphere(0.3, Some(body));
    }
    world
}

fn median(mut measure: impl FnMut() -> f64) -> f64 {
    let mut samples: Vec<f64> = (0..RUNS).map(|_| measure()).collect();
    samples.sort_by(f64::total_cmp);
    samples[RUNS / 2]
}

fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}
