//! MPPI (Williams et al. 2017) as one of the game's planners: predictive sampling's
//! sampler, whose next plan is the cost-weighted average of its candidates at a
//! temperature of its own.

use super::planner::{Follows, PlannerSpec};
use super::sampling::{self, SamplingUpdate};
use crate::settings::{self, DefaultValue as D, Range, Setting};

pub const MPPI_TEMPERATURE: Setting = Setting {
    name: "mppi_temperature",
    label: "MPPI temperature",
    description: "MPPI's temperature, relative to the spread of its candidates' costs.",
    default: D::Float(0.01),
    range: Some(Range::new(0.001, 1.0, 0.001)),
    ..settings::BASE
};

/// MPPI's own parameters: predictive sampling's and its temperature.
pub const PARAMETERS: &[Setting] = &[
    sampling::BASELINE_KNOTS,
    sampling::BASELINE_NOISE,
    sampling::BASELINE_STEERING_ONLY,
    MPPI_TEMPERATURE,
];

/// MPPI: the cost-weighted average of the perturbations becomes the plan.
pub static MPPI: PlannerSpec = PlannerSpec {
    parameters: PARAMETERS,
    build: |config, steps| {
        let temperature = config.parameters.number(&MPPI_TEMPERATURE);
        let update = SamplingUpdate::Weighted { temperature };
        Box::new(sampling::baseline(config, steps, update))
    },
    follows: Follows::Nothing,
};
