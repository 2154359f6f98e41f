//! The whole settings schema: the settings module's entries, the parameters of every
//! planner in the controller registry, and entries added at run time. It lives here,
//! beside the registry, so that the settings module (the schema's types and entries) sits
//! below everything that reads it: the bike, the planners and the ride import it, and it
//! imports none of them.
//!
//! Entries may be added at run time (`extend`): a mod's setting, or a test's throwaway
//! one, then reaches every reader as a compiled entry does; a planner registered at run
//! time (`ControllerKind::register`) brings its parameters the same way.

mod json;

pub use json::schema_json;

use std::sync::{PoisonError, RwLock};

use super::ControllerKind;
use crate::settings::{
    DefaultValue, Owner, Setting, SettingValues, Value, ENTRIES, PLANNER_SEED, TRAJECTORIES,
};

/// Entries added at run time (`extend`).
static EXTENDED: RwLock<Vec<Setting>> = RwLock::new(Vec::new());

/// Every setting: the compiled entries, the registered planners' own parameters, then
/// those added at run time.
pub fn all() -> Vec<Setting> {
    let planners = ControllerKind::planner_parameters();
    let extended = EXTENDED.read().unwrap_or_else(PoisonError::into_inner);
    ENTRIES
        .iter()
        .chain(planners.iter())
        .chain(extended.iter())
        .copied()
        .collect()
}

/// The setting called `name`.
pub fn find(name: &str) -> Option<Setting> {
    all().into_iter().find(|s| s.name == name)
}

/// The values of every setting `keep` accepts, at their defaults.
pub fn values_of(keep: impl Fn(&Setting) -> bool) -> SettingValues {
    SettingValues::holding(all().into_iter().filter(|s| keep(s)))
}

/// `NAME=VALUE` as a tool sets a planner's setting (`--set horizon=0.6`): the setting and
/// its value, checked against its entry and refused, not clamped, when it does not fit.
/// N and the planner's seed are not among them: the tools set those by flags of their own.
pub fn planner_assignment(text: &str) -> Result<(Setting, Value), String> {
    let (name, value) = text
        .split_once('=')
        .ok_or(format!("a planner's setting is NAME=VALUE, not {text}"))?;
    let setting = find(name)
        .filter(|s| s.owner == Owner::Planner)
        .ok_or(format!("{name} is not a planner's setting"))?;
    if [TRAJECTORIES.name, PLANNER_SEED.name].contains(&name) {
        return Err(format!(
            "{name} is set by the tool's own options (N, the seeds)"
        ));
    }
    Ok((setting, setting.parse(value)?))
}

/// Adds `setting` to the schema for the rest of the process (a mod's setting, or a
/// test's); refused when its name is taken or it is not a setting it may be.
pub fn extend(setting: Setting) -> Result<(), String> {
    if find(setting.name).is_some() {
        return Err(format!("a setting is already called {}", setting.name));
    }
    check_entry(&setting)?;
    EXTENDED
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .push(setting);
    Ok(())
}

/// Whether `setting` may join the schema: a number has a range that is not empty, only a
/// name has choices, and its defaults (the player's too) are values it may have.
pub(super) fn check_entry(setting: &Setting) -> Result<(), String> {
    let number = matches!(
        setting.default,
        DefaultValue::Int(_) | DefaultValue::Float(_)
    );
    match setting.range {
        Some(range) if !(range.min <= range.max && range.step >= 0.0) => {
            return Err(format!("{}: the range is empty", setting.name))
        }
        None if number => return Err(format!("{}: a number needs a range", setting.name)),
        _ => {}
    }
    if !setting.choices.is_empty() && !matches!(setting.default, DefaultValue::Text(_)) {
        return Err(format!("{}: only a name has choices", setting.name));
    }
    if setting.player_default.is_some() && !setting.player {
        return Err(format!(
            "{}: only a player setting has a player's default",
            setting.name
        ));
    }
    setting.check(&Value::from(setting.default))?;
    setting.check(&Value::from(setting.player_start()))
}

#[cfg(test)]
mod tests;
