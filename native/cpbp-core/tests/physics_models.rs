//! The exact physics model (direct solver, explicit wheel gyroscopics, arms weaker than
//! the steering): every controller rides in it, and its one-step rollouts predict its
//! master better than the classic model's two-substep rollouts predicted theirs. Heavy:
//! `make test` runs these in a release build; debug builds skip them.

mod common;

use common::{
    ask_lean, assert_rides_straight_for_20_seconds, ride, ride_in,
    rms_lean_error_in_a_15_degree_turn, FRAMES_PER_SECOND,
};
use cpbp_core::control::fidelity::{divergence, Recording, RolloutPhysics};
use cpbp_core::ode::Solver;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::ControllerKind;

const EXACT: PhysicsModel = PhysicsModel::Exact;

/// Lean drift (rad) after 0.5 s of `physics` replaying an arcade ride of `model`'s
/// master at 15 km/h (4 s straight, then 4 s in a 15° turn).
fn drift_after_half_a_second(model: PhysicsModel, physics: RolloutPhysics) -> f64 {
    let mut r = ride_in(model, ControllerKind::Arcade, 15.0, 0);
    Recording::ride(&mut r, 3 * FRAMES_PER_SECOND);
    let mut recording = Recording::ride(&mut r, 4 * FRAMES_PER_SECOND);
    ask_lean(&mut r, 15f64.to_radians());
    recording.extend(Recording::ride(&mut r, 4 * FRAMES_PER_SECOND));
    divergence(r.sim(), &recording, physics, 15, 10, &[15])[0].lean
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn the_exact_rollouts_predict_their_master_better_than_two_classic_substeps_did() {
    let exact = drift_after_half_a_second(
        EXACT,
        RolloutPhysics {
            solver: EXACT.rollout_solver(),
            substeps: EXACT.rollout_substeps(),
        },
    );
    let classic_two = drift_after_half_a_second(
        PhysicsModel::Classic,
        RolloutPhysics {
            solver: Solver::QuickStep,
            substeps: 2,
        },
    );
    assert!(
        exact > 0.0,
        "one step per control step is not the master's physics"
    );
    assert!(
        exact < classic_two,
        "exact {:.2}° against classic x 2 {:.2}°",
        exact.to_degrees(),
        classic_two.to_degrees()
    );
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn every_controller_rides_straight_and_holds_a_turn_in_the_exact_model() {
    for (kind, particles, worst_rms) in [
        (ControllerKind::Arcade, 0, 2.0),
        (ControllerKind::Combined, 10, 2.0),
        (ControllerKind::Optimizer, 10, 4.0),
    ] {
        let mut r = ride_in(EXACT, kind, 15.0, particles);
        assert_rides_straight_for_20_seconds(&mut r);
        let mut r = ride_in(EXACT, kind, 15.0, particles);
        let rms = rms_lean_error_in_a_15_degree_turn(&mut r);
        println!("{kind:?}: RMS lean error {rms:.2}° in a 15° turn");
        assert!(rms < worst_rms, "{kind:?}: {rms:.2}°");
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn the_arcade_controller_rides_at_walking_pace_in_the_exact_model() {
    let mut r = ride_in(EXACT, ControllerKind::Arcade, 8.0, 0);
    ride(&mut r, 20.0, 0.0);
    assert_eq!(r.sim().crashed(), None);
    let speed = r.sim().bike().forward_speed(r.sim().world(), r.sim().up());
    assert!(speed > 1.5, "still riding: {speed:.2} m/s");
}
