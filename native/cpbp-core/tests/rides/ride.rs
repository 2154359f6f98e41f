//! The ride: one control step at a time through the one controller interface, with the
//! start gate, the step and late-plan counts, and plans forgotten when the ride jumps.

use crate::common;

use cpbp_core::bike::Controls;
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use glam::DVec3;

fn ride_with(kind: ControllerKind) -> Ride {
    let mut ride = Ride::new(common::flat_ride(), kind);
    ride.set_intent(Intent {
        drive: common::auto_throttle(15.0),
        ..Intent::default()
    });
    ride
}

fn speed(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().forward_speed(sim.world(), sim.up())
}

#[test]
fn every_controller_has_a_stable_name_and_a_label() {
    for kind in ControllerKind::all() {
        assert_eq!(ControllerKind::from_name(kind.name()), Some(kind));
        assert!(!kind.label().is_empty());
        // Names go into settings files, CSV columns and GDScript strings as they are.
        let name = kind.name();
        assert!(
            name.chars().all(|c| c.is_ascii_lowercase() || c == '_'),
            "{name}"
        );
    }
    let mut names: Vec<_> = ControllerKind::all().iter().map(|k| k.name()).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(
        names.len(),
        ControllerKind::all().len(),
        "names are distinct"
    );
    assert!(ControllerKind::SAMPLING.plans() && ControllerKind::MPPI.offered());
    assert_eq!(ControllerKind::from_name("autopilot"), None);
    assert!(!ControllerKind::MANUAL.offered() && ControllerKind::COMBINED.offered());
}

#[test]
fn the_gate_holds_the_bike_until_the_first_throttle() {
    let mut ride = Ride::new(common::flat_ride(), ControllerKind::ARCADE);
    ride.wait_for_throttle = true;
    assert!(!ride.try_start());
    assert!(ride.is_waiting_for_throttle());
    ride.set_intent(Intent {
        drive: common::auto_throttle(15.0),
        ..Intent::default()
    });
    assert!(ride.try_start(), "a throttle opens it");
    assert!(!ride.is_waiting_for_throttle());
}

#[test]
fn the_arcade_ride_counts_its_steps_and_a_reset_starts_a_new_ride() {
    let mut ride = ride_with(ControllerKind::ARCADE);
    for _ in 0..60 {
        ride.step();
    }
    assert_eq!(ride.steps(), 60);
    assert!(
        speed(&ride) > 2.0,
        "the throttle drove it: {}",
        speed(&ride)
    );
    assert!(
        ride.plan().is_none() && ride.handover().is_none(),
        "arcade has no plans"
    );
    let lean_asked = {
        ride.set_intent(Intent {
            turn: 1.0,
            ..*ride.intent()
        });
        ride.desired_lean()
    };
    assert!(
        lean_asked > 0.1,
        "a right turn asks for a right lean: {lean_asked}"
    );
    ride.reset_to(cpbp_core::bike::Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: glam::DQuat::IDENTITY,
    });
    assert_eq!((ride.steps(), ride.late_plans()), (0, 0));
    assert!(speed(&ride).abs() < 1e-9);
}

#[test]
fn raw_controls_drive_until_the_next_intent() {
    let mut ride = ride_with(ControllerKind::ARCADE);
    let mut brake = Controls::default();
    brake.set(cpbp_core::bike::index::REAR_WHEEL, 0.0);
    ride.set_raw_controls(brake);
    for _ in 0..30 {
        ride.step();
    }
    assert!(speed(&ride).abs() < 0.5, "the raw controls held the wheel");
    ride.set_intent(*ride.intent());
    for _ in 0..30 {
        ride.step();
    }
    assert!(speed(&ride) > 1.0, "the controller drives again");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn a_planner_drives_with_plans_and_switching_forgets_them() {
    let mut ride = ride_with(ControllerKind::COMBINED);
    ride.planner.planning.trajectories = 5;
    ride.planner.wait = PlanWait::EveryPlan;
    for _ in 0..30 {
        ride.step();
    }
    assert_eq!(ride.plan().map(|p| p.paths.len()), Some(5));
    assert_eq!(ride.late_plans(), 0, "every step waited for its plan");
    assert!(ride.handover().is_some_and(|h| h.boundaries == 30));
    ride.set_controller(ControllerKind::ARCADE);
    ride.step();
    assert!(ride.plan().is_none(), "no plan while arcade drives");
    ride.set_controller(ControllerKind::COMBINED);
    ride.step();
    assert_eq!(
        ride.late_plans(),
        0,
        "the first step after a switch has no plan by design"
    );
    ride.step();
    assert!(ride.plan().is_some());
    assert_eq!(ride.sim().crashed(), None);
}

#[test]
fn a_lean_asked_for_directly_replaces_the_turn_and_is_held_to_the_limit() {
    let mut ride = ride_with(ControllerKind::ARCADE);
    let ask = |ride: &mut Ride, lean: f64| {
        ride.set_intent(Intent {
            turn: -1.0,
            lean: Some(lean),
            ..*ride.intent()
        });
        ride.desired_lean()
    };
    assert_eq!(ask(&mut ride, 0.2), 0.2, "the lean wins over the turn");
    assert_eq!(ask(&mut ride, 3.0), 30f64.to_radians(), "held to the limit");
    assert_eq!(ask(&mut ride, f64::NAN), 0.0, "nonsense asks for nothing");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn a_dying_planning_thread_is_reported_the_bike_rides_on_and_a_new_ride_rebuilds_it() {
    let mut ride = common::ride_at(ControllerKind::COMBINED, 15.0, 5);
    common::ride(&mut ride, 1.0, 0.0);
    assert_eq!(ride.failure(), None);
    ride.inject_fault("injected planner fault");
    common::ride(&mut ride, 3.0, 0.0);
    assert_eq!(
        ride.failure(),
        Some("the planner stopped (injected planner fault); arcade steers")
    );
    assert!(
        ride.plan().is_none(),
        "no plan drives: the arcade controller does"
    );
    assert_eq!(ride.sim().crashed(), None, "the fallback kept the bike up");
    assert!(speed(&ride) > 3.0, "and riding: {}", speed(&ride));
    ride.reset_to(cpbp_core::bike::Placement::IDENTITY);
    common::ride(&mut ride, 1.0, 0.0);
    assert_eq!(
        ride.failure(),
        None,
        "the new ride has a new planning thread"
    );
    assert!(ride.plan().is_some());
}
