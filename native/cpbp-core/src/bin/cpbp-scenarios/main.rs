//! The planners side by side on scripted manoeuvres (issue 17): `cpbp-scenarios
//! --controllers combined,optimizer,sampling,mppi --counts 5,10,20 --seeds 0-9
//! [--scenarios turn,slalom,push,walk] [--physics exact] [--skip FILE] [--bike FILE]` rides every controller with every N on every
//! scenario and seed, on flat ground, and prints one CSV row per ride as it ends (`tools/
//! experiment scenarios` saves them and computes the paired statistics). Seed i sets the
//! planner's seed, the bike's heading and the scenario's own draw (the push's strength
//! and side, the slalom's first side), so every controller meets the same ride i.
//!
//! Scenarios: the manoeuvres of `manoeuvres.rs` (a turn, a carve, a slalom, lean
//! reversals, a shove, walking pace); the stops and hill starts of `stops.rs`; the full brakes of `brakes.rs`, which report more
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
mod manoeuvres;
mod outcome;
mod stops;

use std::sync::{Arc, OnceLock};

use cpbp_core::bike::{read_bike_file, BikeParams, Placement, REFERENCE_BIKE};
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

pub(crate) const STEPS_PER_SECOND: f64 = 30.0;

fn scenario_names() -> Vec<&'static str> {
    manoeuvres::SCENARIOS
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
                        manoeuvres::ride(scenario, rider)
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
pub(crate) fn draw(seed: u64, what: u64) -> f64 {
    let mut z = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ what.wrapping_mul(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
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
