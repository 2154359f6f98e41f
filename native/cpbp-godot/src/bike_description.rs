//! `BikeDescription`: a bike as data, a resource file a level designer or a modder
//! edits in the inspector (bikes/*.tres). `BikeSimulation.bike` takes one; a second bike
//! is a second file. Its defaults are the core's reference bike (`BikeParams::default()`);
//! the Rust tools read the same file through `cpbp_core::bike::read_bike_file`.
//! Its looks (paint, bodywork) are the drawing's alone and its engine (`engine`, one of
//! `cpbp_sound`'s layouts) the sound's: the core never sees them.

use cpbp_core::bike::{BikeField, BikeParams, FIELDS};
use cpbp_sound::layout::EngineLayout;
use godot::classes::{ClassDb, IResource, Resource};
use godot::prelude::*;
use godot::register::info::{PropertyHint, PropertyHintInfo, PropertyInfo, PropertyUsageFlags};

use crate::node_settings::range_hint;

/// The reference bike's paint.
const STREET_ORANGE: Color = Color::from_rgb(0.92, 0.35, 0.08);

/// Dimensions, masses and equipment of a bike and its rider: every number of the core's
/// `BikeParams` is a property, listed from the core's bike fields (`cpbp_core::bike::
/// FIELDS`: name, unit, range), the parts' numbers grouped under suspension/, front_brake/,
/// wheelie_control/, feet/ and rider/.
#[derive(GodotClass)]
#[class(base=Resource)]
pub struct BikeDescription {
    /// The bike's name, for people: messages about the bike name it by this.
    #[export]
    name: GString,
    /// Springs and dampers at the fork and the swingarm (off: the thesis's rigid bike,
    /// which then has no anti-wheelie, feet or front brake either).
    #[export]
    suspension: bool,
    /// The colour of the tank and the bodywork.
    #[export]
    paint: Color,
    /// The bodywork drawn on the frame (a `BikeBodywork` resource, fitted to this bike's
    /// size); none draws the standard naked bodywork.
    #[export]
    bodywork: Option<Gd<Resource>>,
    /// How the engine is built, for its sound (`engine/layout`, an `EngineLayout::name`:
    /// four_stroke_single, …); listed from the layouts, so not an `#[export]`.
    engine: String,
    /// One number per bike field, in the field's file unit, as set (checked when built).
    numbers: Vec<f64>,
    /// Properties set that are neither a bike field nor one Godot knows (a field
    /// misspelled, or one from a newer build): the bike is refused naming them, where
    /// Godot would drop them without a word.
    unknown: Vec<String>,
    base: Base<Resource>,
}

/// Each field's value on the reference bike (every part present).
fn reference_numbers() -> Vec<f64> {
    let reference = BikeParams::default();
    FIELDS
        .iter()
        .map(|f| f.value(&reference).unwrap_or(f.range.min))
        .collect()
}

fn index_of(property: &StringName) -> Option<usize> {
    let name = property.to_string();
    FIELDS.iter().position(|f| f.name == name)
}

#[godot_api]
impl IResource for BikeDescription {
    fn init(base: Base<Resource>) -> Self {
        Self {
            name: GString::from("Street 350"),
            suspension: BikeParams::default().suspension.is_some(),
            paint: STREET_ORANGE,
            bodywork: None,
            engine: EngineLayout::default().name.to_owned(),
            numbers: reference_numbers(),
            unknown: Vec::new(),
            base,
        }
    }

    fn on_get_property_list(&mut self) -> Vec<PropertyInfo> {
        let engine = PropertyInfo {
            variant_type: VariantType::STRING,
            class_name: StringName::default(),
            property_name: ENGINE.into(),
            hint_info: PropertyHintInfo {
                hint: PropertyHint::ENUM,
                hint_string: EngineLayout::names().as_str().into(),
            },
            usage: PropertyUsageFlags::DEFAULT,
        };
        // Beside the engine's numbers, so the inspector groups them under one heading.
        let mut properties: Vec<PropertyInfo> = FIELDS.iter().map(field_property).collect();
        let at = FIELDS
            .iter()
            .position(|f| f.name.starts_with("engine/"))
            .unwrap_or(properties.len());
        properties.insert(at, engine);
        properties
    }

    fn on_get(&self, property: StringName) -> Option<Variant> {
        if property == ENGINE {
            return Some(self.engine.to_variant());
        }
        index_of(&property).map(|i| field_variant(i, self.numbers[i]))
    }

    fn on_set(&mut self, property: StringName, value: Variant) -> bool {
        if property == ENGINE {
            // Kept as given, an unknown one too: `problem` names it.
            self.engine = value.try_to::<String>().unwrap_or_default();
            return true;
        }
        let Some(i) = index_of(&property) else {
            let name = property.to_string();
            if !godot_knows(&name) && !self.unknown.contains(&name) {
                self.unknown.push(name);
            }
            return false;
        };
        // Kept as given, a bad one too: building the bike refuses it, naming the field.
        self.numbers[i] = match value.try_to::<bool>() {
            Ok(on) if FIELDS[i].is_switch() => f64::from(u8::from(on)),
            _ => value.try_to::<f64>().unwrap_or(f64::NAN),
        };
        true
    }

    fn on_property_get_revert(&self, property: StringName) -> Option<Variant> {
        if property == ENGINE {
            return Some(EngineLayout::default().name.to_variant());
        }
        index_of(&property).map(|i| field_variant(i, reference_numbers()[i]))
    }
}

/// The property naming the engine's layout, in the inspector beside the engine's numbers.
const ENGINE: &str = "engine/layout";

/// Bike field `f` as an inspector property: a switch, or a number in its range and unit.
fn field_property(f: &BikeField) -> PropertyInfo {
    PropertyInfo {
        variant_type: if f.is_switch() {
            VariantType::BOOL
        } else {
            VariantType::FLOAT
        },
        class_name: StringName::default(),
        property_name: f.name.into(),
        hint_info: if f.is_switch() {
            PropertyHintInfo::none()
        } else {
            range_hint(f.range, f.unit)
        },
        usage: PropertyUsageFlags::DEFAULT,
    }
}

/// Whether `name` is a property Godot itself sets on a bike description: the exported
/// ones (`name`, `paint`, …), a resource's own and an object's metadata.
fn godot_knows(name: &str) -> bool {
    name.starts_with("metadata/")
        || ClassDb::singleton()
            .class_get_property_list("BikeDescription")
            .iter_shared()
            .any(|property| property.get("name").is_some_and(|n| n.to_string() == name))
}

/// Field `i`'s value as the inspector and the file show it: a bool for an on/off field.
fn field_variant(i: usize, number: f64) -> Variant {
    if FIELDS[i].is_switch() {
        (number != 0.0).to_variant()
    } else {
        number.to_variant()
    }
}

#[godot_api]
impl BikeDescription {
    /// Why this bike cannot be built (a number out of its field's range, or a geometry
    /// the core refuses), naming the bike and the field; empty when it can.
    #[func]
    fn problem(&self) -> GString {
        match self.params().and(self.engine()) {
            Ok(_) => GString::new(),
            Err(why) => GString::from(&format!("{}: {why}", self.name)),
        }
    }

    /// The figures a menu quotes, as the core builds the bike (empty when it cannot):
    /// `mass_kg` (the bike without its rider), `power_kw` (at the rear wheel; 0 for no
    /// limit), `max_lean_deg`, `wheelbase_m`, `front_travel_mm`, `rear_travel_mm` (0 on a
    /// rigid bike), `tyre_friction`.
    #[func]
    fn figures(&self) -> VarDictionary {
        let Ok(bike) = self.params() else {
            return VarDictionary::new();
        };
        let travel = |pick: fn(&cpbp_core::bike::Suspension) -> f64| {
            bike.suspension.as_ref().map_or(0.0, |s| pick(s) * 1000.0)
        };
        vdict! {
            "mass_kg" => bike.bike_mass(),
            "power_kw" => bike.rear_drive.max_power_kw,
            "max_lean_deg" => bike.max_lean.to_degrees(),
            "wheelbase_m" => bike.wheelbase,
            "front_travel_mm" => travel(|s| s.front_travel),
            "rear_travel_mm" => travel(|s| s.rear_travel),
            "tyre_friction" => bike.tyre_friction,
        }
    }
}

impl BikeDescription {
    /// The engine's layout, or why the file's is none of them.
    pub fn engine(&self) -> Result<EngineLayout, String> {
        EngineLayout::named(&self.engine).ok_or_else(|| {
            format!(
                "engine '{}' is not one of {}",
                self.engine,
                EngineLayout::names().replace(',', ", ")
            )
        })
    }

    /// The bike's name, for people.
    pub fn name(&self) -> GString {
        self.name.clone()
    }

    /// The bike as the core builds it, or why it cannot be built (a number out of its
    /// field's range, or a geometry the core refuses), naming the field.
    pub fn params(&self) -> Result<BikeParams, String> {
        if !self.unknown.is_empty() {
            return Err(format!(
                "{} not a bike field of this build (misspelled, or from a newer one)",
                quoted_list(&self.unknown)
            ));
        }
        let values = FIELDS
            .iter()
            .map(|f| f.name)
            .zip(self.numbers.iter().copied());
        BikeParams::from_fields(values, self.suspension)
    }
}

/// The bike `description` describes (the reference bike for none), or why it cannot be
/// built, naming its file.
pub fn params_of(description: Option<&Gd<BikeDescription>>) -> Result<BikeParams, String> {
    match description {
        Some(description) => description
            .bind()
            .params()
            .map_err(|why| format!("the bike {}: {why}", description.get_path())),
        None => Ok(BikeParams::default()),
    }
}

/// `'a'`, `'a' and 'b' are`, `'a', 'b' and 'c' are`: the subject of a sentence.
fn quoted_list(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("'{n}'")).collect();
    match quoted.split_last() {
        Some((last, [])) => format!("{last} is"),
        Some((last, rest)) => format!("{} and {last} are", rest.join(", ")),
        None => String::new(),
    }
}
