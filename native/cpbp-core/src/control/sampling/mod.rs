//! The baseline planners of MuJoCo MPC's kind (issue 17): predictive sampling and MPPI,
//! planning over the same [`RolloutSystem`](super::cpbp::RolloutSystem)s, priors and cost
//! as C-PBP, so the three differ only in how they search.

mod planner;
mod spec;
mod spline;

pub use planner::{
    SamplingConfig, SamplingPlanner, SamplingUpdate, EFFECTIVE_SAMPLES, IMPROVEMENT,
};
pub(crate) use spec::baseline;
pub use spec::{BASELINE_KNOTS, BASELINE_NOISE, BASELINE_STEERING_ONLY, PARAMETERS, SAMPLING};
pub use spline::Knots;
