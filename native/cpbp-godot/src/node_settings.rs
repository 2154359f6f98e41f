//! The settings schema's entries as Godot properties: the game node carries the ride's
//! and the planners' settings as properties listed from the schema (name, type, range,
//! unit, default to revert to), so the inspector, scenes and scripts reach each of them
//! with no field written out for it. The schema itself goes to GDScript as dictionaries.

use cpbp_core::ride::schema;
use cpbp_core::settings::{DefaultValue, Range, Setting, SettingValues, Value};
use godot::prelude::*;
use godot::register::info::{PropertyHint, PropertyHintInfo, PropertyInfo, PropertyUsageFlags};

/// The settings the game node holds, at their defaults.
pub(crate) fn node_settings() -> SettingValues {
    schema::values_of(|s| s.owner.on_the_node() && !matches!(s.default, DefaultValue::Text(_)))
}

pub(crate) fn to_variant(value: &Value) -> Variant {
    match value {
        Value::Bool(on) => on.to_variant(),
        Value::Int(n) => n.to_variant(),
        Value::Float(x) => x.to_variant(),
        Value::Text(name) => GString::from(name.as_str()).to_variant(),
    }
}

/// A variant as a setting's value (None for a type no setting takes).
pub(crate) fn from_variant(value: &Variant) -> Option<Value> {
    match value.get_type() {
        VariantType::BOOL => value.try_to::<bool>().ok().map(Value::Bool),
        VariantType::INT => value.try_to::<i64>().ok().map(Value::Int),
        VariantType::FLOAT => value.try_to::<f64>().ok().map(Value::Float),
        VariantType::STRING | VariantType::STRING_NAME => {
            Some(Value::Text(value.stringify().to_string()))
        }
        _ => None,
    }
}

fn variant_type(setting: &Setting) -> VariantType {
    match setting.default {
        DefaultValue::Bool(_) => VariantType::BOOL,
        DefaultValue::Int(_) => VariantType::INT,
        DefaultValue::Float(_) => VariantType::FLOAT,
        DefaultValue::Text(_) => VariantType::STRING,
    }
}

/// The inspector's range hint of a number in `range`, with `unit` after it ("share", a
/// 0–1 fraction, shows none). Settings and bike fields both use it.
pub(crate) fn range_hint(range: Range, unit: &str) -> PropertyHintInfo {
    let suffix = match unit {
        "" | "share" => String::new(),
        unit => format!(",suffix:{unit}"),
    };
    let hint = format!("{},{},{}{suffix}", range.min, range.max, range.step);
    PropertyHintInfo {
        hint: PropertyHint::RANGE,
        hint_string: GString::from(hint.as_str()),
    }
}

/// The inspector's properties for `values`, under a group per owner.
pub(crate) fn property_list(values: &SettingValues) -> Vec<PropertyInfo> {
    let mut list = Vec::new();
    let mut group = "";
    for setting in values.settings() {
        if setting.owner.name() != group {
            group = setting.owner.name();
            let title = format!("{}{} settings", &group[..1].to_uppercase(), &group[1..]);
            list.push(PropertyInfo::new_group(&title, ""));
        }
        list.push(PropertyInfo {
            variant_type: variant_type(setting),
            class_name: StringName::default(),
            property_name: setting.name.into(),
            hint_info: setting
                .range
                .map_or_else(PropertyHintInfo::none, |r| range_hint(r, setting.unit)),
            usage: PropertyUsageFlags::DEFAULT,
        });
    }
    list
}

/// The schema as GDScript reads it: one dictionary per setting.
pub(crate) fn schema_dictionaries() -> Array<VarDictionary> {
    schema::all().iter().map(dictionary).collect()
}

fn dictionary(setting: &Setting) -> VarDictionary {
    let mut entry = VarDictionary::new();
    entry.set("name", &StringName::from(setting.name));
    entry.set("label", setting.label);
    entry.set("description", setting.description);
    entry.set("unit", setting.unit);
    entry.set("default", &to_variant(&Value::from(setting.default)));
    entry.set("owner", setting.owner.name());
    entry.set("player", setting.player);
    if let Some(start) = setting.player_default {
        entry.set("player_default", &to_variant(&Value::from(start)));
    }
    entry.set("menu", setting.menu);
    if let Some(range) = setting.range {
        entry.set("min", range.min);
        entry.set("max", range.max);
        entry.set("step", range.step);
    }
    entry.set("offered", &PackedFloat64Array::from(setting.offered));
    let choices: PackedStringArray = setting.choices.iter().map(|c| GString::from(*c)).collect();
    entry.set("choices", &choices);
    entry
}
