//! An inverted pendulum simulated in ODE, the smallest unstable system with real
//! contact-free rigid-body dynamics, cloned worlds and motors: every planner's first test.

use cpbp_core::control::cpbp::RolloutSystem;
use cpbp_core::ode::{JointId, Mass, World, WorldState};
use glam::{DQuat, DVec3};

pub const DT: f64 = 1.0 / 30.0;
pub const SUBSTEPS: usize = 2;
pub const MAX_TORQUE: f64 = 6.0;

/// A 1 kg rod, 1 m long, hinged at its foot to the world; a velocity motor at the hinge.
pub struct Pendulum {
    pub world: World,
    pub hinge: JointId,
}

impl Pendulum {
    /// Built upright (so the hinge angle is the tilt from upright), then tilted by `tilt`.
    pub fn new(tilt: f64) -> Self {
        let mut world = World::new(DVec3::new(0.0, -9.81, 0.0));
        let rod = world.add_body(Mass::capsule(1.0, 0.03, 1.0), DVec3::new(0.0, 0.5, 0.0));
        let hinge = world.add_hinge(rod, None, DVec3::ZERO, DVec3::Z);
        let rotation = DQuat::from_rotation_z(tilt);
        let centre = rotation * DVec3::new(0.0, 0.5, 0.0);
        world.set_body_quaternion(rod, rotation);
        world.set_body_position(rod, centre);
        Self { world, hinge }
    }

    pub fn tilt(&self) -> f64 {
        self.world.joint_angle(self.hinge, 0)
    }

    pub fn advance(&mut self, velocity: f64) {
        self.world.set_motor(self.hinge, 0, velocity, MAX_TORQUE);
        for _ in 0..SUBSTEPS {
            self.world.step(DT / SUBSTEPS as f64);
        }
    }
}

impl RolloutSystem for Pendulum {
    type State = WorldState;

    fn save(&self) -> WorldState {
        self.world.snapshot()
    }

    fn restore(&mut self, state: &WorldState) {
        self.world.restore(state).expect("built alike");
    }

    fn step(&mut self, u: &[f64], _step: usize) -> Option<f64> {
        self.advance(u[0]);
        let tilt = self.tilt();
        tilt.is_finite().then(|| (tilt / 0.05).powi(2))
    }

    fn features(&self) -> Vec<f64> {
        vec![self.tilt() / 0.1, self.world.hinge_rate(self.hinge)]
    }
}
