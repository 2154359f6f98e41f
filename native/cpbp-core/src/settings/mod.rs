//! The settings schema's types and entries: every setting a player, a level designer, a
//! script or a tool may change, each described once — name, label, unit, default, range,
//! who owns it, whether players see it and where menus show it. The game node's
//! properties and clamps, the player's settings file and its pause menu, and the Python
//! tools (tools/cpbp_experiment/settings.json) all read these entries, so changing a
//! default or a range is one edit in entries.rs; the core's own defaults (the drive, the
//! planners' configs, the simulation's) read their entry too.
//!
//! This is the bottom of the core: it imports nothing of it. The whole schema — these
//! entries, every registered planner's parameters and those added at run time — is
//! `ride::schema`, beside the controller registry.

mod entries;
mod values;

pub use entries::*;
pub use values::{SettingValues, Value};

/// Who reads a setting: the ride (the game node's drive and stepping), the planners, the
/// bike, the game's scripts, what is drawn, or what is heard.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Owner {
    Ride,
    Planner,
    Bike,
    Game,
    Display,
    Sound,
}

impl Owner {
    pub const fn name(self) -> &'static str {
        match self {
            Owner::Ride => "ride",
            Owner::Planner => "planner",
            Owner::Bike => "bike",
            Owner::Game => "game",
            Owner::Display => "display",
            Owner::Sound => "sound",
        }
    }

    /// Whether the game node (`BikeSimulation`) carries the owner's settings as its own
    /// properties.
    pub const fn on_the_node(self) -> bool {
        matches!(self, Owner::Ride | Owner::Planner)
    }
}

/// A setting's default, which is also its type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DefaultValue {
    Bool(bool),
    Int(i64),
    Float(f64),
    /// A name (a level, a camera mode, a controller).
    Text(&'static str),
}

/// Where a number may be set: inclusive bounds and the step sliders move by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub min: f64,
    pub max: f64,
    pub step: f64,
}

impl Range {
    pub const fn new(min: f64, max: f64, step: f64) -> Self {
        Self { min, max, step }
    }

    /// `value` within the range, or `fallback` (clamped too) if it is not a number.
    pub fn clamp(self, value: f64, fallback: f64) -> f64 {
        let value = if value.is_finite() { value } else { fallback };
        value.clamp(self.min, self.max)
    }

    /// A whole-number setting within the range.
    pub fn clamp_count(self, value: i64) -> usize {
        value.clamp(self.min as i64, self.max as i64) as usize
    }
}

/// One setting, described once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setting {
    /// Its name everywhere: the node's property, the settings file's key, the tools' key.
    pub name: &'static str,
    /// What menus call it.
    pub label: &'static str,
    /// One sentence for the inspector, the docs and the tools' help.
    pub description: &'static str,
    /// The unit its numbers are in ("" for none; "share" for 0–1, shown as a percentage).
    pub unit: &'static str,
    pub default: DefaultValue,
    /// What a player's game starts with where it differs from `default`, which the node,
    /// the tools and the committed rows keep (the thesis's planner): the game plans with
    /// a bike's learned cost-to-go, the protocol at its defaults does not. A player
    /// setting only.
    pub player_default: Option<DefaultValue>,
    /// Where a number may be set (None for a switch or a name).
    pub range: Option<Range>,
    /// The values menus offer, when a list suits it better than a slider.
    pub offered: &'static [f64],
    /// The names a name setting may hold, in the order menus list them (empty: any name,
    /// checked by the setting's reader, as a level's or a controller's).
    pub choices: &'static [&'static str],
    pub owner: Owner,
    /// Whether players see it: kept in their settings file.
    pub player: bool,
    /// The menu group it is shown in: a player's ("Riding", "View", "Sound") in the pause
    /// menu, "Lab" for the research tools (the Lab panel of the start and pause menus);
    /// "": not shown.
    pub menu: &'static str,
}

impl Setting {
    /// The default as a number (0 for a name, 1 for true).
    pub const fn default_number(&self) -> f64 {
        match self.default {
            DefaultValue::Bool(on) => on as i64 as f64,
            DefaultValue::Int(n) => n as f64,
            DefaultValue::Float(x) => x,
            DefaultValue::Text(_) => 0.0,
        }
    }

    /// What a player's settings start from: `player_default`, or the default.
    pub const fn player_start(&self) -> DefaultValue {
        match self.player_default {
            Some(start) => start,
            None => self.default,
        }
    }

    /// The range of a number setting; a switch or a name has none and this panics at
    /// compile time when used in a constant.
    pub const fn limit(&self) -> Range {
        match self.range {
            Some(range) => range,
            None => panic!("the setting has no range"),
        }
    }

    /// `text` as this setting's value (a tool's command line): `true` or `false` for a
    /// switch, a number for a number, the name itself for a name; checked as `check`
    /// checks, so a value out of range is refused rather than clamped.
    pub fn parse(&self, text: &str) -> Result<Value, String> {
        let value = match self.default {
            DefaultValue::Bool(_) => match text {
                "true" => Value::Bool(true),
                "false" => Value::Bool(false),
                _ => return Err(format!("{} is true or false, not '{text}'", self.name)),
            },
            DefaultValue::Int(_) => Value::Int(
                text.parse()
                    .map_err(|_| format!("{} takes a whole number, not '{text}'", self.name))?,
            ),
            DefaultValue::Float(_) => Value::Float(
                text.parse()
                    .map_err(|_| format!("{} takes a number, not '{text}'", self.name))?,
            ),
            DefaultValue::Text(_) => Value::Text(text.to_owned()),
        };
        self.check(&value)?;
        Ok(value)
    }

    /// Whether `value` may be this setting's value: the right type, and a number within
    /// the range.
    pub fn check(&self, value: &Value) -> Result<(), String> {
        let in_range = |x: f64| match self.range {
            Some(r) if !(x.is_finite() && (r.min..=r.max).contains(&x)) => Err(format!(
                "{} must be within {}–{}{}, not {x}",
                self.name,
                r.min,
                r.max,
                unit_suffix(self.unit)
            )),
            _ => Ok(()),
        };
        match (self.default, value) {
            (DefaultValue::Bool(_), Value::Bool(_)) => Ok(()),
            (DefaultValue::Text(_), Value::Text(name)) => {
                if self.choices.is_empty() || self.choices.contains(&name.as_str()) {
                    Ok(())
                } else {
                    Err(format!(
                        "{} is one of {}, not '{name}'",
                        self.name,
                        self.choices.join(", ")
                    ))
                }
            }
            (DefaultValue::Int(_), Value::Int(n)) => in_range(*n as f64),
            (DefaultValue::Float(_), Value::Float(x)) => in_range(*x),
            _ => Err(format!(
                "{} takes {}, not {value:?}",
                self.name,
                Value::from(self.default).type_name()
            )),
        }
    }
}

fn unit_suffix(unit: &str) -> String {
    match unit {
        "" | "share" => String::new(),
        unit => format!(" {unit}"),
    }
}
