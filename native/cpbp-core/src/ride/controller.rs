//! One shape for every controller (in the spirit of MuJoCo MPC's `Planner` interface): each
//! turns the ride's state and the player's intent into the controls of the next step, and
//! forgets what it remembered when the ride jumps. The registry names them.

use std::time::Duration;

use crate::bike::{Controls, DriveInput, RiderPosition};
use crate::control::{Goal, HandoverStats, OptimizerConfig, OptimizerMode, Plan, PlanWait};
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
    /// The plan driving the bike now (planners only).
    fn plan(&self) -> Option<&Plan> {
        None
    }
    /// How the planning thread's hand-overs went (planners only).
    fn handover(&self) -> Option<HandoverStats> {
        None
    }
    /// Why it no longer drives as itself (a planner whose thread died: the arcade
    /// controller drives in its place), if so.
    fn failure(&self) -> Option<&str> {
        None
    }
    /// Fails as a dying planning thread would (tests of the fallback and its report);
    /// nothing for controllers without one.
    fn inject_fault(&mut self, _message: &str) {}
}

/// Every controller there is, by its stable name; the menus, the HUD, settings files and
/// the experiment all read this one list.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ControllerKind {
    /// The PD controller on the steering of the thesis (§4.3.2).
    Arcade,
    /// Nobody balances: the bar follows the steering rate input (for inspecting physics).
    Manual,
    /// C-PBP alone (§4.3).
    Optimizer,
    /// C-PBP warm-started with the arcade controller's trajectory.
    Combined,
    /// MuJoCo MPC's predictive sampling (a baseline planner).
    Sampling,
    /// MPPI (a baseline planner).
    Mppi,
}

impl ControllerKind {
    /// In the order the menus list them and the game cycles through them.
    pub const ALL: [ControllerKind; 6] = [
        Self::Optimizer,
        Self::Combined,
        Self::Arcade,
        Self::Sampling,
        Self::Mppi,
        Self::Manual,
    ];

    /// The name settings files, the experiment's CSV and the command line use.
    pub fn name(self) -> &'static str {
        match self {
            Self::Arcade => "arcade",
            Self::Manual => "manual",
            Self::Optimizer => "optimizer",
            Self::Combined => "combined",
            Self::Sampling => "sampling",
            Self::Mppi => "mppi",
        }
    }

    /// What menus show.
    pub fn label(self) -> &'static str {
        match self {
            Self::Arcade => "Arcade (PD)",
            Self::Manual => "Manual (nobody balances)",
            Self::Optimizer => "Optimizer (C-PBP)",
            Self::Combined => "Combined (C-PBP + arcade)",
            Self::Sampling => "Predictive sampling (baseline)",
            Self::Mppi => "MPPI (baseline)",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }

    /// Whether players pick it (menus, the game's cycle); manual is for tests and tools.
    pub fn offered(self) -> bool {
        self != Self::Manual
    }

    /// Whether it plans with trajectories (and so has plans to draw and time).
    pub fn plans(self) -> bool {
        self.planner_mode().is_some()
    }

    /// The planning mode behind a planning controller.
    pub fn planner_mode(self) -> Option<OptimizerMode> {
        match self {
            Self::Optimizer => Some(OptimizerMode::Optimizer),
            Self::Combined => Some(OptimizerMode::Combined),
            Self::Sampling => Some(OptimizerMode::Sampling),
            Self::Mppi => Some(OptimizerMode::Mppi),
            Self::Arcade | Self::Manual => None,
        }
    }

    /// A new controller of this kind for `sim`.
    pub fn build(self, sim: &Simulation, planner: &PlannerSettings) -> Box<dyn Controller> {
        use super::drivers::{ArcadeDriver, ManualDriver, PlannerDriver};
        match (self, self.planner_mode()) {
            (_, Some(mode)) => Box::new(PlannerDriver::new(sim, mode, planner)),
            (Self::Manual, None) => Box::new(ManualDriver),
            _ => Box::<ArcadeDriver>::default(),
        }
    }
}

/// How the planners plan: the optimizer's settings and how long the ride waits for a plan.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannerSettings {
    pub optimizer: OptimizerConfig,
    pub wait: PlanWait,
}

impl Default for PlannerSettings {
    /// The game's: the optimizer's defaults, waiting at most 12 ms at a control step.
    fn default() -> Self {
        Self {
            optimizer: OptimizerConfig::default(),
            wait: PlanWait::AtMost(Duration::from_millis(12)),
        }
    }
}
