//! The physics model as Godot sees it: an enum shown in the inspector and passed to and
//! from GDScript by the core's stable names ("classic", "exact"), as the controller is.

use cpbp_core::physics::PhysicsModel;
use godot::prelude::*;

/// `cpbp_core::physics::PhysicsModel` across the Godot boundary, its variants spelled as
/// the core names them (gdext passes them by their identifiers); a test in
/// tests/native/test_bike_simulation.gd holds the two lists equal.
#[derive(GodotConvert, Var, Export, Clone, Copy, Debug, PartialEq, Eq)]
#[godot(via = GString)]
#[allow(non_camel_case_types)]
pub enum BikePhysics {
    classic,
    exact,
}

impl From<BikePhysics> for PhysicsModel {
    fn from(choice: BikePhysics) -> Self {
        match choice {
            BikePhysics::classic => PhysicsModel::Classic,
            BikePhysics::exact => PhysicsModel::Exact,
        }
    }
}

/// The core's names of every physics model.
pub fn names() -> PackedStringArray {
    PhysicsModel::ALL
        .iter()
        .map(|m| GString::from(m.name()))
        .collect()
}
