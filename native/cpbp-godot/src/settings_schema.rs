//! `SettingsSchema`: the core's settings schema for GDScript (the settings file, the
//! menus) and for the tools' copy of it.

use cpbp_core::ride::schema;
use cpbp_core::settings::{self, DefaultValue, Owner, Range, Setting};
use godot::prelude::*;

use crate::node_settings::{from_variant, schema_dictionaries};

/// Every setting a player, a level designer or a tool may change, each described once by
/// the native core (`cpbp_core::settings`).
#[derive(GodotClass)]
#[class(init, base=RefCounted)]
pub struct SettingsSchema {
    base: Base<RefCounted>,
}

#[godot_api]
impl SettingsSchema {
    /// Every setting as a dictionary: name, label, description, unit, default (whose type
    /// is the setting's), owner (ride, planner, bike, game, display, sound), player
    /// (kept in the player's settings file), menu (the pause menu's group, "" for none),
    /// min, max and step for a number, offered (the values a menu lists, if any) and
    /// choices (the names a name setting may hold; empty for any).
    #[func]
    fn entries() -> Array<VarDictionary> {
        schema_dictionaries()
    }

    /// The schema as the Python tools read it (tools/cpbp_experiment/settings.json).
    #[func]
    fn to_json() -> GString {
        GString::from(schema::schema_json().as_str())
    }

    /// Adds a setting for the rest of the run (a mod's, or a test's), from a dictionary
    /// shaped as `entries()` gives them; returns "" or why it was refused. Every reader of
    /// the schema then has it: the game node's properties (for owner ride or planner), the
    /// settings file and the pause menu (player), the tools' JSON.
    #[func]
    fn extend(entry: VarDictionary) -> GString {
        match setting_of(&entry).and_then(schema::extend) {
            Ok(()) => GString::new(),
            Err(why) => GString::from(why.as_str()),
        }
    }

    /// `NAME=VALUE` as a tool sets a planner's setting (the experiment worker's `--set`):
    /// `{"name": …, "value": …}` with the value of the setting's type, or `{"error": …}`
    /// saying why not (not a planner's setting, a value that does not fit).
    #[func]
    fn planner_assignment(text: GString) -> VarDictionary {
        let mut answer = VarDictionary::new();
        match schema::planner_assignment(&text.to_string()) {
            Ok((setting, value)) => {
                answer.set("name", setting.name);
                answer.set("value", &crate::node_settings::to_variant(&value));
            }
            Err(why) => answer.set("error", why.as_str()),
        }
        answer
    }

    /// Length of one control step (s): the period every controller acts at.
    #[func]
    fn control_period() -> f64 {
        cpbp_core::simulation::SimulationConfig::default().control_dt
    }
}

/// The names a name setting may hold, from the entry's `choices` (strings, in a
/// PackedStringArray or an Array); they live for the rest of the run.
fn choices_of(entry: &VarDictionary) -> &'static [&'static str] {
    let Some(list) = entry.get("choices") else {
        return &[];
    };
    let names: Vec<String> = match list.try_to::<PackedStringArray>() {
        Ok(strings) => strings.as_slice().iter().map(|s| s.to_string()).collect(),
        Err(_) => list
            .try_to::<VarArray>()
            .map(|items| {
                items
                    .iter_shared()
                    .map(|v| v.stringify().to_string())
                    .collect()
            })
            .unwrap_or_default(),
    };
    let leaked: Vec<&'static str> = names
        .into_iter()
        .map(|name| &*Box::leak(name.into_boxed_str()))
        .collect();
    Box::leak(leaked.into_boxed_slice())
}

/// A setting from its dictionary; its strings live for the rest of the run, as compiled
/// entries' do.
fn setting_of(entry: &VarDictionary) -> Result<Setting, String> {
    let text = |key: &str| -> &'static str {
        let value = entry
            .get(key)
            .map_or(String::new(), |v| v.stringify().to_string());
        Box::leak(value.into_boxed_str())
    };
    let number = |key: &str| entry.get(key).and_then(|v| v.try_to::<f64>().ok());
    let name = text("name");
    if name.is_empty() {
        return Err("a setting needs a name".into());
    }
    let Some(default) = entry.get("default").as_ref().and_then(from_variant) else {
        return Err(format!(
            "{name}: the default is not a switch, number or name"
        ));
    };
    let default = default_of(default);
    let owner = [
        Owner::Ride,
        Owner::Planner,
        Owner::Bike,
        Owner::Game,
        Owner::Display,
        Owner::Sound,
    ]
    .into_iter()
    .find(|o| o.name() == text("owner"))
    .ok_or_else(|| format!("{name}: no owner is called '{}'", text("owner")))?;
    let range = match (number("min"), number("max")) {
        (Some(min), Some(max)) => Some(Range::new(min, max, number("step").unwrap_or(0.0))),
        _ => None,
    };
    Ok(Setting {
        name,
        label: text("label"),
        description: text("description"),
        unit: text("unit"),
        default,
        range,
        offered: &[],
        choices: choices_of(entry),
        owner,
        player_default: entry
            .get("player_default")
            .as_ref()
            .and_then(from_variant)
            .map(default_of),
        player: entry.get("player").is_some_and(|v| v.booleanize()),
        menu: text("menu"),
    })
}

/// A value read from a dictionary as a schema default (a name is kept for the process's
/// life, as the compiled entries' are).
fn default_of(value: settings::Value) -> DefaultValue {
    match value {
        settings::Value::Bool(on) => DefaultValue::Bool(on),
        settings::Value::Int(n) => DefaultValue::Int(n),
        settings::Value::Float(x) => DefaultValue::Float(x),
        settings::Value::Text(t) => DefaultValue::Text(Box::leak(t.into_boxed_str())),
    }
}
