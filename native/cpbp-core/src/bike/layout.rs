//! Where the bike's and rider's bodies and joints sit, in the bike frame (x forward, y up,
//! z right, origin on the ground midway between the contact points), derived from
//! [`BikeParams`] and a riding posture.

use glam::DVec3;

use super::params::BikeParams;
use super::posture::bends;

/// Joint centres and key points of the built model.
#[derive(Clone, Debug)]
pub struct Layout {
    pub rear_axle: DVec3,
    pub front_axle: DVec3,
    /// Unit vector up along the steering axis (tilted back by the rake).
    pub steer_axis: DVec3,
    /// Point on the steering axis used as the hinge anchor.
    pub steer_anchor: DVec3,
    /// Top of the fork body, at the handlebar clamp.
    pub fork_top: DVec3,
    /// Bottom of the fork's stanchions, inside the lower legs, and top of the lower legs
    /// (both on the line from the axle up the steering axis).
    pub stanchion_bottom: DVec3,
    pub fork_lower_top: DVec3,
    /// Where the swingarm pivots on the frame.
    pub swingarm_pivot: DVec3,
    /// Rider joints: footpeg (ankle), knee, hip (waist), shoulder, elbow, grip (wrist).
    pub ankle: DVec3,
    pub knee: DVec3,
    pub hip: DVec3,
    pub shoulder: DVec3,
    pub elbow: DVec3,
    pub grip: DVec3,
    /// Top of the head.
    pub head_top: DVec3,
}

/// Segment lengths for a 1.75 m rider (Winter 2009): thigh, shank, hip–shoulder,
/// hip–head top, upper arm, forearm to grip centre.
const THIGH: f64 = 0.43;
const SHANK: f64 = 0.43;
const HIP_TO_SHOULDER: f64 = 0.52;
const HIP_TO_HEAD_TOP: f64 = 0.78;
const UPPER_ARM: f64 = 0.33;
const FOREARM: f64 = 0.36;
/// Length of the fork's lower legs from the axle, and how far up from the axle the
/// stanchions end inside them (m): room for the 130 mm travel with the bushings apart.
const FORK_LOWER_LENGTH: f64 = 0.42;
const STANCHION_OVERLAP: f64 = 0.24;
/// The swingarm's pivot on the frame relative to the rear axle: a swingarm of about
/// 0.57 m sloping down to the axle, as on road bikes of this class.
const SWINGARM_PIVOT_FROM_AXLE: DVec3 = DVec3::new(0.56, 0.09, 0.0);

impl Layout {
    pub fn new(params: &BikeParams) -> Self {
        let half = params.wheelbase / 2.0;
        let r = params.wheel_radius;
        let rear_axle = DVec3::new(-half, r, 0.0);
        let front_axle = DVec3::new(half, r, 0.0);
        let steer_axis = DVec3::new(-params.rake.sin(), params.rake.cos(), 0.0);
        let at_height = steering_axis_at(params);
        let posture = &params.posture;
        let (shoulder, grip) = shoulder_and_grip(params);
        let (footpeg, hip, torso_lean) = (posture.footpeg, posture.hip, posture.torso_lean);
        Self {
            rear_axle,
            front_axle,
            steer_axis,
            steer_anchor: at_height(0.85),
            fork_top: at_height(posture.grip_height - 0.03),
            stanchion_bottom: front_axle + steer_axis * STANCHION_OVERLAP,
            fork_lower_top: front_axle + steer_axis * FORK_LOWER_LENGTH,
            swingarm_pivot: rear_axle + SWINGARM_PIVOT_FROM_AXLE,
            ankle: footpeg,
            knee: bend_point(hip, footpeg, THIGH, SHANK, true),
            hip,
            shoulder,
            elbow: bend_point(shoulder, grip, UPPER_ARM, FOREARM, false),
            grip,
            head_top: hip + DVec3::new(torso_lean.sin(), torso_lean.cos(), 0.0) * HIP_TO_HEAD_TOP,
        }
    }

    /// Whether the rider's legs and arms reach the bike's footpegs and grips
    /// (`Posture::check`): otherwise why, naming the fields.
    pub fn check_posture(params: &BikeParams) -> Result<(), String> {
        let reach = shoulder_and_grip(params);
        params
            .posture
            .check((THIGH, SHANK), (UPPER_ARM, FOREARM), reach)
    }
}

/// The point of the steering axis `h` above the ground: it meets the ground `trail`
/// ahead of the front contact point.
fn steering_axis_at(params: &BikeParams) -> impl Fn(f64) -> DVec3 {
    let steer_axis = DVec3::new(-params.rake.sin(), params.rake.cos(), 0.0);
    let axis_on_ground = DVec3::new(params.wheelbase / 2.0 + params.trail, 0.0, 0.0);
    move |h: f64| axis_on_ground + steer_axis * (h / steer_axis.y)
}

/// The rider's shoulder (the torso leaned from the hip) and the grips.
fn shoulder_and_grip(params: &BikeParams) -> (DVec3, DVec3) {
    let posture = &params.posture;
    let lean = posture.torso_lean;
    let shoulder = posture.hip + DVec3::new(lean.sin(), lean.cos(), 0.0) * HIP_TO_SHOULDER;
    let grip = steering_axis_at(params)(posture.grip_height) - DVec3::X * posture.grip_behind_axis;
    (shoulder, grip)
}

/// The joint between two segments of lengths `la` (from `a`) and `lb` (to `b`) in the
/// mid-plane: the knee bends forward-up, the elbow down-back.
fn bend_point(a: DVec3, b: DVec3, la: f64, lb: f64, forward_up: bool) -> DVec3 {
    let d = (b - a).length();
    assert!(
        bends(d, la, lb),
        "segments cannot reach: BikeParams::check refuses this posture"
    );
    let along = (la * la - lb * lb + d * d) / (2.0 * d);
    let height = (la * la - along * along).sqrt();
    let u = (b - a) / d;
    let normal = DVec3::new(-u.y, u.x, 0.0); // u rotated +90° in the mid-plane
    let side = if (normal.x + normal.y > 0.0) == forward_up {
        1.0
    } else {
        -1.0
    };
    a + u * along + normal * height * side
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_have_their_lengths() {
        let l = Layout::new(&BikeParams::default());
        assert!(((l.knee - l.hip).length() - THIGH).abs() < 1e-9);
        assert!(((l.ankle - l.knee).length() - SHANK).abs() < 1e-9);
        assert!(((l.elbow - l.shoulder).length() - UPPER_ARM).abs() < 1e-9);
        assert!(((l.grip - l.elbow).length() - FOREARM).abs() < 1e-9);
    }

    #[test]
    fn the_knee_points_forward_and_the_elbow_down() {
        let l = Layout::new(&BikeParams::default());
        assert!(l.knee.x > l.hip.x && l.knee.x > l.ankle.x);
        let line = l.shoulder.lerp(l.grip, 0.5);
        assert!(l.elbow.y < line.y);
    }

    #[test]
    fn the_steering_axis_has_the_rake_and_positive_trail() {
        let p = BikeParams::default();
        let l = Layout::new(&p);
        assert!((l.steer_axis.angle_between(DVec3::Y) - p.rake).abs() < 1e-12);
        // Where the axis through the anchor meets the ground, relative to the front contact.
        let ground = l.steer_anchor - l.steer_axis * (l.steer_anchor.y / l.steer_axis.y);
        let trail = ground.x - l.front_axle.x;
        assert!((trail - p.trail).abs() < 1e-12 && trail > 0.0);
        assert!(
            (p.fork_offset() - 0.0407).abs() < 1e-3,
            "offset {}",
            p.fork_offset()
        );
    }
}
