//! Rewinding a ride: every control step it keeps the moment before the step (the master's
//! whole state, the ride's counts, the driving controller's memory), up to a length of
//! time; a rewind puts one of them back, and ridden on with the same intents from there
//! the ride repeats exactly what it did then (a planner, whose thread's memory is not
//! kept, plans afresh from the moment instead).

use std::collections::VecDeque;
use std::fmt;

use super::{ControllerKind, Ride};
use crate::simulation::SimulationState;

/// The ride at the start of a control step.
pub(super) struct Moment {
    sim: SimulationState,
    started: bool,
    steps: u64,
    late_plans: u64,
    last_driver: Option<ControllerKind>,
    /// The memory of the controller that drove the step before (`Controller::memory`).
    memory: Option<Vec<f64>>,
}

/// The moments kept, oldest first, at most `capacity` of them.
#[derive(Default)]
pub(super) struct History {
    moments: VecDeque<Moment>,
    capacity: usize,
}

/// Why a rewind did nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RewindRefusal {
    /// The ride keeps no history (`Ride::keep_history` was not asked).
    NotKept,
    /// Nothing was ridden since the ride started or was placed anew.
    NothingYet,
}

impl fmt::Display for RewindRefusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::NotKept => "this ride keeps no history to rewind",
            Self::NothingYet => "nothing to rewind yet: ride first",
        })
    }
}

impl History {
    pub(super) fn clear(&mut self) {
        self.moments.clear();
    }
}

impl Ride {
    /// Keeps the last `seconds` of the ride (whole control steps) to rewind into; 0 keeps
    /// nothing (the default: the experiment and the tools pay nothing for it).
    pub fn keep_history(&mut self, seconds: f64) {
        let dt = self.sim.config().control_dt;
        let steps = if seconds.is_finite() && seconds > 0.0 {
            (seconds / dt).round() as usize
        } else {
            0
        };
        self.history.capacity = steps;
        while self.history.moments.len() > steps {
            self.history.moments.pop_front();
        }
    }

    /// How far back (s) a rewind can go now.
    pub fn rewindable(&self) -> f64 {
        self.history.moments.len() as f64 * self.sim.config().control_dt
    }

    /// Why a rewind would do nothing now (None: it would go back).
    pub fn rewind_refusal(&self) -> Option<RewindRefusal> {
        if self.history.capacity == 0 {
            Some(RewindRefusal::NotKept)
        } else if self.history.moments.is_empty() {
            Some(RewindRefusal::NothingYet)
        } else {
            None
        }
    }

    /// Puts the ride back `seconds` (whole control steps; as far as the history goes if it
    /// is shorter) and returns how far back it went. The moments after it are dropped.
    pub fn rewind(&mut self, seconds: f64) -> Result<f64, RewindRefusal> {
        if let Some(refusal) = self.rewind_refusal() {
            return Err(refusal);
        }
        let kept = self.history.moments.len();
        let dt = self.sim.config().control_dt;
        let back = if seconds.is_finite() {
            ((seconds / dt).round() as usize).clamp(1, kept)
        } else {
            1
        };
        self.history.moments.truncate(kept - back + 1);
        let moment = self.history.moments.pop_back().expect("at least one kept");
        self.sim.restore_state(&moment.sim);
        self.started = moment.started;
        self.steps = moment.steps;
        self.late_plans = moment.late_plans;
        self.last_driver = moment.last_driver;
        for (kind, controller) in &mut self.built {
            match (&moment.memory, Some(*kind) == moment.last_driver) {
                (Some(memory), true) => controller.recall(memory),
                _ => controller.reset(),
            }
        }
        Ok(back as f64 * dt)
    }

    /// Keeps the moment before a step (when history is kept). A bike standing on its feet
    /// waiting for the first throttle steps too, but that is no ride to go back into.
    pub(super) fn remember_moment(&mut self) {
        if self.history.capacity == 0 || self.is_waiting_for_throttle() {
            return;
        }
        let memory = self
            .last_driver
            .and_then(|kind| self.built_controller(kind))
            .and_then(|controller| controller.memory());
        if self.history.moments.len() == self.history.capacity {
            self.history.moments.pop_front();
        }
        self.history.moments.push_back(Moment {
            sim: self.sim.state(),
            started: self.started,
            steps: self.steps,
            late_plans: self.late_plans,
            last_driver: self.last_driver,
            memory,
        });
    }
}
