//! A log field file (a Godot `LogFieldDescription` resource, .tres) read without Godot,
//! so the trainer and the scenario tool lay the logs the level lays: the `[resource]`
//! section's `key = value` lines; a key the file leaves out keeps `LogField::default()`,
//! as Godot leaves out a property at its default.

use super::log_field::LogField;
use crate::resource_file::resource_properties;

/// The most logs a field may hold (the editor's range too).
pub const MAX_LOGS: usize = 200;

/// A log field file's text as a field, checked; the error names the key.
pub fn parse_log_field(text: &str) -> Result<LogField, String> {
    let mut field = LogField::default();
    for (key, value) in resource_properties(text, "LogFieldDescription")? {
        match key {
            "area" => field.area = pair(key, value)?,
            "radius_range" => field.radius = pair(key, value)?,
            "length_range" => field.length = pair(key, value)?,
            "count" => {
                field.count = value
                    .parse()
                    .map_err(|_| format!("count must be a whole number, not {value}"))?;
            }
            "max_angle_deg" => field.max_angle_deg = number(key, value)?,
            "script" | "resource_name" => {}
            other => return Err(format!("a log field has no {other}")),
        }
    }
    check(&field)?;
    Ok(field)
}

/// Refuses a field no level could hold, naming what is wrong.
pub fn check(field: &LogField) -> Result<(), String> {
    let ordered = |name: &str, [low, high]: [f32; 2], least: f32| {
        if low.is_finite() && high.is_finite() && least <= low && low <= high {
            Ok(())
        } else {
            Err(format!(
                "{name} must run from at least {least} upwards, not {low}–{high}"
            ))
        }
    };
    ordered("radius_range", field.radius, 0.005)?;
    ordered("length_range", field.length, 0.01)?;
    if !(field.area.iter().all(|a| a.is_finite() && *a >= 0.5)) {
        return Err(format!(
            "area must be at least 0.5 m each way, not {:?}",
            field.area
        ));
    }
    if field.count > MAX_LOGS {
        return Err(format!(
            "count must be at most {MAX_LOGS}, not {}",
            field.count
        ));
    }
    if !(0.0..=90.0).contains(&field.max_angle_deg) {
        return Err(format!(
            "max_angle_deg must be within 0–90, not {}",
            field.max_angle_deg
        ));
    }
    Ok(())
}

fn number(key: &str, value: &str) -> Result<f32, String> {
    value
        .parse()
        .map_err(|_| format!("{key} must be a number, not {value}"))
}

/// `Vector2(a, b)` as Godot writes it.
fn pair(key: &str, value: &str) -> Result<[f32; 2], String> {
    let inner = value
        .strip_prefix("Vector2(")
        .and_then(|v| v.strip_suffix(')'))
        .ok_or(format!("{key} must be a Vector2(a, b), not {value}"))?;
    let (a, b) = inner
        .split_once(',')
        .ok_or(format!("{key} must be a Vector2(a, b), not {value}"))?;
    Ok([number(key, a.trim())?, number(key, b.trim())?])
}
