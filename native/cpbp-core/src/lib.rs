//! Counter-Steer's native core: everything that simulates or decides, with no Godot types,
//! so it is tested with `cargo test` and reused by benchmarks and headless experiments.

pub mod benchmark_bicycle;
pub mod bike;
mod build_info;
pub mod control;
pub mod grounds;
pub mod physics;
mod resource_file;
pub mod ride;
pub mod settings;
pub mod simulation;
pub mod terrain;

pub use build_info::{build_info, platform, BuildInfo, Platform};
pub use cpbp_ode as ode;
