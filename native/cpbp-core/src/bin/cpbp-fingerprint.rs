//! Fingerprints of what the planners decide, for refactors and speed-ups that must not
//! change a single plan: `cpbp-fingerprint` rides 3 s with every planning controller in
//! both physics models, waiting for every plan, and prints one hash per ride over every
//! plan it made (chosen sequence, costs, resampling counts, drawn paths) and its final
//! state (guided with the bike's own model, `models/policy-<bike>.safetensors`, as it is). Run it
//! before and after a change; the lines must be identical. Hashes are of
//! the exact bits, so they hold on one platform (compare like with like: the experiment's
//! platform fingerprint says which). `cpbp-fingerprint [N] [--bike FILE]`: N trajectories
//! (10), another bike than the reference (a bike file, scenes/bike/bikes/*.tres).

use cpbp_core::bike::{take_bike_argument, BikeParams, Placement, REFERENCE_BIKE};
use cpbp_core::control::cpbp::RESAMPLES;
use cpbp_core::control::learned::{project_policy, LoadedPolicy};
use cpbp_core::control::{Plan, PlanWait};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::DVec3;
use std::sync::Arc;

/// Control steps per ride (3 s at 30 Hz) and the step the lean request comes at.
const STEPS: u64 = 90;
const LEAN_FROM: u64 = 30;

fn main() {
    let mut arguments: Vec<String> = std::env::args().skip(1).collect();
    let bike = match take_bike_argument(&mut arguments) {
        Ok(bike) => bike,
        Err(why) => {
            eprintln!("cpbp-fingerprint: {why}");
            std::process::exit(2);
        }
    };
    let particles = match trajectory_count(&arguments) {
        Ok(n) => n,
        Err(why) => {
            eprintln!("cpbp-fingerprint: {why}\n{USAGE}");
            std::process::exit(2);
        }
    };
    println!("plans of a 3 s ride, N = {particles}, 2 threads (FNV-1a 64 of their exact bits)");
    if let Some(bike) = &bike {
        // Only another bike is named, so the reference's output stays as it always was.
        println!("bike: {} ({})", bike.name, bike.params.identity());
    }
    let key = bike.as_ref().map_or(REFERENCE_BIKE, |b| b.key.as_str());
    let policy = project_policy(key);
    if let Some(why) = policy.problem() {
        eprintln!("cpbp-fingerprint: {why}");
    }
    let bike = bike.map_or_else(BikeParams::default, |b| b.params);
    for physics in PhysicsModel::ALL {
        for kind in ControllerKind::all().into_iter().filter(|k| k.plans()) {
            let (plans, hash) = fingerprint(physics, kind, particles, (&bike, &policy));
            println!(
                "{:<8} {:<10} {plans:>3} plans {hash:016x}",
                physics.name(),
                kind.name()
            );
        }
    }
}

const USAGE: &str =
    "usage: cpbp-fingerprint [N] [--bike FILE]   (N: trajectories, 10 unless given)";

/// The one optional argument left once the bike is taken: a trajectory count of at least 1.
fn trajectory_count(arguments: &[String]) -> Result<usize, String> {
    match arguments {
        [] => Ok(10),
        [n] => match n.parse::<usize>() {
            Ok(count) if count > 0 => Ok(count),
            _ => Err(format!(
                "the trajectory count must be a whole number of at least 1, not {n:?}"
            )),
        },
        [_, extra, ..] => Err(format!("unexpected argument {extra:?}")),
    }
}

/// Rides `kind` at 10 km/h, asking for 10° of right lean after 1 s; returns the number of
/// plans and the hash over them and the final state.
fn fingerprint(
    physics: PhysicsModel,
    kind: ControllerKind,
    particles: usize,
    (bike, policy): (&BikeParams, &LoadedPolicy),
) -> (usize, u64) {
    let config = SimulationConfig {
        physics,
        bike: bike.clone(),
        ..SimulationConfig::default()
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        ..Placement::IDENTITY
    };
    let sim = Simulation::new(config, Arc::new(Terrain::flat()), spawn);
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = particles;
    ride.planner.planning.threads = 2;
    ride.planner.network = policy.clone();
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(10.0));
    let mut hash = Fnv::default();
    let mut plans = 0;
    let mut last_step = None;
    for step in 0..STEPS {
        if step == LEAN_FROM {
            ride.set_intent(Intent {
                lean: Some(10f64.to_radians()),
                ..*ride.intent()
            });
        }
        ride.step();
        if let Some(plan) = ride.plan().filter(|p| Some(p.step) != last_step) {
            last_step = Some(plan.step);
            plans += 1;
            hash.write(&decisions(plan));
        }
    }
    // The bodies, motors and seed, spelt as before the snapshot also carried the last
    // step's contact flags, so hashes stay comparable with those of earlier builds.
    let end = ride.sim().world().snapshot();
    hash.write(&format!(
        "WorldState {{ bodies: {:?}, motors: {:?}, random_seed: {:?} }}",
        end.bodies, end.motors, end.random_seed
    ));
    (plans, hash.0)
}

/// Everything a plan decided, in Rust's exact (shortest round-trip) float notation; not
/// how long it took.
fn decisions(plan: &Plan) -> String {
    format!(
        "{} {:?} {:?} {} {} {:?} {} {:?}",
        plan.step,
        plan.sequence,
        plan.best_cost,
        plan.diagnostics.count(RESAMPLES),
        plan.blowups,
        plan.paths,
        plan.best,
        plan.warm
    )
}

/// FNV-1a, 64 bits: a fingerprint, not a defence against anyone.
struct Fnv(u64);

impl Default for Fnv {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv {
    fn write(&mut self, text: &str) {
        for byte in text.bytes() {
            self.0 = (self.0 ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}
