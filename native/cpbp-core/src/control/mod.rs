//! Controllers that turn the player's intent into joint motor targets.

mod arcade;
mod bike_rollout;
pub mod cpbp;
mod goal;
mod lean;
pub mod learned;
pub mod mppi;
mod plan_result;
pub mod planner;
mod planning_session;
mod planning_thread;
pub mod sampling;

pub use arcade::{eq_4_12, eq_4_8, ArcadeController, ArcadeGains};
pub use bike_rollout::{bike_priors, BikeRollout, CostTolerances, PlanStart, RolloutPolicy};
pub use goal::Goal;
pub use lean::{
    current_lean_vector, desired_lean, desired_lean_vector, lean_cost, rodrigues, TurnIntent,
};
pub use plan_result::{Diagnostics, PlanPhases, PlanResult, Trajectory, ValueSample};
pub use planner::{BikePlanner, Follows, PlannerSpec};
pub use planning_session::{PlanningConfig, PlanningSession};
pub use planning_thread::{HandoverStats, Plan, PlanWait, PlanningThread};
