//! Mass properties of a rigid body, as ODE computes them for solid shapes.

use crate::{ffi, DVec3};

/// Mass properties of a rigid body, in the body's own frame.
#[derive(Clone, Copy, Debug)]
pub struct Mass {
    pub(crate) raw: ffi::dMass,
}

impl Mass {
    /// A solid sphere of the given total mass (kg) and radius (m).
    pub fn sphere(total: f64, radius: f64) -> Self {
        let mut raw = ffi::dMass::default();
        // SAFETY: `raw` is a valid, exclusively borrowed dMass.
        unsafe { ffi::dMassSetSphereTotal(&mut raw, total, radius) };
        Self { raw }
    }

    /// A solid box of the given total mass (kg) and full side lengths (m).
    pub fn cuboid(total: f64, size: DVec3) -> Self {
        let mut raw = ffi::dMass::default();
        // SAFETY: `raw` is a valid, exclusively borrowed dMass.
        unsafe { ffi::dMassSetBoxTotal(&mut raw, total, size[0], size[1], size[2]) };
        Self { raw }
    }

    /// A solid cylinder along the body's local `axis` (0 = x, 1 = y, 2 = z).
    pub fn cylinder(total: f64, axis: usize, radius: f64, length: f64) -> Self {
        let mut raw = ffi::dMass::default();
        // SAFETY: `raw` is a valid, exclusively borrowed dMass; ODE numbers axes from 1.
        unsafe { ffi::dMassSetCylinderTotal(&mut raw, total, axis as i32 + 1, radius, length) };
        Self { raw }
    }

    /// A solid capsule along the body's local z axis (ODE's capsule direction).
    pub fn capsule(total: f64, radius: f64, length: f64) -> Self {
        let mut raw = ffi::dMass::default();
        // SAFETY: as above; direction 3 is z.
        unsafe { ffi::dMassSetCapsuleTotal(&mut raw, total, 3, radius, length) };
        Self { raw }
    }

    /// A body of the given total mass (kg) and inertia tensor about its centre of mass
    /// (kg·m², in the body's frame), as tabulated for a real part; `None` if ODE finds the
    /// tensor impossible (not positive definite or violating the triangle inequality).
    pub fn with_inertia(total: f64, inertia: [[f64; 3]; 3]) -> Option<Self> {
        let mut raw = ffi::dMass::default();
        let i = inertia;
        // SAFETY: `raw` is a valid, exclusively borrowed dMass; the centre of mass is the
        // body's origin, as ODE requires of a body's mass.
        let valid = unsafe {
            ffi::dMassSetParameters(
                &mut raw, total, 0.0, 0.0, 0.0, i[0][0], i[1][1], i[2][2], i[0][1], i[0][2],
                i[1][2],
            );
            ffi::dMassCheck(&raw) != 0
        };
        let symmetric = i[0][1] == i[1][0] && i[0][2] == i[2][0] && i[1][2] == i[2][1];
        // I_xx + I_yy − I_zz = 2∫z² dm ≥ 0 in any frame, and so on; ODE checks only that
        // the tensor is positive definite.
        let (x, y, z) = (i[0][0], i[1][1], i[2][2]);
        let triangle = x + y >= z && y + z >= x && z + x >= y;
        (valid && symmetric && triangle && total > 0.0).then_some(Self { raw })
    }

    /// Total mass in kg.
    pub fn total(&self) -> f64 {
        self.raw.mass
    }
}
