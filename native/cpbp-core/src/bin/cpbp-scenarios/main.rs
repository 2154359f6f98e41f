//! The planners side by side on scripted manoeuvres (issue 17): `cpbp-scenarios
//! --controllers combined,optimizer,sampling,mppi --counts 5,10,20 --seeds 0-9
//! [--scenarios turn,slalom,push,walk] [--physics exact] [--skip FILE]` rides every controller with every N on every
//! scenario and seed, on flat ground, and prints one CSV row per ride as it ends (`tools/
//! experiment scenarios` saves them and computes the paired statistics). Seed i sets the
//! planner's seed, the bike's heading and the scenario's own draw (the push's strength
//! and side, the slalom's first side), so every controller meets the same ride i.
//!
//! Scenarios: `turn` (3 s straight at 20 km/h, then 15° right; the RMS lean error over
//! the last 5 s), `slalom` (20 km/h, ±15° every 2 s for 12 s; RMS over the last 10 s),
//! `reversals` (25 km/h, ±15° every 2 s for 12 s; the settled error: RMS over the second
//! second of each gate after the first, once the lean has swung over), `push` (15 km/h, a
//! sideways shove of 100–250 N·s at 3 s; the largest lean in the 5 s after it) and `walk` (8 km/h for 20 s; the mean speed over the last 10 s, km/h); the
//! stops and hill starts of `stops.rs`. `arcade` and `learned` ride too, once per seed, as
//! N = 0; `learned` and `guided` with the network in `--model` (the project's by default).

mod stops;

use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

use cpbp_core::bike::Placement;
use cpbp_core::control::learned::{project_model, LoadedPolicy};
use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DQuat, DVec3};

const MANOEUVRES: [&str; 5] = ["turn", "slalom", "reversals", "push", "walk"];
pub(crate) const STEPS_PER_SECOND: f64 = 30.0;

fn scenario_names() -> Vec<&'static str> {
    MANOEUVRES.into_iter().chain(stops::SCENARIOS).collect()
}

struct Args {
    controllers: Vec<ControllerKind>,
    counts: Vec<usize>,
    seeds: Vec<u64>,
    scenarios: Vec<&'static str>,
    physics: PhysicsModel,
    /// Rows already saved ("scenario,controller,N,seed,physics"): not ridden again.
    skip: HashSet<String>,
    /// The learned network's model file (learned, guided).
    model: PathBuf,
}

/// The network the learned and guided controllers ride with, loaded once.
static POLICY: OnceLock<LoadedPolicy> = OnceLock::new();

/// Who rides a scenario: the controller, its trajectory count N (0 for arcade), the seed
/// (heading, planner and the scenario's draw) and the physics.
#[derive(Clone, Copy)]
pub(crate) struct Rider {
    pub kind: ControllerKind,
    pub n: usize,
    pub seed: u64,
    pub physics: PhysicsModel,
}

/// What one ride measured.
pub(crate) struct Outcome {
    pub fell: bool,
    pub metric: f64,
    pub planning_ms: f64,
}

const USAGE: &str = "cpbp-scenarios [--controllers K,K…] [--counts N,N…] [--seeds FIRST-LAST] \
[--scenarios S,S…] [--physics classic|exact] [--skip FILE] [--model FILE]";
const FLAGS: [&str; 7] = [
    "--model",
    "--controllers",
    "--counts",
    "--seeds",
    "--scenarios",
    "--physics",
    "--skip",
];

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    if arguments.iter().any(|a| a == "--help" || a == "-h") {
        println!("usage: {USAGE}\nscenarios: {}", scenario_names().join(", "));
        return;
    }
    let args = match parse(arguments) {
        Ok(args) => args,
        Err(why) => {
            eprintln!("cpbp-scenarios: {why}");
            std::process::exit(2);
        }
    };
    if args.controllers.iter().any(|k| k.uses_network()) {
        let policy = LoadedPolicy::load(&args.model);
        if let Some(why) = policy.problem() {
            eprintln!("cpbp-scenarios: {why}");
            std::process::exit(2);
        }
        POLICY.get_or_init(|| policy);
    }
    println!("scenario,controller,trajectories,seed,physics,fell,metric,planning_ms");
    for &scenario in &args.scenarios {
        for &kind in &args.controllers {
            // A controller that plans nothing rides once, as N = 0.
            let counts = if kind.plans() {
                args.counts.clone()
            } else {
                vec![0]
            };
            for &n in &counts {
                for &seed in &args.seeds {
                    let physics = args.physics.name();
                    let key = format!("{scenario},{},{n},{seed},{physics}", kind.name());
                    if args.skip.contains(&key) {
                        continue;
                    }
                    let rider = Rider {
                        kind,
                        n,
                        seed,
                        physics: args.physics,
                    };
                    let o = if stops::SCENARIOS.contains(&scenario) {
                        stops::ride(scenario, rider)
                    } else {
                        ride_scenario(scenario, rider)
                    };
                    println!("{key},{},{:.4},{:.3}", o.fell, o.metric, o.planning_ms);
                }
            }
        }
    }
}

fn parse(arguments: Vec<String>) -> Result<Args, String> {
    // Anything but a known flag and its value is refused, not ignored: a mistyped flag
    // would otherwise ride the defaults for an hour.
    for (i, argument) in arguments.iter().enumerate() {
        let is_value = i > 0 && FLAGS.contains(&arguments[i - 1].as_str());
        if !is_value && !FLAGS.contains(&argument.as_str()) {
            return Err(format!("unknown argument {argument}; usage: {USAGE}"));
        }
    }
    let value = |flag: &str| {
        arguments
            .iter()
            .position(|a| a == flag)
            .map(|i| {
                arguments
                    .get(i + 1)
                    .cloned()
                    .ok_or(format!("{flag} needs a value"))
            })
            .transpose()
    };
    let controllers = value("--controllers")?
        .unwrap_or("combined,optimizer,sampling,mppi".into())
        .split(',')
        .map(|name| {
            ControllerKind::from_name(name)
                .filter(|k| k.offered())
                .ok_or(format!("not a controller players pick: {name}"))
        })
        .collect::<Result<_, _>>()?;
    let counts = value("--counts")?
        .unwrap_or("5,10,20".into())
        .split(',')
        .map(|n| {
            let limit = cpbp_core::ride::limits::TRAJECTORIES;
            match n.parse::<usize>() {
                Ok(n) if (limit.min..=limit.max).contains(&(n as f64)) => Ok(n),
                _ => Err(format!(
                    "trajectory counts are {}–{}, not {n}",
                    limit.min, limit.max
                )),
            }
        })
        .collect::<Result<_, _>>()?;
    let seeds = value("--seeds")?.unwrap_or("0-9".into());
    let (first, last) = seeds.split_once('-').unwrap_or((&seeds, &seeds));
    let (first, last): (u64, u64) = match (first.parse(), last.parse()) {
        (Ok(a), Ok(b)) if a <= b => (a, b),
        _ => return Err(format!("--seeds is FIRST-LAST, not {seeds}")),
    };
    let names = scenario_names();
    let scenarios = value("--scenarios")?
        .unwrap_or(MANOEUVRES.join(","))
        .split(',')
        .map(|name| {
            names
                .iter()
                .copied()
                .find(|s| *s == name)
                .ok_or(format!("scenarios are {}, not {name}", names.join(", ")))
        })
        .collect::<Result<_, _>>()?;
    let physics = value("--physics")?.unwrap_or("exact".into());
    let physics = PhysicsModel::from_name(&physics)
        .ok_or(format!("--physics is classic or exact, not {physics}"))?;
    let skip = match value("--skip")? {
        Some(path) => std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read {path}: {e}"))?
            .lines()
            .map(|line| line.splitn(6, ',').take(5).collect::<Vec<_>>().join(","))
            .collect(),
        None => HashSet::new(),
    };
    Ok(Args {
        controllers,
        counts,
        seeds: (first..=last).collect(),
        scenarios,
        physics,
        skip,
        model: value("--model")?.map_or_else(project_model, PathBuf::from),
    })
}

/// A number in [0, 1) drawn from `seed` for `what`: the same for every controller.
fn draw(seed: u64, what: u64) -> f64 {
    let mut z = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ what.wrapping_mul(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
}

fn ride_scenario(scenario: &str, rider: Rider) -> Outcome {
    let kmh = match scenario {
        "walk" => 8.0,
        "push" => 15.0,
        "reversals" => 25.0,
        _ => 20.0,
    };
    let mut ride = new_ride(rider, kmh, 0.0);
    let mut planning = Vec::new();
    let mut run = |ride: &mut Ride, seconds: f64, lean: f64, each: &mut dyn FnMut(&Ride)| {
        ride.set_intent(Intent {
            lean: Some(lean),
            ..*ride.intent()
        });
        for _ in 0..(seconds * STEPS_PER_SECOND).round() as usize {
            ride.step();
            planning.extend(ride.plan().map(|p| p.planning_ms));
            each(ride);
        }
    };
    let lean_of = |ride: &Ride| {
        let sim = ride.sim();
        sim.bike().lean(sim.world(), sim.up())
    };
    let mut samples = Vec::new();
    let want = 15f64.to_radians();
    match scenario {
        "turn" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            run(&mut ride, 2.0, want, &mut |_| {});
            run(&mut ride, 5.0, want, &mut |r| {
                samples.push(lean_of(r) - want)
            });
        }
        "slalom" | "reversals" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            let first = if draw(rider.seed, 1) < 0.5 { 1.0 } else { -1.0 };
            // The slalom counts every step of a gate, the swing over included; the
            // reversals only the steps after the gate's first second.
            let settle = if scenario == "reversals" { 1.0 } else { 0.0 };
            let settled_from = (settle * STEPS_PER_SECOND).round() as usize;
            for gate in 0..6 {
                let target = want * if gate % 2 == 0 { first } else { -first };
                let mut step = 0;
                run(&mut ride, 2.0, target, &mut |r| {
                    if gate > 0 && step >= settled_from {
                        samples.push(lean_of(r) - target);
                    }
                    step += 1;
                });
            }
        }
        "push" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            let sim = ride.sim();
            let forward = sim.bike().frame_rotation(sim.world()) * DVec3::X;
            let side = forward.cross(sim.up()).normalize_or_zero();
            let sign = if draw(rider.seed, 2) < 0.5 { 1.0 } else { -1.0 };
            ride.push(side * sign * (100.0 + 150.0 * draw(rider.seed, 3)));
            run(&mut ride, 5.0, 0.0, &mut |r| samples.push(lean_of(r)));
        }
        _ => {
            run(&mut ride, 10.0, 0.0, &mut |_| {});
            run(&mut ride, 10.0, 0.0, &mut |r| {
                let sim = r.sim();
                samples.push(sim.bike().forward_speed(sim.world(), sim.up()) * 3.6);
            });
        }
    }
    let metric = match scenario {
        "turn" | "slalom" | "reversals" => (samples.iter().map(|e| e * e).sum::<f64>()
            / samples.len() as f64)
            .sqrt()
            .to_degrees(),
        "push" => samples
            .iter()
            .fold(0.0, |m: f64, l| m.max(l.abs()))
            .to_degrees(),
        _ => samples.iter().sum::<f64>() / samples.len() as f64,
    };
    Outcome {
        fell: ride.sim().crashed().is_some(),
        metric,
        planning_ms: planning.iter().sum::<f64>() / planning.len().max(1) as f64,
    }
}

/// A ride heading where seed `seed` says, waiting for every plan so the outcome does not
/// depend on the machine, full throttle towards `kmh`: on flat ground, or on an endless
/// slope of `slope` (rad) rising ahead (falling for a negative slope).
pub(crate) fn new_ride(rider: Rider, kmh: f64, slope: f64) -> Ride {
    let Rider {
        kind,
        n,
        seed,
        physics,
    } = rider;
    let heading = DQuat::from_rotation_y(std::f64::consts::TAU * draw(seed, 0));
    let (spawn, terrain) = if slope == 0.0 {
        let spawn = Placement {
            position: DVec3::new(0.0, 0.02, 0.0),
            rotation: heading,
        };
        (spawn, Terrain::flat())
    } else {
        let rotation = heading * DQuat::from_rotation_z(slope);
        let normal = rotation * DVec3::Y;
        let ground = TerrainPiece::ground_through_origin("slope", normal);
        let spawn = Placement {
            position: normal * 0.02,
            rotation,
        };
        (
            spawn,
            Terrain::new(vec![ground]).expect("a plane is valid terrain"),
        )
    };
    let config = SimulationConfig {
        physics,
        ..SimulationConfig::default()
    };
    let mut ride = Ride::new(Simulation::new(config, Arc::new(terrain), spawn), kind);
    ride.planner.optimizer.particles = n;
    ride.planner.optimizer.seed = seed;
    ride.planner.optimizer.policy = POLICY.get().cloned().unwrap_or_default();
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    ride
}

#[cfg(test)]
mod tests {
    use super::parse;

    fn words(line: &str) -> Vec<String> {
        line.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn flags_and_their_values_parse_and_anything_else_is_refused() {
        let args = parse(words("--counts 5,15 --seeds 2-4 --scenarios stop40")).unwrap();
        assert_eq!(args.counts, vec![5, 15]);
        assert_eq!(args.seeds, vec![2, 3, 4]);
        assert_eq!(args.scenarios, vec!["stop40"]);
        for wrong in [
            "--seed 3",
            "stop40",
            "--counts 0",
            "--counts 300",
            "--seeds 4-2",
        ] {
            assert!(parse(words(wrong)).is_err(), "{wrong} was accepted");
        }
    }
}
