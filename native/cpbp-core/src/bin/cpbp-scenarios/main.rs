//! The planners side by side on scripted manoeuvres (issue 17): `cpbp-scenarios
//! --controllers combined,optimizer,sampling,mppi --counts 5,10,20 --seeds 0-9
//! [--scenarios turn,slalom,push,walk] [--physics exact] [--skip FILE] [--bike FILE]` rides every controller with every N on every
//! scenario and seed, on flat ground, and prints one CSV row per ride as it ends (`tools/
//! experiment scenarios` saves them and computes the paired statistics). Seed i sets the
//! planner's seed, the bike's heading and the scenario's own draw (the push's strength
//! and side, the slalom's first side), so every controller meets the same ride i.
//!
//! Scenarios: `turn` (3 s straight at 20 km/h, then 15° right; the RMS lean error over
//! the last 5 s), `carve` (as a player carves a long bend: part throttle towards 40 km/h
//! for 3–5 s, then the stick 0.3–0.7 over for 8 s, asking the 30° limit, with a
//! sideways knock of 20–80 N·s 3 s in; the RMS error from the lean asked over the last
//! 6 s), `slalom` (20 km/h, ±15° every 2 s for 12 s; RMS over the last 10 s),
//! `reversals` (25 km/h, ±15° every 2 s for 12 s; the settled error: RMS over the second
//! second of each gate after the first, once the lean has swung over), `push` (15 km/h, a
//! sideways shove of 100–250 N·s at 3 s; the largest lean in the 5 s after it) and `walk` (8 km/h for 20 s; the mean speed over the last 10 s, km/h); the
//! stops and hill starts of `stops.rs`; the full brakes of `brakes.rs`, which report more
//! than their metric in the row's `extra` column; `logs`, the test level's ride (`logs.rs`).
//! `arcade` and `learned` ride too, once per seed, as N = 0; `learned` and `guided` with
//! the network in `--model` (the bike's own by default, `models/policy-<bike>`). `--set
//! NAME=VALUE` plans with a planner's setting other than its default (`--set horizon=0.6`),
//! through the mapping the game's node uses (`PlannerSettings::from_values`).

mod args;
mod bends;
mod brakes;
mod cambers;
mod logs;
mod outcome;
mod stops;

use std::sync::{Arc, OnceLock};

use cpbp_core::bike::{read_bike_file, BikeParams, DriveInput, Placement, REFERENCE_BIKE};
use cpbp_core::control::learned::{project_policy, project_value, LoadedPolicy, LoadedValue};
use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, PlannerSettings, Ride};
use cpbp_core::settings::SettingValues;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DQuat, DVec3};

use args::{parse, USAGE};
pub(crate) use outcome::{fall_cause, mean_planning_ms, Outcome};

const MANOEUVRES: [&str; 6] = ["turn", "carve", "slalom", "reversals", "push", "walk"];
pub(crate) const STEPS_PER_SECOND: f64 = 30.0;

fn scenario_names() -> Vec<&'static str> {
    MANOEUVRES
        .into_iter()
        .chain(stops::SCENARIOS)
        .chain(brakes::SCENARIOS)
        .chain(cambers::SCENARIOS)
        .chain(bends::SCENARIOS)
        .chain([logs::SCENARIO])
        .collect()
}

/// The network the learned and guided controllers ride with, loaded once.
static POLICY: OnceLock<LoadedPolicy> = OnceLock::new();
/// The bike every ride rides (`--bike`; the reference bike without it).
static BIKE: OnceLock<BikeParams> = OnceLock::new();
/// The planners' settings every ride plans with (`--set`; the defaults without it).
static PLANNER_SETTINGS: OnceLock<SettingValues> = OnceLock::new();
/// The bike's learned cost-to-go, loaded when `--set terminal_value=true` asks for it.
static VALUE: OnceLock<LoadedValue> = OnceLock::new();

/// Who rides a scenario: the controller, its trajectory count N (0 for arcade), the seed
/// (heading, planner and the scenario's draw) and the physics.
#[derive(Clone, Copy)]
pub(crate) struct Rider {
    pub kind: ControllerKind,
    pub n: usize,
    pub seed: u64,
    pub physics: PhysicsModel,
}

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
    let mut key = REFERENCE_BIKE.to_owned();
    if let Some(path) = &args.bike {
        match read_bike_file(path) {
            Ok(bike) => {
                eprintln!("cpbp-scenarios: riding {} ({})", bike.name, path.display());
                BIKE.get_or_init(|| bike.params);
                key = bike.key;
            }
            Err(why) => {
                eprintln!("cpbp-scenarios: {why}");
                std::process::exit(2);
            }
        }
    }
    if args.controllers.iter().any(|k| k.uses_network()) {
        let policy = match &args.model {
            Some(path) => LoadedPolicy::load(path),
            None => project_policy(&key),
        };
        if let Some(why) = policy.problem() {
            eprintln!("cpbp-scenarios: {why}");
            // The learned controller is the network; guided plans without it.
            if args
                .controllers
                .iter()
                .any(|k| k.uses_network() && !k.plans())
            {
                std::process::exit(2);
            }
        }
        POLICY.get_or_init(|| policy);
    }
    let settings = PLANNER_SETTINGS.get_or_init(|| args.planner_settings.clone());
    if settings.flag(&cpbp_core::settings::TERMINAL_VALUE) {
        let value = VALUE.get_or_init(|| project_value(&key));
        if let Some(why) = value.problem() {
            eprintln!("cpbp-scenarios: {why}");
        }
    }
    println!("scenario,controller,trajectories,seed,physics,fell,metric,planning_ms,extra");
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
                    } else if brakes::SCENARIOS.contains(&scenario) {
                        brakes::ride(scenario, rider)
                    } else if cambers::SCENARIOS.contains(&scenario) {
                        cambers::ride(scenario, rider)
                    } else if bends::SCENARIOS.contains(&scenario) {
                        bends::ride(scenario, rider)
                    } else if scenario == logs::SCENARIO {
                        logs::ride(rider)
                    } else {
                        ride_scenario(scenario, rider)
                    };
                    let extra: Vec<String> = o
                        .measures
                        .iter()
                        .map(|(name, value)| format!("{name}={value:.4}"))
                        .collect();
                    if o.fell {
                        let cause = o
                            .fall_cause
                            .as_deref()
                            .unwrap_or("no crash: the scenario's own judgement");
                        eprintln!("cpbp-scenarios: {key} fell: {cause}");
                    }
                    println!(
                        "{key},{},{:.4},{:.3},{}",
                        o.fell,
                        o.metric,
                        o.planning_ms,
                        extra.join(";")
                    );
                }
            }
        }
    }
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
        "carve" => 40.0,
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
        "carve" => {
            // As the game's player rides it: the trigger at 50–100 % of the default motor
            // share (0.6) towards the 40 km/h setting, then after 3–5 s the stick 0.3–0.7
            // over, which asks for the 30° limit from about 25 km/h on.
            ride.set_intent(Intent {
                drive: DriveInput {
                    throttle: 0.6 * (0.5 + 0.5 * draw(rider.seed, 2)),
                    ..ride.intent().drive
                },
                ..*ride.intent()
            });
            run(&mut ride, 3.0 + 2.0 * draw(rider.seed, 3), 0.0, &mut |_| {});
            let side = if draw(rider.seed, 1) < 0.5 { 1.0 } else { -1.0 };
            ride.set_intent(Intent {
                lean: None,
                turn: (0.3 + 0.4 * draw(rider.seed, 4)) * side,
                ..*ride.intent()
            });
            // The track's rollers and kerbs, as a sideways knock 3 s into the turn.
            let knock = (3.0 * STEPS_PER_SECOND) as usize;
            for step in 0..(8.0 * STEPS_PER_SECOND) as usize {
                if step == knock {
                    let sim = ride.sim();
                    let forward = sim.bike().frame_rotation(sim.world()) * DVec3::X;
                    let side = forward.cross(sim.up()).normalize_or_zero();
                    let sign = if draw(rider.seed, 5) < 0.5 { 1.0 } else { -1.0 };
                    ride.push(side * sign * (20.0 + 60.0 * draw(rider.seed, 6)));
                }
                ride.step();
                planning.extend(ride.plan().map(|p| p.planning_ms));
                if step >= (2.0 * STEPS_PER_SECOND) as usize {
                    samples.push(lean_of(&ride) - ride.desired_lean());
                }
            }
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
        "turn" | "carve" | "slalom" | "reversals" => (samples.iter().map(|e| e * e).sum::<f64>()
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
        fall_cause: fall_cause(&ride),
        metric,
        planning_ms: mean_planning_ms(&planning),
        measures: Vec::new(),
    }
}

/// A ride heading where seed `seed` says, waiting for every plan so the outcome does not
/// depend on the machine, full throttle towards `kmh`: on flat ground, or on an endless
/// slope of `slope` (rad) rising ahead (falling for a negative slope).
pub(crate) fn new_ride(rider: Rider, kmh: f64, slope: f64) -> Ride {
    let heading = heading_of(rider.seed);
    if slope == 0.0 {
        let spawn = Placement {
            position: DVec3::new(0.0, 0.02, 0.0),
            rotation: heading,
        };
        return ride_on(rider, kmh, Terrain::flat(), spawn);
    }
    let rotation = heading * DQuat::from_rotation_z(slope);
    new_ride_on_plane(rider, kmh, rotation, rotation)
}

/// A ride on a plane through the origin turned by `plane` from level, the bike spawned on
/// it turned by `bike`.
pub(crate) fn new_ride_on_plane(rider: Rider, kmh: f64, plane: DQuat, bike: DQuat) -> Ride {
    let normal = plane * DVec3::Y;
    let ground = TerrainPiece::ground_through_origin("slope", normal);
    let spawn = Placement {
        position: normal * 0.02,
        rotation: bike,
    };
    let terrain = Terrain::new(vec![ground]).expect("a plane is valid terrain");
    ride_on(rider, kmh, terrain, spawn)
}

/// The heading seed `seed` rides in.
pub(crate) fn heading_of(seed: u64) -> DQuat {
    DQuat::from_rotation_y(std::f64::consts::TAU * draw(seed, 0))
}

/// A ride from `spawn` on `terrain`, as `new_ride` sets it up.
pub(crate) fn ride_on(rider: Rider, kmh: f64, terrain: Terrain, spawn: Placement) -> Ride {
    ride_bike_on(rider, kmh, terrain, spawn, ridden_bike())
}

/// The bike every ride rides (`--bike`; the reference bike without it).
pub(crate) fn ridden_bike() -> BikeParams {
    BIKE.get().cloned().unwrap_or_default()
}

/// `ride_on` with another bike than the one ridden (the same on a wet road, say).
pub(crate) fn ride_bike_on(
    rider: Rider,
    kmh: f64,
    terrain: Terrain,
    spawn: Placement,
    bike: BikeParams,
) -> Ride {
    let Rider {
        kind,
        n,
        seed,
        physics,
    } = rider;
    let config = SimulationConfig {
        physics,
        bike,
        ..SimulationConfig::default()
    };
    let mut ride = Ride::new(Simulation::new(config, Arc::new(terrain), spawn), kind);
    let values = PLANNER_SETTINGS.get_or_init(SettingValues::none);
    let network = POLICY.get().cloned().unwrap_or_default();
    ride.planner = PlannerSettings {
        wait: PlanWait::EveryPlan,
        ..PlannerSettings::from_values(
            values,
            physics,
            network,
            VALUE.get().cloned().unwrap_or_default(),
        )
    };
    ride.planner.planning.trajectories = n;
    ride.planner.planning.seed = seed;
    ride.set_intent(Intent::cruise(kmh));
    ride
}
