//! What the bike examples read from their command line alike: `--bike FILE` (the reference
//! bike without it), `FIELD=VALUE` to change one of its fields (`max_steer_torque=60`), and
//! flags with a value (`--heading 45`).

use cpbp_core::bike::{field, take_bike_argument};
use cpbp_core::simulation::SimulationConfig;

/// The simulation of the bike the arguments name, its fields changed as they say; takes
/// those arguments out of `args`, leaving the example's own. Exits naming what is wrong.
pub fn bike_config(args: &mut Vec<String>, tool: &str) -> SimulationConfig {
    let mut config = SimulationConfig::default();
    match take_bike_argument(args) {
        Ok(Some(bike)) => config.bike = bike.params,
        Ok(None) => {}
        Err(why) => fail(tool, &why),
    }
    let (settings, rest): (Vec<String>, Vec<String>) =
        args.drain(..).partition(|a| a.contains('='));
    *args = rest;
    for setting in &settings {
        let (name, value) = setting.split_once('=').expect("partitioned on '='");
        let Some(field) = field(name) else {
            fail(tool, &format!("{name}: no bike field is called so"));
        };
        let value = value
            .parse()
            .unwrap_or_else(|_| fail(tool, &format!("{setting}: not a number")));
        field
            .apply(&mut config.bike, value)
            .unwrap_or_else(|why| fail(tool, &why));
    }
    config.bike.check().unwrap_or_else(|why| fail(tool, &why));
    config
}

/// Takes `flag VALUE` out of `args`: the value, or None without the flag.
pub fn take_flag(args: &mut Vec<String>, flag: &str, tool: &str) -> Option<String> {
    let at = args.iter().position(|a| a == flag)?;
    if at + 1 >= args.len() {
        fail(tool, &format!("{flag} needs a value"));
    }
    let value = args.remove(at + 1);
    args.remove(at);
    Some(value)
}

pub fn fail(tool: &str, why: &str) -> ! {
    eprintln!("{tool}: {why}");
    std::process::exit(2);
}
