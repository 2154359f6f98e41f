//! A world's collision geoms: adding shapes, placing them, and keeping their order.

use std::os::raw::c_void;
use std::sync::Arc;

use super::{GeomId, World};
use crate::shared_data::{HeightFieldData, TriMeshData};
use crate::tyre::Tyre;
use crate::{ffi, ode_quat, BodyId, DQuat, DVec3};

/// Collision categories: bodies collide with static terrain only, never with each other
/// (a bike's parts are held by joints; the rider must not snag on the bike).
const CATEGORY_BODY: u64 = 1;
const CATEGORY_STATIC: u64 = 2;

impl World {
    /// Adds a sphere geom, attached to `body` or static when `body` is `None`.
    pub fn add_sphere(&mut self, radius: f64, body: Option<BodyId>) -> GeomId {
        // SAFETY: the space is alive; the geom is destroyed with it.
        let geom = unsafe { ffi::dCreateSphere(self.space, radius) };
        self.attach(geom, body)
    }

    /// Adds a box geom with full side lengths, attached to `body` or static.
    pub fn add_box(&mut self, size: DVec3, body: Option<BodyId>) -> GeomId {
        // SAFETY: as for add_sphere.
        let geom = unsafe { ffi::dCreateBox(self.space, size[0], size[1], size[2]) };
        self.attach(geom, body)
    }

    /// Adds a wheel with a round tyre: a torus of outer radius `radius` and crown (tube)
    /// radius `crown`, spinning about its body's local z axis. ODE has no torus; a sphere of
    /// the outer radius finds the contacts and each is moved to where the torus touches, so
    /// a leaning wheel touches in its own plane, as a real tyre does, instead of under its
    /// centre (a sphere is a tyre whose crown is as round as the whole wheel).
    pub fn add_tyre(&mut self, radius: f64, crown: f64, body: BodyId) -> GeomId {
        let geom = self.add_sphere(radius, Some(body));
        self.tyres.push(Tyre {
            radius,
            crown,
            friction_follows_wheel: false,
        });
        // SAFETY: the geom belongs to this world; its data is the tyre's index + 1.
        unsafe { ffi::dGeomSetData(self.geoms[geom.0], self.tyres.len() as *mut c_void) };
        geom
    }

    /// Makes the friction of `tyre`'s contacts act along and across the wheel (`on`) or
    /// along the two axes ODE derives from the contact normal (the default: world axes on
    /// level ground, so grip depends on heading). Does nothing to a geom that is no tyre.
    pub fn set_tyre_friction_follows_wheel(&mut self, tyre: GeomId, on: bool) {
        let geom = self.geoms[tyre.0];
        // SAFETY: the geom belongs to this world; a tyre is a sphere whose data is its
        // index + 1.
        let index = unsafe {
            if ffi::dGeomGetClass(geom) != ffi::dSphereClass as i32 {
                return;
            }
            ffi::dGeomGetData(geom) as usize
        };
        if let Some(tyre) = index.checked_sub(1).and_then(|i| self.tyres.get_mut(i)) {
            tyre.friction_follows_wheel = on;
        }
    }

    /// Adds a capsule geom along its local z axis (cylinder length without the caps).
    pub fn add_capsule(&mut self, radius: f64, length: f64, body: Option<BodyId>) -> GeomId {
        // SAFETY: as for add_sphere.
        let geom = unsafe { ffi::dCreateCapsule(self.space, radius, length) };
        self.attach(geom, body)
    }

    /// Adds a cylinder geom along its local z axis.
    pub fn add_cylinder(&mut self, radius: f64, length: f64, body: Option<BodyId>) -> GeomId {
        // SAFETY: as for add_sphere.
        let geom = unsafe { ffi::dCreateCylinder(self.space, radius, length) };
        self.attach(geom, body)
    }

    /// Adds a static triangle mesh; the data is shared, not copied.
    pub fn add_trimesh(&mut self, data: &Arc<TriMeshData>) -> GeomId {
        // SAFETY: the data outlives the geom: this world keeps an Arc to it and destroys
        // its space (and so the geom) before dropping the Arc.
        let geom = unsafe { ffi::dCreateTriMesh(self.space, data.id, None, None, None) };
        self.shared_meshes.push(Arc::clone(data));
        self.attach(geom, None)
    }

    /// Adds a static height field (Y up, centred on the geom's position).
    pub fn add_heightfield(&mut self, data: &Arc<HeightFieldData>) -> GeomId {
        // SAFETY: as for add_trimesh; 1 = placeable.
        let geom = unsafe { ffi::dCreateHeightfield(self.space, data.id, 1) };
        self.shared_heights.push(Arc::clone(data));
        self.attach(geom, None)
    }

    /// Adds a static infinite plane `normal · p = offset` (normal need not be unit length).
    pub fn add_plane(&mut self, normal: DVec3, offset: f64) -> GeomId {
        // SAFETY: as for add_sphere.
        let geom =
            unsafe { ffi::dCreatePlane(self.space, normal[0], normal[1], normal[2], offset) };
        self.attach(geom, None)
    }

    fn attach(&mut self, geom: ffi::dGeomID, body: Option<BodyId>) -> GeomId {
        // SAFETY: the geom belongs to this world's space; the body to this world.
        unsafe {
            if let Some(body) = body {
                ffi::dGeomSetBody(geom, self.bodies[body.0]);
                ffi::dGeomSetCategoryBits(geom, CATEGORY_BODY as _);
                ffi::dGeomSetCollideBits(geom, CATEGORY_STATIC as _);
            } else {
                ffi::dGeomSetCategoryBits(geom, CATEGORY_STATIC as _);
                ffi::dGeomSetCollideBits(geom, CATEGORY_BODY as _);
            }
        }
        self.geoms.push(geom);
        GeomId(self.geoms.len() - 1)
    }

    /// Sets the world-frame position of a static geom (planes are placed by their equation).
    pub fn set_geom_position(&mut self, geom: GeomId, position: DVec3) {
        // SAFETY: the geom belongs to this world.
        unsafe { ffi::dGeomSetPosition(self.geoms[geom.0], position[0], position[1], position[2]) };
    }

    /// Sets the world-frame orientation of a static geom.
    pub fn set_geom_quaternion(&mut self, geom: GeomId, q: DQuat) {
        let q = ode_quat(q);
        // SAFETY: the geom belongs to this world; q is 4 reals.
        unsafe { ffi::dGeomSetQuaternion(self.geoms[geom.0], q.as_ptr()) };
    }

    /// Places a body geom relative to its body (position and orientation in body frame).
    pub fn set_geom_offset(&mut self, geom: GeomId, position: DVec3, q: DQuat) {
        let q = ode_quat(q);
        // SAFETY: the geom belongs to this world and is attached to a body.
        unsafe {
            let g = self.geoms[geom.0];
            ffi::dGeomSetOffsetPosition(g, position[0], position[1], position[2]);
            ffi::dGeomSetOffsetQuaternion(g, q.as_ptr());
        }
    }

    /// ODE moves a geom to the front of its space's list whenever its body moves, so the
    /// order of collision pairs (and of contacts, which QuickStep is sensitive to) would
    /// depend on history. Marking body geoms moved in reverse creation order each step
    /// makes the list order the same for every world built the same way.
    pub(super) fn canonicalise_geom_order(&mut self) {
        for &geom in self.geoms.iter().rev() {
            // SAFETY: the geom belongs to this world's space.
            unsafe {
                if !ffi::dGeomGetBody(geom).is_null() {
                    ffi::dGeomMoved(geom);
                }
            }
        }
    }
}
