//! The learned networks as the game loads them (the controller's policy, the planners'
//! cost-to-go): read once through Godot's file access (so `res://` works inside an
//! exported pack too) and shared by every bike that asks for the same file; a missing or
//! unusable file is reported once, with the reason, and what needs it says so on the HUD
//! (the arcade controller drives, or the planners plan their whole horizon).

use std::sync::Mutex;

use cpbp_core::bike::REFERENCE_BIKE;
use cpbp_core::control::learned::{
    model_path, no_model_of_its_own, value_model_path, LearnedModel, Loaded, LoadedPolicy,
    LoadedValue,
};
use godot::classes::FileAccess;
use godot::prelude::*;

use crate::bike_description::BikeDescription;

/// The model file of `bike` (none: the reference bike), where `make train BIKE=` writes
/// it: named by the bike file's name (`cpbp_core::control::learned::model_path`). A
/// bike built in code has no file and no model of its own: its name then.
pub(crate) fn bike_model(bike: Option<&Gd<BikeDescription>>) -> Result<GString, String> {
    let key = bike_key(bike)?;
    let model = res_path(&model_path(&key));
    if FileAccess::file_exists(&model) {
        Ok(model)
    } else {
        Err(no_model_of_its_own(&key))
    }
}

/// The cost-to-go file of `bike`, beside its policy (`value_model_path`), whether or not
/// it exists (`value_at` says so when it does not).
pub(crate) fn bike_value(bike: Option<&Gd<BikeDescription>>) -> Result<GString, String> {
    bike_key(bike).map(|key| res_path(&value_model_path(&key)))
}

/// The bike file's name without `.tres` (the reference bike's without a bike).
fn bike_key(bike: Option<&Gd<BikeDescription>>) -> Result<String, String> {
    let Some(bike) = bike else {
        return Ok(REFERENCE_BIKE.to_owned());
    };
    let path = bike.get_path().to_string();
    let key = path
        .rsplit('/')
        .next()
        .and_then(|file| file.strip_suffix(".tres"))
        .unwrap_or_default();
    if key.is_empty() {
        return Err(format!(
            "the bike {} has no file, so no learned model of its own",
            bike.bind().name()
        ));
    }
    Ok(key.to_owned())
}

fn res_path(path: &str) -> GString {
    GString::from(format!("res://{path}").as_str())
}

/// The last policy file asked for and what it gave (a bike asks every physics tick).
static POLICY: Mutex<Option<(String, LoadedPolicy)>> = Mutex::new(None);
/// The same for the cost-to-go.
static VALUE: Mutex<Option<(String, LoadedValue)>> = Mutex::new(None);

/// The network in the model file at `path` (`res://`, `user://` or absolute), loaded on
/// the first ask and kept until another file is asked for.
pub(crate) fn policy_at(path: &GString) -> LoadedPolicy {
    loaded_at(
        &POLICY,
        path,
        "the learned and guided controllers cannot use it",
    )
}

/// The cost-to-go in the model file at `path`, as `policy_at` loads a policy.
pub(crate) fn value_at(path: &GString) -> LoadedValue {
    loaded_at(&VALUE, path, "the planners plan their whole horizon")
}

fn loaded_at<N: LearnedModel>(
    last: &Mutex<Option<(String, Loaded<N>)>>,
    path: &GString,
    so: &str,
) -> Loaded<N> {
    let path = path.to_string();
    let mut last = last.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some((_, network)) = last.as_ref().filter(|(p, _)| *p == path) {
        return network.clone();
    }
    let network = read(&path);
    if let Some(why) = network.problem() {
        godot_warn!("BikeSimulation: {why}; {so}");
    }
    *last = Some((path, network.clone()));
    network
}

fn read<N: LearnedModel>(path: &str) -> Loaded<N> {
    if path.is_empty() {
        return Loaded::missing(format!("no {} is set", N::NAME));
    }
    if !FileAccess::file_exists(path) {
        return Loaded::missing(format!(
            "the {} {path} is missing (make train writes it)",
            N::NAME
        ));
    }
    let bytes = FileAccess::get_file_as_bytes(path);
    if bytes.is_empty() {
        return Loaded::missing(format!(
            "the {} {path} could not be read ({:?})",
            N::NAME,
            FileAccess::get_open_error()
        ));
    }
    Loaded::parse(bytes.as_slice(), path)
}
