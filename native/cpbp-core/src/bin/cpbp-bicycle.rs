//! Coasts the benchmark bicycle (cpbp_core::benchmark_bicycle) and prints what it did as
//! JSON lines for `tools/bicycle_benchmark`: first the parameters under the oracle's
//! names, then one line per speed with the recorded roll and steer.
//!
//! `cpbp-bicycle [--speeds 1,2.5,4] [--solver quickstep|direct] [--dt S] [--duration S]
//! [--gyroscopic implicit|explicit] [--roll-rate RAD_PER_S] [--mu M] [--erp E] [--cfm C]` (the last three: the tyres'
//! contact surface, the game's by default)

use std::process::ExitCode;

use cpbp_core::benchmark_bicycle::{coast, BenchmarkParameters, CoastConfig};
use cpbp_core::ode::{Gyroscopic, Solver};

fn main() -> ExitCode {
    let (speeds, config) = match parse(std::env::args().skip(1).collect()) {
        Ok(parsed) => parsed,
        Err(message) => {
            eprintln!("cpbp-bicycle: {message}");
            return ExitCode::from(2);
        }
    };
    let parameters = BenchmarkParameters::default();
    let named: Vec<String> = parameters
        .named()
        .iter()
        .map(|(name, value)| format!("\"{name}\": {value:e}"))
        .collect();
    println!("{{\"parameters\": {{{}}}}}", named.join(", "));
    for speed in speeds {
        let ridden = coast(&parameters, &CoastConfig { speed, ..config });
        println!(
            "{{\"speed\": {speed}, \"dt\": {dt:e}, \"time\": {}, \"roll\": {}, \"steer\": {}, \
             \"forward_speed\": {}}}",
            list(&ridden.time),
            list(&ridden.roll),
            list(&ridden.steer),
            list(&ridden.speed),
            dt = config.dt,
        );
    }
    ExitCode::SUCCESS
}

fn list(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|v| format!("{v:e}")).collect();
    format!("[{}]", items.join(","))
}

fn parse(arguments: Vec<String>) -> Result<(Vec<f64>, CoastConfig), String> {
    let mut speeds = vec![5.0];
    let mut config = CoastConfig::default();
    let mut pairs = arguments.chunks(2);
    for pair in pairs.by_ref() {
        let [flag, value] = pair else {
            return Err(format!("{} needs a value", pair[0]));
        };
        let number = || {
            value
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && *v > 0.0)
                .ok_or_else(|| format!("{flag} wants a positive number, not {value:?}"))
        };
        match flag.as_str() {
            "--speeds" => {
                speeds = value
                    .split(',')
                    .map(|s| s.trim().parse::<f64>().ok().filter(|v| v.is_finite()))
                    .collect::<Option<Vec<f64>>>()
                    .ok_or_else(|| format!("--speeds wants numbers like 1,2.5, not {value:?}"))?;
            }
            "--solver" => {
                config.solver = match value.as_str() {
                    "quickstep" => Solver::QuickStep,
                    "direct" => Solver::Direct,
                    _ => return Err(format!("--solver is quickstep or direct, not {value:?}")),
                }
            }
            "--gyroscopic" => {
                config.gyroscopic = match value.as_str() {
                    "implicit" => Gyroscopic::Implicit,
                    "explicit" => Gyroscopic::Explicit,
                    _ => {
                        return Err(format!(
                            "--gyroscopic is implicit or explicit, not {value:?}"
                        ))
                    }
                }
            }
            "--dt" => config.dt = number()?,
            "--duration" => config.duration = number()?,
            "--roll-rate" => config.roll_rate = number()?,
            "--mu" => config.surface.mu = number()?,
            "--erp" => config.surface.soft_erp = number()?,
            "--cfm" => config.surface.soft_cfm = number()?,
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok((speeds, config))
}
