//! Control Particle Belief Propagation (Hämäläinen, Rajamäki, Liu 2015), the sampling
//! planner of the thesis (§2.3.3, §4.3.1), written from the specification: N particles
//! simulate K steps ahead in their own copies of the world, sampling controls from
//! Gaussian priors around a followed sequence; low-cost lineages are forked and high-cost
//! ones cut (resampling) and the lowest-cost trajectory's first control is applied.
//!
//! It is generic over [`RolloutSystem`] so that it is tested exactly on toy systems; the
//! bike is one such system.

mod config;
mod frame;
mod planner;
mod priors;
mod refinement;
mod rollout;
mod sequences;
mod spec;

pub use config::{
    CpbpConfig, FrameResult, WarmStart, DEFAULT_SEED, DISAGREEMENT, FALLEN_STEPS, RESAMPLES,
};
pub(crate) use frame::mix;
pub(crate) use planner::rollout_pool;
pub use planner::CpbpPlanner;
pub use priors::{AppliedControls, Priors};
pub use rollout::RolloutSystem;
pub use sequences::shift_one_step;
pub use spec::{
    AGREEING_TRAJECTORIES, AGREEMENT, COMBINED, GUIDED, MUTATION_SCALE, OPTIMIZER, PARAMETERS,
};
