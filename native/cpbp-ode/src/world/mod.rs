//! One ODE world with its collision space and contact joints, owned as a unit.

mod feet;
mod geoms;
mod gyroscopic;

pub use gyroscopic::Gyroscopic;

use std::os::raw::c_void;
use std::ptr;
use std::sync::Arc;

use crate::contact::{near_callback, read_vec3, CollideContext, SurfaceParams};
use crate::feet::Foot;
use crate::ffi;
use crate::joints::JointKind;
use crate::mass::Mass;
use crate::runtime::ensure_thread_data;
use crate::shared_data::{HeightFieldData, TriMeshData};
use crate::springs::Spring;
use crate::tyre::Tyre;
use crate::{ode_quat, BodyState, DQuat, DVec3, StateMismatch, WorldState};

/// Index of a body inside its [`World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyId(pub usize);

/// Index of a collision geom inside its [`World`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GeomId(pub usize);

/// How a world solves its constraints each step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Solver {
    /// ODE's iterative solver (`dWorldQuickStep`, 20 iterations): O(rows) per step, but a
    /// closed chain of joints converges slowly, so it needs short steps to stay stiff.
    #[default]
    QuickStep,
    /// ODE's direct solver (`dWorldStep`): a dense factorisation, O(rows³), exact for
    /// closed loops whatever the step length.
    Direct,
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
    /// Per body: the sum of its terrain contacts' normals in the last step (ground to body).
    ground_normals: Vec<crate::Vec3>,
    /// Per body: its deepest terrain contact in the last step (where and how deep). Only
    /// seen (sparks), never stepped on, so it is not part of a snapshot: a restored world
    /// has none until it steps.
    ground_points: Vec<Option<(crate::Vec3, f64)>>,
    /// Torus tyres: sphere geoms whose contacts are moved to where a torus would touch.
    tyres: Vec<Tyre>,
    /// Feet: sphere geoms that stand on the terrain like a rider's foot (`add_foot`).
    feet: Vec<Foot>,
    /// Shared collision data the geoms read; released only after `Drop` destroyed the space.
    shared_meshes: Vec<Arc<TriMeshData>>,
    shared_heights: Vec<Arc<HeightFieldData>>,
    solver: Solver,
    /// Bodies whose gyroscopic torque is added explicitly (`Gyroscopic::Explicit`).
    explicit_gyroscopic: Vec<usize>,
    /// Spring–dampers on joints, their stops set anew before every step.
    pub(crate) springs: Vec<(crate::JointId, Spring)>,
    /// QuickStep's random sequence (it reorders constraint rows) for this world. ODE keeps
    /// one seed per thread; each step swaps this world's seed in and out, so a world's
    /// steps depend on its own history only, not on what else its thread has stepped.
    random_seed: u64,
}

// SAFETY: a World owns all ODE objects it names and ODE keeps no hidden links between
// worlds; moving it to another thread is safe as long as that thread has ODE data,
// which every method ensures through `ensure_thread_data`.
unsafe impl Send for World {}

impl World {
    /// An empty world with the given gravity (m/s²) and a simple collision space.
    pub fn new(gravity: DVec3) -> Self {
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
                ground_normals: Vec::new(),
                ground_points: Vec::new(),
                tyres: Vec::new(),
                feet: Vec::new(),
                shared_meshes: Vec::new(),
                shared_heights: Vec::new(),
                solver: Solver::default(),
                explicit_gyroscopic: Vec::new(),
                springs: Vec::new(),
                random_seed: 0,
            }
        }
    }

    /// Sets gravity (m/s²).
    pub fn set_gravity(&mut self, gravity: DVec3) {
        // SAFETY: the world is alive.
        unsafe { ffi::dWorldSetGravity(self.world, gravity[0], gravity[1], gravity[2]) };
    }

    /// Chooses the constraint solver for the steps from now on.
    pub fn set_solver(&mut self, solver: Solver) {
        self.solver = solver;
    }

    /// Sets the contact surface used for every contact from now on.
    pub fn set_surface(&mut self, surface: SurfaceParams) {
        self.surface = surface;
    }

    /// Adds a dynamic body with the given mass at a position.
    pub fn add_body(&mut self, mass: Mass, position: DVec3) -> BodyId {
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
            self.ground_normals.push([0.0; 3]);
            self.ground_points.push(None);
        }
        BodyId(self.bodies.len() - 1)
    }

    /// Sets a body's orientation (normalised, as when building a model).
    pub fn set_body_quaternion(&mut self, body: BodyId, q: DQuat) {
        let q = ode_quat(q);
        // SAFETY: the body belongs to this world; q is 4 reals.
        unsafe { ffi::dBodySetQuaternion(self.bodies[body.0], q.as_ptr()) };
    }

    /// Sets a body's world-frame position.
    pub fn set_body_position(&mut self, body: BodyId, p: DVec3) {
        // SAFETY: the body belongs to this world.
        unsafe { ffi::dBodySetPosition(self.bodies[body.0], p[0], p[1], p[2]) };
    }

    /// World-frame angular velocity of a body.
    pub fn body_angular_velocity(&self, body: BodyId) -> DVec3 {
        // SAFETY: as for body_position.
        DVec3::from_array(unsafe { read_vec3(ffi::dBodyGetAngularVel(self.bodies[body.0])) })
    }

    /// Sets the world-frame angular velocity of a body.
    pub fn set_body_angular_velocity(&mut self, body: BodyId, w: DVec3) {
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

    /// The terrain's normal (unit, from the ground towards the body) under a body's
    /// contacts in the last step, averaged over them; none if it touched no terrain.
    pub fn body_ground_normal(&self, body: BodyId) -> Option<DVec3> {
        let sum = DVec3::from_array(self.ground_normals[body.0]);
        (self.touching_static[body.0] && sum.length_squared() > 0.0).then(|| sum.normalize())
    }

    /// Where a body touched the terrain deepest in the last step; none if it touched none,
    /// or if the world was restored from a snapshot since.
    pub fn body_ground_point(&self, body: BodyId) -> Option<DVec3> {
        self.ground_points[body.0].map(|(at, _)| DVec3::from_array(at))
    }

    /// Number of bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    /// World-frame position of a body's centre of mass.
    pub fn body_position(&self, body: BodyId) -> DVec3 {
        // SAFETY: the body belongs to this world; ODE returns a pointer to 3 (padded to 4) reals.
        DVec3::from_array(unsafe { read_vec3(ffi::dBodyGetPosition(self.bodies[body.0])) })
    }

    /// Orientation of a body.
    pub fn body_quaternion(&self, body: BodyId) -> DQuat {
        // SAFETY: the body belongs to this world; ODE returns a pointer to 4 reals, w first.
        unsafe {
            let q = ffi::dBodyGetQuaternion(self.bodies[body.0]);
            DQuat::from_xyzw(*q.add(1), *q.add(2), *q.add(3), *q)
        }
    }

    /// World-frame linear velocity of a body.
    pub fn body_linear_velocity(&self, body: BodyId) -> DVec3 {
        // SAFETY: as for body_position.
        DVec3::from_array(unsafe { read_vec3(ffi::dBodyGetLinearVel(self.bodies[body.0])) })
    }

    /// Sets the world-frame linear velocity of a body.
    pub fn set_body_linear_velocity(&mut self, body: BodyId, velocity: DVec3) {
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
                    position: self.body_position(id).to_array(),
                    quaternion: ode_quat(self.body_quaternion(id)),
                    linear_velocity: self.body_linear_velocity(id).to_array(),
                    angular_velocity,
                }
            })
            .collect();
        let motors = (0..self.joints.len())
            .map(|j| self.motor_state(crate::JointId(j)))
            .collect();
        let (feet_down, feet_extension, feet_leg_direction) = self.feet_state();
        WorldState {
            bodies,
            motors,
            random_seed: self.random_seed,
            touching_static: self.touching_static.clone(),
            feet_touching: self.feet.iter().map(|f| f.touching).collect(),
            feet_down,
            feet_extension,
            feet_leg_direction,
            ground_normals: self.ground_normals.clone(),
        }
    }

    /// Puts every body back into a snapshot's state, exactly (no renormalisation).
    pub fn restore(&mut self, state: &WorldState) -> Result<(), StateMismatch> {
        ensure_thread_data();
        if state.bodies.len() != self.bodies.len()
            || state.motors.len() != self.joints.len()
            || state.touching_static.len() != self.bodies.len()
            || state.ground_normals.len() != self.bodies.len()
            || [state.feet_touching.len(), state.feet_down.len()] != [self.feet.len(); 2]
            || state.feet_extension.len() != self.feet.len()
            || state.feet_leg_direction.len() != self.feet.len()
        {
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
        self.touching_static.copy_from_slice(&state.touching_static);
        self.ground_normals.copy_from_slice(&state.ground_normals);
        self.ground_points.iter_mut().for_each(|p| *p = None);
        self.restore_feet(
            &state.feet_touching,
            &state.feet_down,
            &state.feet_extension,
            &state.feet_leg_direction,
        );
        Ok(())
    }

    /// Restarts this world's QuickStep random sequence, as a new world starts it.
    pub fn reset_random_seed(&mut self) {
        self.random_seed = 0;
    }

    /// Forgets which bodies and feet touched the terrain in the last step, as a new world
    /// starts: bodies placed anew have not touched anything yet, and a ride after a reset
    /// must not step on the history of the ride before it.
    pub fn forget_contacts(&mut self) {
        self.touching_static.iter_mut().for_each(|t| *t = false);
        self.ground_normals.iter_mut().for_each(|n| *n = [0.0; 3]);
        self.ground_points.iter_mut().for_each(|p| *p = None);
        self.feet.iter_mut().for_each(|f| f.touching = false);
    }

    /// Advances the world by `dt` seconds: collision, contact joints, the solver.
    pub fn step(&mut self, dt: f64) {
        ensure_thread_data();
        self.update_springs(dt);
        self.add_explicit_gyroscopic_torques();
        self.canonicalise_geom_order();
        self.forget_contacts();
        let mut context = CollideContext {
            world: self.world,
            contacts: self.contacts,
            surface: self.surface,
            touching_static: &mut self.touching_static,
            ground_normals: &mut self.ground_normals,
            ground_points: &mut self.ground_points,
            tyres: &self.tyres,
            feet: &mut self.feet,
            dt,
            foot_contacts: Vec::new(),
        };
        // SAFETY: the callback only runs during this call and gets a pointer to `context`,
        // which outlives it; all ids belong to this world.
        unsafe {
            ffi::dSpaceCollide(
                self.space,
                (&mut context as *mut CollideContext).cast::<c_void>(),
                Some(near_callback),
            );
            context.attach_foot_contacts();
            // The seed is thread-local in our ODE build: nothing else runs on this thread
            // between setting it and reading it back.
            ffi::dRandSetSeed(self.random_seed as _);
            match self.solver {
                Solver::QuickStep => ffi::dWorldQuickStep(self.world, dt),
                Solver::Direct => ffi::dWorldStep(self.world, dt),
            };
            self.random_seed = ffi::dRandGetSeed() as u64;
            ffi::dJointGroupEmpty(self.contacts);
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
