//! Planning on its own thread and handing plans over at control-step boundaries.
//! Heavy: `make test` runs these in a release build; debug builds skip them.

mod common;

use std::time::Duration;

use cpbp_core::control::{AnytimeOptimizer, OptimizerConfig, OptimizerMode, PlanWait};
use cpbp_core::simulation::Simulation;

fn combined(particles: usize) -> OptimizerConfig {
    OptimizerConfig {
        mode: OptimizerMode::Combined,
        particles,
        ..OptimizerConfig::default()
    }
}

/// Rides `seconds` straight at `kmh`, handing plans over as `anytime.wait` says.
fn ride(
    sim: &mut Simulation,
    anytime: &mut AnytimeOptimizer,
    config: &OptimizerConfig,
    seconds: f64,
    kmh: f64,
) {
    let drive = common::auto_throttle(kmh);
    let mut control = |sim: &Simulation, lean: f64| anytime.controls(sim, lean, &drive, config);
    common::ride(sim, seconds, 0.0, &mut control);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn waiting_for_each_plan_rides_like_planning_in_line() {
    let mut sim = common::flat_ride();
    let config = combined(15);
    let mut anytime = AnytimeOptimizer::new(&sim, PlanWait::EveryPlan);
    ride(&mut sim, &mut anytime, &config, 20.0, 15.0);
    assert_eq!(sim.crashed(), None);
    // Only the very first step has no plan (the arcade controller drives it).
    assert_eq!(anytime.stats.late, 0, "{:?}", anytime.stats);
    let plan = anytime.plan().expect("plans were taken over");
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
    let mut sim = common::flat_ride();
    let config = combined(8);
    let mut anytime = AnytimeOptimizer::new(&sim, PlanWait::AtMost(Duration::ZERO));
    ride(&mut sim, &mut anytime, &config, 10.0, 20.0);
    assert_eq!(sim.crashed(), None);
    assert!(anytime.stats.late > 0, "{:?}", anytime.stats);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn plans_made_before_a_reset_are_never_applied_after_it() {
    let mut sim = common::flat_ride();
    let config = combined(5);
    let mut anytime = AnytimeOptimizer::new(&sim, PlanWait::EveryPlan);
    ride(&mut sim, &mut anytime, &config, 2.0, 15.0);
    assert!(anytime.plan().is_some());
    anytime.reset();
    assert!(anytime.plan().is_none());
    ride(&mut sim, &mut anytime, &config, 1.0, 15.0);
    assert!(anytime.plan().is_some(), "new plans arrive after the reset");
    assert_eq!(sim.crashed(), None);
}
