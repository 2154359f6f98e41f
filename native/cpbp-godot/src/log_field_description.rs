//! `LogFieldDescription`: a field of logs as data (a resource file, e.g. the test level's
//! scenes/levels/test_level/log_field.tres). A `BumpField` node lays its logs from one;
//! the trainer and the scenario tool read the same file (`cpbp_core::grounds`), and the
//! core's generator lays the logs for all of them.

use cpbp_core::grounds::{check_log_field, LogField, MAX_LOGS};
use godot::classes::{IResource, Resource};
use godot::prelude::*;

/// Where a field's logs fall and how big they are; its defaults are the core's
/// (`LogField::default()`).
#[derive(GodotClass)]
#[class(tool, base=Resource)]
pub struct LogFieldDescription {
    /// The area the logs' centres fall in (m): across the way (x) × along it (z).
    #[export]
    area: Vector2,
    /// How many logs.
    #[export(range = (0.0, 200.0, 1.0))]
    count: i32,
    /// Radius range (m); the logs are sunk to their axes, so this is their height.
    #[export]
    radius_range: Vector2,
    /// Length range (m).
    #[export]
    length_range: Vector2,
    /// The largest angle between a log and the line across the way (degrees).
    #[export(range = (0.0, 90.0, 0.5, suffix = "°"))]
    max_angle_deg: f32,
    base: Base<Resource>,
}

#[godot_api]
impl IResource for LogFieldDescription {
    fn init(base: Base<Resource>) -> Self {
        let field = LogField::default();
        Self {
            area: Vector2::new(field.area[0], field.area[1]),
            count: field.count as i32,
            radius_range: Vector2::new(field.radius[0], field.radius[1]),
            length_range: Vector2::new(field.length[0], field.length[1]),
            max_angle_deg: field.max_angle_deg,
            base,
        }
    }

    /// Tells whoever lays the logs (a `BumpField` in the editor) that the field changed,
    /// once the new value is in.
    fn on_set(&mut self, _property: StringName, _value: Variant) -> bool {
        self.base_mut().call_deferred("emit_changed", &[]);
        false
    }
}

#[godot_api]
impl LogFieldDescription {
    /// The logs seed `seed` lays, each a dictionary {radius, length, angle (rad), centre
    /// (Vector3 in the field's frame: x across, the way ahead −z)}; empty, with an error
    /// naming what is wrong, for a field no level could hold.
    #[func]
    fn layout(&self, seed: i64) -> Array<VarDictionary> {
        let field = self.field();
        if let Err(why) = check_log_field(&field) {
            godot_error!("log field {}: {why}", self.base().get_path());
            return Array::new();
        }
        field
            .layout(seed)
            .into_iter()
            .map(|log| {
                let [x, y, z] = log.centre;
                vdict! {
                    "radius" => log.radius,
                    "length" => log.length,
                    "angle" => log.angle,
                    "centre" => Vector3::new(x, y, z),
                }
            })
            .collect()
    }
}

impl LogFieldDescription {
    fn field(&self) -> LogField {
        LogField {
            area: [self.area.x, self.area.y],
            count: usize::try_from(self.count).unwrap_or(0).min(MAX_LOGS + 1),
            radius: [self.radius_range.x, self.radius_range.y],
            length: [self.length_range.x, self.length_range.y],
            max_angle_deg: self.max_angle_deg,
        }
    }
}
