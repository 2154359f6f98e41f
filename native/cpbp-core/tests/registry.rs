//! The controller registry is the one list: a new controller is an entry (its own file,
//! a planner's own folder) and a line in the registry; shown here with throwaway ones, a
//! controller that rides without being registered and a planner registered as a mod
//! registers one, whose parameter then reaches every reader of the schema. (The tools'
//! copies of the built-in registry and schema are checked in tests/tools_copies.rs, a
//! process of its own, so this file's registration never reaches them.)

mod common;

use std::sync::atomic::{AtomicUsize, Ordering};

use cpbp_core::bike::{Controls, CONTROL_DIM};
use cpbp_core::control::{
    BikePlanner, BikeRollout, Diagnostics, Follows, PlanPhases, PlanResult, PlanWait, PlannerSpec,
    PlanningConfig, Trajectory,
};
use cpbp_core::ode::WorldState;
use cpbp_core::ride::{
    schema, Controller, ControllerEntry, ControllerKind, Drives, Intent, Ride, RideState,
};
use cpbp_core::settings::{self, DefaultValue, Range, Setting, Value};

/// A controller that leaves the bar alone and counts how often it was asked.
struct HandsOff;

static HANDS_OFF_ASKED: AtomicUsize = AtomicUsize::new(0);

impl Controller for HandsOff {
    fn controls(&mut self, _state: &RideState<'_>, _intent: &Intent) -> Controls {
        HANDS_OFF_ASKED.fetch_add(1, Ordering::Relaxed);
        Controls::default()
    }

    fn reset(&mut self) {}
}

static HANDS_OFF: ControllerEntry = ControllerEntry {
    name: "hands_off",
    label: "Hands off (a test's)",
    offered: false,
    uses_network: false,
    drives: Drives::Itself(|| Box::new(HandsOff)),
};

#[test]
fn a_new_controller_is_an_entry_and_rides() {
    let kind = ControllerKind::new(&HANDS_OFF);
    let mut ride = Ride::new(common::flat_ride(), kind);
    ride.set_intent(Intent::cruise(10.0));
    for _ in 0..12 {
        ride.step();
    }
    assert_eq!(
        HANDS_OFF_ASKED.load(Ordering::Relaxed),
        12,
        "it drove every step"
    );
    assert_eq!(ride.controller().name(), "hands_off");
    assert!(!kind.plans() && ride.plan().is_none());
    assert_eq!(
        ControllerKind::from_name("hands_off"),
        None,
        "not registered: a test's own"
    );
}

/// A planner that plans the bar held still for the whole horizon, at a cost it marks:
/// its own parameter, which the schema has nowhere else.
struct StillBar {
    steps: usize,
    cost: f64,
}

const STILL_BAR_COST: Setting = Setting {
    name: "still_bar_cost",
    label: "Still bar's cost",
    description: "The cost the still-bar planner marks its plans with (a test's).",
    default: DefaultValue::Float(42.0),
    range: Some(Range::new(0.0, 100.0, 1.0)),
    player: true,
    menu: "Planner",
    ..settings::BASE
};

impl BikePlanner for StillBar {
    fn reset(&mut self) {}

    /// It plans the one trajectory whatever N.
    fn set_trajectories(&mut self, _n: usize) {}

    fn note_applied(&mut self, _control: &[f64]) {}

    fn plan(&mut self, rollouts: &mut [BikeRollout], _start: &WorldState) -> PlanResult {
        assert!(
            !rollouts.is_empty(),
            "one rollout world per trajectory at least"
        );
        let control = Controls::default().values().to_vec();
        let chosen: Vec<f64> = control
            .iter()
            .copied()
            .cycle()
            .take(self.steps * CONTROL_DIM)
            .collect();
        PlanResult {
            control,
            best: 0,
            best_cost: self.cost,
            trajectories: vec![Trajectory {
                controls: chosen.clone(),
                cost: self.cost,
                path: Vec::new(),
            }],
            chosen,
            blowups: 0,
            warm: None,
            diagnostics: Diagnostics::default(),
            value_samples: Vec::new(),
        }
    }

    fn phases(&self) -> PlanPhases {
        PlanPhases::default()
    }
}

static STILL_BAR_PLANNER: PlannerSpec = PlannerSpec {
    parameters: &[STILL_BAR_COST],
    build: |config: &PlanningConfig, steps| {
        let cost = config.parameters.number(&STILL_BAR_COST);
        Box::new(StillBar { steps, cost })
    },
    follows: Follows::Nothing,
};

static STILL_BAR: ControllerEntry = ControllerEntry {
    name: "still_bar",
    label: "Still bar (a test's planner)",
    offered: false,
    uses_network: false,
    drives: Drives::Plans(&STILL_BAR_PLANNER),
};

#[test]
fn a_new_planner_is_registered_as_a_line_and_its_parameter_joins_the_schema() {
    assert_eq!(
        schema::find("still_bar_cost"),
        None,
        "not before it is registered"
    );
    let kind = ControllerKind::register(&STILL_BAR).expect("a new name");
    assert!(kind.plans());
    assert!(
        ControllerKind::register(&STILL_BAR).is_err(),
        "the name is taken"
    );
    assert_eq!(ControllerKind::from_name("still_bar"), Some(kind));
    assert!(ControllerKind::all().contains(&kind));
    // Its parameter reaches every reader of the schema: the game node's properties and
    // the pause menu (its group), the settings files and the tools (the JSON).
    assert_eq!(schema::find("still_bar_cost"), Some(STILL_BAR_COST));
    let on_the_node = schema::values_of(|s| s.owner.on_the_node());
    assert_eq!(on_the_node.get("still_bar_cost"), Some(&Value::Float(42.0)));
    assert!(schema::schema_json().contains("\"name\":\"still_bar_cost\""));
    assert!(schema::schema_json().contains("\"menu\":\"Planner\""));

    let mut ride = Ride::new(common::flat_ride(), kind);
    // Its own parameter is the ride's to set, as the schema's settings are.
    let parameters = &mut ride.planner.planning.parameters;
    assert_eq!(parameters.get("still_bar_cost"), Some(&Value::Float(42.0)));
    assert_eq!(
        parameters.set("still_bar_cost", Value::Float(7.0)),
        Ok(None)
    );
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(10.0));
    for _ in 0..6 {
        ride.step();
    }
    let plan = ride.plan().expect("the ride draws its plan");
    assert_eq!(
        plan.best_cost, 7.0,
        "the plan is the new planner's, at its parameter"
    );
    assert!(!plan.sequence.is_empty());
    assert_eq!(ride.late_plans(), 0);
}

/// A parameter whose name another setting has.
const CLASHING: Setting = Setting {
    name: "horizon",
    label: "A clash",
    description: "A test's parameter under a taken name.",
    ..STILL_BAR_COST
};

static CLASHING_PLANNER: PlannerSpec = PlannerSpec {
    parameters: &[CLASHING],
    build: |_, steps| Box::new(StillBar { steps, cost: 0.0 }),
    follows: Follows::Nothing,
};

static CLASHING_ENTRY: ControllerEntry = ControllerEntry {
    name: "clashing",
    label: "Clashing (a test's planner)",
    offered: false,
    uses_network: false,
    drives: Drives::Plans(&CLASHING_PLANNER),
};

#[test]
fn a_planner_whose_parameter_takes_another_settings_name_is_refused() {
    let why = ControllerKind::register(&CLASHING_ENTRY).unwrap_err();
    assert!(why.contains("horizon"), "{why}");
    assert_eq!(ControllerKind::from_name("clashing"), None);
}
