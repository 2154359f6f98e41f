//! Spring–dampers along a slider or about a hinge, solved implicitly by ODE itself: a joint
//! stop whose low and high positions coincide holds the joint there from both sides, and
//! with the stop's ERP and CFM chosen from the step length h, stiffness k and damping c as
//! ERP = h·k / (h·k + c), CFM = 1 / (h·k + c) the constraint force is exactly the force of
//! a spring of rate k and a damper of rate c, integrated implicitly (ODE's manual, "How do
//! I make 'spring' and 'damper' joints?"). So the spring is stable at any step length,
//! which an explicit force k·x added before the step is not once h·√(k/m) nears 2.
//!
//! Travel ends are hard stops (bump and top-out): outside its travel the joint gets ODE's
//! ordinary one-sided stops at the ends instead of the spring.

use crate::ffi;
use crate::joints::{JointId, JointKind};
use crate::world::World;

/// A linear spring and damper on a joint's position (m along a slider, rad about a
/// hinge), with hard stops at the ends of its travel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spring {
    /// Rate k: N/m along a slider, N·m/rad about a hinge.
    pub stiffness: f64,
    /// Rate c: N·s/m or N·m·s/rad.
    pub damping: f64,
    /// Position where the spring pushes with no force. Beyond a travel end, the spring is
    /// preloaded: it already pushes at that end.
    pub free_position: f64,
    /// The ends of travel (low, high), where hard stops hold the joint.
    pub travel: (f64, f64),
}

impl Spring {
    /// The stop's ERP and CFM that make it this spring over a step of `dt` seconds.
    pub fn erp_cfm(&self, dt: f64) -> (f64, f64) {
        let hk = dt * self.stiffness;
        (hk / (hk + self.damping), 1.0 / (hk + self.damping))
    }
}

impl World {
    /// Makes axis 0 of slider or hinge `joint` a spring–damper (see [`Spring`]); its
    /// stops and their ERP and CFM belong to the spring from now on.
    pub fn set_spring(&mut self, joint: JointId, spring: Spring) {
        let (_, kind) = self.joints[joint.0];
        assert!(
            matches!(kind, JointKind::Hinge | JointKind::Slider),
            "joint {joint:?} is neither a slider nor a hinge"
        );
        assert!(
            spring.stiffness > 0.0 && spring.damping >= 0.0 && spring.travel.0 < spring.travel.1,
            "spring {spring:?} needs a positive rate and a travel"
        );
        self.springs.retain(|(j, _)| *j != joint);
        self.springs.push((joint, spring));
    }

    /// Position of a slider (m) or angle of a hinge (rad) on axis 0.
    pub fn joint_position(&self, joint: JointId) -> f64 {
        let (id, kind) = self.joints[joint.0];
        // SAFETY: the joint belongs to this world and is of the kind matched.
        unsafe {
            match kind {
                JointKind::Slider => ffi::dJointGetSliderPosition(id),
                JointKind::Hinge => ffi::dJointGetHingeAngle(id),
                _ => panic!("joint {joint:?} has no position"),
            }
        }
    }

    /// Rate of `joint_position` (m/s or rad/s).
    pub fn joint_position_rate(&self, joint: JointId) -> f64 {
        let (id, kind) = self.joints[joint.0];
        // SAFETY: as for joint_position.
        unsafe {
            match kind {
                JointKind::Slider => ffi::dJointGetSliderPositionRate(id),
                JointKind::Hinge => ffi::dJointGetHingeAngleRate(id),
                _ => panic!("joint {joint:?} has no position"),
            }
        }
    }

    /// Sets every spring's stops for the coming step of `dt`: inside its travel the stop
    /// is the spring (both stops at the free position, ERP and CFM from k, c and `dt`);
    /// at or past an end, ordinary hard stops at both ends. Depends only on the joint's
    /// position, so a restored world steps exactly as the original.
    pub(crate) fn update_springs(&mut self, dt: f64) {
        for i in 0..self.springs.len() {
            let (joint, spring) = self.springs[i];
            let position = self.joint_position(joint);
            let (lo, hi) = spring.travel;
            let inside = position > lo && position < hi;
            let (erp, cfm) = if inside {
                spring.erp_cfm(dt)
            } else {
                // ODE's defaults for a hard stop: the world's ERP and CFM.
                // SAFETY: the world is alive.
                unsafe { (ffi::dWorldGetERP(self.world), ffi::dWorldGetCFM(self.world)) }
            };
            let (stop_lo, stop_hi) = if inside {
                (spring.free_position, spring.free_position)
            } else {
                (lo, hi)
            };
            self.set_joint_limits(joint, 0, stop_lo, stop_hi);
            self.set_stop_erp_cfm(joint, erp, cfm);
        }
    }
}
