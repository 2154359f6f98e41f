//! `make bench`'s rollout fidelity table.

use std::sync::Arc;

use cpbp_core::bike::DriveInput;
use cpbp_core::ode::Solver;
use cpbp_core::physics::{PhysicsModel, RolloutStepping};
use cpbp_core::ride::fidelity::{divergence, Recording, RolloutPhysics};
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::Simulation;
use cpbp_core::terrain::Terrain;

use crate::{median, rolling_bike, time_per_call};

/// The planning horizon in control steps (1.2 s).
const HORIZON: usize = 36;

/// The deep bend's speed (km/h): where the street bike leans to its 45° (issue 68).
const BEND_KMH: f64 = 60.0;

/// Candidate rollout physics against the master's in `model`: the cost of one planning
/// step (averaged over the horizon) and how far the master's controls replayed open loop
/// drift from its ride after 0.5 s and 1.2 s (worst lean error and centre-of-mass
/// distance over replays started every 1/3 s), with the arcade controller: at 15 km/h on
/// flat ground (straight, then a 15° turn) and over the bump field, and in a deep bend
/// (up to 60 km/h, then the bike's deepest lean, the turn-in among the replays).
pub fn rollout_fidelity(model: PhysicsModel, bumps: &Arc<Terrain>) {
    let flat = rolling_bike(Arc::new(Terrain::flat()), model);
    let master = RolloutPhysics::of(&flat);
    println!();
    println!(
        "Rollout physics against the master's ({} physics: {:?}, {}), arcade at 15 km/h:",
        model.name(),
        master.solver,
        master.stepping
    );
    println!(
        "{:<40} {:>10} {:>28} {:>28} {:>28}",
        "physics",
        "cost",
        "flat: @0.5 s, @1.2 s",
        "bumps: @0.5 s, @1.2 s",
        format!(
            "bend {BEND_KMH} km/h {:.0}°: @0.5 s, @1.2 s",
            flat.config().bike.max_lean.to_degrees()
        )
    );
    let record = |sim: Simulation, turn: bool| {
        let mut ride = Ride::new(sim, ControllerKind::ARCADE);
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
    let deep_bend = |sim: Simulation| {
        let mut ride = Ride::new(sim, ControllerKind::ARCADE);
        ride.set_intent(Intent::cruise(BEND_KMH));
        // Up to speed (about 7 s from 15 km/h), then the 6 s bend recorded.
        (0..270).for_each(|_| {
            ride.step();
        });
        ride.set_intent(Intent {
            lean: Some(ride.sim().config().bike.max_lean),
            ..Intent::cruise(BEND_KMH)
        });
        let recording = Recording::ride(&mut ride, 180);
        (ride, recording)
    };
    let rides = [
        record(flat.replica(), true),
        record(rolling_bike(bumps.clone(), model), false),
        deep_bend(flat.replica()),
    ];
    // One planning step on average over the horizon (lead steps included).
    let cost = |physics: RolloutPhysics| {
        let mut world = flat.new_world();
        world.restore(&flat.world().snapshot()).expect("same model");
        world.set_solver(physics.solver);
        let control_dt = flat.config().control_dt;
        let mut horizon = || {
            for step in 0..HORIZON {
                let (substeps, dt) = physics.stepping.ode_steps_at(step, control_dt);
                (0..substeps).for_each(|_| world.step(dt));
            }
        };
        median(|| time_per_call(5, &mut horizon)) / HORIZON as f64
    };
    // Costs are against the classic rollouts, so both tables share one scale.
    let reference = cost(RolloutPhysics {
        solver: Solver::QuickStep,
        stepping: RolloutStepping::uniform(4),
    });
    let uniform = |solver, substeps| (solver, RolloutStepping::uniform(substeps));
    let lead = |lead_steps| RolloutStepping {
        substeps: 1,
        lead_steps,
        lead_substeps: 2,
    };
    let finer_lead = |substeps| RolloutStepping {
        substeps,
        lead_steps: 12,
        lead_substeps: 4,
    };
    let candidates: Vec<(Solver, RolloutStepping)> = match model {
        PhysicsModel::Classic => vec![
            uniform(Solver::QuickStep, 4),
            uniform(Solver::QuickStep, 2),
            uniform(Solver::QuickStep, 1),
            uniform(Solver::Direct, 4),
            uniform(Solver::Direct, 2),
            uniform(Solver::Direct, 1),
        ],
        PhysicsModel::Exact => vec![
            uniform(Solver::Direct, 4),
            uniform(Solver::Direct, 2),
            (Solver::Direct, lead(18)),
            (Solver::Direct, lead(12)),
            (Solver::Direct, lead(6)),
            uniform(Solver::Direct, 1),
            // Finer lead steps, for the deep bend.
            (Solver::Direct, finer_lead(1)),
            (Solver::Direct, finer_lead(2)),
        ],
    };
    for (solver, stepping) in candidates {
        let physics = RolloutPhysics { solver, stepping };
        let drift: Vec<String> = rides
            .iter()
            .map(|(ride, recording)| {
                let [half, whole] =
                    divergence(ride.sim(), recording, physics, HORIZON, 10, &[15, HORIZON])
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
        let chosen = if physics == RolloutPhysics::planned_in(&flat) {
            " (the model's)"
        } else {
            ""
        };
        let label = format!("{solver:?}, {stepping}{chosen}");
        let ratio = cost(physics) / reference;
        println!(
            "{label:<40} {ratio:>9.2}x {:>28} {:>28} {:>28}",
            drift[0], drift[1], drift[2]
        );
    }
}
