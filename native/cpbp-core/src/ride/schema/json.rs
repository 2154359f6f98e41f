//! The schema as JSON, for readers outside Rust: the Python tools read it from
//! tools/cpbp_experiment/settings.json, which a test holds equal to this.

use serde_json::{json, Value as Json};

use super::all;
use crate::settings::{DefaultValue, Setting, AUTO_TRAJECTORY_RANGE};

fn entry(setting: &Setting) -> Json {
    let (kind, default) = match setting.default {
        DefaultValue::Bool(on) => ("bool", json!(on)),
        DefaultValue::Int(n) => ("int", json!(n)),
        DefaultValue::Float(x) => ("float", json!(x)),
        DefaultValue::Text(name) => ("text", json!(name)),
    };
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
