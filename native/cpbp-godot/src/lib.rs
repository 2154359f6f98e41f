//! Counter-Steer's GDExtension entry point: the Godot classes that wrap `cpbp-core`.

mod bike_description;
mod bike_events;
mod bike_foot;
mod bike_ground;
mod bike_horizon;
mod bike_queries;
mod bike_rewind;
mod bike_rider;
mod bike_settings;
mod bike_shape;
mod bike_simulation;
mod bike_synth;
mod controller_choice;
mod convert;
mod log_field_description;
mod native_info;
mod node_settings;
mod ode_world;
mod physics_choice;
mod plan_handover;
mod policy_model;
mod settings_schema;
mod terrain_check;
mod terrain_import;

use godot::prelude::*;

struct CounterSteerExtension;

// SAFETY: this is the one entry point of the library; gdext's macro generates the
// `gdext_rust_init` symbol named in addons/cpbp/cpbp.gdextension.
#[gdextension]
unsafe impl ExtensionLibrary for CounterSteerExtension {}
