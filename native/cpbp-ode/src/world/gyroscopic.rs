//! The gyroscopic torque −ω × Iω of a body, explicitly.
//!
//! ODE computes it implicitly by default (Lacoursière 2006): the torque that would turn a
//! *free* body's momentum implicitly, applied before the constraints are solved. That is
//! stable for any body, but for a wheel held by its axle it weakens the coupling between
//! spin and frame: a gyroscope on a pivot precesses 7 % too fast at 1/120 s (−1 % with the
//! explicit term, tests/world.rs), and the benchmark bicycle capsizes from 4.9 m/s instead
//! of 6.0 (docs/physics.md). Wheels therefore take the explicit term: ODE's own is
//! switched off for them and this torque is added before every step. The explicit term
//! is not for free tumbling bodies: a free wheel wobbling at 2 rad/s while spinning at
//! 20 rad/s gains about 8 % of its rate per second at 1/120 s.

use super::World;
use crate::ffi;
use crate::BodyId;

/// How a body's gyroscopic torque enters its step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Gyroscopic {
    /// ODE's implicit term: stable for any body, damps fast precession.
    #[default]
    Implicit,
    /// −ω × Iω from the step's starting velocity: exact precession for a symmetric
    /// spinner such as a wheel; not for tumbling asymmetric bodies.
    Explicit,
}

impl World {
    /// Chooses how `body`'s gyroscopic torque is computed.
    pub fn set_gyroscopic(&mut self, body: BodyId, mode: Gyroscopic) {
        let raw = self.bodies[body.0];
        // SAFETY: the body belongs to this live world.
        unsafe { ffi::dBodySetGyroscopicMode(raw, i32::from(mode == Gyroscopic::Implicit)) };
        self.explicit_gyroscopic.retain(|b| *b != body.0);
        if mode == Gyroscopic::Explicit {
            self.explicit_gyroscopic.push(body.0);
        }
    }

    /// Adds the explicit gyroscopic torque to every body that asked for it. ODE clears a
    /// body's torque accumulator after each step, so this is done before each step.
    pub(super) fn add_explicit_gyroscopic_torques(&mut self) {
        for &index in &self.explicit_gyroscopic {
            let body = self.bodies[index];
            // SAFETY: the body belongs to this live world; ODE returns pointers to its
            // 3×4 row-major rotation and its angular velocity, read before any change.
            unsafe {
                let mut mass: ffi::dMass = std::mem::zeroed();
                ffi::dBodyGetMass(body, &mut mass);
                let r = std::slice::from_raw_parts(ffi::dBodyGetRotation(body), 12);
                let w = std::slice::from_raw_parts(ffi::dBodyGetAngularVel(body), 3);
                let torque = gyroscopic_torque(r, &mass.I, [w[0], w[1], w[2]]);
                ffi::dBodyAddTorque(body, torque[0], torque[1], torque[2]);
            }
        }
    }
}

/// −ω × (R I Rᵀ ω) for a body with rotation `r` and body-frame inertia `inertia` (both
/// ODE's 3×4 row-major matrices) turning at `w` (world frame).
fn gyroscopic_torque(r: &[f64], inertia: &[f64], w: [f64; 3]) -> [f64; 3] {
    let row = |m: &[f64], i: usize, v: [f64; 3]| {
        m[4 * i] * v[0] + m[4 * i + 1] * v[1] + m[4 * i + 2] * v[2]
    };
    let column = |m: &[f64], i: usize, v: [f64; 3]| m[i] * v[0] + m[4 + i] * v[1] + m[8 + i] * v[2];
    let in_body = [column(r, 0, w), column(r, 1, w), column(r, 2, w)];
    let momentum_body = [
        row(inertia, 0, in_body),
        row(inertia, 1, in_body),
        row(inertia, 2, in_body),
    ];
    let l = [
        row(r, 0, momentum_body),
        row(r, 1, momentum_body),
        row(r, 2, momentum_body),
    ];
    [
        -(w[1] * l[2] - w[2] * l[1]),
        -(w[2] * l[0] - w[0] * l[2]),
        -(w[0] * l[1] - w[1] * l[0]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    const IDENTITY: [f64; 12] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];

    #[test]
    fn a_body_spinning_about_a_principal_axis_feels_no_torque() {
        let inertia = [2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        assert_eq!(
            gyroscopic_torque(&IDENTITY, &inertia, [0.0, 0.0, 5.0]),
            [0.0; 3]
        );
    }

    #[test]
    fn a_precessing_wheel_feels_the_textbook_torque() {
        // Spin 10 rad/s about z (spin inertia 2), precession 1 rad/s about y (diametral 1):
        // L = (0, 1, 20), −ω × L = −((1·20 − 10·1), 0, 0) = (−10, 0, 0).
        let inertia = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
        assert_eq!(
            gyroscopic_torque(&IDENTITY, &inertia, [0.0, 1.0, 10.0]),
            [-10.0, 0.0, 0.0]
        );
    }

    #[test]
    fn the_torque_turns_with_the_body() {
        // The same wheel turned 90° about x (its spin axis now along −y in the world).
        let turned = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        let inertia = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
        // Body-frame ω (0, 1, 10) is world ω = R·(0, 1, 10) = (0, −10, 1).
        let torque = gyroscopic_torque(&turned, &inertia, [0.0, -10.0, 1.0]);
        // In the world the torque is R·(−10, 0, 0).
        assert_eq!(torque, [-10.0, 0.0, 0.0]);
    }
}
