//! `OdeWorld`: a bare ODE world for tools and tests (spheres, planes, stepping).

use cpbp_core::ode::{BodyId, Mass, World};
use glam::DVec3;
use godot::prelude::*;

use crate::convert::{dvec3, vector3};

/// A bare ODE world: drop spheres onto planes and step it. The bike simulation has its own
/// node; this class is for tests, experiments and checking the native module works.
#[derive(GodotClass)]
#[class(base=RefCounted)]
pub struct OdeWorld {
    world: World,
    base: Base<RefCounted>,
}

#[godot_api]
impl IRefCounted for OdeWorld {
    fn init(base: Base<RefCounted>) -> Self {
        Self {
            world: World::new(DVec3::new(0.0, -9.81, 0.0)),
            base,
        }
    }
}

#[godot_api]
impl OdeWorld {
    /// Sets gravity in m/s². Non-finite components are rejected.
    #[func]
    fn set_gravity(&mut self, gravity: Vector3) {
        if !gravity.is_finite() {
            godot_error!("OdeWorld.set_gravity: gravity must be finite, got {gravity}");
            return;
        }
        self.world.set_gravity(dvec3(gravity));
    }

    /// Adds a static horizontal ground plane at the given height.
    #[func]
    fn add_ground_plane(&mut self, height: f64) {
        if !height.is_finite() {
            godot_error!("OdeWorld.add_ground_plane: height must be finite, got {height}");
            return;
        }
        self.world.add_plane(DVec3::new(0.0, 1.0, 0.0), height);
    }

    /// Adds a solid sphere body that collides; returns its id, or -1 on invalid input.
    #[func]
    fn add_sphere_body(&mut self, mass: f64, radius: f64, position: Vector3) -> i64 {
        let valid = mass.is_finite() && mass > 0.0 && radius.is_finite() && radius > 0.0;
        if !valid || !position.is_finite() {
            godot_error!(
                "OdeWorld.add_sphere_body: need mass > 0, radius > 0 and a finite position \
                 (got mass {mass}, radius {radius}, position {position})"
            );
            return -1;
        }
        let body = self
            .world
            .add_body(Mass::sphere(mass, radius), dvec3(position));
        self.world.add_sphere(radius, Some(body));
        body.0 as i64
    }

    /// Advances the world by `dt` seconds (0 < dt ≤ 1).
    #[func]
    fn step(&mut self, dt: f64) {
        if !(dt.is_finite() && dt > 0.0 && dt <= 1.0) {
            godot_error!("OdeWorld.step: dt must be in (0, 1] seconds, got {dt}");
            return;
        }
        self.world.step(dt);
    }

    /// Number of bodies.
    #[func]
    fn body_count(&self) -> i64 {
        self.world.body_count() as i64
    }

    /// Position of a body's centre of mass; zero (with an error) for an unknown id.
    #[func]
    fn body_position(&self, body: i64) -> Vector3 {
        self.body(body)
            .map(|id| vector3(self.world.body_position(id)))
            .unwrap_or(Vector3::ZERO)
    }

    /// Linear velocity of a body; zero (with an error) for an unknown id.
    #[func]
    fn body_linear_velocity(&self, body: i64) -> Vector3 {
        self.body(body)
            .map(|id| vector3(self.world.body_linear_velocity(id)))
            .unwrap_or(Vector3::ZERO)
    }
}

impl OdeWorld {
    fn body(&self, body: i64) -> Option<BodyId> {
        if (0..self.world.body_count() as i64).contains(&body) {
            Some(BodyId(body as usize))
        } else {
            godot_error!(
                "OdeWorld: no body {body} (the world has {})",
                self.world.body_count()
            );
            None
        }
    }
}
