//! Where the rider sits on the bike: footpeg, seat (the hip), the torso's lean and the
//! handlebar's grips, in the bike frame (x forward, y up, from the ground midway between
//! the contact points). A bike's own numbers (`posture/…` fields): a dirt bike's pegs,
//! seat and bar sit higher than a road bike's, a sport bike's bar lower and further
//! forward. The rider's segment lengths are the rider's, the same on every bike
//! (`layout.rs`); a posture those segments cannot reach is refused (`Posture::check`).

use glam::DVec3;

/// The rider's posture on a bike.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Posture {
    /// The footpeg (the ankle's joint), in the mid-plane (z 0).
    pub footpeg: DVec3,
    /// The hip on the seat (the waist's joint), in the mid-plane.
    pub hip: DVec3,
    /// The torso's lean forward from upright (rad).
    pub torso_lean: f64,
    /// The grips' height above the ground (m), on the steering axis's line.
    pub grip_height: f64,
    /// How far (m) the grips sit behind the steering axis.
    pub grip_behind_axis: f64,
}

impl Default for Posture {
    /// A naked road bike's, of the reference's class: seat at 0.85 m, pegs at 0.38 m
    /// 0.15 m ahead of it, the torso 20° forward, grips at 1.05 m just behind the axis.
    fn default() -> Self {
        Self {
            footpeg: DVec3::new(-0.10, 0.38, 0.0),
            hip: DVec3::new(-0.25, 0.85, 0.0),
            torso_lean: 0.349, // 20°
            grip_height: 1.05,
            grip_behind_axis: 0.06,
        }
    }
}

impl Posture {
    /// Whether a leg of `thigh` and `shank` reaches from hip to footpeg, and an arm of
    /// `upper_arm` and `forearm` from `shoulder` to `grip`, each with a bend: otherwise
    /// why, naming the fields to change.
    pub fn check(
        &self,
        (thigh, shank): (f64, f64),
        (upper_arm, forearm): (f64, f64),
        (shoulder, grip): (DVec3, DVec3),
    ) -> Result<(), String> {
        let leg = (self.footpeg - self.hip).length();
        if !bends(leg, thigh, shank) {
            return Err(format!(
                "posture/footpeg_* and posture/hip_* are {leg:.3} m apart: the rider's leg \
                 ({thigh} + {shank} m) cannot reach with a bend"
            ));
        }
        let arm = (grip - shoulder).length();
        if !bends(arm, upper_arm, forearm) {
            return Err(format!(
                "the grips (posture/grip_height, posture/grip_behind_axis) are {arm:.3} m \
                 from the shoulder (posture/hip_*, posture/torso_lean_deg): the rider's arm \
                 ({upper_arm} + {forearm} m) cannot reach with a bend"
            ));
        }
        Ok(())
    }
}

/// Whether two segments of lengths `a` and `b` span `d` with a bend between them.
pub(super) fn bends(d: f64, a: f64, b: f64) -> bool {
    d < a + b && d > (a - b).abs()
}
