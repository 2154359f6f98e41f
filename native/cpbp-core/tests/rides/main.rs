//! The controllers' rides: minutes of planning, fast only in a release build (`make test`
//! runs them there; debug builds skip the planners' rides).
//!
//! One test binary rather than one per file: every integration test is linked on its
//! own, and with the release profile's thin LTO that took about 25 s of a core per file,
//! 16 files' worth of it per CI run. `auto_trajectories` stays a binary of its own: it
//! loads every core and needs the machine to itself once the load goes.

#[path = "../common/mod.rs"]
mod common;

mod air_control;
mod anytime;
mod arcade_gains;
mod braked_turn;
mod camber_feet;
mod contact_patch;
mod deep_lean;
mod engine;
mod every_bike;
mod falling_off;
mod feet;
mod front_brake;
mod learned;
mod optimizer;
mod physics_models;
mod reproducible;
mod ride;
mod rider_position;
mod sampling_planners;
mod stopping;
mod street_brakes;
mod suspension;
mod wheelie_control;
mod wrists;
