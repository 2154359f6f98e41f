//! C-PBP as the game's planners (thesis §4.3): its parameter, and the three ways the
//! registry rides it — alone, warm-started by the arcade controller, and following the
//! learned network. Everything else knows it through these specs.

use super::{CpbpConfig, CpbpPlanner, Priors, WarmStart};
use crate::control::bike_rollout::{bike_priors, BikeRollout};
use crate::control::plan_result::{PlanPhases, PlanResult};
use crate::control::planner::{BikePlanner, Follows, PlannerSpec};
use crate::control::planning_session::PlanningConfig;
use crate::ode::WorldState;
use crate::settings::{self, DefaultValue as D, Range, Setting};

pub const MUTATION_SCALE: Setting = Setting {
    name: "mutation_scale",
    label: "Mutation scale",
    description: "C-PBP: how far the followed sequences are mutated, as a share of the \
                  control priors' σ (σm = scale · σ0).",
    default: D::Float(0.2),
    range: Some(Range::new(0.01, 1.0, 0.01)),
    ..settings::BASE
};

/// C-PBP's own parameters (every mode's).
pub const PARAMETERS: &[Setting] = &[MUTATION_SCALE];

/// C-PBP alone; trajectory 1 replays the last plan's local refinement (thesis §4.3).
pub static OPTIMIZER: PlannerSpec = PlannerSpec {
    parameters: PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Refinement)),
    follows: Follows::Nothing,
};

/// C-PBP warm-started with the arcade controller's trajectory (thesis §4.3.2).
pub static COMBINED: PlannerSpec = PlannerSpec {
    parameters: PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Policy)),
    follows: Follows::Arcade,
};

/// C-PBP warm-started with the learned network's trajectory (issue 34): the network
/// proposes, the planner checks and refines, so a few trajectories should do.
pub static GUIDED: PlannerSpec = PlannerSpec {
    parameters: PARAMETERS,
    build: |config, steps| Box::new(Cpbp::new(config, steps, WarmRoute::Policy)),
    follows: Follows::Network,
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
            record_values_after: config.record_values_after.clone(),
            ..CpbpConfig::default()
        };
        let priors = Priors {
            mutation_scale: config.parameters.number(&MUTATION_SCALE),
            ..bike_priors()
        };
        Self {
            planner: CpbpPlanner::new(planner_config, priors),
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
