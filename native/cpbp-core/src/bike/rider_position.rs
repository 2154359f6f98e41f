//! Where the player wants the rider's weight on the bike (thesis §6.4: "the right stick
//! could be used to move the character … lean forwards to limit wheelies and lean
//! backwards … to make them easier to start"): forward/back and side to side, each in
//! [−1, 1], as MX Bikes and MXGP put it on the right stick.
//!
//! The request means two things, defined once here: a pose for the rider's waist (what the
//! arcade controller and the planners' pose prior hold) and the rider's centre of mass
//! relative to the frame that pose puts it at (what the planners' cost asks for).

use glam::DVec3;

/// Rider joints with motors, in control order after the rear wheel (waist ×3, knee,
/// shoulder ×3, elbow, wrist ×3): `Bike::rider_joint_angles`' length.
pub const RIDER_JOINTS: usize = 11;

/// Offsets of the rider's joint angles from the riding pose (rad, `RIDER_JOINTS` order) at
/// full deflection forward: the waist pitches the torso over the tank (Euler axis 0 is
/// about the rider's right; negative leans forward), inside its ±0.7 rad limit, and the
/// shoulder and wrist take the angles the arms settle at on the bar. Every joint of the
/// loop foot → waist → arms → bar gets a consistent target: with the waist's alone the
/// weak arms give way, and where the rider ends up depends on where he came from.
pub const FORWARD_POSE: [f64; RIDER_JOINTS] =
    [-0.55, 0.0, 0.0, 0.0, 0.39, 0.0, 0.0, 0.0, -0.17, 0.0, 0.0];
/// The same, full deflection back: the torso pitched back, the arms straightened.
pub const BACK_POSE: [f64; RIDER_JOINTS] =
    [0.55, 0.0, 0.0, 0.0, -0.53, 0.0, 0.0, 0.0, 0.35, 0.0, 0.0];
/// The same, full deflection to the right: the waist rolls the torso right (axis 2,
/// nearly its ±0.4 rad limit) and twists it a little, and the shoulder and wrist let the
/// arms follow. The planners found this pose for themselves (measured at 15 km/h); with
/// the waist alone the legs roll the other way about the passive ankle and the weight
/// moves half as far.
pub const RIGHT_POSE: [f64; RIDER_JOINTS] =
    [0.0, -0.12, 0.38, 0.0, 0.0, 0.0, -0.18, 0.0, 0.0, -0.23, 0.0];

/// How far (m) the rider's centre of mass moves relative to the frame at full deflection,
/// forward (x) and to the right (z): where the planners' cost asks for it, and what the
/// poses above give (measured at 15 km/h on flat ground in the exact physics: +8 cm over
/// the tank, −10 cm back, ±8 cm sideways; `tests/rides/rider_position.rs` holds every
/// controller to 80 % of it).
pub const COM_REACH_FORWARD: f64 = 0.09;
pub const COM_REACH_RIGHT: f64 = 0.08;

/// The player's request, each component in [−1, 1]: +forward moves the rider's weight
/// towards the handlebar, +right towards the rider's right.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RiderPosition {
    pub forward: f64,
    pub right: f64,
}

impl RiderPosition {
    /// The riding pose: no weight shift asked for.
    pub const NEUTRAL: Self = Self {
        forward: 0.0,
        right: 0.0,
    };

    /// The request with every number valid: out-of-range components are clamped, and a
    /// non-finite one counts as released (0). The bool says whether anything changed.
    pub fn sanitized(self) -> (Self, bool) {
        let unit = |v: f64| {
            if v.is_finite() {
                v.clamp(-1.0, 1.0)
            } else {
                0.0
            }
        };
        let clean = Self {
            forward: unit(self.forward),
            right: unit(self.right),
        };
        let changed = clean.forward != self.forward || clean.right != self.right;
        (clean, changed)
    }

    /// How firmly the rider holds the position, 0–1: the stick's larger deflection. A
    /// released stick leaves the rider free to use the body for balance as the planners
    /// always have; a stick held at full deflection holds the weight where it points.
    pub fn engagement(&self) -> f64 {
        let (p, _) = self.sanitized();
        p.forward.abs().max(p.right.abs())
    }

    /// Offsets of the rider's joint angles from the riding pose that put the weight
    /// where asked: the full-deflection poses scaled by the stick (left mirrors right).
    pub fn pose(&self) -> [f64; RIDER_JOINTS] {
        let (p, _) = self.sanitized();
        if p == Self::NEUTRAL {
            // Exactly the riding pose (no −0.0 from 0 × a negative offset).
            return [0.0; RIDER_JOINTS];
        }
        let fore_aft = if p.forward >= 0.0 {
            FORWARD_POSE
        } else {
            BACK_POSE
        };
        std::array::from_fn(|i| p.forward.abs() * fore_aft[i] + p.right * RIGHT_POSE[i])
    }

    /// Where the pose puts the rider's centre of mass relative to where the riding pose
    /// has it, in the frame's axes (x forward, y up, z right; m).
    pub fn com_offset(&self) -> DVec3 {
        let (p, _) = self.sanitized();
        DVec3::new(
            p.forward * COM_REACH_FORWARD,
            0.0,
            p.right * COM_REACH_RIGHT,
        )
    }

    /// A measured offset of the rider's centre of mass (frame axes, m) in the request's
    /// units: ±1 at the reach. For the HUD.
    pub fn from_com_offset(offset: DVec3) -> Self {
        Self {
            forward: offset.x / COM_REACH_FORWARD,
            right: offset.z / COM_REACH_RIGHT,
        }
    }
}

/// Rider-position cost: how far the rider's centre of mass is from where the player asks,
/// fore/aft and sideways (heights are free), squared in units of `tolerance` (m), as
/// eq. 4.7 squares the lean error in units of its s; scaled by how firmly the stick is
/// held, or by `released` where that is firmer: a released stick adds nothing unless the
/// bike's planners hold the rider in the riding pose (`BikeParams::planners_rider_hold`).
pub fn rider_position_cost(
    asked: &RiderPosition,
    offset: DVec3,
    tolerance: f64,
    released: f64,
) -> f64 {
    let engagement = asked.engagement().max(released);
    if engagement == 0.0 {
        return 0.0;
    }
    let error = offset - asked.com_offset();
    engagement * (error.x * error.x + error.z * error.z) / (tolerance * tolerance)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_numbers_are_released_or_clamped() {
        let (p, changed) = RiderPosition {
            forward: f64::NAN,
            right: 3.0,
        }
        .sanitized();
        assert!(changed);
        assert_eq!(
            p,
            RiderPosition {
                forward: 0.0,
                right: 1.0
            }
        );
        let (_, changed) = RiderPosition {
            forward: -0.5,
            right: 0.25,
        }
        .sanitized();
        assert!(!changed);
        assert_eq!(
            RiderPosition {
                forward: f64::INFINITY,
                right: -0.4
            }
            .engagement(),
            0.4
        );
    }

    #[test]
    fn the_neutral_request_asks_nothing_of_the_pose_or_the_cost() {
        assert_eq!(RiderPosition::NEUTRAL.pose(), [0.0; RIDER_JOINTS]);
        assert_eq!(RiderPosition::NEUTRAL.engagement(), 0.0);
        let anywhere = DVec3::new(0.3, -0.1, 0.2);
        assert_eq!(
            rider_position_cost(&RiderPosition::NEUTRAL, anywhere, 0.03, 0.0),
            0.0
        );
    }

    #[test]
    fn the_cost_by_hand() {
        // Full forward: asked 0.09 m forward; measured 0.03 forward, 0.03 right, tolerance
        // 0.03 m: ((0.06)² + (0.03)²) / 0.03² = 5, engagement 1.
        let asked = RiderPosition {
            forward: 1.0,
            right: 0.0,
        };
        let offset = DVec3::new(0.03, 0.5, 0.03);
        let cost = rider_position_cost(&asked, offset, 0.03, 0.0);
        assert!((cost - 5.0).abs() < 1e-9, "{cost}");
        // Half deflection halves how firmly it is held.
        let half = RiderPosition {
            forward: 0.5,
            right: 0.0,
        };
        let at_target = DVec3::new(0.045, 0.0, 0.0);
        assert!(rider_position_cost(&half, at_target, 0.03, 0.0).abs() < 1e-12);
        let off = rider_position_cost(&half, DVec3::new(0.075, 0.0, 0.0), 0.03, 0.0);
        assert!((off - 0.5).abs() < 1e-9, "{off}");
    }

    #[test]
    fn a_bike_that_holds_the_rider_costs_a_released_stick_away_from_the_riding_pose() {
        // 6 cm right of the riding pose, tolerance 3 cm: (0.06 / 0.03)² = 4 at full hold.
        let off = DVec3::new(0.0, 0.2, 0.06);
        let released = RiderPosition::NEUTRAL;
        assert_eq!(rider_position_cost(&released, off, 0.03, 0.0), 0.0);
        let held = rider_position_cost(&released, off, 0.03, 0.1);
        assert!((held - 0.4).abs() < 1e-9, "{held}");
        // A stick held harder than the hold is held as firmly as the stick says.
        let half_right = RiderPosition {
            forward: 0.0,
            right: 0.5,
        };
        let asked = half_right.com_offset();
        let firm = rider_position_cost(&half_right, asked + off, 0.03, 0.1);
        assert!((firm - 2.0).abs() < 1e-9, "{firm}");
    }

    #[test]
    fn the_pose_and_the_reading_are_each_others_units() {
        let p = RiderPosition {
            forward: -0.6,
            right: 0.8,
        };
        let back = RiderPosition::from_com_offset(p.com_offset());
        assert!((back.forward - p.forward).abs() < 1e-12 && (back.right - p.right).abs() < 1e-12);
        assert!(p.pose()[0] > 0.0, "leaning back pitches the waist back");
        assert!(p.pose()[2] > 0.0, "leaning right rolls it right");
    }
}
