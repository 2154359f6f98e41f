//! Feet: sphere geoms on a body that stand on the terrain with a leg's give and a sole's
//! grip instead of a rigid body's. A foot is off the ground (disabled: ODE skips it when
//! colliding) until put down, and its touching the terrain is reported apart from the
//! body's, so a rider's foot on the road is not a part of the bike on the road. A foot
//! may have a leg that stretches (`World::set_foot_leg`): its sole then sits that far
//! along the leg from where it was built, and the stretch is part of the world's state.

use crate::{ffi, DVec3};

/// How a foot meets the ground: a spring–damper along the contact normal (the leg) and
/// Coulomb friction (the sole).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FootSurface {
    /// Coulomb friction coefficient of the sole.
    pub mu: f64,
    /// Spring rate (N/m) and damping (N·s/m) of the leg along the contact normal.
    pub stiffness: f64,
    pub damping: f64,
}

impl FootSurface {
    /// The contact's ERP and CFM that make it that spring–damper over a step of `dt` s
    /// (ODE's manual, "Joint error and the error reduction parameter": ERP = h k /
    /// (h k + c), CFM = 1 / (h k + c)).
    pub(crate) fn erp_cfm(&self, dt: f64) -> (f64, f64) {
        let denominator = dt * self.stiffness + self.damping;
        (dt * self.stiffness / denominator, 1.0 / denominator)
    }
}

/// A foot of a world: its geom and whether it touched the terrain in the last step.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Foot {
    pub(crate) geom: ffi::dGeomID,
    pub(crate) surface: FootSurface,
    pub(crate) touching: bool,
    /// The leg that moves the sole, if it has one (a foot without is fixed where built).
    pub(crate) leg: Option<Leg>,
}

/// A leg that stretches: the sole sits `extension` metres along `direction` (a unit
/// vector in the body's frame) from `sole`, where the foot was built on the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Leg {
    pub(crate) sole: DVec3,
    pub(crate) direction: DVec3,
    pub(crate) extension: f64,
}

impl Leg {
    /// Where the sole sits on the body (the geom's offset).
    pub(crate) fn sole_offset(&self) -> DVec3 {
        self.sole + self.direction * self.extension
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn erp_and_cfm_make_the_spring_and_damper() {
        let surface = FootSurface {
            mu: 0.8,
            stiffness: 20_000.0,
            damping: 1_000.0,
        };
        let (erp, cfm) = surface.erp_cfm(0.01);
        // h k = 200, h k + c = 1 200.
        assert!((erp - 200.0 / 1200.0).abs() < 1e-15);
        assert!((cfm - 1.0 / 1200.0).abs() < 1e-15);
    }
}
