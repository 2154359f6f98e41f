//! One interface for every trajectory planner of the bike, in the shape of MuJoCo MPC's
//! `Planner` (reset, optimise a policy, the action from it, timing by phase): C-PBP alone
//! and warm-started by the arcade controller, predictive sampling and MPPI all plan
//! through it, and a planner is built from a [`PlannerSpec`], which is all the controller
//! registry (`ride::ControllerKind`) needs to know of it. A planner is a folder of its own
//! (`control/cpbp/spec.rs`, `control/sampling/spec.rs`, `control/mppi/`) declaring its
//! parameters and its spec, and one line in the registry; nothing else knows its
//! parameters.

use super::bike_rollout::BikeRollout;
use super::plan_result::{PlanPhases, PlanResult};
use super::planning_session::PlanningConfig;
use crate::ode::WorldState;
use crate::settings::Setting;

/// A planner over the bike's rollout worlds.
pub trait BikePlanner: Send {
    /// Forgets previous plans (after a reset, a lift or a teleport).
    fn reset(&mut self);
    /// The control the master really applied last, when it was not this planner's own
    /// first control (a fallback, a plan that arrived late): the smoothness priors of
    /// the next plan start from it.
    fn note_applied(&mut self, control: &[f64]);
    /// Plans from `start` with one rollout world per trajectory (`rollouts.len()` ≥ N);
    /// the result's `control` is what to apply now, `chosen` the sequence it heads.
    fn plan(&mut self, rollouts: &mut [BikeRollout], start: &WorldState) -> PlanResult;
    /// Where the last plan's time went.
    fn phases(&self) -> PlanPhases;
    /// Plans with `n` trajectories from the next plan on, keeping what it remembers (the
    /// game's automatic N moves it while riding).
    fn set_trajectories(&mut self, n: usize);
}

/// How to build a planner, and what its rollouts need.
#[derive(Debug)]
pub struct PlannerSpec {
    /// The planner's own parameters, as settings-schema entries: the game node, the
    /// settings files and the tools list them with the schema's; `build` reads their
    /// values from `config.parameters`.
    pub parameters: &'static [Setting],
    /// A new planner with `config`'s settings, planning `steps` control steps ahead.
    pub build: fn(config: &PlanningConfig, steps: usize) -> Box<dyn BikePlanner>,
    /// The controller trajectory 1 rides with, live (combined and guided modes).
    pub follows: Follows,
}

/// Which controller a planner's trajectory 1 follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Follows {
    /// None: C-PBP replays its last refinement there, the baselines their nominal plan.
    Nothing,
    /// The arcade controller (combined mode).
    Arcade,
    /// The learned network (guided mode); the arcade controller while there is none.
    Network,
}
