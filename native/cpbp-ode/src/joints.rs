//! Joints between bodies: ball, hinge and slider (with limits and a velocity motor) and
//! the Euler angular motor that drives a ball joint about three axes.

use crate::ffi;
use crate::world::{BodyId, World};
use crate::DVec3;

/// Index of a joint inside its [`World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct JointId(pub usize);

/// ODE numbers the parameters of a joint's second and third axis in groups 0x100 apart.
const PARAM_GROUP: i32 = 0x100;

/// Velocity-motor settings of a joint, per axis (1 for hinges, 3 for Euler motors), the
/// angles an Euler motor cached during the last step, and whether the joint is switched
/// off (a rider let go of the bike). The settings are controls and the angles are
/// derived, but all are state: a restored world must read and step exactly as the
/// original.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MotorState {
    pub velocity: [f64; 3],
    pub max_force: [f64; 3],
    pub cached_angles: [f64; 3],
    pub disabled: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum JointKind {
    Ball,
    Hinge,
    Slider,
    EulerMotor,
}

impl JointKind {
    /// Number of motorised axes.
    pub(crate) fn motor_axes(self) -> usize {
        match self {
            JointKind::Ball => 0,
            JointKind::Hinge | JointKind::Slider => 1,
            JointKind::EulerMotor => 3,
        }
    }
}

impl World {
    /// A ball-and-socket joint at a world-frame anchor; `b = None` attaches to the world.
    pub fn add_ball(&mut self, a: BodyId, b: Option<BodyId>, anchor: DVec3) -> JointId {
        // SAFETY: the world and bodies are alive; the joint is owned by the world.
        let joint = unsafe {
            let joint = ffi::dJointCreateBall(self.world, std::ptr::null_mut());
            ffi::dJointAttach(joint, self.bodies[a.0], self.body_or_world(b));
            ffi::dJointSetBallAnchor(joint, anchor[0], anchor[1], anchor[2]);
            joint
        };
        self.push_joint(joint, JointKind::Ball)
    }

    /// A hinge at a world-frame anchor about a world-frame axis; its angle is 0 as built.
    pub fn add_hinge(
        &mut self,
        a: BodyId,
        b: Option<BodyId>,
        anchor: DVec3,
        axis: DVec3,
    ) -> JointId {
        // SAFETY: as for add_ball.
        let joint = unsafe {
            let joint = ffi::dJointCreateHinge(self.world, std::ptr::null_mut());
            ffi::dJointAttach(joint, self.bodies[a.0], self.body_or_world(b));
            ffi::dJointSetHingeAnchor(joint, anchor[0], anchor[1], anchor[2]);
            ffi::dJointSetHingeAxis(joint, axis[0], axis[1], axis[2]);
            joint
        };
        self.push_joint(joint, JointKind::Hinge)
    }

    /// A slider (prismatic joint) along a world-frame axis; its position is 0 as built and
    /// grows as `a` moves along the axis relative to `b`.
    pub fn add_slider(&mut self, a: BodyId, b: Option<BodyId>, axis: DVec3) -> JointId {
        // SAFETY: as for add_ball.
        let joint = unsafe {
            let joint = ffi::dJointCreateSlider(self.world, std::ptr::null_mut());
            ffi::dJointAttach(joint, self.bodies[a.0], self.body_or_world(b));
            ffi::dJointSetSliderAxis(joint, axis[0], axis[1], axis[2]);
            joint
        };
        self.push_joint(joint, JointKind::Slider)
    }

    /// An Euler-mode angular motor between two bodies (for a ball joint): axis 0 is fixed
    /// to `a`, axis 2 to `b`, both given in world frame and perpendicular; ODE derives
    /// axis 1 and the three angles every step (so they need no saving in snapshots).
    pub fn add_euler_motor(&mut self, a: BodyId, b: BodyId, axis0: DVec3, axis2: DVec3) -> JointId {
        // SAFETY: as for add_ball.
        let joint = unsafe {
            let joint = ffi::dJointCreateAMotor(self.world, std::ptr::null_mut());
            ffi::dJointAttach(joint, self.bodies[a.0], self.bodies[b.0]);
            ffi::dJointSetAMotorMode(joint, ffi::dAMotorEuler as i32);
            ffi::dJointSetAMotorAxis(joint, 0, 1, axis0[0], axis0[1], axis0[2]);
            ffi::dJointSetAMotorAxis(joint, 2, 2, axis2[0], axis2[1], axis2[2]);
            joint
        };
        self.push_joint(joint, JointKind::EulerMotor)
    }

    /// Limits of a hinge or slider (axis 0; rad or m) or an Euler motor (axes 0–2; rad).
    pub fn set_joint_limits(&mut self, joint: JointId, axis: usize, lo: f64, hi: f64) {
        let (id, kind, group) = self.axis_params(joint, axis);
        // SAFETY: the joint belongs to this world and has this axis.
        unsafe {
            self.set_param(id, kind, group + ffi::dParamLoStop as i32, lo);
            self.set_param(id, kind, group + ffi::dParamHiStop as i32, hi);
            // Setting lo again makes it stick when the new lo exceeds the old hi.
            self.set_param(id, kind, group + ffi::dParamLoStop as i32, lo);
        }
    }

    /// ERP and CFM of axis 0's stops (a spring uses them; see `springs`).
    pub(crate) fn set_stop_erp_cfm(&mut self, joint: JointId, erp: f64, cfm: f64) {
        let (id, kind, group) = self.axis_params(joint, 0);
        // SAFETY: the joint belongs to this world and has axis 0.
        unsafe {
            self.set_param(id, kind, group + ffi::dParamStopERP as i32, erp);
            self.set_param(id, kind, group + ffi::dParamStopCFM as i32, cfm);
        }
    }

    /// Target angular velocity (rad/s) and force limit (N·m) of one motor axis.
    pub fn set_motor(&mut self, joint: JointId, axis: usize, velocity: f64, max_force: f64) {
        let (id, kind, group) = self.axis_params(joint, axis);
        // SAFETY: the joint belongs to this world and has this axis.
        unsafe {
            self.set_param(id, kind, group + ffi::dParamVel as i32, velocity);
            self.set_param(id, kind, group + ffi::dParamFMax as i32, max_force);
        }
    }

    /// Switches a joint off (the bodies it held move freely) or back on.
    pub fn set_joint_enabled(&mut self, joint: JointId, enabled: bool) {
        let (id, _) = self.joints[joint.0];
        // SAFETY: the joint belongs to this world.
        unsafe {
            if enabled {
                ffi::dJointEnable(id);
            } else {
                ffi::dJointDisable(id);
            }
        }
    }

    /// How far apart (m) a ball joint's anchor is on its two bodies: about zero while the
    /// joint holds, growing once it is switched off and the bodies drift apart.
    pub fn ball_anchor_gap(&self, joint: JointId) -> f64 {
        let (id, kind) = self.joints[joint.0];
        debug_assert_eq!(kind, JointKind::Ball);
        let (mut a, mut b) = ([0.0; 4], [0.0; 4]);
        // SAFETY: a ball joint of this world; ODE writes 3 (of 4, dVector3) reals to each.
        unsafe {
            ffi::dJointGetBallAnchor(id, a.as_mut_ptr());
            ffi::dJointGetBallAnchor2(id, b.as_mut_ptr());
        }
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    }

    /// Whether a joint holds its bodies (see `set_joint_enabled`).
    pub fn joint_enabled(&self, joint: JointId) -> bool {
        // SAFETY: the joint belongs to this world.
        unsafe { ffi::dJointIsEnabled(self.joints[joint.0].0) != 0 }
    }

    /// Motor settings of a joint, and whether it is switched off.
    pub fn motor_state(&self, joint: JointId) -> MotorState {
        let (id, kind) = self.joints[joint.0];
        let mut state = MotorState {
            disabled: !self.joint_enabled(joint),
            ..MotorState::default()
        };
        for axis in 0..kind.motor_axes() {
            let group = PARAM_GROUP * axis as i32;
            // SAFETY: the joint belongs to this world and has this axis.
            unsafe {
                state.velocity[axis] = self.param(id, kind, group + ffi::dParamVel as i32);
                state.max_force[axis] = self.param(id, kind, group + ffi::dParamFMax as i32);
                if kind == JointKind::EulerMotor {
                    state.cached_angles[axis] = ffi::dJointGetAMotorAngle(id, axis as i32);
                }
            }
        }
        state
    }

    /// Restores motor settings saved by [`World::motor_state`].
    pub fn set_motor_state(&mut self, joint: JointId, state: &MotorState) {
        let (id, kind) = self.joints[joint.0];
        self.set_joint_enabled(joint, !state.disabled);
        for axis in 0..kind.motor_axes() {
            self.set_motor(joint, axis, state.velocity[axis], state.max_force[axis]);
            if kind == JointKind::EulerMotor {
                // SAFETY: an Euler motor of this world; our ODE build lets this set the
                // cached angle in Euler mode (tools/build-ode.sh, patch 3).
                unsafe { ffi::dJointSetAMotorAngle(id, axis as i32, state.cached_angles[axis]) };
            }
        }
    }

    /// Puts every motor back as built: every joint on, no target velocity, no force, and
    /// Euler motors' cached angles at zero. Otherwise a ride started afresh would inherit the last
    /// ride's motor settings through its snapshots, and a planner reading the cached
    /// angles before the first step would see the old ride's pose.
    pub fn reset_motors(&mut self) {
        for joint in 0..self.joints.len() {
            self.set_motor_state(JointId(joint), &MotorState::default());
        }
    }

    /// Angle (radians) of a hinge, or of one Euler-motor axis as of the last step.
    pub fn joint_angle(&self, joint: JointId, axis: usize) -> f64 {
        let (id, kind) = self.joints[joint.0];
        // SAFETY: the joint belongs to this world.
        unsafe {
            match kind {
                JointKind::Hinge => ffi::dJointGetHingeAngle(id),
                JointKind::EulerMotor => ffi::dJointGetAMotorAngle(id, axis as i32),
                JointKind::Ball | JointKind::Slider => 0.0,
            }
        }
    }

    /// Angular rate (rad/s) of a hinge.
    pub fn hinge_rate(&self, joint: JointId) -> f64 {
        let (id, kind) = self.joints[joint.0];
        assert_eq!(kind, JointKind::Hinge, "joint {joint:?} is not a hinge");
        // SAFETY: the joint is a hinge of this world.
        unsafe { ffi::dJointGetHingeAngleRate(id) }
    }

    /// Number of joints (contacts excluded).
    pub fn joint_count(&self) -> usize {
        self.joints.len()
    }

    /// The joint, its kind and the parameter group of `axis`; panics if it has no such
    /// axis (a programming error: joints are built by this crate's callers once).
    fn axis_params(&self, joint: JointId, axis: usize) -> (ffi::dJointID, JointKind, i32) {
        let (id, kind) = self.joints[joint.0];
        assert!(
            axis < kind.motor_axes(),
            "joint {joint:?} has no axis {axis}"
        );
        (id, kind, PARAM_GROUP * axis as i32)
    }

    fn push_joint(&mut self, joint: ffi::dJointID, kind: JointKind) -> JointId {
        self.joints.push((joint, kind));
        JointId(self.joints.len() - 1)
    }

    fn body_or_world(&self, body: Option<BodyId>) -> ffi::dBodyID {
        body.map_or(std::ptr::null_mut(), |b| self.bodies[b.0])
    }

    /// # Safety
    /// `id` must be a live joint of kind `kind` with the parameter's axis.
    unsafe fn set_param(&self, id: ffi::dJointID, kind: JointKind, param: i32, value: f64) {
        // SAFETY: guaranteed by the caller.
        unsafe {
            match kind {
                JointKind::Hinge => ffi::dJointSetHingeParam(id, param, value),
                JointKind::Slider => ffi::dJointSetSliderParam(id, param, value),
                JointKind::EulerMotor => ffi::dJointSetAMotorParam(id, param, value),
                JointKind::Ball => {}
            }
        }
    }

    /// # Safety
    /// As for `set_param`.
    unsafe fn param(&self, id: ffi::dJointID, kind: JointKind, param: i32) -> f64 {
        // SAFETY: guaranteed by the caller.
        unsafe {
            match kind {
                JointKind::Hinge => ffi::dJointGetHingeParam(id, param),
                JointKind::Slider => ffi::dJointGetSliderParam(id, param),
                JointKind::EulerMotor => ffi::dJointGetAMotorParam(id, param),
                JointKind::Ball => 0.0,
            }
        }
    }
}
