//! Integral action for the network alone. The network maps the state to a steering angle,
//! so a small error in what it learned stays as a steady lean error in a long turn (the
//! round-3 model held a 15° turn 0.26° short, every seed alike). The arcade controller
//! does not have this: it integrates a steering *rate*, so it keeps turning the bar until
//! the lean is right. The trim adds that integral outside the network: it moves the lean
//! the network is asked for by the error that stays, within a small bound, so the network
//! still sees a request like those it was trained on.
//!
//! Classic anti-windup: it integrates only near a steady state (the lean within
//! [`TRIM_WINDOW`] of the request, at riding speed) and otherwise drains, so a slalom's
//! swings, a fall or a stop leave nothing behind.

use super::super::Goal;

/// How fast (1/s) the trim takes up a lean error that stays: the remaining error decays
/// with a time constant of 1 / gain. In the scenario tool's 15° turn (RMS over the last
/// 5 s) 1/s left 0.063°, 2/s 0.039°, 3/s 0.024°, 5/s 0.036° (the loop starts to ring).
pub const TRIM_GAIN: f64 = 3.0;

/// The most the request is moved (rad): 2°, eight times the bias measured, small against
/// the requests' spread in training.
pub const TRIM_LIMIT: f64 = 2.0 * std::f64::consts::PI / 180.0;

/// Lean errors (rad) larger than this are a manoeuvre under way, not a bias: 3°. At 6° the
/// trim winds up while a turn is entered and the shove's largest lean grows by 1.2°.
pub const TRIM_WINDOW: f64 = 3.0 * std::f64::consts::PI / 180.0;

/// Below this forward speed (m/s) the steering no longer holds a lean the same way (the
/// walking pace, the stops); the trim drains there.
pub const TRIM_MIN_SPEED: f64 = 2.0;

/// The integral of the lean error, in the request's units (rad).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LeanTrim {
    trim: f64,
}

impl LeanTrim {
    /// The current correction (rad, positive asks for more lean to the right).
    pub fn trim(&self) -> f64 {
        self.trim
    }

    /// Forgets the correction (the ride jumped).
    pub fn reset(&mut self) {
        self.trim = 0.0;
    }

    /// Takes one control step of `dt` seconds at lean `lean` and forward speed `speed`
    /// into account and returns `goal` with its lean moved by the trim. Non-finite
    /// measurements leave the trim as it was.
    pub fn trimmed(&mut self, goal: &Goal, lean: f64, speed: f64, dt: f64) -> Goal {
        let error = goal.lean - lean;
        if error.is_finite() && speed.is_finite() && dt.is_finite() && dt > 0.0 {
            let settled = error.abs() < TRIM_WINDOW && speed >= TRIM_MIN_SPEED;
            self.trim = if settled {
                (self.trim + TRIM_GAIN * error * dt).clamp(-TRIM_LIMIT, TRIM_LIMIT)
            } else {
                self.trim * (-TRIM_GAIN * dt).exp()
            };
        }
        Goal {
            lean: goal.lean + self.trim,
            ..*goal
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bike::DriveInput;

    const DT: f64 = 1.0 / 30.0;

    /// A bike whose lean settles to the request less a constant bias, with a lag.
    fn ride(trim: &mut LeanTrim, asked: f64, bias: f64, speed: f64, seconds: f64) -> f64 {
        let goal = Goal::riding(asked, DriveInput::default());
        let mut lean = asked;
        for _ in 0..(seconds / DT) as usize {
            let request = trim.trimmed(&goal, lean, speed, DT).lean;
            lean += (request - bias - lean) * (DT / 0.3);
        }
        lean
    }

    #[test]
    fn a_steady_bias_is_taken_out() {
        let mut trim = LeanTrim::default();
        let bias = 0.26_f64.to_radians();
        let lean = ride(&mut trim, 15_f64.to_radians(), bias, 5.5, 8.0);
        assert!(
            (lean - 15_f64.to_radians()).abs() < 0.01_f64.to_radians(),
            "{}",
            lean.to_degrees()
        );
        assert!((trim.trim() - bias).abs() < 0.01_f64.to_radians());
    }

    #[test]
    fn the_trim_is_bounded_and_drains() {
        let mut trim = LeanTrim::default();
        // An error inside the window that no trim can close: the trim stops at its limit.
        ride(&mut trim, 0.0, 2.5_f64.to_radians(), 5.5, 10.0);
        assert_eq!(trim.trim(), TRIM_LIMIT);
        // At walking pace it drains instead of integrating.
        ride(&mut trim, 0.0, 0.0, 1.0, 5.0);
        assert!(trim.trim().abs() < 0.01 * TRIM_LIMIT);
        trim.reset();
        assert_eq!(trim.trim(), 0.0);
    }

    #[test]
    fn a_manoeuvre_and_broken_numbers_leave_it_alone() {
        let mut trim = LeanTrim::default();
        let goal = Goal::riding(0.3, DriveInput::default());
        // 17° off: a turn being entered, not a bias.
        assert_eq!(trim.trimmed(&goal, 0.0, 5.0, DT).lean, 0.3);
        assert_eq!(trim.trimmed(&goal, f64::NAN, 5.0, DT).lean, 0.3);
        assert_eq!(trim.trimmed(&goal, 0.29, f64::INFINITY, DT).lean, 0.3);
        assert_eq!(trim.trim(), 0.0);
    }
}
