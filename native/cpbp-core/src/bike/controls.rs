//! The bike's control vector, as in the thesis (§4.2): 13 joint target angular velocities
//! and 5 force-limit tuning values, one per class of joint.

/// Number of joint velocity targets.
pub const JOINT_TARGETS: usize = 13;
/// Number of force-limit tuning values.
pub const FORCE_TUNINGS: usize = 5;
/// Length of the control vector the optimizer samples.
pub const CONTROL_DIM: usize = JOINT_TARGETS + FORCE_TUNINGS;

/// Meaning of each entry of [`Controls::values`].
pub mod index {
    /// Steering hinge (rad/s, positive steers left).
    pub const STEER: usize = 0;
    /// Rear wheel (rad/s, positive rolls forward): throttle and brake.
    pub const REAR_WHEEL: usize = 1;
    /// Waist (torso on upper leg), three Euler axes: pitch, twist, roll.
    pub const WAIST: usize = 2;
    pub const KNEE: usize = 5;
    /// Shoulder, three Euler axes.
    pub const SHOULDER: usize = 6;
    pub const ELBOW: usize = 9;
    /// Wrist (hand on the handlebar), three Euler axes.
    pub const WRIST: usize = 10;
    /// Force tunings, in [`super::ForceClass`] order.
    pub const FORCE: usize = 13;
}

/// The five classes of joints whose force limits are tuned together.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ForceClass {
    Steering = 0,
    RearWheel = 1,
    Waist = 2,
    Knee = 3,
    Arms = 4,
}

/// Largest torque (N·m) of each force class at tuning 1. The rear wheel's covers braking
/// at about 1 g for bike and rider (0.30 m · 225 kg · 9.81 m/s² ≈ 660 N·m). The rider's
/// single leg and arm stand for both sides, so they get both sides' strength (knee and
/// hip extensors reach 200–300 N·m each in adults).
pub const MAX_TORQUE: [f64; FORCE_TUNINGS] = [60.0, 700.0, 600.0, 500.0, 200.0];

/// The entries the player's throttle and brake set directly (`DriveInput::apply`): the
/// rear wheel's velocity and force tuning. The planners and the learned controller decide
/// every other entry.
pub const DRIVE_ENTRIES: [usize; 2] = [
    index::REAR_WHEEL,
    index::FORCE + ForceClass::RearWheel as usize,
];

/// Lower and upper bound of every control entry.
pub const LOWER: [f64; CONTROL_DIM] = [
    -4.0, -10.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, -3.0, //
    0.05, 0.0, 0.05, 0.05, 0.05,
];
/// Upper bounds; the rear wheel's allows about 90 km/h with 0.30 m wheels.
pub const UPPER: [f64; CONTROL_DIM] = [
    4.0, 85.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, //
    1.0, 1.0, 1.0, 1.0, 1.0,
];

/// A control vector within bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Controls {
    values: [f64; CONTROL_DIM],
}

impl Default for Controls {
    /// Hold still: zero velocities, full force everywhere but the rear wheel, which rolls
    /// freely (tuning 0) so an idle bike neither brakes nor drives.
    fn default() -> Self {
        let mut values = [0.0; CONTROL_DIM];
        values[index::FORCE..].copy_from_slice(&[1.0, 0.0, 1.0, 1.0, 1.0]);
        Self { values }
    }
}

impl Controls {
    /// Builds controls from raw numbers: out-of-range values are clamped to the bounds and
    /// non-finite ones replaced by the default's value. Returns how many were changed so
    /// callers can warn about bad input.
    pub fn sanitized(raw: &[f64; CONTROL_DIM]) -> (Self, usize) {
        let fallback = Self::default().values;
        let mut changed = 0;
        let mut values = [0.0; CONTROL_DIM];
        for i in 0..CONTROL_DIM {
            let v = if raw[i].is_finite() {
                raw[i]
            } else {
                fallback[i]
            };
            values[i] = v.clamp(LOWER[i], UPPER[i]);
            if values[i] != raw[i] {
                changed += 1;
            }
        }
        (Self { values }, changed)
    }

    /// The entries, within bounds.
    pub fn values(&self) -> &[f64; CONTROL_DIM] {
        &self.values
    }

    /// Sets one entry, clamped to its bounds (non-finite input keeps the current value).
    pub fn set(&mut self, i: usize, value: f64) {
        if value.is_finite() {
            self.values[i] = value.clamp(LOWER[i], UPPER[i]);
        }
    }

    /// One entry.
    pub fn get(&self, i: usize) -> f64 {
        self.values[i]
    }

    /// Torque limit (N·m) of a force class at this control's tuning.
    pub fn max_torque(&self, class: ForceClass) -> f64 {
        MAX_TORQUE[class as usize] * self.values[index::FORCE + class as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_ordered_and_contain_the_default() {
        let default = Controls::default();
        for i in 0..CONTROL_DIM {
            assert!(LOWER[i] < UPPER[i], "entry {i}");
            assert!((LOWER[i]..=UPPER[i]).contains(&default.get(i)), "entry {i}");
        }
    }

    #[test]
    fn bad_numbers_are_clamped_or_replaced() {
        let mut raw = [0.5; CONTROL_DIM];
        raw[index::STEER] = f64::NAN;
        raw[index::REAR_WHEEL] = f64::INFINITY;
        raw[index::KNEE] = -1e300;
        raw[index::FORCE] = 7.0;
        let (controls, changed) = Controls::sanitized(&raw);
        assert_eq!(changed, 4);
        assert_eq!(controls.get(index::STEER), 0.0);
        assert_eq!(controls.get(index::REAR_WHEEL), 0.0);
        assert_eq!(controls.get(index::KNEE), LOWER[index::KNEE]);
        assert_eq!(controls.get(index::FORCE), 1.0);
    }

    #[test]
    fn max_torque_scales_with_the_tuning() {
        let mut controls = Controls::default();
        controls.set(index::FORCE + ForceClass::RearWheel as usize, 0.5);
        assert_eq!(
            controls.max_torque(ForceClass::RearWheel),
            0.5 * MAX_TORQUE[1]
        );
    }
}
