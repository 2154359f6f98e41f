//! The rider's side of a built bike: joint angles, the pose servo every controller starts
//! from, where the rider's weight is, and how hard the arms hold while braking.

use glam::DVec3;

use super::{Bike, Part};
use crate::bike::controls::{index, Controls, ForceClass, MAX_TORQUE};
use crate::bike::drive::brake_level;
use crate::bike::manual::POSE_GAIN;
use crate::bike::rider_position::RIDER_JOINTS;
use crate::bike::wheelie_control::PitchRequest;
use crate::ode::World;

/// The shoulder motor's axis that swings the arm fore and aft (about the frame's lateral
/// axis: `Builder::ball_with_motor`'s first), the one a braking rider braces.
const SHOULDER_SWING: usize = 0;

/// The wrist motor's axis on the steering axis when the wrists follow the bar
/// (`BikeParams::rider_wrists_follow_bar`).
const WRIST_ABOUT_STEERING: usize = 2;

impl Bike {
    /// Sets the rider's joint motors from the control vector (`held`: the pitch the
    /// rider's weight asks for, as `apply_pitching` takes it).
    pub(super) fn set_rider_motors(
        &self,
        world: &mut World,
        controls: &Controls,
        held: PitchRequest,
    ) {
        let c = controls.values();
        let waist = controls.max_torque(ForceClass::Waist);
        let arms = controls.max_torque(ForceClass::Arms) * self.arm_strength;
        let braced = self.braced_arms(controls, arms);
        let arms_held = self.arms_held_sideways(world, controls, held);
        for axis in 0..3 {
            world.set_motor(self.waist, axis, c[index::WAIST + axis], waist);
            // Held in a stoppie the rider locks the whole body to the bar.
            let shoulder = if axis == SHOULDER_SWING || held.stoppie > 0.0 {
                braced
            } else {
                arms
            };
            let (shoulder_target, wrist_target) = arms_held
                .as_ref()
                .filter(|_| axis != SHOULDER_SWING)
                .map_or((c[index::SHOULDER + axis], c[index::WRIST + axis]), |h| {
                    h[axis]
                });
            world.set_motor(self.shoulder, axis, shoulder_target, shoulder);
            // A bar that turns in the hand only meets the arm's damping: holding the
            // hand's pose there instead, on a foot as well, a bike stopped in a turn
            // twisted the bar as the pose came back and fell (the naked 700's braked
            // turn: 30 of 30 with the pose held on a foot, none damped).
            let wrist_target =
                if axis == WRIST_ABOUT_STEERING && self.params.rider_wrists_follow_bar {
                    0.0
                } else {
                    wrist_target
                };
            world.set_motor(self.wrist, axis, wrist_target, arms);
        }
        world.set_motor(
            self.knee,
            0,
            c[index::KNEE],
            controls.max_torque(ForceClass::Knee),
        );
        world.set_motor(self.elbow, 0, c[index::ELBOW], braced);
    }

    /// Angles of the rider's joint axes that have motors, in control order after the
    /// rear wheel (waist ×3, knee, shoulder ×3, elbow, wrist ×3); 0 in the riding pose.
    pub fn rider_joint_angles(&self, world: &World) -> [f64; RIDER_JOINTS] {
        let mut angles = [0.0; RIDER_JOINTS];
        for axis in 0..3 {
            angles[axis] = world.joint_angle(self.waist, axis);
            angles[index::SHOULDER - index::WAIST + axis] = world.joint_angle(self.shoulder, axis);
            angles[index::WRIST - index::WAIST + axis] = world.joint_angle(self.wrist, axis);
        }
        angles[index::KNEE - index::WAIST] = world.joint_angle(self.knee, 0);
        angles[index::ELBOW - index::WAIST] = world.joint_angle(self.elbow, 0);
        angles
    }

    /// Velocity targets that bring every rider joint back to the riding pose: a velocity
    /// servo (`gain` 1/s) on each joint angle, within the control bounds. The pose prior
    /// of the optimizer and the arcade controller's pose hold both start from this.
    pub fn pose_hold(&self, world: &World, gain: f64, controls: &mut Controls) {
        self.pose_hold_at(world, gain, &[0.0; RIDER_JOINTS], controls);
    }

    /// The same servo towards the riding pose offset by `pose` (rad per rider joint, as
    /// `RiderPosition::pose` gives it).
    pub fn pose_hold_at(
        &self,
        world: &World,
        gain: f64,
        pose: &[f64; RIDER_JOINTS],
        controls: &mut Controls,
    ) {
        for (i, angle) in self.rider_joint_angles(world).into_iter().enumerate() {
            controls.set(index::WAIST + i, -gain * (angle - pose[i]));
        }
    }

    /// Where the rider's centre of mass is relative to where the riding pose has it, in
    /// the frame's axes (x forward, y up, z right; m): the weight shift the player asks
    /// for with `RiderPosition`.
    pub fn rider_offset(&self, world: &World) -> DVec3 {
        let rider = &Part::ALL[Part::LowerLeg as usize..];
        let (mut now, mut rest, mut mass) = (DVec3::ZERO, DVec3::ZERO, 0.0);
        for &part in rider {
            let m = world.body_mass(self.body(part));
            now += world.body_position(self.body(part)) * m;
            rest += self.rest[part as usize].0 * m;
            mass += m;
        }
        let frame = self.body(Part::Frame);
        let (frame_rest, frame_rest_rotation) = self.rest[Part::Frame as usize];
        let local =
            self.frame_rotation(world).inverse() * (now / mass - world.body_position(frame));
        local - frame_rest_rotation.inverse() * (rest / mass - frame_rest)
    }

    /// The torque limit (N·m) of the elbow and of the shoulder's fore-and-aft swing:
    /// `arms`, or braking, towards the bike's `rider_brace` share of the arms' full
    /// strength (`MAX_TORQUE`) with the brake's level. A rider braking hard holds the body
    /// up against the deceleration, with the knees on the tank and the arms; this rider
    /// has no knees on the tank, and with the exact model's weak arms
    /// (`PhysicsModel::arm_strength`) the body pivots on the pegs towards the bars,
    /// carrying the centre of mass 0.1–0.15 m forward over the front tyre, which lowers
    /// what tips the bike by a sixth. The shoulder's other axes and the wrists keep the
    /// arms' strength (`arms_held_sideways` holds their pose): braced sideways too, the
    /// arms carried a planner's random shoulder targets out at full strength, and the
    /// rider's weight went 0.2 m sideways in the last metres of a stop (the optimizer at
    /// N = 10 fell in 6 of 60 full brakes). In a stoppie the
    /// rider asks for, the whole shoulder braces: braced fore and aft only, the bike fell
    /// over sideways on its nose. None on the reference bike (`rider_brace` 0).
    pub(super) fn braced_arms(&self, controls: &Controls, arms: f64) -> f64 {
        let brace = self.params.rider_brace;
        let level = brake_level(controls);
        if brace <= 0.0 || level.is_nan() || level <= 0.0 {
            return arms;
        }
        let braced = MAX_TORQUE[ForceClass::Arms as usize] * brace;
        arms + (braced - arms).max(0.0) * level.min(1.0)
    }

    /// Braking on a bike whose rider braces, the targets of the arms' sideways axes (the
    /// shoulder's and the wrist's other than fore and aft; per axis, shoulder then wrist)
    /// blended by the brake's level towards holding the riding pose; None otherwise. A
    /// planner exploring every joint (the optimizer alone) sends them random targets, and
    /// over a stop from 90 km/h they walked the wrists to their ±34° limits and moved the
    /// rider's weight 0.2 m to one side in the last metres, where no steering holds the
    /// bike (optimizer-15 fell there). Holding them at a constant angle instead let the
    /// bar's load creep them the same way; bracing them sideways locked the bar to the
    /// rider and the bike fell at once. Not in a stoppie the rider asks for, and none on
    /// the reference bike (`rider_brace` 0).
    pub(super) fn arms_held_sideways(
        &self,
        world: &World,
        controls: &Controls,
        held: PitchRequest,
    ) -> Option<[(f64, f64); 3]> {
        let level = brake_level(controls);
        // A brake level that is not a number holds nothing.
        let braking = level > 0.0;
        if self.params.rider_brace <= 0.0 || held.stoppie > 0.0 || !braking {
            return None;
        }
        let hold = level.min(1.0);
        let angles = self.rider_joint_angles(world);
        let c = controls.values();
        let towards_pose = |target: f64, angle: f64| target + hold * (-POSE_GAIN * angle - target);
        Some(std::array::from_fn(|axis| {
            (
                towards_pose(
                    c[index::SHOULDER + axis],
                    angles[index::SHOULDER - index::WAIST + axis],
                ),
                towards_pose(
                    c[index::WRIST + axis],
                    angles[index::WRIST - index::WAIST + axis],
                ),
            )
        }))
    }
}
