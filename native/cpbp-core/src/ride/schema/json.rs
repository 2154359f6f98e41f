//! The schema as JSON, for readers outside Rust: the Python tools read it from
//! tools/cpbp_experiment/settings.json, which a test holds equal to this.

use serde_json::{json, Value as Json};

use super::all;
use crate::settings::{DefaultValue, Setting, AUTO_TRAJECTORY_RANGE};

fn kind_of(default: DefaultValue) -> &'static str {
    match default {
        DefaultValue::Bool(_) => "bool",
        DefaultValue::Int(_) => "int",
        DefaultValue::Float(_) => "float",
        DefaultValue::Text(_) => "text",
    }
}

fn json_of(default: DefaultValue) -> Json {
    match default {
        DefaultValue::Bool(on) => json!(on),
        DefaultValue::Int(n) => json!(n),
        DefaultValue::Float(x) => json!(x),
        DefaultValue::Text(name) => json!(name),
    }
}

fn entry(setting: &Setting) -> Json {
    let (kind, default) = (kind_of(setting.default), json_of(setting.default));
    let mut entry = json!({
        "name": setting.name,
        "label": setting.label,
        "description": setting.description,
        "unit": setting.unit,
        "type": kind,
        "default": default,
        "owner": setting.owner.name(),
        "player": setting.player,
        "menu": setting.menu,
    });
    if let Some(range) = setting.range {
        entry["range"] = json!([range.min, range.max, range.step]);
    }
    if let Some(start) = setting.player_default {
        entry["player_default"] = json_of(start);
    }
    if !setting.offered.is_empty() {
        entry["offered"] = json!(setting.offered);
    }
    if !setting.choices.is_empty() {
        entry["choices"] = json!(setting.choices);
    }
    entry
}

/// Every setting (the compiled entries, the registered planners' parameters and any added
/// at run time), one JSON object per line in a list, and the automatic trajectory choice's range.
pub fn schema_json() -> String {
    let lines: Vec<String> = all().iter().map(|s| format!("    {}", entry(s))).collect();
    let auto = AUTO_TRAJECTORY_RANGE;
    format!(
        "{{\n  \"settings\": [\n{}\n  ],\n  \"auto_trajectories\": [{}, {}]\n}}\n",
        lines.join(",\n"),
        auto.min,
        auto.max
    )
}
