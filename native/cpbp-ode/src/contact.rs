//! Contact generation: which geoms touch, where a tyre's torus meets the ground, and the
//! surface every contact joint gets.

use std::os::raw::c_void;

use crate::feet::Foot;
use crate::tyre::{rolling_direction, Tyre};
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
    /// Per body, the sum of the normals (ground to body) of its contacts with the terrain.
    pub(crate) ground_normals: &'a mut Vec<Vec3>,
    /// Per body, its deepest contact with the terrain: where, and how deep.
    pub(crate) ground_points: &'a mut Vec<Option<(Vec3, f64)>>,
    pub(crate) tyres: &'a [Tyre],
    pub(crate) feet: &'a mut [Foot],
    /// The step's length (s): a foot's spring–damper depends on it.
    pub(crate) dt: f64,
    /// The feet's contacts of this step, by foot: their joints are made after every other
    /// contact's, in foot order, so their rows do not depend on the order ODE's space
    /// happens to list its geoms in (which after a reset differs from a fresh world's).
    pub(crate) foot_contacts: Vec<(usize, ffi::dContact, ffi::dBodyID, ffi::dBodyID)>,
}

impl CollideContext<'_> {
    /// Makes the contact joints of the feet gathered during the collision, in foot order.
    pub(crate) fn attach_foot_contacts(&mut self) {
        self.foot_contacts.sort_by_key(|(foot, ..)| *foot);
        for (_, contact, b1, b2) in &self.foot_contacts {
            // SAFETY: the world, group and bodies are this world's, alive for the step.
            unsafe {
                let joint = ffi::dJointCreateContact(self.world, self.contacts, contact);
                ffi::dJointAttach(joint, *b1, *b2);
            }
        }
    }
}

/// Surface mode of a contact: soft, with friction proportional to the normal force (the
/// pyramid of `dContactApprox1`). A tyre's contact also sets `dContactApprox1_N`, which
/// without rolling friction changes nothing in the contact itself: it asks the direct
/// solver (ODE patch 04) to bound the tyre's friction by the normal force its own
/// traction loads, so a spinning or locked wheel grips with the weight it carries.
fn friction_mode(tyre: bool) -> i32 {
    let pyramid = ffi::dContactApprox1_1 | ffi::dContactApprox1_2;
    let loaded = if tyre { ffi::dContactApprox1_N } else { 0 };
    (ffi::dContactSoftERP | ffi::dContactSoftCFM | pyramid | loaded) as i32
}

/// Reads a vector ODE handed out as a pointer to at least three reals.
///
/// # Safety
/// `p` must point to three readable `f64`s.
pub(crate) unsafe fn read_vec3(p: *const f64) -> Vec3 {
    // SAFETY: guaranteed by the caller.
    unsafe { [*p, *p.add(1), *p.add(2)] }
}

/// What `shape_tyre` made of a contact.
enum Shaped {
    /// Neither geom is a tyre: the contact as ODE found it.
    NotTyre,
    /// A tyre's, moved to where its torus touches; `rolling` is the direction its friction
    /// follows when the tyre asks for that (`Tyre::friction_follows_wheel`).
    Tyre { rolling: Option<[f64; 3]> },
}

/// If either geom is a tyre, moves the contact to where its torus touches. Returns `None`
/// when the torus does not touch there (the contact is dropped).
///
/// # Safety
/// `o1` and `o2` must be live geoms whose data is 0 or a tyre index + 1 into `tyres`.
unsafe fn shape_tyre(
    tyres: &[Tyre],
    o1: ffi::dGeomID,
    o2: ffi::dGeomID,
    contact: &mut ffi::dContactGeom,
) -> Option<Shaped> {
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
            let position = [contact.pos[0], contact.pos[1], contact.pos[2]];
            return match tyre.contact(centre, axle, normal, contact.depth, position) {
                Some(touch) => {
                    let p = touch.position;
                    let n = touch.normal;
                    contact.pos = [p[0], p[1], p[2], 0.0];
                    contact.normal = [n[0] * sign, n[1] * sign, n[2] * sign, 0.0];
                    contact.depth = touch.depth;
                    let rolling = if tyre.friction_follows_wheel {
                        rolling_direction(axle, touch.normal)
                    } else {
                        None
                    };
                    Some(Shaped::Tyre { rolling })
                }
                None => None,
            };
        }
        Some(Shaped::NotTyre)
    }
}

/// Whether `contact` repeats one already made for this pair: at an edge of a mesh ODE
/// reports one contact per face meeting there, which a tyre turns into the same point.
fn repeats(made: &[ffi::dContactGeom], contact: &ffi::dContactGeom) -> bool {
    made.iter()
        .any(|c| c.pos == contact.pos && c.normal == contact.normal && c.depth == contact.depth)
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
        let foot = context
            .feet
            .iter()
            .position(|f| f.geom == o1 || f.geom == o2);
        if let Some(index) = foot {
            let foot = &mut context.feet[index];
            let (erp, cfm) = foot.surface.erp_cfm(context.dt);
            for contact in contacts.iter_mut().take(count.max(0) as usize) {
                contact.surface.mode = friction_mode(false);
                contact.surface.mu = foot.surface.mu;
                contact.surface.soft_erp = erp;
                contact.surface.soft_cfm = cfm;
                context.foot_contacts.push((index, *contact, b1, b2));
            }
            foot.touching |= count > 0;
            return;
        }
        let mut made: Vec<ffi::dContactGeom> = Vec::new();
        for contact in contacts.iter_mut().take(count.max(0) as usize) {
            let (tyre, rolling) = match shape_tyre(context.tyres, o1, o2, &mut contact.geom) {
                None => continue,
                Some(Shaped::NotTyre) => (false, None),
                Some(Shaped::Tyre { .. }) if repeats(&made, &contact.geom) => continue,
                Some(Shaped::Tyre { rolling }) => (true, rolling),
            };
            made.push(contact.geom);
            contact.surface.mode = friction_mode(tyre);
            if let Some(d) = rolling {
                contact.surface.mode |= ffi::dContactFDir1 as i32;
                contact.fdir1 = [d[0], d[1], d[2], 0.0];
            }
            contact.surface.mu = context.surface.mu;
            contact.surface.soft_erp = context.surface.soft_erp;
            contact.surface.soft_cfm = context.surface.soft_cfm;
            let joint = ffi::dJointCreateContact(context.world, context.contacts, contact);
            ffi::dJointAttach(joint, b1, b2);
        }
        if !made.is_empty() && (b1.is_null() || b2.is_null()) {
            // ODE's normal points into o1: towards the body when the body is o1's.
            let (body, sign) = if b1.is_null() { (b2, -1.0) } else { (b1, 1.0) };
            let index = ffi::dBodyGetData(body) as usize;
            context.touching_static[index] = true;
            let sum = &mut context.ground_normals[index];
            for contact in &made {
                for (axis, total) in sum.iter_mut().enumerate() {
                    *total += sign * contact.normal[axis];
                }
            }
            let deepest = &mut context.ground_points[index];
            for contact in &made {
                if deepest.is_none_or(|(_, depth)| contact.depth > depth) {
                    let at = [contact.pos[0], contact.pos[1], contact.pos[2]];
                    *deepest = Some((at, contact.depth));
                }
            }
        }
    }
}
