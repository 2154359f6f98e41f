//! The rollouts' physics predicts the bike the master rides (issue 13's first fidelity
//! guard): the master's controls replayed open loop from its recorded states.

mod common;

use common::{ask_lean, ride_at, FRAMES_PER_SECOND};
use cpbp_core::control::PlanningConfig;
use cpbp_core::ode::Solver;
use cpbp_core::physics::RolloutStepping;
use cpbp_core::ride::fidelity::{divergence, Recording, RolloutPhysics};
use cpbp_core::ride::{ControllerKind, Ride};

/// Half a second and the planning horizon (1.2 s), in control steps.
const AT: [usize; 2] = [15, 36];

/// An arcade ride at 15 km/h: 3 s to get going, then 4 s straight and 4 s in a 15° turn.
fn recorded_ride() -> (Ride, Recording) {
    let mut ride = ride_at(ControllerKind::ARCADE, 15.0, 0);
    Recording::ride(&mut ride, 3 * FRAMES_PER_SECOND);
    let mut recording = Recording::ride(&mut ride, 4 * FRAMES_PER_SECOND);
    ask_lean(&mut ride, 15f64.to_radians());
    let turn = Recording::ride(&mut ride, 4 * FRAMES_PER_SECOND);
    recording.extend(turn);
    (ride, recording)
}

#[test]
fn the_masters_own_physics_replays_its_ride_exactly() {
    let (ride, recording) = recorded_ride();
    let master = RolloutPhysics::of(ride.sim());
    for found in divergence(ride.sim(), &recording, master, 36, 10, &AT) {
        assert_eq!(found.lean, 0.0);
        assert_eq!(found.position, 0.0);
    }
}

#[test]
fn the_optimizers_rollouts_predict_the_master_far_better_than_two_substeps_do() {
    // Two QuickStep substeps per control step predicted a less stable bike and the
    // planners fell at 10 km/h with them: the default rollouts must do much better.
    let (ride, recording) = recorded_ride();
    let config = PlanningConfig::default();
    let chosen = RolloutPhysics {
        solver: config.rollout_solver,
        stepping: config.rollout_stepping,
    };
    let two = RolloutPhysics {
        solver: Solver::QuickStep,
        stepping: RolloutStepping::uniform(2),
    };
    let chosen = divergence(ride.sim(), &recording, chosen, 36, 10, &AT);
    let two = divergence(ride.sim(), &recording, two, 36, 10, &AT);
    for (chosen, two) in chosen.iter().zip(&two) {
        assert!(two.lean > 0.01, "two substeps differ measurably: {two:?}");
        assert!(chosen.lean <= two.lean / 4.0, "{chosen:?} against {two:?}");
        assert!(
            chosen.position <= two.position / 4.0,
            "{chosen:?} against {two:?}"
        );
    }
}
