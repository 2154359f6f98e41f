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

pub const AGREEING_TRAJECTORIES: Setting = Setting {
    name: "agreeing_trajectories",
    label: "Trajectories when agreeing",
    description: "C-PBP: how many trajectories plan after a plan whose trajectories agreed \
                  on what to do (their first controls within the agreement below); 0 plans \
                  every step with all of them.",
    default: D::Int(0),
    range: Some(Range::new(0.0, 64.0, 1.0)),
    ..settings::BASE
};
pub const AGREEMENT: Setting = Setting {
    name: "agreement",
    label: "Agreement",
    description: "C-PBP: trajectories agree when their first controls' largest standard \
                  deviation is below this share of the control priors' σ.",
    default: D::Float(0.02),
    range: Some(Range::new(0.001, 2.0, 0.001)),
    ..settings::BASE
};

/// C-PBP's own parameters (every mode's).
pub const PARAMETERS: &[Setting] = &[MUTATION_SCALE, AGREEING_TRAJECTORIES, AGREEMENT];

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
    /// N: the trajectories of a plan after one whose trajectories disagreed.
    trajectories: usize,
    /// The trajectories after a plan whose trajectories agreed (0: always N) and below
    /// which disagreement they agree (issue 59: a count that follows the disagreement).
    agreeing: usize,
    agreement: f64,
    last_disagreement: Option<f64>,
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
            trajectories: config.trajectories.max(1),
            agreeing: config.parameters.count(&AGREEING_TRAJECTORIES),
            agreement: config.parameters.number(&AGREEMENT),
            last_disagreement: None,
        }
    }

    /// The trajectories of the next plan: fewer after one whose trajectories agreed.
    fn next_count(&self) -> usize {
        count_after(
            self.last_disagreement,
            self.trajectories,
            self.agreeing,
            self.agreement,
        )
    }
}

/// N after a plan whose trajectories disagreed `last` (None: no plan yet), `agreeing`
/// (at most N; 0: never fewer) after one below `agreement`.
fn count_after(last: Option<f64>, n: usize, agreeing: usize, agreement: f64) -> usize {
    match last {
        Some(d) if agreeing > 0 && d < agreement => agreeing.min(n),
        _ => n,
    }
}

impl BikePlanner for Cpbp {
    fn reset(&mut self) {
        self.planner.reset();
        self.last_disagreement = None;
    }

    fn note_applied(&mut self, control: &[f64]) {
        self.planner.note_applied(control);
    }

    fn plan(&mut self, rollouts: &mut [BikeRollout], start: &WorldState) -> PlanResult {
        let warm = match self.warm {
            WarmRoute::Refinement => WarmStart::Refinement,
            WarmRoute::Policy => WarmStart::Policy,
        };
        self.planner.config.particles = self.next_count();
        let frame = self.planner.plan(rollouts, start, warm);
        self.last_disagreement = Some(frame.disagreement);
        frame.plan()
    }

    fn phases(&self) -> PlanPhases {
        self.planner.phases
    }

    fn set_trajectories(&mut self, n: usize) {
        self.trajectories = n.max(1);
    }
}

#[cfg(test)]
mod tests {
    use super::count_after;

    #[test]
    fn fewer_trajectories_plan_only_after_a_plan_whose_trajectories_agreed() {
        assert_eq!(
            count_after(None, 5, 2, 0.02),
            5,
            "the first plan: all of them"
        );
        assert_eq!(count_after(Some(0.01), 5, 2, 0.02), 2);
        assert_eq!(
            count_after(Some(0.02), 5, 2, 0.02),
            5,
            "at the bound: disagreed"
        );
        assert_eq!(count_after(Some(0.0), 5, 0, 0.02), 5, "0: never fewer");
        assert_eq!(count_after(Some(0.0), 3, 8, 0.02), 3, "never more than N");
    }
}
