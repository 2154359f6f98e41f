//! `make bench`: prints the performance figures recorded in docs/benchmarks.md.
//! Timings are medians of several runs so one noisy run does not move them.

use std::sync::Arc;
use std::time::{Duration, Instant};

use cpbp_core::bike::{Controls, DriveInput, Placement};
use cpbp_core::control::fidelity::{divergence, Recording, RolloutPhysics};
use cpbp_core::control::{BikeOptimizer, OptimizerConfig, OptimizerMode, PlanWait};
use cpbp_core::ode::{Mass, Solver, World};
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

const RUNS: usize = 7;
const ODE_DT: f64 = 1.0 / 120.0;

fn main() {
    let info = cpbp_core::build_info();
    println!(
        "Counter-Steer benchmarks (native {}, {} threads available)",
        info.version,
        threads()
    );
    println!("ODE: {}", info.ode.raw);
    println!();
    println!("{:<58} {:>14}", "figure", "value");
    let row = |name: &str, value: String| println!("{name:<58} {value:>14}");

    for bodies in [1, 15] {
        let micros = median(|| sphere_step_cost(bodies, 2_000));
        row(
            &format!("ODE step, {bodies} sphere(s) resting on a plane"),
            format!("{micros:.2} µs"),
        );
    }

    let flat = rolling_bike(Arc::new(Terrain::flat()));
    let bumps = rolling_bike(bump_field());
    row(
        "bike + rider: one ODE step (1/120 s), flat ground",
        format!("{:.2} µs", median(|| bike_step_cost(&flat))),
    );
    row(
        "bike + rider: one ODE step, trimesh bump field (2 048 tris)",
        format!("{:.2} µs", median(|| bike_step_cost(&bumps))),
    );
    let (snapshot, restore) = snapshot_costs(&flat);
    row("snapshot of the bike world", format!("{snapshot:.2} µs"));
    row("restore of the bike world", format!("{restore:.2} µs"));
    let mut raw = [0.0; 3];
    for thread_count in [1, 2] {
        raw[thread_count] = median(|| parallel_steps_per_second(&flat, 16, thread_count));
        row(
            &format!("16 bike worlds stepped on {thread_count} thread(s)"),
            format!("{:.0} steps/s", raw[thread_count]),
        );
    }

    for substeps in [4, 2] {
        println!();
        println!(
            "C-PBP, combined mode, 1.2 s horizon (36 steps x {substeps} ODE steps), riding at 15 km/h:"
        );
        println!(
            "{:<14} {:>16} {:>16} {:>12}",
            "trajectories", "1 thread (ms)", "2 threads (ms)", "efficiency"
        );
        let mut largest_real_time = 0;
        for n in [5, 10, 15, 32, 64, 128] {
            let one = planning_ms(&flat, n, 1, substeps);
            let two = planning_ms(&flat, n, 2, substeps);
            // ODE steps the planner runs per frame (particle 1 rides the arcade controller).
            let steps = (n * 36 * substeps) as f64;
            let efficiency = steps / (two / 1000.0) / raw[2];
            println!("{n:<14} {one:>16.1} {two:>16.1} {efficiency:>12.2}");
            if two <= 1000.0 / 30.0 {
                largest_real_time = n;
            }
        }
        println!(
            "largest N planning within the 33 ms control period on 2 threads: {largest_real_time}"
        );
    }

    rollout_fidelity(&flat, &bump_field());

    println!();
    println!("Hand-over: planning thread, game loop paced at 30 control steps/s, 6 s riding:");
    println!(
        "{:<14} {:>14} {:>14} {:>14} {:>10}",
        "trajectories", "plan (ms)", "mean wait", "max wait", "late"
    );
    for n in [5, 15, 24, 32] {
        let h = handover(&Arc::new(Terrain::flat()), n);
        println!(
            "{n:<14} {:>14.1} {:>11.2} ms {:>11.2} ms {:>9.0}%",
            h.0,
            h.1,
            h.2,
            h.3 * 100.0
        );
    }
}

/// Median milliseconds per control step of the combined planner with `n` trajectories.
fn planning_ms(sim: &Simulation, n: usize, threads: usize, rollout_substeps: usize) -> f64 {
    let config = OptimizerConfig {
        mode: OptimizerMode::Combined,
        particles: n,
        threads,
        rollout_substeps,
        ..OptimizerConfig::default()
    };
    let mut optimizer = BikeOptimizer::new(sim, config);
    let drive = DriveInput {
        throttle: 0.6,
        brake: 0.0,
        max_speed: 15.0 / 3.6,
    };
    for _ in 0..3 {
        optimizer.controls(sim, 0.0, &drive); // warm-up: memory, thread pool
    }
    let mut samples: Vec<f64> = (0..9)
        .map(|_| {
            let start = Instant::now();
            optimizer.controls(sim, 0.0, &drive);
            start.elapsed().as_secs_f64() * 1000.0
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

/// Rides 6 s in real time with the planner on its own thread, waiting at most 10 ms at a
/// boundary: (mean planning ms, mean wait ms, max wait ms, share of late boundaries).
fn handover(terrain: &Arc<Terrain>, n: usize) -> (f64, f64, f64, f64) {
    // The game's ride: the combined controller behind the one controller interface.
    let mut ride = Ride::new(rolling_bike(terrain.clone()), ControllerKind::Combined);
    ride.planner.optimizer.particles = n;
    ride.planner.wait = PlanWait::AtMost(Duration::from_millis(10));
    ride.set_intent(Intent {
        drive: DriveInput {
            throttle: 1.0,
            brake: 0.0,
            max_speed: 15.0 / 3.6,
        },
        ..Intent::default()
    });
    let period = Duration::from_secs_f64(1.0 / 30.0);
    let mut boundary = Instant::now();
    let (mut planning, mut plans, mut last_plan_step) = (0.0, 0, None);
    for _ in 0..180 {
        ride.step();
        if let Some(plan) = ride.plan() {
            if last_plan_step != Some(plan.step) {
                last_plan_step = Some(plan.step);
                planning += plan.planning_ms;
                plans += 1;
            }
        }
        boundary += period;
        std::thread::sleep(boundary.saturating_duration_since(Instant::now()));
    }
    let stats = ride.handover().unwrap_or_default();
    (
        planning / plans.max(1) as f64,
        stats.mean_wait_ms(),
        stats.max_wait_ms,
        stats.late as f64 / stats.boundaries.max(1) as f64,
    )
}

fn sphere_step_cost(bodies: usize, steps: usize) -> f64 {
    let mut world = World::new([0.0, -9.81, 0.0]);
    world.add_plane([0.0, 1.0, 0.0], 0.0);
    for i in 0..bodies {
        let body = world.add_body(Mass::sphere(10.0, 0.3), [i as f64, 0.3, 0.0]);
        world.add_sphere(0.3, Some(body));
    }
    time_per_call(steps, || world.step(ODE_DT))
}

/// A 64 m × 64 m grid of 1 m cells with gentle bumps, as one triangle mesh.
fn bump_field() -> Arc<Terrain> {
    let n = 32;
    let cell = 2.0;
    let height = |i: usize, j: usize| 0.06 * ((i as f64 * 1.3).sin() * (j as f64 * 0.7).cos());
    let corner = |i: usize, j: usize| {
        DVec3::new(i as f64 * cell - 32.0, height(i, j), j as f64 * cell - 32.0)
    };
    let mut vertices = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (
                corner(i, j),
                corner(i + 1, j),
                corner(i + 1, j + 1),
                corner(i, j + 1),
            );
            vertices.extend([a, d, c, a, c, b]);
        }
    }
    Arc::new(Terrain::new(vec![piece(TerrainShape::TriMesh { vertices })]).expect("valid mesh"))
}

fn piece(shape: TerrainShape) -> TerrainPiece {
    TerrainPiece {
        source: "bench".into(),
        shape,
        placement: Placement {
            position: DVec3::ZERO,
            rotation: DQuat::IDENTITY,
        },
    }
}

/// A simulation whose bike is riding at 15 km/h with the rider holding the pose.
fn rolling_bike(terrain: Arc<Terrain>) -> Simulation {
    let spawn = Placement {
        position: DVec3::new(-25.0, 0.1, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let mut sim = Simulation::new(SimulationConfig::default(), terrain, spawn);
    let mut controls = Controls::default();
    cpbp_core::bike::DriveInput {
        throttle: 0.6,
        brake: 0.0,
        max_speed: 15.0 / 3.6,
    }
    .apply(0.3, &mut controls);
    for _ in 0..30 {
        sim.bike().pose_hold(sim.world(), 5.0, &mut controls);
        sim.set_controls(controls);
        sim.step();
    }
    sim
}

fn bike_step_cost(sim: &Simulation) -> f64 {
    let mut world = sim.new_world();
    world.restore(&sim.world().snapshot()).expect("same model");
    time_per_call(600, || world.step(ODE_DT))
}

fn snapshot_costs(sim: &Simulation) -> (f64, f64) {
    let mut world = sim.new_world();
    let state = sim.world().snapshot();
    let snapshot = median(|| {
        time_per_call(20_000, || {
            drop(std::hint::black_box(sim.world().snapshot()))
        })
    });
    let restore = median(|| {
        time_per_call(20_000, || {
            world
                .restore(std::hint::black_box(&state))
                .expect("same model")
        })
    });
    (snapshot, restore)
}

/// ODE steps per second when `worlds` bike worlds are split over `thread_count` threads,
/// each restoring from the master and stepping a 1.2 s horizon (the planner's workload).
fn parallel_steps_per_second(sim: &Simulation, worlds: usize, thread_count: usize) -> f64 {
    let state = sim.world().snapshot();
    let mut all: Vec<World> = (0..worlds).map(|_| sim.new_world()).collect();
    let horizon = 144; // 1.2 s at 1/120 s
    let start = Instant::now();
    std::thread::scope(|scope| {
        for chunk in all.chunks_mut(worlds.div_ceil(thread_count)) {
            let state = &state;
            scope.spawn(move || {
                for world in chunk {
                    world.restore(state).expect("same model");
                    for _ in 0..horizon {
                        world.step(ODE_DT);
                    }
                }
            });
        }
    });
    (worlds * horizon) as f64 / start.elapsed().as_secs_f64()
}

fn time_per_call(calls: usize, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..calls {
        f();
    }
    start.elapsed().as_secs_f64() * 1e6 / calls as f64
}

fn median(mut measure: impl FnMut() -> f64) -> f64 {
    let mut samples: Vec<f64> = (0..RUNS).map(|_| measure()).collect();
    samples.sort_by(f64::total_cmp);
    samples[RUNS / 2]
}

fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// Candidate rollout physics against the master's: the cost of one control step and how
/// far the master's controls replayed open loop drift from its ride after 0.5 s and 1.2 s
/// (worst lean error and centre-of-mass distance over replays started every 1/3 s), on flat ground (straight, then a 15°
/// turn) and over the bump field, with the arcade controller at 15 km/h.
fn rollout_fidelity(flat: &Simulation, bumps: &Arc<Terrain>) {
    println!();
    println!("Rollout physics against the master's (QuickStep x 4), arcade at 15 km/h:");
    println!(
        "{:<16} {:>10} {:>28} {:>28}",
        "physics", "cost", "flat: @0.5 s, @1.2 s", "bumps: @0.5 s, @1.2 s"
    );
    let record = |sim: Simulation, turn: bool| {
        let mut ride = Ride::new(sim, ControllerKind::Arcade);
        let mut intent = Intent {
            drive: DriveInput {
                throttle: 1.0,
                brake: 0.0,
                max_speed: 15.0 / 3.6,
            },
            lean: Some(0.0),
            ..Intent::default()
        };
        ride.set_intent(intent);
        let mut recording = Recording::ride(&mut ride, 120);
        intent.lean = Some(if turn { 15f64.to_radians() } else { 0.0 });
        ride.set_intent(intent);
        recording.extend(Recording::ride(&mut ride, 120));
        (ride, recording)
    };
    let rides = [
        record(flat.replica(), true),
        record(rolling_bike(bumps.clone()), false),
    ];
    let master = RolloutPhysics {
        solver: Solver::QuickStep,
        substeps: 4,
    };
    let cost = |physics: RolloutPhysics| {
        let mut world = flat.new_world();
        world.restore(&flat.world().snapshot()).expect("same model");
        world.set_solver(physics.solver);
        let dt = 1.0 / 30.0 / physics.substeps as f64;
        median(|| time_per_call(150, || (0..physics.substeps).for_each(|_| world.step(dt))))
    };
    let reference = cost(master);
    for (solver, substeps) in [
        (Solver::QuickStep, 4),
        (Solver::QuickStep, 2),
        (Solver::QuickStep, 1),
        (Solver::Direct, 4),
        (Solver::Direct, 2),
        (Solver::Direct, 1),
    ] {
        let physics = RolloutPhysics { solver, substeps };
        let drift: Vec<String> = rides
            .iter()
            .map(|(ride, recording)| {
                let [half, whole] = divergence(ride.sim(), recording, physics, 36, 10, &[15, 36])
                    .try_into()
                    .expect("two horizons");
                format!(
                    "{:.1}° {:.2} m, {:.1}° {:.2} m",
                    half.lean.to_degrees(),
                    half.position,
                    whole.lean.to_degrees(),
                    whole.position
                )
            })
            .collect();
        let label = format!("{solver:?} x {substeps}");
        let ratio = cost(physics) / reference;
        println!(
            "{label:<16} {ratio:>9.2}x {:>22} {:>22}",
            drift[0], drift[1]
        );
    }
}
