//! One shape for every controller (in the spirit of MuJoCo MPC's `Planner` interface): each
//! turns the ride's state and the player's intent into the controls of the next step, and
//! forgets what it remembered when the ride jumps. The registry (`registry.rs`) names
//! them.

use std::time::Duration;

use crate::bike::{Controls, DriveInput, RiderPosition};
use crate::control::learned::LoadedPolicy;
use crate::control::{Goal, HandoverStats, Plan, PlanWait, PlanningConfig};
use crate::settings;
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

/// How the planners plan: the planning settings, the learned network and how long the
/// ride waits for a plan.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannerSettings {
    /// Every planner's settings; `planning.trajectories` is N, or where the automatic
    /// choice starts from.
    pub planning: PlanningConfig,
    /// The learned network: the learned controller drives with it, and the ride hands it
    /// to a planner that follows it (guided mode).
    pub network: LoadedPolicy,
    pub wait: PlanWait,
    /// Move N while riding to what this machine plans in time (`AutoTrajectories`).
    /// Only where the ride waits at most a while for a plan: a ride that waits for every
    /// plan is never late, and must repeat exactly whatever the machine.
    pub auto_trajectories: bool,
}

impl PlannerSettings {
    /// Whether N moves with the machine's speed.
    pub fn picks_trajectories(&self) -> bool {
        self.auto_trajectories && matches!(self.wait, PlanWait::AtMost(_))
    }
}

/// Longest the game waits at a control step for a plan: a frame of 60 Hz less what
/// the step itself and the drawing need, so a slow plan never stalls the game.
pub const GAME_PLAN_WAIT: Duration =
    Duration::from_millis(settings::PLAN_WAIT_MS.default_number() as u64);

impl Default for PlannerSettings {
    /// The game's: the planners' defaults, no network, waiting at most `GAME_PLAN_WAIT`
    /// at a step.
    fn default() -> Self {
        Self {
            planning: PlanningConfig::default(),
            network: LoadedPolicy::default(),
            wait: PlanWait::AtMost(GAME_PLAN_WAIT),
            auto_trajectories: settings::AUTO_TRAJECTORIES.default_number() != 0.0,
        }
    }
}
