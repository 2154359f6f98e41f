//! One shape for every controller (in the spirit of MuJoCo MPC's `Planner` interface): each
//! turns the ride's state and the player's intent into the controls of the next step, and
//! forgets what it remembered when the ride jumps. The registry (`registry.rs`) names
//! them.

use super::PlannerSettings;
use crate::bike::{Controls, DriveInput, RiderPosition};
use crate::control::{Goal, HandoverStats, Plan};
use crate::simulation::Simulation;

/// What the player asks for.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Intent {
    /// Throttle and brake.
    pub drive: DriveInput,
    /// Turn command in [−1, 1], positive right: the path's curvature, from which the lean
    /// the controllers aim for follows with the speed (eq. 4.4).
    pub turn: f64,
    /// A lean (rad, positive right) asked for directly instead of through `turn`: scripted
    /// rides and tests ask for a lean, not a curvature. Held to the turn's lean limit.
    pub lean: Option<f64>,
    /// Steering rate (rad/s, positive left) for the manual controller; 0 lets the bar
    /// spring back to centre.
    pub steer_rate: f64,
    /// Where the rider's weight goes on the bike (the right stick).
    pub rider: RiderPosition,
}

impl Intent {
    /// Full throttle towards `kmh`, asking for no lean: how scripted rides (tests, the
    /// scenario runner, tools) set off.
    pub fn cruise(kmh: f64) -> Self {
        Self {
            drive: DriveInput {
                throttle: 1.0,
                brake: 0.0,
                max_speed: kmh / 3.6,
            },
            lean: Some(0.0),
            ..Self::default()
        }
    }
}

/// What a controller sees of the ride at a control step.
pub struct RideState<'a> {
    pub sim: &'a Simulation,
    /// The intent as the controllers serve it: the lean the turn command asks for at
    /// this speed, the drive and the rider position, sanitised.
    pub goal: Goal,
    /// How the planners plan (ignored by the others).
    pub planner: &'a PlannerSettings,
}

/// A controller: arcade, manual, the planners, and those to come.
pub trait Controller: Send {
    /// Controls for the next control step; called once per step, before the step.
    fn controls(&mut self, state: &RideState<'_>, intent: &Intent) -> Controls;
    /// Forgets plans and memory: the ride was placed anew, lifted, or another controller
    /// drove in between, so what it remembers is for a state long gone.
    fn reset(&mut self);
    /// What it remembers from step to step, as numbers a rewind keeps and puts back
    /// (`recall`), so the ride goes on from a moment exactly as it did then; None for a
    /// controller whose memory cannot be kept so (a planner and its thread), which a
    /// rewind resets instead.
    fn memory(&self) -> Option<Vec<f64>> {
        None
    }
    /// Takes back what `memory` gave.
    fn recall(&mut self, _memory: &[f64]) {}
    /// The plan driving the bike now (planners only).
    fn plan(&self) -> Option<&Plan> {
        None
    }
    /// How the planning thread's hand-overs went (planners only).
    fn handover(&self) -> Option<HandoverStats> {
        None
    }
    /// What keeps it from driving as itself, as the HUD says it (a planner whose thread
    /// died, the learned controller without a model: who drives instead), if anything.
    fn failure(&self) -> Option<&str> {
        None
    }
    /// Whether it must be built anew before the next ride (its planning thread died).
    fn died(&self) -> bool {
        false
    }
    /// Fails as a dying planning thread would (tests of the fallback and its report);
    /// nothing for controllers without one.
    fn inject_fault(&mut self, _message: &str) {}
    /// Trajectories it plans with now (planners only): the setting's, or the automatic
    /// choice's.
    fn trajectories(&self) -> Option<usize> {
        None
    }
}
