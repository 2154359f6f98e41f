//! `BikeSimulation`'s contact with the ground as the game's effects read it: each tyre's
//! contact and slide (tyre marks, smoke), where the bike itself scrapes the road (sparks),
//! and the gravity the grip is measured against.

use glam::DVec3;
use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

/// A point (global) with a speed (m/s) as its fourth number.
fn point_and_speed(p: DVec3, speed: f64) -> Vector4 {
    Vector4::new(p.x as f32, p.y as f32, p.z as f32, speed as f32)
}

#[godot_api(secondary)]
impl BikeSimulation {
    /// Each tyre's lowest point (global), rear then front, and how fast it slides over the
    /// ground (m/s) as its fourth number: what tyre marks and smoke answer. The tyres'
    /// friction is the bike description's `tyre_friction`.
    #[func]
    fn get_tyres(&self) -> Array<Vector4> {
        let Some(s) = self.sim() else {
            return Array::new();
        };
        let (bike, up) = (s.bike(), s.up());
        let (rear, front) = bike.tyre_contacts(s.world(), up);
        let (rear_slip, front_slip) = bike.tyre_slip_speeds(s.world(), up);
        Array::from(&[
            point_and_speed(rear, rear_slip),
            point_and_speed(front, front_slip),
        ])
    }

    /// Where the bike itself (not a tyre, not the rider) touched the ground in the last
    /// step, one point (global) a body, each with how fast it slides there (m/s) as its
    /// fourth number: what throws sparks. Empty while only the tyres touch.
    #[func]
    fn get_scrapes(&self) -> Array<Vector4> {
        let Some(s) = self.sim() else {
            return Array::new();
        };
        s.bike()
            .scrapes(s.world(), s.up())
            .into_iter()
            .map(|(at, speed)| point_and_speed(at, speed))
            .collect()
    }

    /// The simulation's gravity (m/s²).
    #[func]
    fn get_gravity(&self) -> f64 {
        self.sim().map_or(0.0, |s| s.config().gravity.length())
    }
}
