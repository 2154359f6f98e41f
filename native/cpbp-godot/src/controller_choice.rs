//! The controller as Godot sees it: a property holding one of the registry's names
//! ("combined"), shown in the inspector as a drop-down of every registered controller, so
//! settings files, the HUD, the menus and the experiment's CSV all spell a controller one
//! way and a new controller needs no line here.

use std::borrow::Cow;

use cpbp_core::ride::ControllerKind;
use godot::meta::conv::ByValue;
use godot::meta::error::ConvertError;
use godot::meta::shape::{EnumeratorShape, GodotShape};
use godot::meta::{GodotConvert, ToArg};
use godot::prelude::*;
use godot::register::property::{Export, Var};

/// A registered controller across the Godot boundary, passed by its name. A name the
/// registry does not know is refused with an error naming the ones it does, and the
/// property keeps its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ControllerChoice(pub ControllerKind);

impl GodotConvert for ControllerChoice {
    type Via = GString;

    fn godot_shape() -> GodotShape {
        GodotShape::Enum {
            variant_type: VariantType::STRING,
            enumerators: Cow::Owned(
                ControllerKind::all()
                    .iter()
                    .map(|kind| EnumeratorShape::new_string(kind.name()))
                    .collect(),
            ),
            godot_name: None,
            is_bitfield: false,
        }
    }
}

impl ToGodot for ControllerChoice {
    type Pass = ByValue;

    fn to_godot(&self) -> ToArg<'_, GString, ByValue> {
        GString::from(self.0.name())
    }
}

impl FromGodot for ControllerChoice {
    fn try_from_godot(name: GString) -> Result<Self, ConvertError> {
        kind_named(&name).map(Self).ok_or_else(|| {
            let known: Vec<&str> = ControllerKind::all().iter().map(|k| k.name()).collect();
            ConvertError::new(format!(
                "no controller is called \"{name}\" (the registry has {})",
                known.join(", ")
            ))
        })
    }
}

impl Var for ControllerChoice {
    type PubType = Self;

    fn var_get(field: &Self) -> GString {
        field.to_godot()
    }

    /// A name the registry does not know (a typo in a scene, an old settings file) is
    /// reported, and the controller stays as it was.
    fn var_set(field: &mut Self, name: GString) {
        match Self::try_from_godot(name) {
            Ok(choice) => *field = choice,
            Err(refusal) => godot_error!("BikeSimulation.controller: {refusal}"),
        }
    }

    fn var_pub_get(field: &Self) -> Self {
        *field
    }

    fn var_pub_set(field: &mut Self, value: Self) {
        *field = value;
    }
}

impl Export for ControllerChoice {}

/// The registry's names of the controllers players pick, in menu order.
pub fn offered_names() -> PackedStringArray {
    offered_names_where(|_| true)
}

/// The controllers players pick that `usable` lets through, by name, in the menus' order.
pub fn offered_names_where(usable: impl Fn(ControllerKind) -> bool) -> PackedStringArray {
    ControllerKind::all()
        .into_iter()
        .filter(|k| k.offered() && usable(*k))
        .map(|k| GString::from(k.name()))
        .collect()
}

/// The controller named `name`, if there is one.
pub fn kind_named(name: &GString) -> Option<ControllerKind> {
    ControllerKind::from_name(&name.to_string())
}
