//! The exact physics model (direct solver, explicit wheel gyroscopics, arms weaker than
//! the steering): every controller rides in it, and its rollouts (one direct step per
//! planning step, two at first) predict its master better than the classic model's
//! two-substep rollouts predicted theirs. Heavy: `make test` runs these in a release
//! build; debug builds skip them.

use crate::common;

use common::{
    ask_lean, assert_rides_straight_for_20_seconds, ride, ride_in,
    rms_lean_error_in_a_15_degree_turn, FRAMES_PER_SECOND,
};
use cpbp_core::ode::Solver;
use cpbp_core::physics::{PhysicsModel, RolloutStepping};
use cpbp_core::ride::fidelity::{divergence, Recording, RolloutPhysics};
use cpbp_core::ride::ControllerKind;

const EXACT: PhysicsModel = PhysicsModel::Exact;

/// Lean drift (rad) after `steps` control steps of `physics` replaying an arcade ride of
/// `model`'s master at 15 km/h (4 s straight, then 4 s in a 15° turn).
fn drift_after(model: PhysicsModel, physics: RolloutPhysics, steps: usize) -> f64 {
    let mut r = ride_in(model, ControllerKind::ARCADE, 15.0, 0);
    Recording::ride(&mut r, 3 * FRAMES_PER_SECOND);
    let mut recording = Recording::ride(&mut r, 4 * FRAMES_PER_SECOND);
    ask_lean(&mut r, 15f64.to_radians());
    recording.extend(Recording::ride(&mut r, 4 * FRAMES_PER_SECOND));
    divergence(r.sim(), &recording, physics, steps, 10, &[steps])[0].lean
}

fn drift_after_half_a_second(model: PhysicsModel, physics: RolloutPhysics) -> f64 {
    drift_after(model, physics, 15)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn the_exact_rollouts_lead_steps_halve_the_drift_where_the_plan_is_decided() {
    let stepping = EXACT.rollout_stepping();
    let lead = stepping.lead_steps;
    assert!(lead > 0 && stepping.lead_substeps > stepping.substeps);
    let drift = |stepping| {
        let physics = RolloutPhysics {
            solver: EXACT.rollout_solver(),
            stepping,
        };
        drift_after(EXACT, physics, lead)
    };
    let (chosen, one_step) = (drift(stepping), drift(RolloutStepping::uniform(1)));
    println!(
        "lean drift after {lead} steps: {:.2}° ({stepping}), {:.2}° (1 per step)",
        chosen.to_degrees(),
        one_step.to_degrees()
    );
    assert!(
        chosen <= one_step / 2.0,
        "after {lead} steps: {:.2}° against one step's {:.2}°",
        chosen.to_degrees(),
        one_step.to_degrees()
    );
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
            stepping: EXACT.rollout_stepping(),
        },
    );
    let classic_two = drift_after_half_a_second(
        PhysicsModel::Classic,
        RolloutPhysics {
            solver: Solver::QuickStep,
            stepping: RolloutStepping::uniform(2),
        },
    );
    assert!(
        exact > 0.0,
        "the exact rollouts are not the master's physics"
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
        (ControllerKind::ARCADE, 0, 2.0),
        (ControllerKind::COMBINED, 10, 2.0),
        (ControllerKind::OPTIMIZER, 10, 4.0),
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
    let mut r = ride_in(EXACT, ControllerKind::ARCADE, 8.0, 0);
    ride(&mut r, 20.0, 0.0);
    assert_eq!(r.sim().crashed(), None);
    let speed = r.sim().bike().forward_speed(r.sim().world(), r.sim().up());
    assert!(speed > 1.5, "still riding: {speed:.2} m/s");
}
