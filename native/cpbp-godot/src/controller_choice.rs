//! The controller as Godot sees it: a real enum, shown in the inspector and passed to and
//! from GDScript as the registry's stable names ("combined"), so settings files, the HUD,
//! the menus and the experiment's CSV all spell a controller one way.

use cpbp_core::ride::ControllerKind;
use godot::prelude::*;

/// `cpbp_core::ride::ControllerKind` across the Godot boundary. The variants are spelled
/// as the registry names them because gdext passes them to Godot by their identifiers;
/// tests/native/test_bike_simulation.gd holds the two lists equal.
#[derive(GodotConvert, Var, Export, Clone, Copy, Debug, PartialEq, Eq)]
#[godot(via = GString)]
#[allow(non_camel_case_types)]
pub enum BikeController {
    optimizer,
    combined,
    arcade,
    sampling,
    mppi,
    manual,
}

impl From<BikeController> for ControllerKind {
    fn from(choice: BikeController) -> Self {
        match choice {
            BikeController::optimizer => ControllerKind::Optimizer,
            BikeController::combined => ControllerKind::Combined,
            BikeController::arcade => ControllerKind::Arcade,
            BikeController::sampling => ControllerKind::Sampling,
            BikeController::mppi => ControllerKind::Mppi,
            BikeController::manual => ControllerKind::Manual,
        }
    }
}

impl From<ControllerKind> for BikeController {
    fn from(kind: ControllerKind) -> Self {
        match kind {
            ControllerKind::Optimizer => BikeController::optimizer,
            ControllerKind::Combined => BikeController::combined,
            ControllerKind::Arcade => BikeController::arcade,
            ControllerKind::Sampling => BikeController::sampling,
            ControllerKind::Mppi => BikeController::mppi,
            ControllerKind::Manual => BikeController::manual,
        }
    }
}

/// The registry's names of the controllers players pick, in menu order.
pub fn offered_names() -> PackedStringArray {
    ControllerKind::ALL
        .iter()
        .filter(|k| k.offered())
        .map(|k| GString::from(k.name()))
        .collect()
}

/// The controller named `name`, if there is one.
pub fn kind_named(name: &GString) -> Option<ControllerKind> {
    ControllerKind::from_name(&name.to_string())
}
