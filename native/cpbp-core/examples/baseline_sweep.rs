//! How the baseline planners' defaults were chosen (docs/results-history.md, "Planners
//! side by side"): `native/target/release/examples/baseline_sweep N [--dims steering,all]
//! [--noise 0.1,0.25,0.5] [--knots 6] [--temperature 0.03,0.1,0.3]` rides predictive
//! sampling and MPPI with every setting of the grid in the game's physics on flat ground,
//! two planner seeds each, and prints per setting: how many of the walking-pace rides
//! (8 km/h, 20 s straight) stayed up, and the RMS lean error in a 15° turn at 20 km/h
//! (the mean over the rides that stayed up; a fall counts in the fall column). The
//! temperature is MPPI's alone.

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::control::mppi::MPPI_TEMPERATURE;
use cpbp_core::control::sampling::{BASELINE_KNOTS, BASELINE_NOISE, BASELINE_STEERING_ONLY};
use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::settings::Value;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};

const SEEDS: [u64; 2] = [1, 2];

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = arguments
        .first()
        .map_or(10, |a| a.parse().expect("N, a whole number"));
    let list = |flag: &str, default: &str| -> Vec<String> {
        let value = arguments
            .iter()
            .position(|a| a == flag)
            .and_then(|i| arguments.get(i + 1))
            .map_or(default, String::as_str);
        value.split(',').map(str::to_string).collect()
    };
    let numbers = |flag: &str, default: &str| -> Vec<f64> {
        list(flag, default)
            .iter()
            .map(|x| {
                x.parse()
                    .unwrap_or_else(|_| panic!("{flag}: numbers, not {x}"))
            })
            .collect()
    };
    let dims = list("--dims", "steering,all");
    let (noises, knots) = (numbers("--noise", "0.1,0.25,0.5"), numbers("--knots", "6"));
    let temperatures = numbers("--temperature", "0.03,0.1,0.3");
    println!(
        "{:<10} {:>9} {:>6} {:>6} {:>6} {:>12} {:>14} {:>6}",
        "planner", "dims", "knots", "noise", "temp", "8 km/h up", "15° turn RMS", "falls"
    );
    for kind in [ControllerKind::SAMPLING, ControllerKind::MPPI] {
        let temperatures = if kind == ControllerKind::MPPI {
            temperatures.clone()
        } else {
            vec![MPPI_TEMPERATURE.default_number()]
        };
        for dim in &dims {
            for (&noise, &knots) in noises
                .iter()
                .flat_map(|n| knots.iter().map(move |k| (n, k)))
            {
                for &temperature in &temperatures {
                    let settings = Baseline {
                        knots: knots as usize,
                        noise,
                        temperature,
                        steering_only: dim == "steering",
                    };
                    report(kind, n, &settings);
                }
            }
        }
    }
}

/// One combination of the baselines' parameters.
struct Baseline {
    knots: usize,
    noise: f64,
    temperature: f64,
    steering_only: bool,
}

fn report(kind: ControllerKind, n: usize, settings: &Baseline) {
    let walked = SEEDS
        .iter()
        .filter(|&&seed| {
            let mut ride = ride(kind, n, settings, seed, 8.0);
            ride_for(&mut ride, 20.0, 0.0);
            ride.sim().crashed().is_none()
        })
        .count();
    let (mut errors, mut falls) = (Vec::new(), 0);
    for &seed in &SEEDS {
        match turn_rms(&mut ride(kind, n, settings, seed, 20.0)) {
            Some(rms) => errors.push(rms),
            None => falls += 1,
        }
    }
    let rms = match errors.len() {
        0 => "–".to_string(),
        k => format!("{:.2}°", errors.iter().sum::<f64>() / k as f64),
    };
    println!(
        "{:<10} {:>9} {:>6} {:>6} {:>6} {:>10}/{} {:>14} {:>6}",
        kind.name(),
        if settings.steering_only {
            "steering"
        } else {
            "all"
        },
        settings.knots,
        settings.noise,
        settings.temperature,
        walked,
        SEEDS.len(),
        rms,
        falls
    );
}

/// A ride in the game's physics on flat ground, full throttle towards `kmh`.
fn ride(kind: ControllerKind, n: usize, settings: &Baseline, seed: u64, kmh: f64) -> Ride {
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(0.3),
    };
    let config = SimulationConfig {
        physics: PhysicsModel::Exact,
        ..SimulationConfig::default()
    };
    let sim = Simulation::new(config, Arc::new(Terrain::flat()), spawn);
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = n;
    ride.planner.planning.seed = seed;
    let parameters = &mut ride.planner.planning.parameters;
    for (setting, value) in [
        (BASELINE_KNOTS, Value::Int(settings.knots as i64)),
        (BASELINE_NOISE, Value::Float(settings.noise)),
        (MPPI_TEMPERATURE, Value::Float(settings.temperature)),
        (BASELINE_STEERING_ONLY, Value::Bool(settings.steering_only)),
    ] {
        parameters.include(&[setting]);
        parameters
            .set(setting.name, value)
            .expect("within the parameter's range");
    }
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    ride
}

fn ride_for(ride: &mut Ride, seconds: f64, lean: f64) {
    ride.set_intent(Intent {
        lean: Some(lean),
        ..*ride.intent()
    });
    for _ in 0..(seconds * 30.0) as usize {
        ride.step();
    }
}

/// 3 s straight, 2 s into a 15° right lean, then the RMS error (degrees) over 5 s; None
/// if the bike fell.
fn turn_rms(ride: &mut Ride) -> Option<f64> {
    let want = 15f64.to_radians();
    ride_for(ride, 3.0, 0.0);
    ride_for(ride, 2.0, want);
    let mut squares = 0.0;
    for _ in 0..150 {
        ride.step();
        let sim = ride.sim();
        squares += (sim.bike().lean(sim.world(), sim.up()) - want).powi(2);
    }
    ride.sim()
        .crashed()
        .is_none()
        .then(|| (squares / 150.0).sqrt().to_degrees())
}
