//! A ride: the master simulation, the controller that drives it and the player's intent,
//! stepped one control period at a time. The game's `BikeSimulation` node, the headless
//! experiment, the benchmarks and the tests all ride through this, so the rules (the start
//! gate, when plans are forgotten, what counts as a late plan) exist once.

mod auto_trajectories;
mod controller;
mod drivers;
pub mod fidelity;
pub mod limits;
mod planner_settings;
mod registry;
mod rewind;
pub mod schema;

pub use auto_trajectories::AutoTrajectories;
pub use controller::{Controller, Intent, RideState};
pub use planner_settings::{PlannerSettings, GAME_PLAN_WAIT};
pub use registry::{ControllerEntry, ControllerKind, Drives};
pub use rewind::RewindRefusal;

use std::sync::Arc;

use glam::DVec3;

use crate::bike::{Controls, Placement};
use crate::control::{Goal, HandoverStats, Plan, TurnIntent};
use crate::settings::LEAN_SHARE;
use crate::simulation::{Simulation, StepEvents};
use crate::terrain::Terrain;

pub struct Ride {
    sim: Simulation,
    kind: ControllerKind,
    /// Controllers built so far, kept so switching back does not rebuild a planner's
    /// thread and worlds; each is reset before it drives again.
    built: Vec<(ControllerKind, Box<dyn Controller>)>,
    /// Who drove the last step (None: raw controls, or nobody yet).
    last_driver: Option<ControllerKind>,
    intent: Intent,
    raw_controls: Option<Controls>,
    turn: TurnIntent,
    pub planner: PlannerSettings,
    /// The ride starts with the first throttle (a level's clock waits for it). A bike
    /// without feet to stand on (the thesis's rigid bike) is also held where it was
    /// placed until then: standing still, no steering can balance it.
    pub wait_for_throttle: bool,
    started: bool,
    steps: u64,
    late_plans: u64,
    /// The moments a rewind can go back to (`keep_history`).
    history: rewind::History,
}

impl Ride {
    /// A ride of `sim` driven by a `kind` controller, with the game's planner settings.
    pub fn new(sim: Simulation, kind: ControllerKind) -> Self {
        let mut planner = PlannerSettings::default();
        planner.planning = planner.planning.rolling_out_in(sim.config().physics);
        if let Some(spec) = kind.planner() {
            planner.planning.parameters.include(spec.parameters);
        }
        let turn = TurnIntent::for_bike(&sim.config().bike);
        Self {
            sim,
            kind,
            built: Vec::new(),
            last_driver: None,
            intent: Intent::default(),
            raw_controls: None,
            turn,
            planner,
            wait_for_throttle: false,
            started: false,
            steps: 0,
            late_plans: 0,
            history: rewind::History::default(),
        }
    }

    pub fn sim(&self) -> &Simulation {
        &self.sim
    }

    pub fn controller(&self) -> ControllerKind {
        self.kind
    }

    /// Who drives from the next step on.
    pub fn set_controller(&mut self, kind: ControllerKind) {
        self.kind = kind;
    }

    pub fn intent(&self) -> &Intent {
        &self.intent
    }

    /// The player's intent from the next step on; the controller drives again.
    pub fn set_intent(&mut self, intent: Intent) {
        self.intent = intent;
        self.raw_controls = None;
    }

    /// All controls set directly until the next intent (tools and tests).
    pub fn set_raw_controls(&mut self, controls: Controls) {
        self.raw_controls = Some(controls);
    }

    /// The lean (rad, positive right) the player asks for: the one asked for directly, or
    /// the turn command's at the current speed.
    pub fn desired_lean(&self) -> f64 {
        if let Some(lean) = self.intent.lean {
            let limit = self.turn.max_lean;
            return if lean.is_finite() {
                lean.clamp(-limit, limit)
            } else {
                0.0
            };
        }
        let s = &self.sim;
        let speed = s.bike().forward_speed(s.world(), s.up());
        self.turn
            .lean_for(self.intent.turn, speed, s.config().gravity.length())
    }

    /// Opens the start gate when the ride may start (no waiting asked for, a throttle, or
    /// raw controls); true once it is open.
    pub fn try_start(&mut self) -> bool {
        self.started |= !self.wait_for_throttle
            || self.intent.drive.throttle > 0.0
            || self.raw_controls.is_some();
        self.started
    }

    /// Opens the start gate whatever the input (headless runs step explicitly).
    pub fn start(&mut self) {
        self.started = true;
    }

    /// True while the bike must be held still: waiting for the first throttle without
    /// feet to stand on (`BikeParams::feet`).
    pub fn holds_the_bike(&self) -> bool {
        self.is_waiting_for_throttle() && self.sim.bike().params().feet.is_none()
    }

    /// True while the bike stands waiting for the first throttle.
    pub fn is_waiting_for_throttle(&self) -> bool {
        !self.started && self.wait_for_throttle
    }

    /// Control steps since the ride was built or last placed.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Steps since the ride was last placed at which a planner drove without the plan for
    /// that step (late, or none): 0 for a ride that repeats exactly.
    pub fn late_plans(&self) -> u64 {
        self.late_plans
    }

    /// The plan driving the bike, while a planner drives.
    pub fn plan(&self) -> Option<&Plan> {
        let driver = self.last_driver.filter(|k| k.plans())?;
        self.built_controller(driver)?.plan()
    }

    /// Trajectories the active planner plans with now: the setting's N, or the one the
    /// automatic choice settled on (None for controllers that do not plan, or before the
    /// planner ran).
    pub fn trajectories(&self) -> Option<usize> {
        self.built_controller(self.kind)?.trajectories()
    }

    /// Hand-over statistics of the active planner (None for the others, or before it ran).
    pub fn handover(&self) -> Option<HandoverStats> {
        self.built_controller(self.kind)?.handover()
    }

    /// What keeps the active controller from driving as itself (its planning thread died,
    /// or there is no learned model) and who drives instead, if anything. Placing the
    /// ride anew builds a planner whose thread died again.
    pub fn failure(&self) -> Option<&str> {
        self.built_controller(self.kind)?.failure()
    }

    /// Whether the active controller's planning thread died (a fault, not a missing
    /// model).
    pub fn controller_died(&self) -> bool {
        self.built_controller(self.kind).is_some_and(|c| c.died())
    }

    /// Makes the active controller fail as a dying planning thread would (tests).
    pub fn inject_fault(&mut self, message: &str) {
        let kind = self.kind;
        if let Some((_, controller)) = self.built.iter_mut().find(|(k, _)| *k == kind) {
            controller.inject_fault(message);
        }
    }

    /// Simulates one control step with the active controller (or the raw controls).
    pub fn step(&mut self) -> StepEvents {
        self.remember_moment();
        let goal = self.goal();
        let controls = match self.raw_controls {
            Some(controls) => {
                self.last_driver = None;
                controls
            }
            // Nobody rides a bike whose rider fell off: no controller, no planning.
            None if !self.sim.rider_is_on() => {
                self.last_driver = None;
                Controls::slack()
            }
            None => self.controls_of_active(goal),
        };
        self.sim.set_controls(controls);
        self.sim.set_pitch_request(goal.pitch_request());
        let events = self.sim.step();
        self.steps += 1;
        if events.recovered_from.is_some() {
            self.forget_plans();
            self.history.clear();
        }
        events
    }

    /// Puts the bike at rest at `placement`, which becomes the spawn point: a new ride.
    pub fn reset_to(&mut self, placement: Placement) {
        self.sim.reset_to(placement);
        // A controller whose planning thread died starts afresh with the new ride.
        self.built.retain(|(_, controller)| !controller.died());
        self.forget_plans();
        self.history.clear();
        self.started = false;
        self.steps = 0;
        self.late_plans = 0;
    }

    /// Shoves the bike (see `Simulation::push`); the controller carries on.
    pub fn push(&mut self, impulse: DVec3) {
        self.sim.push(impulse);
    }

    /// Stands a fallen bike up where it lies.
    pub fn lift_upright(&mut self) {
        self.sim.lift_upright();
        self.forget_plans();
        self.history.clear();
    }

    /// The player's aids: ABS (`SimulationConfig::abs`) and the share of the bike's lean the
    /// turn may ask for (0.5–1). A change of ABS keeps the ride's state; the planners'
    /// worlds brake the old way, so they are built anew when next they drive.
    pub fn set_aids(&mut self, abs: bool, lean_share: f64) {
        if self.sim.config().abs != abs {
            self.sim.set_abs(abs);
            self.built.retain(|(kind, _)| !kind.plans());
            self.history.clear();
        }
        let share = LEAN_SHARE
            .range
            .map_or(1.0, |range| range.clamp(lean_share, 1.0));
        self.turn = TurnIntent::for_bike(&self.sim.config().bike);
        self.turn.max_lean *= share;
    }

    /// Swaps the terrain (a level changed), keeping the ride's state. The planners' worlds
    /// have the old terrain, so they are built anew when next they drive.
    pub fn set_terrain(&mut self, terrain: Arc<Terrain>) {
        self.sim.set_terrain(terrain);
        self.built.retain(|(kind, _)| !kind.plans());
        // The moments kept were on the old terrain.
        self.history.clear();
    }

    /// What the controllers serve this step: the intent with the turn made a lean.
    pub fn goal(&self) -> Goal {
        Goal {
            lean: self.desired_lean(),
            drive: self.intent.drive,
            rider: self.intent.rider.sanitized().0,
        }
    }

    fn controls_of_active(&mut self, goal: Goal) -> Controls {
        let kind = self.kind;
        if !self.built.iter().any(|(k, _)| *k == kind) {
            let controller = kind.build(&self.sim, &self.planner);
            self.built.push((kind, controller));
        }
        let fresh_driver = self.last_driver != Some(kind);
        let state = RideState {
            sim: &self.sim,
            goal,
            planner: &self.planner,
        };
        let (_, controller) = self
            .built
            .iter_mut()
            .find(|(k, _)| *k == kind)
            .expect("built above");
        // What it remembers is from before another controller (or raw controls) drove.
        if fresh_driver {
            controller.reset();
        }
        let late_before = controller.handover().map_or(0, |h| h.late);
        let controls = controller.controls(&state, &self.intent);
        self.late_plans += controller.handover().map_or(0, |h| h.late) - late_before;
        self.last_driver = Some(kind);
        controls
    }

    fn built_controller(&self, kind: ControllerKind) -> Option<&dyn Controller> {
        self.built
            .iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, c)| c.as_ref())
    }

    fn forget_plans(&mut self) {
        for (_, controller) in &mut self.built {
            controller.reset();
        }
    }
}
