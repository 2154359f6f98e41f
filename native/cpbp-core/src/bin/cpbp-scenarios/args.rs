//! The scenario runner's command line: which controllers, counts, seeds and scenarios
//! to ride, and the rows already saved to skip.

use std::collections::HashSet;
use std::path::PathBuf;

use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{schema, ControllerKind};
use cpbp_core::settings::{Owner, SettingValues};

use super::{manoeuvres, scenario_names};

pub(crate) struct Args {
    pub controllers: Vec<ControllerKind>,
    pub counts: Vec<usize>,
    pub seeds: Vec<u64>,
    pub scenarios: Vec<&'static str>,
    pub physics: PhysicsModel,
    /// Rows already saved ("scenario,controller,N,seed,physics"): not ridden again.
    pub skip: HashSet<String>,
    /// The learned network's model file (learned, guided); none: the bike's own.
    pub model: Option<PathBuf>,
    /// The bike file ridden (a game's scenes/bike/bikes/*.tres); none: the reference bike.
    pub bike: Option<PathBuf>,
    /// The planners' settings (`--set NAME=VALUE`, the rest at their defaults).
    pub planner_settings: SettingValues,
}

pub(crate) const USAGE: &str =
    "cpbp-scenarios [--controllers K,K…] [--counts N,N…] [--seeds FIRST-LAST] \
[--scenarios S,S…|all] [--physics classic|exact] [--skip FILE] [--model FILE] [--bike FILE] \
[--set NAME=VALUE]…";
const FLAGS: [&str; 9] = [
    "--set",
    "--model",
    "--bike",
    "--controllers",
    "--counts",
    "--seeds",
    "--scenarios",
    "--physics",
    "--skip",
];

pub(crate) fn parse(arguments: Vec<String>) -> Result<Args, String> {
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
    // `all`: every scenario, as a bike's table is ridden again after its physics changed.
    let scenarios = match value("--scenarios")?.as_deref() {
        Some("all") => names.join(","),
        Some(listed) => listed.to_string(),
        None => manoeuvres::SCENARIOS.join(","),
    };
    let scenarios = scenarios
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
        model: value("--model")?.map(PathBuf::from),
        bike: value("--bike")?.map(PathBuf::from),
        planner_settings: planner_settings(&arguments)?,
    })
}

/// The planners' settings with each `--set NAME=VALUE` (repeatable) applied
/// (`schema::planner_assignment`: a planner's setting, its value checked against its
/// entry; N and the seed have flags of their own).
fn planner_settings(arguments: &[String]) -> Result<SettingValues, String> {
    let mut values = schema::values_of(|s| s.owner == Owner::Planner);
    let assignments = arguments
        .windows(2)
        .filter(|pair| pair[0] == "--set")
        .map(|pair| pair[1].as_str());
    for assignment in assignments {
        let (setting, value) = schema::planner_assignment(assignment)?;
        values.set(setting.name, value)?;
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::parse;
    use cpbp_core::settings::Value;

    fn words(line: &str) -> Vec<String> {
        line.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn flags_and_their_values_parse_and_anything_else_is_refused() {
        let args = parse(words("--counts 5,15 --seeds 2-4 --scenarios stop40")).unwrap();
        assert_eq!(args.counts, vec![5, 15]);
        assert_eq!(args.seeds, vec![2, 3, 4]);
        assert_eq!(args.scenarios, vec!["stop40"]);
        let all = parse(words("--scenarios all")).unwrap().scenarios;
        assert_eq!(all, super::scenario_names());
        let set = parse(words("--set horizon=0.6 --set mutation_scale=0.3")).unwrap();
        assert_eq!(
            set.planner_settings.get("horizon"),
            Some(&Value::Float(0.6))
        );
        assert_eq!(
            set.planner_settings.get("mutation_scale"),
            Some(&Value::Float(0.3))
        );
        for wrong in [
            "--set horizon",
            "--set horizon=9",
            "--set trajectories=8",
            "--set max_speed_kmh=20",
            "--set no_such=1",
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
