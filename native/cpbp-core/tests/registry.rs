//! The controller registry is the one list: a new controller or planner is an entry (its
//! own file) and a line in `ControllerKind::ALL`; shown here with throwaway ones that ride
//! without being registered. The tools' copy of the list (for the Python experiment
//! tooling) is checked against it.

mod common;

use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

use cpbp_core::bike::{Controls, CONTROL_DIM};
use cpbp_core::control::{
    BikePlanner, BikeRollout, Diagnostics, Follows, PlanPhases, PlanResult, PlanWait, PlannerSpec,
    PlanningConfig, Trajectory,
};
use cpbp_core::ode::WorldState;
use cpbp_core::ride::{
    Controller, ControllerEntry, ControllerKind, Drives, Intent, Ride, RideState,
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
fn a_new_planner_is_a_spec_and_an_entry_and_plans_on_the_planning_thread() {
    let kind = ControllerKind::new(&STILL_BAR);
    assert!(kind.plans());
    let mut ride = Ride::new(common::flat_ride(), kind);
    // Its own parameter is the ride's to set, as the schema's settings are.
    let parameters = &mut ride.planner.optimizer.parameters;
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

/// The registry as the Python tools read it (tools/cpbp_experiment/controllers.json).
fn registry_json() -> String {
    let entries: Vec<String> = ControllerKind::ALL
        .iter()
        .map(|k| {
            format!(
                "    {{\"name\": \"{}\", \"label\": \"{}\", \"offered\": {}, \"plans\": {}}}",
                k.name(),
                k.label(),
                k.offered(),
                k.plans()
            )
        })
        .collect();
    format!(
        "{{\n  \"controllers\": [\n{}\n  ]\n}}\n",
        entries.join(",\n")
    )
}

/// Holds the tools' copy `file` (in tools/cpbp_experiment/) equal to `expected`, what
/// `source` makes of it; with UPDATE_REGISTRY set, writes it first.
fn assert_tools_copy_is_current(file: &str, expected: &str, source: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tools/cpbp_experiment")
        .join(file);
    if std::env::var_os("UPDATE_REGISTRY").is_some() {
        std::fs::write(&path, expected).expect("write the tools' copy");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(
        committed,
        expected,
        "{} differs from {source}: run `UPDATE_REGISTRY=1 tools/cargo test --release -p \
         cpbp-core --test registry` and commit it",
        path.display()
    );
}

#[test]
fn the_tools_copy_of_the_registry_is_current() {
    assert_tools_copy_is_current("controllers.json", &registry_json(), "ControllerKind::ALL");
}

/// The settings schema as the Python tools read it (tools/cpbp_experiment/settings.json).
#[test]
fn the_tools_copy_of_the_settings_schema_is_current() {
    let schema = cpbp_core::settings::schema_json();
    assert_tools_copy_is_current("settings.json", &schema, "cpbp_core::settings");
}
