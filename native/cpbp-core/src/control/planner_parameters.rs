//! The built-in planners' own parameters, as settings-schema entries their specs
//! declare (`PlannerSpec::parameters`): C-PBP's mutation scale, the baselines' knots,
//! noise and what they sample, MPPI's temperature. The schema lists them with its own
//! entries (`settings::all`), so the game node, the settings files and the tools have
//! them; no config struct holds them.

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

pub const MPPI_TEMPERATURE: Setting = Setting {
    name: "mppi_temperature",
    label: "MPPI temperature",
    description: "MPPI's temperature, relative to the spread of its candidates' costs.",
    default: D::Float(0.01),
    range: Some(Range::new(0.001, 1.0, 0.001)),
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

/// C-PBP's (optimizer, combined, guided).
pub const CPBP_PARAMETERS: &[Setting] = &[MUTATION_SCALE];
/// Predictive sampling's.
pub const SAMPLING_PARAMETERS: &[Setting] =
    &[BASELINE_KNOTS, BASELINE_NOISE, BASELINE_STEERING_ONLY];
/// MPPI's: predictive sampling's and its temperature.
pub const MPPI_PARAMETERS: &[Setting] = &[
    BASELINE_KNOTS,
    BASELINE_NOISE,
    BASELINE_STEERING_ONLY,
    MPPI_TEMPERATURE,
];
