//! What a planner returns, the same for every planner (C-PBP, predictive sampling, MPPI, a
//! test's): the control to apply, the chosen sequence and one record per trajectory.
//! What only one planner has goes in its `Diagnostics`, named numbers the HUD and the
//! bench show without knowing which planner made them.

/// Where a frame's time went (ms): rolling the trajectories out (the part that spreads over
/// the threads), reading the plan back from them, and the rest (choosing what each
/// trajectory follows, resampling, bookkeeping) on the planning thread alone.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanPhases {
    pub total_ms: f64,
    pub rollouts_ms: f64,
    pub conclude_ms: f64,
}

impl PlanPhases {
    /// The phases of a frame that started at `started`, rolled out for `rollouts` and
    /// began concluding at `concluding`.
    pub fn measured(
        started: std::time::Instant,
        rollouts: std::time::Duration,
        concluding: std::time::Instant,
    ) -> Self {
        Self {
            total_ms: started.elapsed().as_secs_f64() * 1000.0,
            rollouts_ms: rollouts.as_secs_f64() * 1000.0,
            conclude_ms: concluding.elapsed().as_secs_f64() * 1000.0,
        }
    }

    /// The planning thread's own share: neither rollouts nor concluding.
    pub fn other_ms(&self) -> f64 {
        (self.total_ms - self.rollouts_ms - self.conclude_ms).max(0.0)
    }
}

/// One trajectory of a plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory {
    /// Its control sequence (K·D values).
    pub controls: Vec<f64>,
    /// Its total (state + control) cost.
    pub cost: f64,
    /// Its trace points, one per step, when the system gives them (for drawing).
    pub path: Vec<[f64; 3]>,
}

/// A planner's own numbers about a plan, by name (C-PBP: "resamples", "fallen steps").
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Diagnostics(pub Vec<(&'static str, f64)>);

impl Diagnostics {
    /// The number called `name`, if the planner gives one.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, v)| *v)
    }

    /// A count called `name` (0 when the planner gives none).
    pub fn count(&self, name: &str) -> usize {
        self.get(name).map_or(0, |v| v as usize)
    }
}

/// What a plan found.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanResult {
    /// The first control of `chosen`: apply it now.
    pub control: Vec<f64>,
    /// The sequence (K·D values) the controller applies, `control` first: the best
    /// trajectory's, or MPPI's cost-weighted average of all of them.
    pub chosen: Vec<f64>,
    /// Index of the cheapest trajectory, and its cost.
    pub best: usize,
    pub best_cost: f64,
    pub trajectories: Vec<Trajectory>,
    /// Rollouts that blew up (restored and given the blow-up cost).
    pub blowups: usize,
    /// The trajectory that replayed a warm start (the followed controller's or a
    /// refinement), if one did.
    pub warm: Option<usize>,
    pub diagnostics: Diagnostics,
    /// States a trajectory passed, each with the cost its plan then added by the horizon
    /// (when the planner was asked to record them: the data of a learned cost-to-go).
    pub value_samples: Vec<ValueSample>,
}

/// A state a plan's trajectory passed and what the rest of the horizon cost from it.
#[derive(Clone, Debug, PartialEq)]
pub struct ValueSample {
    /// The system's features there (`RolloutSystem::value_features`).
    pub features: Vec<f64>,
    /// Planning steps from there to the horizon.
    pub remaining_steps: usize,
    /// The least total (state + control) cost any trajectory through that state added
    /// from there to the horizon.
    pub cost_to_go: f64,
}

impl PlanResult {
    /// One trajectory per (sequence, cost, path); a missing path is empty.
    pub fn trajectories_of(
        sequences: Vec<Vec<f64>>,
        costs: &[f64],
        paths: Vec<Vec<[f64; 3]>>,
    ) -> Vec<Trajectory> {
        let mut paths = paths.into_iter();
        sequences
            .into_iter()
            .zip(costs)
            .map(|(controls, &cost)| Trajectory {
                controls,
                cost,
                path: paths.next().unwrap_or_default(),
            })
            .collect()
    }
}
