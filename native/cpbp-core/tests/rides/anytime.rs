//! Planning on its own thread and handing plans over at control-step boundaries.
//! Heavy: `make test` runs these in a release build; debug builds skip them.

use crate::common;

use std::time::Duration;

use cpbp_core::control::{cpbp, Goal, PlanWait, PlanningConfig, PlanningThread};
use cpbp_core::ride::ControllerKind;

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn waiting_for_each_plan_rides_like_planning_in_line() {
    let mut ride = common::ride_at(ControllerKind::COMBINED, 15.0, 15);
    common::ride(&mut ride, 20.0, 0.0);
    assert_eq!(ride.sim().crashed(), None);
    // Only the very first step has no plan (the arcade controller drives it).
    let handover = ride.handover().expect("a planner drove");
    assert_eq!((handover.late, ride.late_plans()), (0, 0), "{handover:?}");
    let plan = ride.plan().expect("plans were taken over");
    assert_eq!(plan.paths.len(), 15);
    assert!(plan.paths.iter().all(|p| p.len() == 36));
    assert!(plan.best < 15);
    assert_eq!(
        plan.warm,
        Some(1),
        "combined mode replays the arcade rollout"
    );
    // The best path starts where the bike is, give or take one step of riding.
    let start = plan.paths[plan.best][0];
    let sim = ride.sim();
    let com = sim.bike().center_of_mass(sim.world());
    assert!(start.distance(com) < 0.5, "{start} vs {com}");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn a_planner_that_cannot_keep_up_never_stalls_the_game_or_drops_the_bike() {
    // Never waiting while the master runs far faster than real time: most boundaries
    // find no plan for their step and replay the last plan open loop or fall back.
    let mut ride = common::ride_at(ControllerKind::COMBINED, 20.0, 8);
    ride.planner.wait = PlanWait::AtMost(Duration::ZERO);
    ride.planner.auto_trajectories = false;
    common::ride(&mut ride, 10.0, 0.0);
    assert_eq!(ride.sim().crashed(), None);
    assert!(ride.late_plans() > 0, "{:?}", ride.handover());
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn plans_made_before_a_reset_are_never_applied_after_it() {
    // The hand-over itself, below the ride: a reset drops plans already in flight.
    let mut sim = common::flat_ride();
    let config = PlanningConfig {
        trajectories: 5,
        ..PlanningConfig::default()
    };
    let mut anytime = PlanningThread::new(&sim, &cpbp::COMBINED, PlanWait::EveryPlan);
    let drive = common::auto_throttle(15.0);
    let ride =
        |sim: &mut cpbp_core::simulation::Simulation, anytime: &mut PlanningThread, steps| {
            for _ in 0..steps {
                let controls = anytime.controls(sim, &Goal::riding(0.0, drive), &config, None);
                sim.set_controls(controls);
                sim.step();
            }
        };
    ride(&mut sim, &mut anytime, 60);
    assert!(anytime.plan().is_some());
    anytime.reset();
    assert!(anytime.plan().is_none());
    ride(&mut sim, &mut anytime, 30);
    assert!(anytime.plan().is_some(), "new plans arrive after the reset");
    assert_eq!(sim.crashed(), None);
}
