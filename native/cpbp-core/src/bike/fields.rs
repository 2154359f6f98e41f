//! Every number of `BikeParams` as a named field of a bike file, with its unit, the range
//! the core builds a bike in and the scale from the file's unit to the model's (degrees
//! to radians, km/h to m/s). The game's `BikeDescription` lists these as its properties
//! and the Rust tools read a bike file (bikes/*.tres) through them (`bike_file.rs`), so a
//! bike means the same numbers on both sides. A field of a part the bike lacks (the
//! suspension's on a rigid bike) is kept in the file and not used.

use super::BikeParams;
use crate::settings::Range;

/// One number of a bike.
#[derive(Clone, Copy)]
pub struct BikeField {
    /// Its key in a bike file; "part/field" for a part's (the inspector groups them).
    pub name: &'static str,
    /// The file's unit.
    pub unit: &'static str,
    pub range: Range,
    /// From the file's unit to the model's.
    unit_change: UnitChange,
    get: fn(&BikeParams) -> Option<f64>,
    set: fn(&mut BikeParams, f64),
}

impl BikeField {
    /// Whether the field is on/off (1 or 0): a bike file and the inspector show it as a
    /// bool, `true` or `false`.
    pub fn is_switch(&self) -> bool {
        matches!(self.unit_change, UnitChange::Switch)
    }

    /// The field's value on `bike`, in the file's unit (None: the bike lacks the part).
    pub fn value(&self, bike: &BikeParams) -> Option<f64> {
        (self.get)(bike).map(|v| match self.unit_change {
            UnitChange::None | UnitChange::Switch => v,
            UnitChange::Degrees => v.to_degrees(),
            UnitChange::Kmh => v * 3.6,
        })
    }

    /// Sets the field on `bike` from a value in the file's unit, checked against its range.
    pub fn apply(&self, bike: &mut BikeParams, value: f64) -> Result<(), String> {
        let r = self.range;
        if !(value.is_finite() && (r.min..=r.max).contains(&value)) {
            let unit = if self.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", self.unit)
            };
            return Err(format!(
                "{} must be within {}–{}{unit}, not {value}",
                self.name, r.min, r.max
            ));
        }
        if matches!(self.unit_change, UnitChange::Switch) && value != 0.0 && value != 1.0 {
            return Err(format!("{} is 1 (on) or 0 (off), not {value}", self.name));
        }
        let value = match self.unit_change {
            UnitChange::None | UnitChange::Switch => value,
            UnitChange::Degrees => value.to_radians(),
            UnitChange::Kmh => value / 3.6,
        };
        (self.set)(bike, value);
        Ok(())
    }
}

/// How a file's number becomes the model's, written as the reference bike's literals
/// are (`25f64.to_radians()`, `30.0 / 3.6`): the reference file builds the bit-same bike.
#[derive(Clone, Copy)]
enum UnitChange {
    None,
    /// An on/off field: 1 on, 0 off (a bike file holds numbers), nothing in between.
    Switch,
    Degrees,
    Kmh,
}
use UnitChange::{Degrees as DEG, Kmh as KMH, None as SAME, Switch as ON_OFF};

macro_rules! field {
    ($name:literal, $unit:literal, $min:expr, $max:expr, $step:expr, $scale:expr, $($path:tt)+) => {
        BikeField {
            name: $name,
            unit: $unit,
            range: Range::new($min, $max, $step),
            unit_change: $scale,
            get: field!(@get $($path)+),
            set: field!(@set $($path)+),
        }
    };
    (@get [$index:literal]) => { |b: &BikeParams| Some(b.rider_masses[$index]) };
    (@set [$index:literal]) => { |b: &mut BikeParams, v| b.rider_masses[$index] = v };
    (@get $part:ident / $($field:ident).+) => {
        |b: &BikeParams| b.$part.as_ref().map(|p| p.$($field).+)
    };
    (@set $part:ident / $($field:ident).+) => {
        |b: &mut BikeParams, v| if let Some(p) = b.$part.as_mut() { p.$($field).+ = v; }
    };
    // A bool of the model, read and written as 1 or 0 (`ON_OFF`).
    (@get flag $part:ident / $field:ident) => {
        |b: &BikeParams| b.$part.as_ref().map(|p| if p.$field { 1.0 } else { 0.0 })
    };
    (@set flag $part:ident / $field:ident) => {
        |b: &mut BikeParams, v| if let Some(p) = b.$part.as_mut() { p.$field = v != 0.0; }
    };
    (@get flag $field:ident) => { |b: &BikeParams| Some(if b.$field { 1.0 } else { 0.0 }) };
    (@set flag $field:ident) => { |b: &mut BikeParams, v| b.$field = v != 0.0 };
    (@get $($field:ident).+) => { |b: &BikeParams| Some(b.$($field).+) };
    (@set $($field:ident).+) => { |b: &mut BikeParams, v| b.$($field).+ = v };
}

/// Every field, in the order the inspector shows them. Degrees convert exactly as the
/// reference bike's literals (`to_radians`) do: the reference file builds the bit-same bike.
pub const FIELDS: &[BikeField] = &[
    field! { "wheelbase", "m", 0.9, 2.0, 0.01, SAME, wheelbase },
    field! { "wheel_radius", "m", 0.15, 0.5, 0.005, SAME, wheel_radius },
    field! { "tyre_crown", "m", 0.02, 0.12, 0.005, SAME, tyre_crown },
    field! { "rake_deg", "°", 10.0, 40.0, 0.5, DEG, rake },
    field! { "trail", "m", 0.01, 0.2, 0.005, SAME, trail },
    field! { "frame_mass", "kg", 20.0, 300.0, 1.0, SAME, frame_mass },
    field! { "rear_wheel_mass", "kg", 2.0, 40.0, 0.5, SAME, rear_wheel_mass },
    field! { "front_wheel_mass", "kg", 2.0, 40.0, 0.5, SAME, front_wheel_mass },
    field! { "fork_mass", "kg", 1.0, 30.0, 0.5, SAME, fork_mass },
    field! { "fork_lower_mass", "kg", 0.5, 15.0, 0.5, SAME, fork_lower_mass },
    field! { "swingarm_mass", "kg", 1.0, 20.0, 0.5, SAME, swingarm_mass },
    field! { "steer_limit_deg", "°", 10.0, 60.0, 1.0, DEG, steer_limit },
    field! { "max_steer_torque", "N·m", 20.0, 200.0, 1.0, SAME, max_steer_torque },
    field! { "arcade_tuned_kmh", "km/h", 0.0, 100.0, 1.0, KMH, arcade_tuned_speed },
    field! { "tyre_friction", "", 0.3, 1.5, 0.05, SAME, tyre_friction },
    field! { "tyre_friction_follows_wheel", "", 0.0, 1.0, 1.0, ON_OFF, flag tyre_friction_follows_wheel },
    field! { "max_lean_deg", "°", 15.0, 60.0, 0.5, DEG, max_lean },
    field! { "planners_cost_frame_roll", "", 0.0, 1.0, 1.0, ON_OFF, flag planners_cost_frame_roll },
    field! { "planners_exact_from_lean_deg", "°", 15.0, 90.0, 0.5, DEG, planners_exact_from_lean },
    field! { "planners_slide_tolerance", "m/s", 0.0, 10.0, 0.1, SAME, planners_slide_tolerance },
    field! { "planners_grip_share", "", 0.0, 1.0, 0.01, SAME, planners_grip_share },
    field! { "planners_lean_reference", "", 0.0, 1.0, 1.0, ON_OFF, flag planners_lean_reference },
    field! { "planners_lean_lookahead", "", 0.0, 1.0, 1.0, ON_OFF, flag planners_lean_lookahead },
    field! { "planners_rider_hold", "", 0.0, 1.0, 0.01, SAME, planners_rider_hold },
    field! { "planners_rider_hold_speed", "m/s", 0.0, 30.0, 0.1, SAME, planners_rider_hold_speed },
    field! { "engine/max_torque", "N·m", 50.0, 3_000.0, 10.0, SAME, rear_drive.max_torque },
    field! { "engine/max_power_kw", "kW", 0.0, 300.0, 0.5, SAME, rear_drive.max_power_kw },
    field! { "rear_brake/max_torque", "N·m", 50.0, 3_000.0, 10.0, SAME, rear_drive.brake_torque },
    field! { "posture/footpeg_x", "m", -0.6, 0.4, 0.005, SAME, posture.footpeg.x },
    field! { "posture/footpeg_y", "m", 0.2, 0.7, 0.005, SAME, posture.footpeg.y },
    field! { "posture/hip_x", "m", -0.7, 0.3, 0.005, SAME, posture.hip.x },
    field! { "posture/hip_y", "m", 0.6, 1.2, 0.005, SAME, posture.hip.y },
    field! { "posture/torso_lean_deg", "°", -10.0, 60.0, 0.5, DEG, posture.torso_lean },
    field! { "posture/grip_height", "m", 0.7, 1.4, 0.005, SAME, posture.grip_height },
    field! { "posture/grip_behind_axis", "m", -0.1, 0.3, 0.005, SAME, posture.grip_behind_axis },
    field! { "rider/lower_leg_mass", "kg", 2.0, 30.0, 0.05, SAME, [0] },
    field! { "rider/upper_leg_mass", "kg", 4.0, 40.0, 0.05, SAME, [1] },
    field! { "rider/torso_mass", "kg", 15.0, 100.0, 0.05, SAME, [2] },
    field! { "rider/upper_arm_mass", "kg", 1.0, 12.0, 0.05, SAME, [3] },
    field! { "rider/lower_arm_mass", "kg", 1.0, 10.0, 0.05, SAME, [4] },
    field! { "rider/brace_share", "", 0.0, 1.0, 0.05, SAME, rider_brace },
    field! { "rider/wrists_follow_bar", "", 0.0, 1.0, 1.0, ON_OFF, flag rider_wrists_follow_bar },
    field! { "suspension/front_travel", "m", 0.05, 0.35, 0.005, SAME, suspension / front_travel },
    field! { "suspension/rear_travel", "m", 0.05, 0.35, 0.005, SAME, suspension / rear_travel },
    field! { "suspension/sag", "", 0.1, 0.5, 0.01, SAME, suspension / sag },
    field! { "suspension/rear_sag", "", 0.1, 0.5, 0.01, SAME, suspension / rear_sag },
    field! { "suspension/front_rate", "N/m", 2_000.0, 80_000.0, 500.0, SAME, suspension / front_rate },
    field! { "suspension/rear_rate", "N/m", 2_000.0, 100_000.0, 500.0, SAME, suspension / rear_rate },
    field! { "suspension/damping_ratio", "", 0.05, 1.5, 0.05, SAME, suspension / damping_ratio },
    field! { "front_brake/max_torque", "N·m", 50.0, 3_000.0, 10.0, SAME, front_brake / max_torque },
    field! { "front_brake/full_above", "m", 0.0, 0.1, 0.001, SAME, front_brake / full_above },
    field! { "front_brake/none_below", "m", 0.0, 0.1, 0.001, SAME, front_brake / none_below },
    field! { "front_brake/tipping_share", "", 0.0, 1.0, 0.01, SAME, front_brake / tipping_share },
    field! { "front_brake/tipping_lookahead", "s", 0.0, 1.0, 0.01, SAME, front_brake / tipping_lookahead },
    field! { "front_brake/ramp_time", "s", 0.0, 1.0, 0.01, SAME, front_brake / ramp_time },
    field! { "front_brake/cornering_lean_deg", "°", 0.0, 90.0, 0.5, DEG, front_brake / cornering_lean },
    field! { "front_brake/ease_below", "m/s", 0.0, 5.0, 0.1, SAME, front_brake / ease_below },
    field! { "front_brake/ease_to", "", 0.1, 1.0, 0.05, SAME, front_brake / ease_to },
    field! { "front_brake/righting_reserve", "", 0.0, 1.0, 1.0, ON_OFF, flag front_brake / righting_reserve },
    field! { "front_brake/hold_gain", "1/m", 0.0, 20.0, 0.1, SAME, front_brake / hold_gain },
    field! { "front_brake/hold_rate_gain", "s/m", 0.0, 10.0, 0.1, SAME, front_brake / hold_rate_gain },
    field! { "front_brake/rear_share", "", 0.0, 1.0, 0.05, SAME, front_brake / rear_share },
    field! { "front_brake/abs_slip", "", 0.01, 0.5, 0.01, SAME, front_brake / abs_slip },
    field! { "front_brake/abs_above", "m/s", 0.0, 10.0, 0.1, SAME, front_brake / abs_above },
    field! { "wheelie_control/full_torque_above", "m", 0.0, 0.1, 0.001, SAME, wheelie_control / full_torque_above },
    field! { "wheelie_control/no_torque_below", "m", 0.0, 0.1, 0.001, SAME, wheelie_control / no_torque_below },
    field! { "wheelie_control/hold_gain", "1/m", 0.0, 20.0, 0.1, SAME, wheelie_control / hold_gain },
    field! { "wheelie_control/hold_rate_gain", "s/m", 0.0, 10.0, 0.1, SAME, wheelie_control / hold_rate_gain },
    field! { "wheelie_control/hold_brake", "", 0.0, 1.0, 0.05, SAME, wheelie_control / hold_brake },
    field! { "wheelie_control/hold_headroom_kmh", "km/h", 0.0, 100.0, 1.0, KMH, wheelie_control / hold_headroom },
    field! { "wheelie_control/lift_upright_within_deg", "°", 0.0, 45.0, 0.5, DEG, wheelie_control / lift_upright_within },
    field! { "wheelie_control/lift_none_beyond_deg", "°", 0.0, 60.0, 0.5, DEG, wheelie_control / lift_none_beyond },
    field! { "wheelie_control/overrun_margin", "m/s", 0.0, 10.0, 0.1, SAME, wheelie_control / overrun_margin },
    field! { "wheelie_control/overrun_share", "", 0.0, 1.0, 0.05, SAME, wheelie_control / overrun_share },
    field! { "wheelie_control/air_share", "", 0.0, 1.0, 0.05, SAME, wheelie_control / air_share },
    field! { "feet/x", "m", -0.5, 0.5, 0.005, SAME, feet / right_foot.x },
    field! { "feet/y", "m", -0.3, 0.5, 0.005, SAME, feet / right_foot.y },
    field! { "feet/z", "m", 0.1, 0.8, 0.005, SAME, feet / right_foot.z },
    field! { "feet/radius", "m", 0.01, 0.2, 0.005, SAME, feet / radius },
    field! { "feet/friction", "", 0.1, 1.5, 0.05, SAME, feet / surface.mu },
    field! { "feet/stiffness", "N/m", 1_000.0, 500_000.0, 1_000.0, SAME, feet / surface.stiffness },
    field! { "feet/damping", "N·s/m", 10.0, 50_000.0, 10.0, SAME, feet / surface.damping },
    field! { "feet/down_below", "m/s", 0.0, 5.0, 0.05, SAME, feet / down_below },
    field! { "feet/straighten_rate", "1/s", 0.0, 30.0, 0.5, SAME, feet / straighten_rate },
    field! { "feet/reach", "m", 0.0, 0.6, 0.005, SAME, feet / reach },
    field! { "feet/prop_lean_deg", "°", 0.5, 15.0, 0.5, DEG, feet / prop_lean },
    field! { "feet/leg_speed", "m/s", 0.1, 5.0, 0.1, SAME, feet / leg_speed },
    field! { "feet/push_time", "s", 0.05, 5.0, 0.05, SAME, feet / push_time },
    field! { "feet/prop_until", "m/s", 0.0, 5.0, 0.05, SAME, feet / prop_until },
    field! { "feet/steady_reach", "", 0.0, 1.0, 1.0, ON_OFF, flag feet / steady_reach },
    field! { "feet/plumb_legs", "", 0.0, 1.0, 1.0, ON_OFF, flag feet / plumb_legs },
];

/// The field called `name`.
pub fn field(name: &str) -> Option<&'static BikeField> {
    FIELDS.iter().find(|f| f.name == name)
}

impl BikeParams {
    /// The reference bike with `values` (file keys and numbers in the file's units) set
    /// and `sprung` or rigid, checked field by field and then as a whole; the error names
    /// the field.
    pub fn from_fields<'a>(
        values: impl IntoIterator<Item = (&'a str, f64)>,
        sprung: bool,
    ) -> Result<BikeParams, String> {
        let mut bike = BikeParams::default();
        for (name, value) in values {
            let field = field(name).ok_or_else(|| format!("no bike field is called {name}"))?;
            field.apply(&mut bike, value)?;
        }
        let bike = if sprung { bike } else { bike.rigid() };
        bike.check()?;
        Ok(bike)
    }

    /// Whether the fields make a bike the core can build: the tyre's crown within the
    /// wheel, the steering axis between the wheels, the rider's legs and arms reaching
    /// its footpegs and grips, the front brake's (unless both are 0) and the
    /// anti-wheelie's thresholds in order.
    pub fn check(&self) -> Result<(), String> {
        if self.tyre_crown >= self.wheel_radius {
            return Err("tyre_crown must be smaller than wheel_radius".into());
        }
        if self.fork_offset() <= 0.0 {
            return Err(format!(
                "trail {} m is too long for rake_deg {}° and wheel_radius {} m: the fork \
                 would have no offset",
                self.trail,
                self.rake.to_degrees(),
                self.wheel_radius
            ));
        }
        super::layout::Layout::check_posture(self)?;
        if let Some(brake) = &self.front_brake {
            let window_off = brake.full_above == 0.0 && brake.none_below == 0.0;
            if brake.none_below >= brake.full_above && !window_off {
                return Err(
                    "front_brake/none_below must be below front_brake/full_above \
                            (both 0: no compression window)"
                        .into(),
                );
            }
        }
        if let Some(control) = &self.wheelie_control {
            if control.no_torque_below >= control.full_torque_above {
                return Err(
                    "wheelie_control/no_torque_below must be below full_torque_above".into(),
                );
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
