//! The C-PBP planner balancing an inverted pendulum simulated in ODE: the smallest
//! unstable system with real contacts-free rigid-body dynamics, cloned worlds and motors.

use cpbp_core::bike::to_quat;
use cpbp_core::control::cpbp::{Planner, PlannerConfig, Priors, RolloutSystem, WarmStart};
use cpbp_core::ode::{JointId, Mass, World, WorldState};
use glam::DQuat;

const DT: f64 = 1.0 / 30.0;
const SUBSTEPS: usize = 2;
const MAX_TORQUE: f64 = 6.0;

/// A 1 kg rod, 1 m long, hinged at its foot to the world; a velocity motor at the hinge.
struct Pendulum {
    world: World,
    hinge: JointId,
}

impl Pendulum {
    /// Built upright (so the hinge angle is the tilt from upright), then tilted by `tilt`.
    fn new(tilt: f64) -> Self {
        let mut world = World::new([0.0, -9.81, 0.0]);
        let rod = world.add_body(Mass::capsule(1.0, 0.03, 1.0), [0.0, 0.5, 0.0]);
        let hinge = world.add_hinge(rod, None, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let rotation = DQuat::from_rotation_z(tilt);
        let centre = rotation * glam::DVec3::new(0.0, 0.5, 0.0);
        world.set_body_quaternion(rod, to_quat(rotation));
        world.set_body_position(rod, centre.to_array());
        Self { world, hinge }
    }

    fn tilt(&self) -> f64 {
        self.world.joint_angle(self.hinge, 0)
    }

    fn advance(&mut self, velocity: f64) {
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

fn planner() -> Planner {
    let priors = Priors::uniform(1, 2.0, 1.0, 0.2, 4.0);
    let config = PlannerConfig {
        particles: 16,
        steps: 24,
        seed: 1,
        ..PlannerConfig::default()
    };
    Planner::new(config, priors)
}

#[test]
fn left_alone_the_pendulum_falls() {
    let mut free = Pendulum::new(0.2);
    for _ in 0..60 {
        free.world.set_motor(free.hinge, 0, 0.0, 0.0);
        free.world.step(DT / 2.0);
        free.world.step(DT / 2.0);
    }
    assert!(free.tilt().abs() > 1.0, "tilt {}", free.tilt());
}

#[test]
fn the_planner_brings_it_upright_and_keeps_it_there() {
    let mut master = Pendulum::new(0.3);
    let mut systems: Vec<Pendulum> = (0..16).map(|_| Pendulum::new(0.3)).collect();
    let mut planner = planner();
    let mut tilts = Vec::new();
    for _ in 0..150 {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        let refined = result.refined.as_ref().expect("features given");
        assert!(refined.iter().all(|u| (-4.0..=4.0).contains(u)));
        master.advance(result.control[0]);
        tilts.push(master.tilt());
    }
    let last = &tilts[90..];
    let worst = last.iter().map(|t| t.abs()).fold(0.0, f64::max);
    assert!(worst < 0.05, "worst tilt over the last 2 s: {worst} rad");
}
