//! A ride repeats exactly: the same ride from a new `Simulation` ends in the same state,
//! bit for bit, whatever its thread simulated before or simulates in between. Results,
//! resumed experiments, paired comparisons and replays all lean on this.
//! The planner rides are heavy: `make test` runs this file in a release build.

mod common;

use cpbp_core::control::{
    AnytimeOptimizer, ArcadeController, OptimizerConfig, OptimizerMode, PlanWait,
};
use cpbp_core::ode::WorldState;
use cpbp_core::simulation::Simulation;

#[derive(Clone, Copy, Debug)]
enum Driver {
    Arcade,
    Planner(OptimizerMode),
}

/// Rides 3 s at `kmh` asking for a 10° right lean after 1 s, from a new simulation, and
/// returns the final state. `between` runs after every control step (other work on the
/// same thread).
fn ride(driver: Driver, kmh: f64, between: &mut impl FnMut()) -> WorldState {
    let mut sim = common::flat_ride();
    let drive = common::auto_throttle(kmh);
    let mut arcade = ArcadeController::default();
    let config = |mode| OptimizerConfig {
        mode,
        particles: 5,
        threads: 2,
        ..OptimizerConfig::default()
    };
    let mut planner = match driver {
        Driver::Planner(mode) => Some((
            AnytimeOptimizer::new(&sim, PlanWait::EveryPlan),
            config(mode),
        )),
        Driver::Arcade => None,
    };
    for step in 0..90 {
        let lean = if step < 30 { 0.0 } else { 10f64.to_radians() };
        let controls = match &mut planner {
            Some((anytime, config)) => anytime.controls(&sim, lean, &drive, config),
            None => {
                let dt = sim.config().control_dt;
                arcade.controls(sim.bike(), sim.world(), lean, &drive, sim.up(), dt)
            }
        };
        sim.set_controls(controls);
        sim.step();
        between();
    }
    if let Some((anytime, _)) = &planner {
        assert_eq!(anytime.stats.late, 0, "every step waited for its plan");
    }
    sim.world().snapshot()
}

/// Another ride on the calling thread, stepped one control step per call.
fn other_ride() -> impl FnMut() {
    let mut sim: Simulation = common::flat_ride();
    let mut arcade = ArcadeController::default();
    let drive = common::auto_throttle(20.0);
    move || {
        let dt = sim.config().control_dt;
        let controls = arcade.controls(sim.bike(), sim.world(), -0.1, &drive, sim.up(), dt);
        sim.set_controls(controls);
        sim.step();
    }
}

/// The ride alone on a new thread, then on a thread that rode something else first and
/// steps another simulation between its steps: both must end in the same state.
fn assert_repeats(driver: Driver) {
    let alone = std::thread::spawn(move || ride(driver, 10.0, &mut || {}))
        .join()
        .unwrap();
    let after_others = std::thread::spawn(move || {
        ride(Driver::Arcade, 20.0, &mut || {});
        let mut other = other_ride();
        ride(driver, 10.0, &mut other)
    })
    .join()
    .unwrap();
    assert!(
        alone == after_others,
        "{driver:?}: the ride depended on what its thread simulated"
    );
    // And not trivially: another speed ends elsewhere.
    assert!(ride(Driver::Arcade, 12.0, &mut || {}) != alone);
}

#[test]
fn an_arcade_ride_does_not_depend_on_its_thread() {
    assert_repeats(Driver::Arcade);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn a_combined_ride_does_not_depend_on_its_thread() {
    assert_repeats(Driver::Planner(OptimizerMode::Combined));
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn an_optimizer_ride_does_not_depend_on_its_thread() {
    assert_repeats(Driver::Planner(OptimizerMode::Optimizer));
}
