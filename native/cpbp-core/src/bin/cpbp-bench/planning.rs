//! What a plan costs: the combined planner on 1 … all the machine's threads, its
//! efficiency against its own rollouts stepped alone, and from those, the N that would
//! plan in real time on machines with more cores (docs/benchmarks.md).

use std::sync::Arc;
use std::time::Instant;

use cpbp_core::bike::Controls;
use cpbp_core::control::{PlanningConfig, PlanningSession};
use cpbp_core::ode::World;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::ControllerKind;
use cpbp_core::simulation::Simulation;
use cpbp_core::terrain::Terrain;

use crate::{median, rolling_bike, threads};

/// Trajectory counts the table plans with.
const COUNTS: [usize; 6] = [5, 10, 15, 32, 64, 128];
/// Core counts the real-time N is projected for.
const PROJECTED_CORES: [usize; 3] = [4, 8, 16];

/// The combined planner's cost in `model`'s physics on flat ground at 15 km/h: ms per
/// control step for each N on 1 … all threads (1, 2, 4, … on a machine with many), the
/// same rollouts stepped without the planner on all threads, the efficiency (the second
/// over the first), the largest real-time N, and (for the game's physics) the projection.
/// `references`: one classic bike step and one 15-sphere step (µs), for the cost of a
/// planning step as a ratio.
pub fn planning_table(model: PhysicsModel, references: Option<[f64; 2]>) {
    let flat = rolling_bike(Arc::new(Terrain::flat()), model);
    let stepping = model.rollout_stepping();
    let solver = model.rollout_solver();
    let thread_counts = thread_counts(threads());
    let most = *thread_counts.last().expect("one thread at least");
    println!();
    println!(
        "C-PBP, combined mode, {} physics: 1.2 s horizon (36 steps, {solver:?} {stepping}), 15 km/h, ms per control step:",
        model.name()
    );
    let heads: Vec<String> = thread_counts
        .iter()
        .map(|t| {
            format!(
                "{:>12}",
                format!("{t} thread{}", if *t == 1 { "" } else { "s" })
            )
        })
        .collect();
    println!(
        "{:<14} {} {:>18} {:>12}",
        "trajectories",
        heads.join(" "),
        "rollouts alone",
        "efficiency"
    );
    let (mut largest_real_time, mut rows) = (0, Vec::new());
    for n in COUNTS {
        let times: Vec<Timed> = thread_counts
            .iter()
            .map(|&t| planning_ms(&flat, ControllerKind::COMBINED, n, t))
            .collect();
        let last = times.last().expect("one thread count at least");
        let all = &last.ms;
        let alone = median(|| rollouts_alone_ms(&flat, &last.sequences, most));
        let cells: Vec<String> = times.iter().map(|t| format!("{:>12.1}", t.ms)).collect();
        println!(
            "{n:<14} {} {alone:>15.1} ms {:>12.2}",
            cells.join(" "),
            alone / all
        );
        if *all <= control_period_ms(&flat) {
            largest_real_time = n;
        }
        rows.push((n, times[0].ms, *all));
    }
    println!(
        "largest N planning within the {:.0} ms control period on {most} thread(s): {largest_real_time}",
        control_period_ms(&flat)
    );
    let one_thread_64 = rows.iter().find(|r| r.0 == 64).map_or(0.0, |r| r.1);
    let per_step = one_thread_64 * 1000.0 / (64 * 36) as f64;
    print!("one planning step of one trajectory (N = 64, 1 thread): {per_step:.1} µs");
    match references {
        Some([bike_step, spheres]) => println!(
            " = {:.2} classic bike steps = {:.2} 15-sphere steps",
            per_step / bike_step,
            per_step / spheres
        ),
        None => println!(),
    }
    if model == PhysicsModel::default() && most > 1 {
        project(&rows, most, control_period_ms(&flat));
    }
}

/// 1, 2, 4, … up to and including `available`.
fn thread_counts(available: usize) -> Vec<usize> {
    let mut counts: Vec<usize> = std::iter::successors(Some(1), |t| Some(t * 2))
        .take_while(|&t| t < available)
        .collect();
    counts.push(available.max(1));
    counts
}

fn control_period_ms(sim: &Simulation) -> f64 {
    sim.config().control_dt * 1000.0
}

/// Real-time N on more cores, from this machine's figures: a trajectory costs what it
/// cost on one thread at the largest N (where the worlds no longer fit in cache, as on a
/// machine planning many), the trajectories split ⌈N / t⌉ per thread (a thread steps
/// whole trajectories), at the parallel efficiency measured here on `most` threads (its
/// median over the table: measured speed-up over the best the split allows). What this
/// leaves out is said in docs/benchmarks.md: memory bandwidth shared by more cores, and
/// the master's own step beside the planning.
fn project(rows: &[(usize, f64, f64)], most: usize, period_ms: f64) {
    let &(largest, one_thread, _) = rows.last().expect("a row at least");
    let per_trajectory = one_thread / largest as f64;
    let mut efficiencies: Vec<f64> = rows
        .iter()
        .map(|&(n, one, all)| (one / all) / (n as f64 / n.div_ceil(most) as f64))
        .collect();
    efficiencies.sort_by(f64::total_cmp);
    let efficiency = efficiencies[efficiencies.len() / 2];
    println!(
        "{per_trajectory:.2} ms a trajectory on one thread (N = {largest}); speed-up on {most} \
         threads over the best its split allows, median {efficiency:.2}"
    );
    for cores in PROJECTED_CORES {
        let plan_ms = |n: usize| per_trajectory * n.div_ceil(cores) as f64 / efficiency;
        let real_time = (1..=4096).take_while(|&n| plan_ms(n) <= period_ms).last();
        println!(
            "projected on {cores:>2} cores: largest real-time N {:>4}  (N = 64 in {:.1} ms, N = 128 in {:.1} ms)",
            real_time.unwrap_or(0),
            plan_ms(64),
            plan_ms(128)
        );
    }
}

/// What timing a planner found.
pub struct Timed {
    /// Median milliseconds per control step.
    pub ms: f64,
    /// The last plan's final trajectories.
    pub sequences: Vec<Vec<Controls>>,
    /// The planner's diagnostics (`PlanResult::diagnostics`), each the mean over the
    /// timed plans.
    pub diagnostics: Vec<(&'static str, f64)>,
}

/// Planning controller `kind` with `n` trajectories, rolling out in the simulation's
/// physics model, timed over several control steps.
pub fn planning_ms(sim: &Simulation, kind: ControllerKind, n: usize, threads: usize) -> Timed {
    planning_ms_with(sim, kind, n, threads, |_| {})
}

/// `planning_ms` with the planning configuration changed by `adjust` (a horizon, the
/// cost-to-go).
pub fn planning_ms_with(
    sim: &Simulation,
    kind: ControllerKind,
    n: usize,
    threads: usize,
    adjust: impl FnOnce(&mut PlanningConfig),
) -> Timed {
    let model = sim.config().physics;
    let spec = kind.planner().expect("a planning controller");
    let mut config = PlanningConfig {
        trajectories: n,
        threads,
        ..PlanningConfig::default()
    }
    .rolling_out_in(model);
    adjust(&mut config);
    let mut optimizer = PlanningSession::new(sim, spec, config);
    optimizer.follow(crate::bike_policy().network().cloned());
    let goal = crate::cruising_goal();
    for _ in 0..3 {
        optimizer.controls(sim, &goal); // warm-up: memory, thread pool
    }
    const PLANS: usize = 9;
    let mut diagnostics: Vec<(&'static str, f64)> = Vec::new();
    let mut samples: Vec<f64> = (0..PLANS)
        .map(|_| {
            let start = Instant::now();
            optimizer.controls(sim, &goal);
            let ms = start.elapsed().as_secs_f64() * 1000.0;
            for &(name, value) in optimizer.last_plan().map_or(&[][..], |p| &p.diagnostics.0) {
                match diagnostics.iter_mut().find(|(n, _)| *n == name) {
                    Some((_, sum)) => *sum += value / PLANS as f64,
                    None => diagnostics.push((name, value / PLANS as f64)),
                }
            }
            ms
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    Timed {
        ms: samples[PLANS / 2],
        sequences: optimizer.sequences(),
        diagnostics,
    }
}

/// Milliseconds to step a plan's final trajectories from the master's state in the
/// model's rollout physics, one world each, split over `thread_count` threads: the
/// planner's physics without the planner (no sampling, costs, resampling or restores).
fn rollouts_alone_ms(sim: &Simulation, sequences: &[Vec<Controls>], thread_count: usize) -> f64 {
    let model = sim.config().physics;
    let state = sim.world().snapshot();
    let mut worlds: Vec<World> = sequences
        .iter()
        .map(|_| {
            let mut world = sim.new_world();
            world.set_solver(model.rollout_solver());
            world
        })
        .collect();
    let (stepping, control_dt) = (model.rollout_stepping(), sim.config().control_dt);
    let per_thread = sequences.len().div_ceil(thread_count);
    let start = Instant::now();
    std::thread::scope(|scope| {
        for (worlds, sequences) in worlds
            .chunks_mut(per_thread)
            .zip(sequences.chunks(per_thread))
        {
            let (state, bike) = (&state, sim.bike());
            scope.spawn(move || {
                for (world, sequence) in worlds.iter_mut().zip(sequences) {
                    world.restore(state).expect("same model");
                    for (step, controls) in sequence.iter().enumerate() {
                        bike.apply(world, controls);
                        let (substeps, dt) = stepping.ode_steps_at(step, control_dt);
                        (0..substeps).for_each(|_| world.step(dt));
                    }
                }
            });
        }
    });
    start.elapsed().as_secs_f64() * 1000.0
}
