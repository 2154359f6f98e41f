//! `cpbp-learn generate --out DIR --episodes FIRST-LAST [--trajectories N] [--seconds S]
//! [--noise X] [--jobs J]`: the planner rides the episodes of those seeds as the expert
//! and each is saved as one shard in DIR (`episode-SEED.safetensors`). Episodes already
//! saved are skipped, so a stopped run continues where it was; progress and an ETA are
//! printed as episodes end. With `--learner MODEL` the network drives and the planner
//! labels the states it leads to (a DAgger round). With `--bike FILE` (a bike file, as
//! the game reads it) the episodes ride that bike; `train` then records it in the model
//! and refuses data of two bikes. With `--values` the expert's plans are recorded for a
//! learned cost-to-go too (the states its trajectories reach, with what the rest of the
//! horizon cost from them), which `train-value` trains on (`training_run.rs`). With
//! `--short-planner VALUE_MODEL` the game's planner (combined, N = 5) drives on a short
//! horizon (`--short-horizon`, 0.6 s) ended by that cost-to-go while the expert labels: a
//! DAgger round of the cost-to-go.
//!
//! `cpbp-learn summary --out DIR`: what the saved episodes hold (rows, the speeds they
//! cover, each output's mean and spread), every shard checked against this build's
//! feature list.

mod episode;
mod family;
mod grounds;
mod shard;
mod train;
mod training_run;
mod wheelies;

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use cpbp_core::bike::take_bike_argument;
use cpbp_core::control::learned::{
    output_entries, LoadedValue, PolicyNetwork, FEATURE_COUNT, FEATURE_NAMES, OUTPUT_COUNT,
};
use cpbp_core::settings;
use episode::{Episode, ExpertSettings};

const USAGE: &str = "cpbp-learn generate --out DIR --episodes FIRST-LAST [--trajectories N] \
[--seconds S] [--noise X] [--jobs J] [--learner MODEL] [--family mixed|logs|carving|shoves|braking|wheelies] \
[--bike FILE] [--values] [--short-planner VALUE_MODEL [--short-horizon S]]\n       \
cpbp-learn train|train-value --data DIR[,DIR…] --model FILE [--losses CSV] [--epochs E] \
[--seed S] [--hidden W,W…] [--weight-decay D]\n       \
cpbp-learn summary --out DIR";

struct Generate {
    out: PathBuf,
    seeds: std::ops::RangeInclusive<u64>,
    settings: ExpertSettings,
    jobs: usize,
    /// The network that drives while the expert labels (DAgger), if any.
    learner: Option<PolicyNetwork>,
}

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    if arguments.is_empty() || arguments.iter().any(|a| a == "--help" || a == "-h") {
        println!("usage: {USAGE}");
        return;
    }
    let result = match arguments[0].as_str() {
        "generate" => parse(&arguments[1..]).and_then(generate),
        "train" => training_run::train_command(&arguments[1..], training_run::Kind::Policy),
        "train-value" => training_run::train_command(&arguments[1..], training_run::Kind::Value),
        "summary" => match &arguments[1..] {
            [flag, dir] if flag == "--out" => summary(&PathBuf::from(dir)),
            _ => Err(format!("summary needs --out DIR\nusage: {USAGE}")),
        },
        other => Err(format!("unknown command '{other}'\nusage: {USAGE}")),
    };
    if let Err(message) = result {
        eprintln!("cpbp-learn: {message}");
        std::process::exit(2);
    }
}

fn parse(arguments: &[String]) -> Result<Generate, String> {
    let mut arguments = arguments.to_vec();
    let mut settings = ExpertSettings::default();
    if let Some(bike) = take_bike_argument(&mut arguments)? {
        println!("riding {}", bike.name);
        settings.bike = bike.params;
    }
    if let Some(at) = arguments.iter().position(|a| a == "--values") {
        arguments.remove(at);
        settings.values = true;
    }
    let mut out = None;
    let mut seeds = None;
    let mut jobs = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut learner = None;
    // The planner's own setting: the game's default value horizon, below the expert's.
    let (mut short_value, mut short_horizon) = (None, settings::VALUE_HORIZON_S.default_number());
    let expert_horizon = settings::HORIZON_S.default_number();
    let mut it = arguments.iter();
    while let Some(flag) = it.next() {
        let value = it
            .next()
            .ok_or_else(|| format!("{flag} needs a value\nusage: {USAGE}"))?;
        let number = |what: &str| -> Result<f64, String> {
            value
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && *v >= 0.0)
                .ok_or_else(|| format!("{what} must be a number ≥ 0, not '{value}'"))
        };
        match flag.as_str() {
            "--out" => out = Some(PathBuf::from(value)),
            "--episodes" => {
                let (first, last) = value.split_once('-').unwrap_or((value, value));
                let parse = |s: &str| s.parse::<u64>().map_err(|_| format!("bad seed '{s}'"));
                let (first, last) = (parse(first)?, parse(last)?);
                if first > last {
                    return Err(format!("--episodes {value}: the first is after the last"));
                }
                seeds = Some(first..=last);
            }
            "--trajectories" => settings.trajectories = number("--trajectories")?.max(1.0) as usize,
            "--seconds" => settings.seconds = number("--seconds")?.clamp(1.0, 600.0),
            "--noise" => settings.noise = number("--noise")?.min(0.5),
            "--family" => {
                settings.family = episode::Family::from_name(value).ok_or_else(|| {
                    format!(
                        "--family is mixed, logs, carving, shoves, braking or wheelies, not '{value}'"
                    )
                })?;
            }
            "--jobs" => jobs = number("--jobs")?.max(1.0) as usize,
            "--short-planner" => {
                let value = LoadedValue::load(std::path::Path::new(value));
                if let Some(why) = value.problem() {
                    return Err(format!("--short-planner: {why}"));
                }
                short_value = Some(value);
            }
            "--short-horizon" => {
                short_horizon = number("--short-horizon")?;
                let shortest = settings::VALUE_HORIZON_S.limit().min;
                if !(shortest..expert_horizon).contains(&short_horizon) {
                    return Err(format!(
                        "--short-horizon is {shortest}–{expert_horizon} s (the expert plans \
                         {expert_horizon}), not {value}"
                    ));
                }
            }
            "--learner" => {
                let network = PolicyNetwork::load(std::path::Path::new(value))
                    .map_err(|e| format!("--learner {value}: {e}"))?;
                learner = Some(network);
            }
            other => return Err(format!("unknown option '{other}'\nusage: {USAGE}")),
        }
    }
    settings.short_planner = short_value.map(|value| episode::ShortPlanner {
        value,
        horizon: short_horizon,
    });
    Ok(Generate {
        out: out.ok_or("--out is required")?,
        seeds: seeds.ok_or("--episodes is required")?,
        settings,
        jobs,
        learner,
    })
}

fn generate(run: Generate) -> Result<(), String> {
    std::fs::create_dir_all(&run.out)
        .map_err(|e| format!("cannot create {}: {e}", run.out.display()))?;
    let missing: Vec<u64> = run
        .seeds
        .clone()
        .filter(|&seed| !shard::shard_path(&run.out, seed).exists())
        .collect();
    let total = run.seeds.clone().count();
    println!(
        "{} of {total} episodes to ride into {} (expert: combined, N = {}, exact physics, \
         noise {}; {}; {} jobs)",
        missing.len(),
        run.out.display(),
        run.settings.trajectories,
        run.settings.noise,
        match (&run.settings.short_planner, &run.learner) {
            (Some(short), _) => format!(
                "combined N = {} drives on {} s ended by the cost-to-go",
                episode::SHORT_PLANNER_N,
                short.horizon
            ),
            (None, Some(_)) => "the learner drives".to_string(),
            (None, None) => "the expert drives".to_string(),
        },
        run.jobs
    );
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(run.jobs)
        .build()
        .map_err(|e| e.to_string())?;
    let (started, done, rows) = (Instant::now(), AtomicUsize::new(0), AtomicUsize::new(0));
    pool.install(|| {
        missing.par_iter().try_for_each(|&seed| {
            let episode = Episode::draw(seed, &run.settings);
            let records = episode::ride(&episode, &run.settings, run.learner.as_ref());
            shard::write(&run.out, &episode, &run.settings, &records)
                .map_err(|e| format!("cannot save episode {seed}: {e}"))?;
            let finished = done.fetch_add(1, Ordering::SeqCst) + 1;
            let rows = rows.fetch_add(records.features.len(), Ordering::SeqCst)
                + records.features.len();
            let elapsed = started.elapsed().as_secs_f64();
            let eta = elapsed / finished as f64 * (missing.len() - finished) as f64;
            println!(
                "[{finished}/{}] episode {seed} ({}, {} steps{}) · {rows} rows · elapsed {} · ETA {}",
                missing.len(),
                episode.ground.label(),
                records.features.len(),
                if records.crashed { ", crashed" } else { "" },
                clock(elapsed),
                clock(eta)
            );
            Ok(())
        })
    })
}

fn summary(dir: &std::path::Path) -> Result<(), String> {
    let paths = shard::shard_paths(dir)?;
    let (mut rows, mut speeds) = (0, (f32::INFINITY, f32::NEG_INFINITY));
    let mut sums = [(0.0f64, 0.0f64); OUTPUT_COUNT];
    for path in &paths {
        let shard::ShardRows {
            features,
            labels,
            rows: n,
            ..
        } = shard::read(path)?;
        rows += n;
        let speed_at = FEATURE_NAMES
            .iter()
            .position(|n| *n == "speed")
            .unwrap_or(0);
        for speed in features.iter().skip(speed_at).step_by(FEATURE_COUNT) {
            speeds = (speeds.0.min(*speed), speeds.1.max(*speed));
        }
        for row in labels.chunks_exact(OUTPUT_COUNT) {
            for (sum, &value) in sums.iter_mut().zip(row) {
                *sum = (sum.0 + f64::from(value), sum.1 + f64::from(value).powi(2));
            }
        }
    }
    println!(
        "{} episodes, {rows} rows, speeds {:.1}…{:.1} km/h",
        paths.len(),
        speeds.0 * 3.6,
        speeds.1 * 3.6
    );
    for (entry, (sum, squares)) in output_entries().iter().zip(sums) {
        let mean = sum / rows.max(1) as f64;
        let spread = (squares / rows.max(1) as f64 - mean * mean).max(0.0).sqrt();
        println!("control u{entry:<2} mean {mean:+.3} spread {spread:.3}");
    }
    Ok(())
}

fn clock(seconds: f64) -> String {
    let s = seconds.round() as u64;
    format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
}

#[cfg(test)]
mod family_tests;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod value_tests;
