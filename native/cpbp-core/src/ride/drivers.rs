//! The controllers behind the registry: thin adapters from the one controller interface to
//! the arcade controller, manual driving and the planning thread.

use super::auto_trajectories::AutoTrajectories;
use super::controller::{Controller, Intent, RideState};
use super::PlannerSettings;
use crate::bike::{manual_controls, Controls};
use crate::control::learned::{LeanTrim, LoadedPolicy, NonFiniteFeature, FEATURE_NAMES};
use crate::control::{
    ArcadeController, Follows, HandoverStats, Plan, PlannerSpec, PlanningConfig, PlanningThread,
};
use crate::simulation::Simulation;

/// The arcade controller (thesis §4.3.2) on the master.
#[derive(Default)]
pub struct ArcadeDriver(ArcadeController);

impl ArcadeDriver {
    pub fn boxed() -> Box<dyn Controller> {
        Box::<Self>::default()
    }
}

impl Controller for ArcadeDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        self.0.controls_of(state.sim, &state.goal)
    }

    fn reset(&mut self) {
        self.0.reset();
    }

    fn memory(&self) -> Option<Vec<f64>> {
        Some(self.0.memory())
    }

    fn recall(&mut self, memory: &[f64]) {
        self.0.recall(memory);
    }
}

/// The learned network (issue 34) on the master. The arcade controller keeps its memory
/// in step on every step and drives instead while there is no usable model, or at a step
/// whose state the network cannot read. The trim gives the network the integral action it
/// lacks (`LeanTrim`).
#[derive(Default)]
pub struct LearnedDriver {
    arcade: ArcadeController,
    trim: LeanTrim,
    /// Why the arcade controller drove the last step, if it did.
    problem: Option<String>,
}

impl LearnedDriver {
    pub fn boxed() -> Box<dyn Controller> {
        Box::<Self>::default()
    }

    /// Records why arcade drives, formatting the sentence only when the reason changes
    /// (this runs every control step).
    fn note(&mut self, reason: &str, sentence: impl FnOnce() -> String) {
        if !self
            .problem
            .as_deref()
            .is_some_and(|p| p.starts_with(reason))
        {
            self.problem = Some(sentence());
        }
    }
}

impl Controller for LearnedDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        let arcade = self.arcade.controls_of(state.sim, &state.goal);
        let policy = &state.planner.network;
        let Some(network) = policy.network() else {
            let why = policy.problem().unwrap_or("no learned model");
            self.note(why, || format!("{why}; arcade steers"));
            return arcade;
        };
        let sim = state.sim;
        let (bike, world, up) = (sim.bike(), sim.world(), sim.up());
        let goal = self.trim.trimmed(
            &state.goal,
            bike.lean(world, up),
            bike.forward_speed(world, up),
            sim.config().control_dt,
        );
        match network.controls(bike, world, &goal, up) {
            Ok(controls) => {
                self.problem = None;
                Controls::sanitized(controls.values()).0
            }
            Err(NonFiniteFeature(i)) => {
                let reason = "the network cannot read the state";
                self.note(reason, || {
                    format!(
                        "{reason} ({} is not a number); arcade steers",
                        FEATURE_NAMES[i]
                    )
                });
                arcade
            }
        }
    }

    fn reset(&mut self) {
        self.arcade.reset();
        self.trim.reset();
        self.problem = None;
    }

    fn failure(&self) -> Option<&str> {
        self.problem.as_deref()
    }
}

/// Nobody balances: the bar follows the steering rate input.
pub struct ManualDriver;

impl ManualDriver {
    pub fn boxed() -> Box<dyn Controller> {
        Box::new(Self)
    }
}

impl Controller for ManualDriver {
    fn controls(&mut self, state: &RideState<'_>, intent: &Intent) -> Controls {
        manual_controls(
            state.sim.bike(),
            state.sim.world(),
            &intent.drive,
            intent.steer_rate,
        )
    }

    fn reset(&mut self) {}

    fn memory(&self) -> Option<Vec<f64>> {
        // It remembers nothing from step to step.
        Some(Vec::new())
    }
}

/// A planner on its own thread, handed over at control steps.
pub struct PlannerDriver {
    anytime: PlanningThread,
    /// The automatic N, while the settings ask for it; it outlives resets (the machine
    /// did not change) but starts afresh when N's setting or the choice does.
    auto: Option<(usize, AutoTrajectories)>,
    /// The step of the last plan whose time `auto` was told.
    timed_plan: Option<u64>,
    trajectories: usize,
    /// Whether trajectory 1 follows the learned network (guided mode).
    follows_network: bool,
    /// What keeps it from planning as itself, as the HUD says it, and whether that is a
    /// dead thread, a missing model and a missing cost-to-go.
    failure: Option<String>,
    failure_state: (bool, bool, bool),
}

impl PlannerDriver {
    pub fn new(sim: &Simulation, spec: &'static PlannerSpec, planner: &PlannerSettings) -> Self {
        Self {
            anytime: PlanningThread::new(sim, spec, planner.wait),
            auto: None,
            timed_plan: None,
            trajectories: planner.planning.trajectories,
            follows_network: spec.follows == Follows::Network,
            failure: None,
            failure_state: (false, false, false),
        }
    }

    /// The automatic N for the next request, while the settings ask for one (it starts
    /// afresh from the setting's N when that changes).
    fn automatic(&mut self, settings: &PlannerSettings, period_s: f64) -> Option<usize> {
        let start = settings.planning.trajectories;
        if !settings.picks_trajectories() {
            self.auto = None;
            return None;
        }
        match &mut self.auto {
            Some((from, _)) if *from == start => {}
            slot => *slot = Some((start, AutoTrajectories::new(start, period_s))),
        }
        self.auto.as_ref().map(|(_, auto)| auto.trajectories())
    }

    /// Keeps the HUD's sentence on what stops the planner being itself up to date; the
    /// sentence is formatted only when that changes (this runs every control step).
    fn note_failure(&mut self, policy: &LoadedPolicy, config: &PlanningConfig) {
        let died = self.anytime.failure();
        let missing = policy.problem().filter(|_| self.follows_network);
        let no_value = config.value_problem();
        let state = (died.is_some(), missing.is_some(), no_value.is_some());
        if state == self.failure_state {
            return;
        }
        self.failure_state = state;
        if let Some(died) = died {
            self.failure = Some(format!("the planner stopped ({died}); arcade steers"));
            return;
        }
        let guided = missing.map(|why| format!("{why}; the arcade controller guides the planner"));
        let whole = no_value.map(|why| format!("{why}; it plans its whole horizon"));
        self.failure = match (guided, whole) {
            (Some(guided), Some(whole)) => Some(format!("{guided}. {whole}")),
            (guided, whole) => guided.or(whole),
        };
    }

    /// Tells the automatic N how the step went: the newest plan's time, and whether the
    /// step's plan was late.
    fn note_step(&mut self, late: bool) {
        let Some((_, auto)) = &mut self.auto else {
            return;
        };
        if let Some(plan) = self
            .anytime
            .plan()
            .filter(|p| Some(p.step) != self.timed_plan)
        {
            auto.note_plan(plan.planning_ms, plan.trajectories);
            self.timed_plan = Some(plan.step);
        }
        auto.note_step(late);
    }
}

impl Controller for PlannerDriver {
    fn controls(&mut self, state: &RideState<'_>, _intent: &Intent) -> Controls {
        self.anytime.wait = state.planner.wait;
        let mut config = state.planner.planning.clone();
        let period = state.sim.config().control_dt;
        if let Some(n) = self.automatic(state.planner, period) {
            config.trajectories = n;
        }
        self.trajectories = config.trajectories;
        let late_before = self.anytime.stats.late;
        let network = state
            .planner
            .network
            .network()
            .filter(|_| self.follows_network);
        let mut controls = self
            .anytime
            .controls(state.sim, &state.goal, &config, network);
        // The triggers act at once, as they do for every controller: the plan was made
        // a step ago, with the triggers as they were then.
        let radius = state.sim.bike().params().wheel_radius;
        state.goal.drive.apply(radius, &mut controls);
        self.note_step(self.anytime.stats.late > late_before);
        self.note_failure(&state.planner.network, &config);
        controls
    }

    fn trajectories(&self) -> Option<usize> {
        Some(self.trajectories)
    }

    fn reset(&mut self) {
        self.anytime.reset();
    }

    fn plan(&self) -> Option<&Plan> {
        self.anytime.plan()
    }

    fn handover(&self) -> Option<HandoverStats> {
        Some(self.anytime.stats)
    }

    fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    fn died(&self) -> bool {
        self.anytime.failure().is_some()
    }

    fn inject_fault(&mut self, message: &str) {
        self.anytime.inject_fault(message);
    }
}
