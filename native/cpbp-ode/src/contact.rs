//! Contact generation: which geoms touch, where a tyre's torus meets the ground, and the
//! surface every contact joint gets.

use std::os::raw::c_void;

use crate::{ffi, Vec3};

/// Most contact points generated for one pair of geoms in one step.
const MAX_CONTACTS_PER_PAIR: usize = 8;

/// Contact surface shared by every contact of a world: Coulomb friction and softness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceParams {
    /// Coulomb friction coefficient.
    pub mu: f64,
    /// Contact constraint error reduction (0–1).
    pub soft_erp: f64,
    /// Contact constraint force mixing (softness).
    pub soft_cfm: f64,
}

impl Default for SurfaceParams {
    fn default() -> Self {
        Self {
            mu: 1.0,
            soft_erp: 0.2,
            soft_cfm: 1e-5,
        }
    }
}

/// What the collision callback needs of the world being stepped.
pub(crate) struct CollideContext<'a> {
    pub(crate) world: ffi::dWorldID,
    pub(crate) contacts: ffi::dJointGroupID,
    pub(crate) surface: SurfaceParams,
    pub(crate) touching_static: &'a mut Vec<bool>,
    pub(crate) tyres: &'a [Tyre],
}

/// A torus tyre on a sphere geom (see `World::add_tyre`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tyre {
    pub(crate) radius: f64,
    pub(crate) crown: f64,
}

impl Tyre {
    /// Moves a contact found for the bounding sphere to where the torus touches: `centre`
    /// and `axle` of the wheel, `normal` pointing from the ground towards the wheel, and the
    /// sphere's penetration `depth`. Returns the torus contact's position and depth, or
    /// `None` when the torus does not reach the ground there.
    fn contact(
        &self,
        centre: [f64; 3],
        axle: [f64; 3],
        normal: [f64; 3],
        depth: f64,
    ) -> Option<([f64; 3], f64)> {
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let add =
            |a: [f64; 3], b: [f64; 3], k: f64| [a[0] + b[0] * k, a[1] + b[1] * k, a[2] + b[2] * k];
        // The ground plane through the sphere's deepest point, raised by the penetration.
        let surface = add(add(centre, normal, -self.radius), normal, depth);
        // Towards the ground within the wheel's plane.
        let down = add(
            [-normal[0], -normal[1], -normal[2]],
            axle,
            dot(normal, axle),
        );
        let length = dot(down, down).sqrt();
        let tube = if length < 1e-9 {
            centre // lying flat: the tube circle is level, use the centre
        } else {
            add(centre, down, (self.radius - self.crown) / length)
        };
        let height = dot(
            [
                tube[0] - surface[0],
                tube[1] - surface[1],
                tube[2] - surface[2],
            ],
            normal,
        );
        let torus_depth = self.crown - height;
        (torus_depth > 0.0).then(|| (add(tube, normal, -self.crown), torus_depth))
    }
}

/// Reads a vector ODE handed out as a pointer to at least three reals.
///
/// # Safety
/// `p` must point to three readable `f64`s.
pub(crate) unsafe fn read_vec3(p: *const f64) -> Vec3 {
    // SAFETY: guaranteed by the caller.
    unsafe { [*p, *p.add(1), *p.add(2)] }
}

/// If either geom is a tyre, moves the contact to where its torus touches. Returns false
/// when the torus does not touch there (the contact is dropped).
///
/// # Safety
/// `o1` and `o2` must be live geoms whose data is 0 or a tyre index + 1 into `tyres`.
unsafe fn shape_tyre(
    tyres: &[Tyre],
    o1: ffi::dGeomID,
    o2: ffi::dGeomID,
    contact: &mut ffi::dContactGeom,
) -> bool {
    // SAFETY: guaranteed by the caller; ODE returns pointers to 3 (position) and 12
    // (rotation, row-major 3×4) reals.
    unsafe {
        for (geom, sign) in [(o1, 1.0), (o2, -1.0)] {
            let index = ffi::dGeomGetData(geom) as usize;
            if index == 0 || ffi::dGeomGetClass(geom) != ffi::dSphereClass as i32 {
                continue;
            }
            let tyre = tyres[index - 1];
            let centre = read_vec3(ffi::dGeomGetPosition(geom));
            let r = ffi::dGeomGetRotation(geom);
            // The body's local z in world coordinates.
            let axle = [*r.add(2), *r.add(6), *r.add(10)];
            // ODE's normal points into o1; we want it from the ground towards the wheel.
            let n = contact.normal;
            let normal = [n[0] * sign, n[1] * sign, n[2] * sign];
            return match tyre.contact(centre, axle, normal, contact.depth) {
                Some((position, depth)) => {
                    contact.pos = [position[0], position[1], position[2], 0.0];
                    contact.depth = depth;
                    true
                }
                None => false,
            };
        }
        true
    }
}

/// ODE's collision callback for `dSpaceCollide`: creates the contact joints of one pair.
///
/// # Safety
/// `data` must be a live `CollideContext` of the world whose space holds both geoms.
pub(crate) unsafe extern "C" fn near_callback(
    data: *mut c_void,
    o1: ffi::dGeomID,
    o2: ffi::dGeomID,
) {
    // SAFETY: `data` is the CollideContext passed by World::step, alive for this call; the
    // geoms come from that world's space.
    unsafe {
        let context = &mut *(data as *mut CollideContext);
        let b1 = ffi::dGeomGetBody(o1);
        let b2 = ffi::dGeomGetBody(o2);
        if b1.is_null() && b2.is_null() {
            return;
        }
        if !b1.is_null()
            && !b2.is_null()
            && ffi::dAreConnectedExcluding(b1, b2, ffi::dJointTypeContact as i32) != 0
        {
            return;
        }
        let mut contacts: [ffi::dContact; MAX_CONTACTS_PER_PAIR] = Default::default();
        let count = ffi::dCollide(
            o1,
            o2,
            MAX_CONTACTS_PER_PAIR as i32,
            &mut contacts[0].geom,
            std::mem::size_of::<ffi::dContact>() as i32,
        );
        let mut created = 0;
        for contact in contacts.iter_mut().take(count.max(0) as usize) {
            if !shape_tyre(context.tyres, o1, o2, &mut contact.geom) {
                continue;
            }
            created += 1;
            contact.surface.mode =
                (ffi::dContactSoftERP | ffi::dContactSoftCFM | ffi::dContactApprox1) as i32;
            contact.surface.mu = context.surface.mu;
            contact.surface.soft_erp = context.surface.soft_erp;
            contact.surface.soft_cfm = context.surface.soft_cfm;
            let joint = ffi::dJointCreateContact(context.world, context.contacts, contact);
            ffi::dJointAttach(joint, b1, b2);
        }
        if created > 0 && (b1.is_null() || b2.is_null()) {
            let body = if b1.is_null() { b2 } else { b1 };
            context.touching_static[ffi::dBodyGetData(body) as usize] = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_upright_tyre_touches_like_a_sphere() {
        let tyre = Tyre {
            radius: 0.3,
            crown: 0.06,
        };
        let (pos, depth) = tyre
            .contact([0.0, 0.29, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 0.01)
            .unwrap();
        assert!((depth - 0.01).abs() < 1e-12);
        assert!((pos[1] - (-0.01)).abs() < 1e-12 && pos[2].abs() < 1e-12);
    }

    #[test]
    fn a_leaning_tyre_touches_in_its_own_plane() {
        // Leaning 30° to +z (top towards +z): the contact stays in the wheel's plane, so it
        // lies (r − ρ) sin 30° to the −z side of the centre, which leans out beyond it; a
        // sphere would touch right under the centre.
        let (r, crown, lean) = (0.3, 0.06, 30f64.to_radians());
        let tyre = Tyre { radius: r, crown };
        let axle = [0.0, -lean.sin(), lean.cos()];
        let resting = (r - crown) * lean.cos() + crown;
        let centre = [0.0, resting - 0.002, 0.0];
        let sphere_depth = r - centre[1];
        let (pos, depth) = tyre
            .contact(centre, axle, [0.0, 1.0, 0.0], sphere_depth)
            .unwrap();
        assert!((depth - 0.002).abs() < 1e-12, "depth {depth}");
        assert!(
            (pos[2] + (r - crown) * lean.sin()).abs() < 1e-12,
            "contact at z = {}",
            pos[2]
        );
    }

    #[test]
    fn a_tyre_lying_flat_rests_on_its_crown() {
        let tyre = Tyre {
            radius: 0.3,
            crown: 0.06,
        };
        let (_, depth) = tyre
            .contact([0.0, 0.05, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], 0.25)
            .unwrap();
        assert!((depth - 0.01).abs() < 1e-12);
        assert_eq!(
            tyre.contact([0.0, 0.07, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], 0.23),
            None
        );
    }
}
