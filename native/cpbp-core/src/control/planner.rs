//! One interface for every trajectory planner of the bike, in the shape of MuJoCo MPC's
//! `Planner` (reset, optimise a policy, the action from it, timing by phase): C-PBP alone
//! and warm-started by the arcade controller, predictive sampling and MPPI all plan
//! through it, and a planner is built from a [`PlannerSpec`], which is all the controller
//! registry (`ride::ControllerKind`) needs to know of it. A new planner is a new file with
//! its spec and one line in the registry.

use super::bike_rollout::{bike_priors, BikeRollout};
use super::cpbp::{CpbpConfig, CpbpPlanner, Priors, WarmStart};
use super::plan_result::{PlanPhases, PlanResult};
use super::planner_parameters::*;
use super::planning_session::PlanningConfig;
use super::sampling::{SamplingConfig, SamplingPlanner, SamplingUpdate};
use crate::bike::{index, CONTROL_DIM};
use crate::ode::WorldState;
use crate::ride::ControllerKind;
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

/// C-PBP alone; trajectory 1 replays the last plan's local refinement (thesis §4.3).
pub static OPTIMIZER: PlannerSpec = PlannerSpec {
    parameters: CPBP_PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Refinement)),
    follows: Follows::Nothing,
};

/// C-PBP warm-started with the arcade controller's trajectory (thesis §4.3.2).
pub static COMBINED: PlannerSpec = PlannerSpec {
    parameters: CPBP_PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Policy)),
    follows: Follows::Arcade,
};

/// C-PBP warm-started with the learned network's trajectory (issue 34): the network
/// proposes, the planner checks and refines, so a few trajectories should do.
pub static GUIDED: PlannerSpec = PlannerSpec {
    parameters: CPBP_PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Policy)),
    follows: Follows::Network,
};

/// MuJoCo MPC's predictive sampling: the cheapest of a nominal plan and its perturbations
/// becomes the plan.
pub static SAMPLING: PlannerSpec = PlannerSpec {
    parameters: SAMPLING_PARAMETERS,
    build: |config, steps| Box::new(sampling(config, steps, SamplingUpdate::Best)),
    follows: Follows::Nothing,
};

/// MPPI: the cost-weighted average of the perturbations becomes the plan.
pub static MPPI: PlannerSpec = PlannerSpec {
    parameters: MPPI_PARAMETERS,
    build: |config, steps| {
        let temperature = config.parameters.number(&MPPI_TEMPERATURE);
        Box::new(sampling(
            config,
            steps,
            SamplingUpdate::Weighted { temperature },
        ))
    },
    follows: Follows::Nothing,
};

/// What C-PBP's trajectory 1 replays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum WarmRoute {
    Refinement,
    /// The followed controller's (arcade or the network).
    Policy,
}

/// C-PBP with the warm start its mode takes.
struct Cpbp {
    planner: CpbpPlanner,
    warm: WarmRoute,
}

impl Cpbp {
    fn new(config: &PlanningConfig, steps: usize, warm: WarmRoute) -> Self {
        let planner_config = CpbpConfig {
            particles: config.trajectories.max(1),
            steps,
            seed: config.seed,
            threads: config.threads,
            // Only the optimizer alone replays a refinement: computing one for combined
            // mode would cost without being used.
            refine: warm == WarmRoute::Refinement,
            control_cost_weight: config.control_cost_weight,
            ..CpbpConfig::default()
        };
        Self {
            planner: CpbpPlanner::new(planner_config, priors(config)),
            warm,
        }
    }
}

impl BikePlanner for Cpbp {
    fn reset(&mut self) {
        self.planner.reset();
    }

    fn note_applied(&mut self, control: &[f64]) {
        self.planner.note_applied(control);
    }

    fn plan(&mut self, rollouts: &mut [BikeRollout], start: &WorldState) -> PlanResult {
        let warm = match self.warm {
            WarmRoute::Refinement => WarmStart::Refinement,
            WarmRoute::Policy => WarmStart::Policy,
        };
        self.planner.plan(rollouts, start, warm).plan()
    }

    fn phases(&self) -> PlanPhases {
        self.planner.phases
    }

    fn set_trajectories(&mut self, n: usize) {
        self.planner.config.particles = n.max(1);
    }
}

/// Predictive sampling or MPPI as their parameters say.
fn sampling(config: &PlanningConfig, steps: usize, update: SamplingUpdate) -> SamplingPlanner {
    let values = &config.parameters;
    let sampled = values
        .flag(&BASELINE_STEERING_ONLY)
        .then(|| (0..CONTROL_DIM).map(|d| d == index::STEER).collect());
    let sampling_config = SamplingConfig {
        samples: config.trajectories.max(1),
        steps,
        knots: values.count(&BASELINE_KNOTS).max(2),
        noise: values.number(&BASELINE_NOISE),
        update,
        sampled,
        control_cost_weight: config.control_cost_weight,
        seed: config.seed,
        threads: config.threads,
        ..SamplingConfig::default()
    };
    SamplingPlanner::new(sampling_config, priors(config))
}

impl BikePlanner for SamplingPlanner {
    fn reset(&mut self) {
        SamplingPlanner::reset(self);
    }

    fn note_applied(&mut self, control: &[f64]) {
        SamplingPlanner::note_applied(self, control);
    }

    fn plan(&mut self, rollouts: &mut [BikeRollout], start: &WorldState) -> PlanResult {
        SamplingPlanner::plan(self, rollouts, start)
    }

    fn phases(&self) -> PlanPhases {
        self.phases
    }

    fn set_trajectories(&mut self, n: usize) {
        self.config.samples = n.max(1);
    }
}

fn priors(config: &PlanningConfig) -> Priors {
    bike_priors(config.parameters.number(&MUTATION_SCALE))
}

/// Every parameter of the registered planners, each once, in the registry's order.
pub fn registered_parameters() -> Vec<Setting> {
    let mut all: Vec<Setting> = Vec::new();
    let specs = ControllerKind::ALL.iter().filter_map(|k| k.planner());
    for setting in specs.flat_map(|spec| spec.parameters) {
        if all.iter().all(|s| s.name != setting.name) {
            all.push(*setting);
        }
    }
    all
}
