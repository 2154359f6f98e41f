//! One ODE world with its collision space and contact joints, owned as a unit.

use std::os::raw::c_void;
use std::ptr;
use std::sync::Arc;

use crate::ffi;
use crate::joints::JointKind;
use crate::runtime::ensure_thread_data;
use crate::shared_data::{HeightFieldData, TriMeshData};
use crate::{BodyState, Quat, StateMismatch, Vec3, WorldState};

/// Most contact points generated for one pair of geoms in one step.
const MAX_CONTACTS_PER_PAIR: usize = 8;

/// Index of a body inside its [`World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyId(pub usize);

/// Index of a collision geom inside its [`World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GeomId(pub usize);

/// Mass properties of a rigid body, in the body's own frame.
#[derive(Clone, Copy, Debug)]
pub struct Mass {
    raw: ffi::dMass,
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
    pub fn cuboid(total: f64, size: Vec3) -> Self {
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

    /// Total mass in kg.
    pub fn total(&self) -> f64 {
        self.raw.mass
    }
}

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

/// An ODE world, its collision space, its contact joints, bodies and geoms.
///
/// Everything is destroyed together when the `World` is dropped, so handles cannot dangle.
pub struct World {
    pub(crate) world: ffi::dWorldID,
    space: ffi::dSpaceID,
    contacts: ffi::dJointGroupID,
    threading: ffi::dThreadingImplementationID,
    pub(crate) bodies: Vec<ffi::dBodyID>,
    pub(crate) joints: Vec<(ffi::dJointID, JointKind)>,
    geoms: Vec<ffi::dGeomID>,
    surface: SurfaceParams,
    /// Per body: whether it touched a static geom (terrain) in the last step.
    touching_static: Vec<bool>,
    /// Torus tyres: sphere geoms whose contacts are moved to where a torus would touch.
    tyres: Vec<Tyre>,
    /// Shared collision data the geoms read; released only after `Drop` destroyed the space.
    shared_meshes: Vec<Arc<TriMeshData>>,
    shared_heights: Vec<Arc<HeightFieldData>>,
    /// QuickStep's random sequence (it reorders constraint rows) for this world. ODE keeps
    /// one seed per thread; each step swaps this world's seed in and out, so a world's
    /// steps depend on its own history only, not on what else its thread has stepped.
    random_seed: u64,
}

/// Collision categories: bodies collide with static terrain only, never with each other
/// (a bike's parts are held by joints; the rider must not snag on the bike).
const CATEGORY_BODY: u64 = 1;
const CATEGORY_STATIC: u64 = 2;

// SAFETY: a World owns all ODE objects it names and ODE keeps no hidden links between
// worlds; moving it to another thread is safe as long as that thread has ODE data,
// which every method ensures through `ensure_thread_data`.
unsafe impl Send for World {}

impl World {
    /// An empty world with the given gravity (m/s²) and a simple collision space.
    pub fn new(gravity: Vec3) -> Self {
        ensure_thread_data();
        // SAFETY: ODE is initialised; the returned ids are owned by this World.
        unsafe {
            let world = ffi::dWorldCreate();
            ffi::dWorldSetGravity(world, gravity[0], gravity[1], gravity[2]);
            let space = ffi::dSimpleSpaceCreate(ptr::null_mut());
            let contacts = ffi::dJointGroupCreate(0);
            // Without its own implementation a world steps through ODE's one global
            // self-threaded implementation, whose wakeup flag races when several threads
            // step their own worlds at once (as the rollouts do).
            let threading = ffi::dThreadingAllocateSelfThreadedImplementation();
            ffi::dWorldSetStepThreadingImplementation(
                world,
                ffi::dThreadingImplementationGetFunctions(threading),
                threading,
            );
            Self {
                world,
                space,
                contacts,
                threading,
                bodies: Vec::new(),
                joints: Vec::new(),
                geoms: Vec::new(),
                surface: SurfaceParams::default(),
                touching_static: Vec::new(),
                tyres: Vec::new(),
                shared_meshes: Vec::new(),
                shared_heights: Vec::new(),
                random_seed: 0,
            }
        }
    }

    /// Sets gravity (m/s²).
    pub fn set_gravity(&mut self, gravity: Vec3) {
        // SAFETY: the world is alive.
        unsafe { ffi::dWorldSetGravity(self.world, gravity[0], gravity[1], gravity[2]) };
    }

    /// Sets the contact surface used for every contact from now on.
    pub fn set_surface(&mut self, surface: SurfaceParams) {
        self.surface = surface;
    }

    /// Adds a dynamic body with the given mass at a position.
    pub fn add_body(&mut self, mass: Mass, position: Vec3) -> BodyId {
        ensure_thread_data();
        // SAFETY: the world is alive; the body is owned by it and recorded here.
        unsafe {
            let body = ffi::dBodyCreate(self.world);
            ffi::dBodySetMass(body, &mass.raw);
            ffi::dBodySetPosition(body, position[0], position[1], position[2]);
            // The body's index, read back by the contact callback.
            ffi::dBodySetData(body, self.bodies.len() as *mut c_void);
            self.bodies.push(body);
            self.touching_static.push(false);
        }
        BodyId(self.bodies.len() - 1)
    }

    /// Adds a sphere geom, attached to `body` or static when `body` is `None`.
    pub fn add_sphere(&mut self, radius: f64, body: Option<BodyId>) -> GeomId {
        // SAFETY: the space is alive; the geom is destroyed with it.
        let geom = unsafe { ffi::dCreateSphere(self.space, radius) };
        self.attach(geom, body)
    }

    /// Adds a box geom with full side lengths, attached to `body` or static.
    pub fn add_box(&mut self, size: Vec3, body: Option<BodyId>) -> GeomId {
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
        self.tyres.push(Tyre { radius, crown });
        // SAFETY: the geom belongs to this world; its data is the tyre's index + 1.
        unsafe { ffi::dGeomSetData(self.geoms[geom.0], self.tyres.len() as *mut c_void) };
        geom
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
    pub fn add_plane(&mut self, normal: Vec3, offset: f64) -> GeomId {
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
    pub fn set_geom_position(&mut self, geom: GeomId, position: Vec3) {
        // SAFETY: the geom belongs to this world.
        unsafe { ffi::dGeomSetPosition(self.geoms[geom.0], position[0], position[1], position[2]) };
    }

    /// Sets the world-frame orientation of a static geom.
    pub fn set_geom_quaternion(&mut self, geom: GeomId, q: Quat) {
        // SAFETY: the geom belongs to this world; q is 4 reals.
        unsafe { ffi::dGeomSetQuaternion(self.geoms[geom.0], q.as_ptr()) };
    }

    /// Places a body geom relative to its body (position and orientation in body frame).
    pub fn set_geom_offset(&mut self, geom: GeomId, position: Vec3, q: Quat) {
        // SAFETY: the geom belongs to this world and is attached to a body.
        unsafe {
            let g = self.geoms[geom.0];
            ffi::dGeomSetOffsetPosition(g, position[0], position[1], position[2]);
            ffi::dGeomSetOffsetQuaternion(g, q.as_ptr());
        }
    }

    /// Sets a body's orientation (normalised, as when building a model).
    pub fn set_body_quaternion(&mut self, body: BodyId, q: Quat) {
        // SAFETY: the body belongs to this world; q is 4 reals.
        unsafe { ffi::dBodySetQuaternion(self.bodies[body.0], q.as_ptr()) };
    }

    /// Sets a body's world-frame position.
    pub fn set_body_position(&mut self, body: BodyId, p: Vec3) {
        // SAFETY: the body belongs to this world.
        unsafe { ffi::dBodySetPosition(self.bodies[body.0], p[0], p[1], p[2]) };
    }

    /// World-frame angular velocity of a body.
    pub fn body_angular_velocity(&self, body: BodyId) -> Vec3 {
        // SAFETY: as for body_position.
        unsafe { read_vec3(ffi::dBodyGetAngularVel(self.bodies[body.0])) }
    }

    /// Sets the world-frame angular velocity of a body.
    pub fn set_body_angular_velocity(&mut self, body: BodyId, w: Vec3) {
        // SAFETY: the body belongs to this world.
        unsafe { ffi::dBodySetAngularVel(self.bodies[body.0], w[0], w[1], w[2]) };
    }

    /// Mass of a body in kg.
    pub fn body_mass(&self, body: BodyId) -> f64 {
        let mut mass = ffi::dMass::default();
        // SAFETY: the body belongs to this world; `mass` is exclusively borrowed.
        unsafe { ffi::dBodyGetMass(self.bodies[body.0], &mut mass) };
        mass.mass
    }

    /// Whether a body touched a static geom (terrain) during the last step.
    pub fn body_touches_static(&self, body: BodyId) -> bool {
        self.touching_static[body.0]
    }

    /// Number of bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    /// World-frame position of a body's centre of mass.
    pub fn body_position(&self, body: BodyId) -> Vec3 {
        // SAFETY: the body belongs to this world; ODE returns a pointer to 3 (padded to 4) reals.
        unsafe { read_vec3(ffi::dBodyGetPosition(self.bodies[body.0])) }
    }

    /// Orientation of a body as a quaternion (w, x, y, z).
    pub fn body_quaternion(&self, body: BodyId) -> Quat {
        // SAFETY: the body belongs to this world; ODE returns a pointer to 4 reals.
        unsafe {
            let q = ffi::dBodyGetQuaternion(self.bodies[body.0]);
            [*q, *q.add(1), *q.add(2), *q.add(3)]
        }
    }

    /// World-frame linear velocity of a body.
    pub fn body_linear_velocity(&self, body: BodyId) -> Vec3 {
        // SAFETY: as for body_position.
        unsafe { read_vec3(ffi::dBodyGetLinearVel(self.bodies[body.0])) }
    }

    /// Sets the world-frame linear velocity of a body.
    pub fn set_body_linear_velocity(&mut self, body: BodyId, velocity: Vec3) {
        // SAFETY: the body belongs to this world.
        unsafe {
            ffi::dBodySetLinearVel(self.bodies[body.0], velocity[0], velocity[1], velocity[2])
        };
    }

    /// Copies the dynamic state of every body and the stepping random seed.
    pub fn snapshot(&self) -> WorldState {
        ensure_thread_data();
        let bodies = (0..self.bodies.len())
            .map(|i| {
                let id = BodyId(i);
                // SAFETY: the body belongs to this world; ODE returns a pointer to 3 reals.
                let angular_velocity =
                    unsafe { read_vec3(ffi::dBodyGetAngularVel(self.bodies[i])) };
                BodyState {
                    position: self.body_position(id),
                    quaternion: self.body_quaternion(id),
                    linear_velocity: self.body_linear_velocity(id),
                    angular_velocity,
                }
            })
            .collect();
        let motors = (0..self.joints.len())
            .map(|j| self.motor_state(crate::JointId(j)))
            .collect();
        WorldState {
            bodies,
            motors,
            random_seed: self.random_seed,
        }
    }

    /// Puts every body back into a snapshot's state, exactly (no renormalisation).
    pub fn restore(&mut self, state: &WorldState) -> Result<(), StateMismatch> {
        ensure_thread_data();
        if state.bodies.len() != self.bodies.len() || state.motors.len() != self.joints.len() {
            return Err(StateMismatch {
                expected_bodies: self.bodies.len(),
                found_bodies: state.bodies.len(),
                expected_joints: self.joints.len(),
                found_joints: state.motors.len(),
            });
        }
        for (j, motor) in state.motors.iter().enumerate() {
            self.set_motor_state(crate::JointId(j), motor);
        }
        for (&body, s) in self.bodies.iter().zip(&state.bodies) {
            // SAFETY: the body belongs to this world; the quaternion is 4 reals.
            unsafe {
                ffi::dBodySetPosition(body, s.position[0], s.position[1], s.position[2]);
                ffi::dBodySetQuaternionExact(body, s.quaternion.as_ptr());
                let v = s.linear_velocity;
                ffi::dBodySetLinearVel(body, v[0], v[1], v[2]);
                let w = s.angular_velocity;
                ffi::dBodySetAngularVel(body, w[0], w[1], w[2]);
            }
        }
        self.random_seed = state.random_seed;
        Ok(())
    }

    /// Restarts this world's QuickStep random sequence, as a new world starts it.
    pub fn reset_random_seed(&mut self) {
        self.random_seed = 0;
    }

    /// Advances the world by `dt` seconds: collision, contact joints, QuickStep.
    pub fn step(&mut self, dt: f64) {
        ensure_thread_data();
        self.canonicalise_geom_order();
        self.touching_static.iter_mut().for_each(|t| *t = false);
        let mut context = CollideContext {
            world: self.world,
            contacts: self.contacts,
            surface: self.surface,
            touching_static: &mut self.touching_static,
            tyres: &self.tyres,
        };
        // SAFETY: the callback only runs during this call and gets a pointer to `context`,
        // which outlives it; all ids belong to this world.
        unsafe {
            ffi::dSpaceCollide(
                self.space,
                (&mut context as *mut CollideContext).cast::<c_void>(),
                Some(near_callback),
            );
            // The seed is thread-local in our ODE build: nothing else runs on this thread
            // between setting it and reading it back.
            ffi::dRandSetSeed(self.random_seed as _);
            ffi::dWorldQuickStep(self.world, dt);
            self.random_seed = ffi::dRandGetSeed() as u64;
            ffi::dJointGroupEmpty(self.contacts);
        }
    }
}

impl World {
    /// ODE moves a geom to the front of its space's list whenever its body moves, so the
    /// order of collision pairs (and of contacts, which QuickStep is sensitive to) would
    /// depend on history. Marking body geoms moved in reverse creation order each step
    /// makes the list order the same for every world built the same way.
    fn canonicalise_geom_order(&mut self) {
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

impl Drop for World {
    fn drop(&mut self) {
        ensure_thread_data();
        // SAFETY: the ids are owned by this World and destroyed exactly once; destroying the
        // space destroys its geoms (cleanup is on by default), the world its bodies and joints.
        unsafe {
            ffi::dJointGroupDestroy(self.contacts);
            ffi::dSpaceDestroy(self.space);
            ffi::dWorldDestroy(self.world);
            ffi::dThreadingFreeImplementation(self.threading);
        }
    }
}

struct CollideContext<'a> {
    world: ffi::dWorldID,
    contacts: ffi::dJointGroupID,
    surface: SurfaceParams,
    touching_static: &'a mut Vec<bool>,
    tyres: &'a [Tyre],
}

/// A torus tyre on a sphere geom (see `World::add_tyre`).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tyre {
    radius: f64,
    crown: f64,
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
unsafe fn read_vec3(p: *const f64) -> Vec3 {
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
            let axle = [*r.add(2), *r.add(6), *r.add(10)]; // the body's local z in world
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

unsafe extern "C" fn near_callback(data: *mut c_void, o1: ffi::dGeomID, o2: ffi::dGeomID) {
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

    const G: f64 = 9.81;

    #[test]
    fn a_dropped_body_falls_half_g_t_squared() {
        let mut world = World::new([0.0, -G, 0.0]);
        let ball = world.add_body(Mass::sphere(1.0, 0.1), [0.0, 10.0, 0.0]);
        let dt = 1.0 / 240.0;
        let steps = 240;
        for _ in 0..steps {
            world.step(dt);
        }
        let t = dt * steps as f64;
        let fallen = 10.0 - world.body_position(ball)[1];
        // Semi-implicit Euler overshoots ½gt² by ½g·t·dt; allow that and no more.
        let exact = 0.5 * G * t * t;
        assert!(
            (fallen - exact).abs() <= 0.5 * G * t * dt + 1e-9,
            "fell {fallen}, ½gt² = {exact}"
        );
        assert!((world.body_linear_velocity(ball)[1] + G * t).abs() < 1e-9);
    }

    #[test]
    fn a_sphere_comes_to_rest_on_a_plane() {
        let mut world = World::new([0.0, -G, 0.0]);
        world.add_plane([0.0, 1.0, 0.0], 0.0);
        let ball = world.add_body(Mass::sphere(2.0, 0.25), [0.0, 1.0, 0.0]);
        world.add_sphere(0.25, Some(ball));
        for _ in 0..600 {
            world.step(1.0 / 120.0);
        }
        let y = world.body_position(ball)[1];
        assert!((y - 0.25).abs() < 0.01, "sphere rests at {y}, radius 0.25");
        assert!(world.body_linear_velocity(ball)[1].abs() < 1e-3);
    }

    #[test]
    fn many_threads_step_their_own_worlds_with_contacts_at_once() {
        // The rollouts step one world per thread; this must be race-free (no shared
        // threading dispatcher, thread-local collision caches) and give identical results.
        let simulate = || {
            let mut world = World::new([0.0, -G, 0.0]);
            world.add_plane([0.0, 1.0, 0.0], 0.0);
            let ball = world.add_body(Mass::sphere(1.0, 0.2), [0.0, 0.5, 0.0]);
            world.add_sphere(0.2, Some(ball));
            world.add_box([0.5, 0.5, 0.5], None);
            for _ in 0..2000 {
                world.step(1.0 / 240.0);
            }
            world.body_position(ball)
        };
        let reference = simulate();
        let handles: Vec<_> = (0..8).map(|_| std::thread::spawn(simulate)).collect();
        for handle in handles {
            assert_eq!(handle.join().unwrap(), reference);
        }
    }

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

    #[test]
    fn worlds_can_move_between_threads() {
        let mut world = World::new([0.0, -G, 0.0]);
        let ball = world.add_body(Mass::sphere(1.0, 0.1), [0.0, 0.0, 0.0]);
        let world = std::thread::spawn(move || {
            world.step(0.1);
            world
        })
        .join()
        .unwrap();
        assert!(world.body_position(ball)[1] < 0.0);
    }
}
