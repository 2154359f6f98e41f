//! Predictive sampling as one of the game's planners: its parameters (shared with MPPI,
//! which plans with the same sampler) and its spec.

use super::{SamplingConfig, SamplingPlanner, SamplingUpdate};
use crate::bike::{index, CONTROL_DIM};
use crate::control::bike_rollout::{bike_priors, BikeRollout};
use crate::control::plan_result::{PlanPhases, PlanResult};
use crate::control::planner::{BikePlanner, Follows, PlannerSpec};
use crate::control::planning_session::PlanningConfig;
use crate::ode::WorldState;
use crate::settings::{self, DefaultValue as D, Range, Setting};

pub const BASELINE_KNOTS: Setting = Setting {
    name: "baseline_knots",
    label: "Baseline knots",
    description: "The baseline planners (sampling, mppi): knots of a plan over the horizon.",
    default: D::Int(10),
    range: Some(Range::new(2.0, 36.0, 1.0)),
    ..settings::BASE
};

pub const BASELINE_NOISE: Setting = Setting {
    name: "baseline_noise",
    label: "Baseline noise",
    description: "The baselines' knot perturbation, as a share of the steering prior's σ.",
    default: D::Float(0.5),
    range: Some(Range::new(0.05, 2.0, 0.05)),
    ..settings::BASE
};

pub const BASELINE_STEERING_ONLY: Setting = Setting {
    name: "baseline_steering_only",
    label: "Baselines steer only",
    description: "The baselines plan the steering alone, the rider on the pose PD (else \
                  every joint).",
    default: D::Bool(true),
    ..settings::BASE
};

/// Predictive sampling's own parameters (MPPI's too).
pub const PARAMETERS: &[Setting] = &[BASELINE_KNOTS, BASELINE_NOISE, BASELINE_STEERING_ONLY];

/// MuJoCo MPC's predictive sampling: the cheapest of a nominal plan and its perturbations
/// becomes the plan.
pub static SAMPLING: PlannerSpec = PlannerSpec {
    parameters: PARAMETERS,
    build: |config, steps| Box::new(baseline(config, steps, SamplingUpdate::Best)),
    follows: Follows::Nothing,
};

/// The sampler as `config`'s parameters set it, making its next plan by `update`.
pub(crate) fn baseline(
    config: &PlanningConfig,
    steps: usize,
    update: SamplingUpdate,
) -> SamplingPlanner {
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
    // The sampler perturbs by its own noise, never by C-PBP's mutation σ.
    SamplingPlanner::new(sampling_config, bike_priors())
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
