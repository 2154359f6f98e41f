//! The learned controller's model as the game loads it: read once through Godot's file
//! access (so `res://` works inside an exported pack too) and shared by every bike that
//! asks for the same file; a missing or unusable file is reported once, with the reason,
//! and the controllers that need it say so on the HUD while the arcade controller drives.

use std::sync::Mutex;

use cpbp_core::bike::REFERENCE_BIKE;
use cpbp_core::control::learned::{model_path, no_model_of_its_own, LoadedPolicy};
use godot::classes::FileAccess;
use godot::prelude::*;

use crate::bike_description::BikeDescription;

/// The model file of `bike` (none: the reference bike), where `make train BIKE=` writes
/// it: named by the bike file's name (`cpbp_core::control::learned::model_path`). A
/// bike built in code has no file and no model of its own: its name then.
pub(crate) fn bike_model(bike: Option<&Gd<BikeDescription>>) -> Result<GString, String> {
    let Some(bike) = bike else {
        return Ok(res_path(REFERENCE_BIKE));
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
    let model = res_path(key);
    if FileAccess::file_exists(&model) {
        Ok(model)
    } else {
        Err(no_model_of_its_own(key))
    }
}

fn res_path(bike: &str) -> GString {
    GString::from(format!("res://{}", model_path(bike)).as_str())
}

/// The last file asked for and what it gave (a bike asks every physics tick).
static LOADED: Mutex<Option<(String, LoadedPolicy)>> = Mutex::new(None);

/// The network in the model file at `path` (`res://`, `user://` or absolute), loaded on
/// the first ask and kept until another file is asked for.
pub(crate) fn policy_at(path: &GString) -> LoadedPolicy {
    let path = path.to_string();
    let mut loaded = LOADED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some((_, policy)) = loaded.as_ref().filter(|(p, _)| *p == path) {
        return policy.clone();
    }
    let policy = read(&path);
    if let Some(why) = policy.problem() {
        godot_warn!("BikeSimulation: {why}; the learned and guided controllers cannot use it");
    }
    *loaded = Some((path, policy.clone()));
    policy
}

fn read(path: &str) -> LoadedPolicy {
    if path.is_empty() {
        return LoadedPolicy::missing("no learned model is set");
    }
    if !FileAccess::file_exists(path) {
        return LoadedPolicy::missing(format!(
            "the learned model {path} is missing (make train writes it)"
        ));
    }
    let bytes = FileAccess::get_file_as_bytes(path);
    if bytes.is_empty() {
        return LoadedPolicy::missing(format!(
            "the learned model {path} could not be read ({:?})",
            FileAccess::get_open_error()
        ));
    }
    LoadedPolicy::parse(bytes.as_slice(), path)
}
