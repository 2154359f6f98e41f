//! Snapshots of a world's dynamic state as plain data, for branching rollouts.
//!
//! `restore(snapshot)` followed by K steps reproduces the original's K steps bit for bit:
//! quaternions are restored without renormalising (a patched-in ODE function), the
//! constraint-reordering random seed is part of the state (tests fail without either).
//! `World::step` also puts the space's geoms in a canonical order first: ODE moves a geom
//! to the front of its space whenever it moves, so pair order could depend on history
//! (the current tests pass without this safeguard too).

use crate::{MotorState, Quat, Vec3};

/// Position, orientation and velocities of one body.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyState {
    pub position: Vec3,
    pub quaternion: Quat,
    pub linear_velocity: Vec3,
    pub angular_velocity: Vec3,
}

impl BodyState {
    /// True when every component is a finite number.
    pub fn is_finite(&self) -> bool {
        self.position
            .iter()
            .chain(&self.quaternion)
            .chain(&self.linear_velocity)
            .chain(&self.angular_velocity)
            .all(|v| v.is_finite())
    }
}

/// The dynamic state of a whole world. Contacts are not part of it: they are regenerated
/// by collision every step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WorldState {
    pub bodies: Vec<BodyState>,
    /// Motor settings of every joint, in joint order (zeros for unmotorised joints).
    pub motors: Vec<MotorState>,
    /// The world's QuickStep random seed (it reorders constraint rows each step).
    pub random_seed: u64,
    /// Per body, whether it touched the terrain in the last step, and per foot, whether
    /// it stood on it: what a step is asked before it runs (a wheelie holds only with the
    /// rear wheel down), so without them a world restored from elsewhere would step on
    /// its own history.
    pub touching_static: Vec<bool>,
    pub feet_touching: Vec<bool>,
    /// Per foot, whether it is down and how far its leg is stretched (m): a rider's choice
    /// of foot and the leg's reach are carried from step to step, so a rollout branched
    /// from a snapshot goes on with the same foot as the ride.
    pub feet_down: Vec<bool>,
    pub feet_extension: Vec<f64>,
    /// Per foot, the way its leg stretches now (a unit vector in its body's frame; zero
    /// for a foot without a leg): a leg that hangs plumb turns in the frame as the body
    /// rolls (`World::set_foot_leg_direction`).
    pub feet_leg_direction: Vec<Vec3>,
    /// Per body, the sum of its contacts' normals with the terrain in the last step (from
    /// the ground towards the body; zero where it touched none): the slope under a wheel,
    /// which a step may read before it runs, as it reads the flags above.
    pub ground_normals: Vec<Vec3>,
}

/// Restoring a snapshot into a world of a different shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateMismatch {
    pub expected_bodies: usize,
    pub found_bodies: usize,
    pub expected_joints: usize,
    pub found_joints: usize,
}

impl std::fmt::Display for StateMismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "snapshot has {} bodies and {} joints, the world has {} and {}",
            self.found_bodies, self.found_joints, self.expected_bodies, self.expected_joints
        )
    }
}

impl std::error::Error for StateMismatch {}
