//! The rider's goal in numbers (thesis §4.3.1): the player's turn becomes a desired lean
//! (eqs. 4.1–4.4), the desired lean becomes a vector (4.5–4.6), and the angle between it
//! and the bike's actual lean vector is the cost (4.7).

use glam::{DMat3, DVec3};

use crate::bike::BikeParams;

/// Desired lean θ (rad) for riding a circle of signed curvature `curvature` (1/m, positive
/// to the right) at `speed` (m/s): tan θ = v²/(r g) (eq. 4.4), positive leaning right.
pub fn desired_lean(speed: f64, curvature: f64, gravity: f64) -> f64 {
    (speed * speed * curvature / gravity).atan()
}

/// Rotation by `angle` about the unit `axis` (Rodrigues' formula, eq. 4.5):
/// R = cos θ I + sin θ [k]ₓ + (1 − cos θ) k ⊗ k.
pub fn rodrigues(axis: DVec3, angle: f64) -> DMat3 {
    let k = axis;
    let cross = DMat3::from_cols(
        DVec3::new(0.0, k.z, -k.y),
        DVec3::new(-k.z, 0.0, k.x),
        DVec3::new(k.y, -k.x, 0.0),
    );
    let outer = DMat3::from_cols(k * k.x, k * k.y, k * k.z);
    DMat3::IDENTITY * angle.cos() + cross * angle.sin() + outer * (1.0 - angle.cos())
}

/// Desired lean vector b_d = R u_d (eq. 4.6): world down rotated about the bike's forward
/// axis by the desired lean. Rotating down by +θ about forward tips it to the left, which
/// is where the ground support lies, seen from the centre of mass, when leaning right.
pub fn desired_lean_vector(forward: DVec3, up: DVec3, lean: f64) -> DVec3 {
    rodrigues(forward.normalize(), lean) * -up
}

/// Current lean vector: from the centre of mass to the ground support point.
pub fn current_lean_vector(center_of_mass: DVec3, support: DVec3) -> DVec3 {
    (support - center_of_mass).normalize_or_zero()
}

/// Lean cost c = ∠(b_d, x̂_s − x_com)² / s² (eq. 4.7), `tolerance` = s (rad).
pub fn lean_cost(desired: DVec3, current: DVec3, tolerance: f64) -> f64 {
    let angle = desired.angle_between(current);
    (angle / tolerance).powi(2)
}

/// Eq. 4.7 in the roll plane only: both vectors projected on the plane across `heading`
/// before the angle is taken. In a wheelie the wheelie control holds the pitch, so the
/// planners answer for the roll alone.
pub fn roll_lean_cost(desired: DVec3, current: DVec3, heading: DVec3, tolerance: f64) -> f64 {
    let across = |v: DVec3| v - heading * v.dot(heading);
    lean_cost(across(desired), across(current), tolerance)
}

/// The lean cost of a bike whose planners hold its frame's roll (`BikeParams::
/// planners_cost_frame_roll`): ((roll − desired) / s)², both about the heading.
pub fn frame_roll_cost(roll: f64, desired: f64, tolerance: f64) -> f64 {
    ((roll - desired) / tolerance).powi(2)
}

/// The deepest lean of the centre of mass (eq. 4.7's, rad) a steady turn holds asking
/// `share` of the tyres' friction `mu`: there tan θ = a / g, and a ≤ share · μ · g. `None`
/// for a share of 0: the planners' goal is held to nothing (`BikeParams::
/// planners_grip_share`).
pub fn grip_lean_limit(mu: f64, share: f64) -> Option<f64> {
    (share > 0.0).then(|| (share * mu).atan())
}

/// The time scale (s) of a bike's fall over from its lean, an inverted pendulum's √(h / g)
/// for a centre of mass `height` above the contact line (about 0.25 s on the street bike).
pub fn fall_time_scale(height: f64, gravity: f64) -> f64 {
    (height / gravity).sqrt()
}

/// The lean `t` s into a plan that started at `start` and approaches `asked` with the time
/// constant `tau`: a first-order reference, as predictive controllers give a set point
/// (`BikeParams::planners_lean_reference`).
pub fn lean_on_the_way(start: f64, asked: f64, t: f64, tau: f64) -> f64 {
    asked + (start - asked) * (-t / tau.max(1e-6)).exp()
}

/// The lean (rad) a bike rolling at `rate` (rad/s) reaches in `tau` s, its fall's time
/// scale, if the roll goes on: what a lean cost looking ahead holds to the goal
/// (`BikeParams::planners_lean_lookahead`), as a sliding surface e + τ·ė does.
pub fn lean_ahead(lean: f64, rate: f64, tau: f64) -> f64 {
    lean + rate * tau
}

/// The player's turn: a stick value in [−1, 1] (positive right) scales the curvature up
/// to `max_curvature`; the lean it asks for is limited to `max_lean`, the bike's
/// (`BikeParams::max_lean`), so the player cannot ask for more than the bike can hold at
/// the current speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurnIntent {
    pub max_curvature: f64,
    pub max_lean: f64,
}

impl TurnIntent {
    /// Tightest circle 3 m in radius; at most `bike`'s lean.
    pub fn for_bike(bike: &BikeParams) -> Self {
        Self {
            max_curvature: 1.0 / 3.0,
            max_lean: bike.max_lean,
        }
    }
}

impl Default for TurnIntent {
    /// The reference bike's.
    fn default() -> Self {
        Self::for_bike(&BikeParams::default())
    }
}

impl TurnIntent {
    /// Desired lean (rad) for a stick value at a speed; non-finite input counts as 0.
    pub fn lean_for(&self, stick: f64, speed: f64, gravity: f64) -> f64 {
        let stick = if stick.is_finite() {
            stick.clamp(-1.0, 1.0)
        } else {
            0.0
        };
        let speed = if speed.is_finite() { speed } else { 0.0 };
        desired_lean(speed, stick * self.max_curvature, gravity)
            .clamp(-self.max_lean, self.max_lean)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const G: f64 = 9.81;

    #[test]
    fn eq_4_4_desired_lean() {
        // 36 km/h = 10 m/s on a 20 m circle: tan θ = 100 / (20 · 9.81) = 0.50968.
        let theta = desired_lean(10.0, 1.0 / 20.0, G);
        assert!((theta - 0.50968f64.atan()).abs() < 1e-5);
        assert!(
            (theta.to_degrees() - 27.0).abs() < 0.02,
            "{}",
            theta.to_degrees()
        );
        assert_eq!(desired_lean(10.0, 0.0, G), 0.0);
        assert!(
            (desired_lean(10.0, -1.0 / 20.0, G) + theta).abs() < 1e-12,
            "left turns lean left"
        );
    }

    #[test]
    fn eq_4_5_rodrigues_matches_a_quaternion_rotation() {
        let axis = DVec3::new(1.0, 2.0, -0.5).normalize();
        let v = DVec3::new(0.3, -1.0, 0.7);
        let by_formula = rodrigues(axis, 0.8) * v;
        let by_quaternion = glam::DQuat::from_axis_angle(axis, 0.8) * v;
        assert!((by_formula - by_quaternion).length() < 1e-12);
    }

    #[test]
    fn eq_4_6_desired_lean_vector_by_hand() {
        // Forward +x, up +y, 30° lean right: down (0, −1, 0) turns to (0, −cos 30°, −sin 30°).
        let b_d = desired_lean_vector(DVec3::X, DVec3::Y, 30f64.to_radians());
        assert!(
            (b_d - DVec3::new(0.0, -0.866_025_4, -0.5)).length() < 1e-6,
            "{b_d}"
        );
        // Upright: straight down.
        assert!((desired_lean_vector(DVec3::X, DVec3::Y, 0.0) + DVec3::Y).length() < 1e-12);
    }

    #[test]
    fn eq_4_7_lean_cost_by_hand() {
        // Desired straight down, current 10° off, tolerance 5°: (10/5)² = 4.
        let current = DVec3::new(0.0, -10f64.to_radians().cos(), 10f64.to_radians().sin());
        let c = lean_cost(-DVec3::Y, current, 5f64.to_radians());
        assert!((c - 4.0).abs() < 1e-9, "{c}");
        assert_eq!(lean_cost(-DVec3::Y, -DVec3::Y, 0.1), 0.0);
    }

    #[test]
    fn the_frame_roll_cost_is_the_squared_roll_error_in_tolerances() {
        let (deg, s) = (f64::to_radians, 5f64.to_radians());
        assert!((frame_roll_cost(deg(45.0), deg(35.0), s) - 4.0).abs() < 1e-12);
        assert_eq!(frame_roll_cost(deg(-20.0), deg(-20.0), s), 0.0);
        // A frame leaned 45° with its centre of mass at 41.2° (the street bike's crown)
        // meets a 45° goal; eq. 4.7 still finds 3.8° missing.
        let com = desired_lean_vector(DVec3::X, DVec3::Y, deg(41.2));
        let eq_4_7 = lean_cost(desired_lean_vector(DVec3::X, DVec3::Y, deg(45.0)), com, s);
        assert!((eq_4_7 - (3.8f64 / 5.0).powi(2)).abs() < 1e-9, "{eq_4_7}");
        assert_eq!(frame_roll_cost(deg(45.0), deg(45.0), s), 0.0);
    }

    #[test]
    fn the_grip_limit_is_the_lean_whose_turn_asks_that_share_of_the_friction() {
        assert_eq!(grip_lean_limit(1.0, 0.0), None);
        let limit = grip_lean_limit(1.0, 0.9).unwrap().to_degrees();
        assert!((limit - 41.99).abs() < 0.01, "{limit}");
        // All of it: tan 45° = 1, the turn's lateral acceleration is g.
        let all = grip_lean_limit(1.0, 1.0).unwrap().to_degrees();
        assert!((all - 45.0).abs() < 1e-9, "{all}");
        let wet = grip_lean_limit(0.5, 0.9).unwrap().to_degrees();
        assert!((wet - 24.23).abs() < 0.01, "{wet}");
    }

    #[test]
    fn the_lean_on_the_way_starts_where_the_plan_does_and_closes_in_on_the_goal() {
        let tau = fall_time_scale(0.6, 9.81);
        assert!((tau - 0.2473).abs() < 1e-4, "{tau}");
        assert!((lean_on_the_way(0.1, 0.7, 0.0, tau) - 0.1).abs() < 1e-12);
        // One time constant in, 1 − 1/e of the way.
        let one = lean_on_the_way(0.0, 1.0, tau, tau);
        assert!((one - (1.0 - (-1f64).exp())).abs() < 1e-12, "{one}");
        assert!((lean_on_the_way(0.0, 1.0, 10.0 * tau, tau) - 1.0).abs() < 1e-4);
        // Leaning out of a bend as into one.
        assert!(lean_on_the_way(0.7, 0.0, tau, tau) < 0.7);
    }

    #[test]
    fn the_roll_plane_cost_ignores_pitch() {
        // 30° nose up about the right (z) axis costs nothing in roll; 10° of roll does.
        let pitched = glam::DQuat::from_rotation_z(30f64.to_radians()) * -DVec3::Y;
        assert!(roll_lean_cost(-DVec3::Y, pitched, DVec3::X, 0.1) < 1e-20);
        assert!(lean_cost(-DVec3::Y, pitched, 0.1) > 20.0);
        let rolled = glam::DQuat::from_rotation_x(10f64.to_radians()) * pitched;
        let c = roll_lean_cost(-DVec3::Y, rolled, DVec3::X, 5f64.to_radians());
        assert!(c > 3.0 && c < 6.0, "{c}");
    }

    #[test]
    fn the_stick_cannot_lean_past_the_bikes_limit() {
        let deeper = BikeParams {
            max_lean: 45f64.to_radians(),
            ..BikeParams::default()
        };
        let lean = TurnIntent::for_bike(&deeper).lean_for(-1.0, 60.0 / 3.6, G);
        assert!((lean + 45f64.to_radians()).abs() < 1e-12, "{lean}");
        let intent = TurnIntent::default();
        assert_eq!(intent.lean_for(0.0, 8.0, G), 0.0);
        assert!((intent.lean_for(1.0, 25.0 / 3.6, G) - 30f64.to_radians()).abs() < 1e-12);
        assert!(intent.lean_for(-0.2, 3.0, G) < 0.0);
        assert_eq!(intent.lean_for(f64::NAN, 8.0, G), 0.0);
    }
}
