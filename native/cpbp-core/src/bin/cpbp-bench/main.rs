//! `make bench`: prints the performance figures recorded in docs/benchmarks.md.
//! Timings are medians of several runs so one noisy run does not move them.
//! `cpbp-bench planning` prints only the game physics' planning table, for comparing two
//! builds run alternately; `cpbp-bench learned` only the learned controller's cost;
//! `cpbp-bench auto-n` only the automatic N under load; `cpbp-bench planners` only the
//! planners side by side, with their diagnostics; `cpbp-bench fidelity` only the rollout
//! fidelity tables; `cpbp-bench horizon` only what shorter horizons and the learned
//! cost-to-go save (issue 59).
//! `--bike FILE` (`make bench BIKE=FILE`) measures another bike than the reference.

mod auto_n;
mod fidelity;
mod handover;
mod horizon;
mod learned;
mod planning;

use planning::{planning_ms, planning_table};

use std::sync::{Arc, OnceLock};
use std::time::Instant;

use cpbp_core::bike::{
    take_bike_argument, BikeParams, Controls, DriveInput, Placement, REFERENCE_BIKE,
};
use cpbp_core::control::learned::{project_policy, project_value, LoadedPolicy, LoadedValue};
use cpbp_core::grounds::RollingBumps;
use cpbp_core::ode::{Mass, World};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::ControllerKind;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};
use rand::SeedableRng;
use rand_pcg::Pcg64;

const RUNS: usize = 7;
const ODE_DT: f64 = 1.0 / 120.0;

/// The bike every figure rides (`--bike FILE`; the reference bike without it).
static BIKE: OnceLock<BikeParams> = OnceLock::new();
/// Its file's name, which names its learned model (`REFERENCE_BIKE` without `--bike`).
static BIKE_KEY: OnceLock<String> = OnceLock::new();

/// The learned network of the bike ridden (guided plans without one, and says so).
fn bike_policy() -> LoadedPolicy {
    project_policy(BIKE_KEY.get().map_or(REFERENCE_BIKE, String::as_str))
}

/// The learned cost-to-go of the bike ridden (the horizon table leaves its rows out
/// without one, and says so).
fn bike_value() -> LoadedValue {
    project_value(BIKE_KEY.get().map_or(REFERENCE_BIKE, String::as_str))
}

fn main() {
    let info = cpbp_core::build_info();
    println!(
        "Counter-Steer benchmarks (native {}, {} threads available)",
        info.version,
        threads()
    );
    println!("ODE: {}", info.ode.raw);
    let mut arguments: Vec<String> = std::env::args().skip(1).collect();
    match take_bike_argument(&mut arguments) {
        Ok(Some(bike)) => {
            println!("bike: {} ({})", bike.name, bike.params.identity());
            BIKE.get_or_init(|| bike.params);
            BIKE_KEY.get_or_init(|| bike.key);
            if let Some(why) = bike_policy().problem() {
                println!("{why}");
            }
        }
        Ok(None) => {}
        Err(why) => {
            eprintln!("cpbp-bench: {why}");
            std::process::exit(2);
        }
    }
    println!();
    let row = |name: &str, value: String| println!("{name:<58} {value:>14}");
    match arguments.first().map(String::as_str) {
        Some("planning") => return planning_table(PhysicsModel::default(), None),
        Some("learned") => {
            let sim = rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default());
            return learned::inference_cost(&sim, row);
        }
        Some("auto-n") => return auto_n::under_load(),
        Some("horizon") => {
            let sim = rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default());
            return horizon::horizon_table(&sim, row);
        }
        Some("planners") => return planners_side_by_side(),
        Some("fidelity") => {
            return PhysicsModel::ALL
                .into_iter()
                .for_each(|model| fidelity::rollout_fidelity(model, &bump_field()))
        }
        _ => {}
    }
    println!("{:<58} {:>14}", "figure", "value");

    let mut spheres = 0.0;
    for bodies in [1, 15] {
        spheres = median(|| sphere_step_cost(bodies, 2_000));
        row(
            &format!("ODE step, {bodies} sphere(s) resting on a plane"),
            format!("{spheres:.2} µs"),
        );
    }

    let flat = rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::Classic);
    let bumps = rolling_bike(bump_field(), PhysicsModel::Classic);
    let bike_step = median(|| bike_step_cost(&flat));
    row(
        "bike + rider: one ODE step (1/120 s), flat ground",
        format!("{bike_step:.2} µs"),
    );
    row(
        "bike + rider: one ODE step, trimesh bump field (2 048 tris)",
        format!("{:.2} µs", median(|| bike_step_cost(&bumps))),
    );
    row(
        "friction along the wheel ÷ world axes, one ODE step (paired)",
        format!("{:.3}", friction_direction_cost()),
    );
    let (snapshot, restore) = snapshot_costs(&flat);
    row("snapshot of the bike world", format!("{snapshot:.2} µs"));
    row("restore of the bike world", format!("{restore:.2} µs"));
    let game_flat = rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default());
    learned::inference_cost(&game_flat, row);
    for model in PhysicsModel::ALL {
        planning_table(model, Some([bike_step, spheres]));
    }

    planners_side_by_side();
    horizon::horizon_table(&game_flat, row);

    for model in PhysicsModel::ALL {
        fidelity::rollout_fidelity(model, &bump_field());
    }

    handover::handover_table("", [5, 15, 24, 32, 48], |_| {});
    auto_n::under_load();
}

/// Every planning mode's cost per control step in the game's physics on 2 threads.
fn planners_side_by_side() {
    let flat = rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default());
    let planners: Vec<ControllerKind> = ControllerKind::all()
        .into_iter()
        .filter(|k| k.plans())
        .collect();
    println!();
    println!(
        "Planners side by side ({} physics, 2 threads), ms per control step:",
        PhysicsModel::default().name()
    );
    let names: Vec<String> = planners
        .iter()
        .map(|k| format!("{:>10}", k.name()))
        .collect();
    println!("{:<14} {}", "trajectories", names.join(" "));
    let mut diagnostics = Vec::new();
    for n in [5, 10, 20, 64] {
        let timed: Vec<_> = planners
            .iter()
            .map(|&kind| (kind, planning_ms(&flat, kind, n, 2)))
            .collect();
        let cells: Vec<String> = timed
            .iter()
            .map(|(_, t)| format!("{:>10.1}", t.ms))
            .collect();
        println!("{n:<14} {}", cells.join(" "));
        if n == 20 {
            diagnostics = timed;
        }
    }
    // What the HUD's planner line shows of each plan, at N = 20.
    println!("Their own numbers about a plan at N = 20 (means over the timed plans):");
    for (kind, timed) in diagnostics {
        let named: Vec<String> = timed
            .diagnostics
            .iter()
            .map(|(name, value)| format!("{name} {value:.2}"))
            .collect();
        let named = if named.is_empty() {
            "none".to_string()
        } else {
            named.join(", ")
        };
        println!("{:<14} {named}", kind.name());
    }
}

fn sphere_step_cost(bodies: usize, steps: usize) -> f64 {
    let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
    world.add_plane(DVec3::new(0.0, 1.0, 0.0), 0.0);
    for i in 0..bodies {
        let body = world.add_body(Mass::sphere(10.0, 0.3), DVec3::new(i as f64, 0.3, 0.0));
        world.add_sphere(0.3, Some(body));
    }
    time_per_call(steps, || world.step(ODE_DT))
}

/// A 64 m × 64 m grid of 2 m cells of the core's rolling bumps, ±6 cm about the ground's
/// level, as one triangle mesh (the levels' shape).
fn bump_field() -> Arc<Terrain> {
    let height = 0.12;
    let bumps = RollingBumps::draw(&mut Pcg64::seed_from_u64(2015), height);
    let mut mesh = bumps.tri_mesh(32, 2.0);
    // Crests and troughs about the ground's level, where the bike is spawned.
    mesh.placement.position.y = -height / 2.0;
    Arc::new(Terrain::new(vec![mesh]).expect("valid mesh"))
}

/// What every timed plan and network is asked: upright at 15 km/h on part throttle, as
/// `rolling_bike` rides.
fn cruising_goal() -> cpbp_core::control::Goal {
    cpbp_core::control::Goal::riding(
        0.0,
        DriveInput {
            throttle: 0.6,
            brake: 0.0,
            max_speed: 15.0 / 3.6,
        },
    )
}

/// A simulation in `physics` whose bike is riding at 15 km/h with the rider holding the
/// pose.
fn rolling_bike(terrain: Arc<Terrain>, physics: PhysicsModel) -> Simulation {
    rolling(terrain, physics, BIKE.get().cloned().unwrap_or_default())
}

/// `bike` rolling at 15 km/h, a second after it set off.
fn rolling(terrain: Arc<Terrain>, physics: PhysicsModel, bike: BikeParams) -> Simulation {
    let spawn = Placement {
        position: DVec3::new(-25.0, 0.1, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let config = SimulationConfig {
        physics,
        bike,
        ..SimulationConfig::default()
    };
    let mut sim = Simulation::new(config, terrain, spawn);
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

/// What friction along the wheel costs (issue 68): one ODE step of the bike in the game's
/// physics with its tyres' friction following the wheel, over one with ODE's world axes;
/// the two timed alternately, the median of the paired ratios.
fn friction_direction_cost() -> f64 {
    let bike = BIKE.get().cloned().unwrap_or_default();
    let [along, axes] = [true, false].map(|follows| {
        let bike = BikeParams {
            tyre_friction_follows_wheel: follows,
            ..bike.clone()
        };
        rolling(Arc::new(Terrain::flat()), PhysicsModel::default(), bike)
    });
    median(|| bike_step_cost(&along) / bike_step_cost(&axes))
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
