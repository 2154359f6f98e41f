//! Safe, minimal bindings to ODE 0.16 (double precision, thread-local collision data).
//!
//! All `unsafe` of the project lives in this crate. The API is shaped so that no handle
//! can outlive what it names: one [`World`] owns its ODE world, collision space, contact
//! joint group, bodies and geoms, and hands out plain index handles ([`BodyId`], [`GeomId`]).

mod contact;
mod feet;
mod ffi;
mod joints;
mod mass;
mod runtime;
mod shared_data;
mod springs;
mod state;
mod tyre;
mod world;

pub use contact::SurfaceParams;
pub use feet::FootSurface;
pub use joints::{JointId, MotorState};
pub use mass::Mass;
pub use runtime::{c_library_version, configuration, ensure_thread_data, Configuration};
pub use shared_data::{HeightFieldData, TriMeshData};
pub use springs::Spring;
pub use state::{BodyState, StateMismatch, WorldState};
pub use world::{BodyId, GeomId, Gyroscopic, Solver, World};

/// The API's vectors and rotations are glam's; ODE's own numbers appear only in snapshots
/// ([`BodyState`]), as ODE keeps them.
pub use glam::{DQuat, DVec3};

/// Three components as ODE keeps them (double precision), in snapshots.
pub type Vec3 = [f64; 3];
/// A quaternion in ODE's order (w, x, y, z), in snapshots.
pub type Quat = [f64; 4];

/// glam's quaternion (x, y, z, w) in ODE's order.
pub(crate) fn ode_quat(q: DQuat) -> Quat {
    [q.w, q.x, q.y, q.z]
}
