//! The planner's settings, what particle 1 replays, and what a frame returns.

use crate::control::{Diagnostics, PlanResult, ValueSample};

/// The name C-PBP's plans give their resampling count among the diagnostics.
pub const RESAMPLES: &str = "resamples";
/// The name of the share of a plan's particle steps simulated after the particle's
/// lineage had fallen: what stopping fallen trajectories could save (measured: about
/// 0.1 %, so they are not stopped; docs/learned-controller.md).
pub const FALLEN_STEPS: &str = "fallen steps";

/// The name of how much a plan's trajectories disagree on the control to apply now
/// (`Priors::disagreement`), what a trajectory count that follows it reads.
pub const DISAGREEMENT: &str = "disagreement";

/// Sizes and tuning of the planner; defaults are the specification's.
#[derive(Clone, Debug, PartialEq)]
pub struct CpbpConfig {
    /// N, the number of trajectories.
    pub particles: usize,
    /// K, the planning steps (horizon / step length).
    pub steps: usize,
    /// Share of particles that follow no previous sequence (explore from the priors).
    pub uniform_bias: f64,
    /// Resample when the effective sample size drops below this share of N.
    pub resample_threshold: f64,
    /// Cost given to a rollout whose simulation blew up.
    pub blowup_cost: f64,
    /// Seed of every random draw; the same seed and inputs give the same plan, whatever
    /// the number of threads.
    pub seed: u64,
    /// Worker threads for the rollouts (0: one per core).
    pub threads: usize,
    /// Compute the local refinement (Gaussian back-propagation) each frame, for
    /// [`WarmStart::Refinement`] to replay next frame.
    pub refine: bool,
    /// Ridge λ of the refinement's regression (absolute: features are unit-scaled).
    pub ridge: f64,
    /// Scale of the control (prior) cost in a trajectory's total. With many controlled
    /// dimensions and one costed state feature, the prior terms can outweigh the state
    /// cost that the choice of the best trajectory is about.
    pub control_cost_weight: f64,
    /// Steps after which every particle's state is recorded with the cost its lineage
    /// then adds by the horizon (`FrameResult::value_samples`), the data a learned
    /// cost-to-go is trained on; empty (the default) records none.
    pub record_values_after: Vec<usize>,
}

/// The planners' seed unless told otherwise, the seed setting's default: the same seed,
/// start and inputs give the same ride.
pub const DEFAULT_SEED: u64 = crate::settings::PLANNER_SEED.default_number() as u64;

impl Default for CpbpConfig {
    fn default() -> Self {
        Self {
            particles: 32,
            steps: 36,
            uniform_bias: 0.2,
            resample_threshold: 0.5,
            blowup_cost: 1e6,
            seed: DEFAULT_SEED,
            threads: 0,
            refine: true,
            ridge: 1e-3,
            control_cost_weight: 1.0,
            record_values_after: Vec::new(),
        }
    }
}

/// What particle 1 replays exactly in a frame (particle 0 always replays the last best):
/// the C-PBP paper's warm starts, one route per frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WarmStart<'a> {
    /// Nothing: particle 1 samples like the others.
    Nothing,
    /// The caller's sequence (K·D values; another length is ignored).
    Sequence(&'a [f64]),
    /// Last frame's local refinement, shifted one step, once there is one.
    Refinement,
    /// The system's own controller, step by step (`RolloutSystem::policy`): the same
    /// trajectory as replaying that controller's rollout, without simulating it first on
    /// one thread while the others wait.
    Policy,
}

/// What a C-PBP frame found: the plan (`plan()` gives it as every planner's) and what
/// only C-PBP has, its resampling, refinement and beliefs.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameResult {
    /// The best trajectory's first control: apply it now.
    pub control: Vec<f64>,
    /// Total (state + control) cost of the best trajectory.
    pub best_cost: f64,
    /// Index of the best particle.
    pub best: usize,
    /// Each final particle's control sequence (K·D values) and total cost.
    pub sequences: Vec<Vec<f64>>,
    pub costs: Vec<f64>,
    /// The sequence (K·D values) the controller applies, `control` first: the best
    /// trajectory's, or MPPI's cost-weighted average of all of them.
    pub chosen: Vec<f64>,
    /// How many of the K steps resampled.
    pub resamples: usize,
    /// Rollouts that blew up (restored and given `blowup_cost`).
    pub blowups: usize,
    /// Share of the frame's particle steps taken after the particle's lineage had fallen.
    pub fallen_steps: f64,
    /// How far apart the final trajectories' first controls are (`Priors::disagreement`).
    pub disagreement: f64,
    /// The refined sequence (K·D values, within bounds), when the system has features.
    pub refined: Option<Vec<f64>>,
    /// Each final particle's belief (weights of next frame's choice of sequences).
    pub beliefs: Vec<f64>,
    /// Each final particle's trace points, one per step, when the system gives them.
    pub paths: Vec<Vec<[f64; 3]>>,
    /// Whether particle 1 replayed a warm start.
    pub warm_started: bool,
    /// The states recorded for a cost-to-go (`CpbpConfig::record_values_after`).
    pub value_samples: Vec<ValueSample>,
}

impl FrameResult {
    /// The frame as every planner's plan, its resampling count among the diagnostics.
    pub fn plan(self) -> PlanResult {
        PlanResult {
            control: self.control,
            chosen: self.chosen,
            best: self.best,
            best_cost: self.best_cost,
            trajectories: PlanResult::trajectories_of(self.sequences, &self.costs, self.paths),
            blowups: self.blowups,
            // Particle 1 replays the warm start (`WarmStart`).
            warm: self.warm_started.then_some(1),
            diagnostics: Diagnostics(vec![
                (RESAMPLES, self.resamples as f64),
                (FALLEN_STEPS, self.fallen_steps),
                (DISAGREEMENT, self.disagreement),
            ]),
            value_samples: self.value_samples,
        }
    }
}
