//! Trajectories that have fallen (issue 59): C-PBP counts the particle steps taken after a
//! lineage fell, and with `stop_fallen` stops simulating them. On a toy whose fall is
//! final and costs the same every step after it, stopping changes no plan, only how much
//! is simulated.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use cpbp_core::control::cpbp::{CpbpConfig, CpbpPlanner, Priors, RolloutSystem, WarmStart};

const DT: f64 = 0.1;
/// The mass is held near the edge, so the planner's explorations go over it.
const TARGET: f64 = 0.9;
const EDGE: f64 = 1.0;
/// What every step costs once the mass is over the edge (the bike's crash cost).
const FALLEN_COST: f64 = 400.0;
const PARTICLES: usize = 8;
const STEPS: usize = 12;

/// A mass moved along a line by its control, which falls for good past the edge.
#[derive(Clone, Default)]
struct Ledge {
    x: f64,
    over: bool,
    steps: Arc<AtomicUsize>,
}

impl RolloutSystem for Ledge {
    type State = (f64, bool);

    fn save(&self) -> (f64, bool) {
        (self.x, self.over)
    }

    fn restore(&mut self, state: &(f64, bool)) {
        (self.x, self.over) = *state;
    }

    fn step(&mut self, u: &[f64], _step: usize) -> Option<f64> {
        self.steps.fetch_add(1, Ordering::SeqCst);
        if !self.over {
            self.x += u[0] * DT;
            self.over = self.x > EDGE;
        }
        Some(if self.over {
            FALLEN_COST
        } else {
            ((self.x - TARGET) / 0.1).powi(2)
        })
    }

    fn fallen(&self) -> bool {
        self.over
    }
}

/// Plans 20 frames from rest, the master following; returns each frame's control, its
/// share of steps after falls, and how many steps the rollouts simulated.
fn ride(stop_fallen: bool) -> (Vec<Vec<f64>>, Vec<f64>, usize) {
    let steps = Arc::new(AtomicUsize::new(0));
    let system = Ledge {
        steps: Arc::clone(&steps),
        ..Ledge::default()
    };
    let mut systems = vec![system; PARTICLES];
    let mut master = Ledge::default();
    let mut planner = CpbpPlanner::new(
        CpbpConfig {
            particles: PARTICLES,
            steps: STEPS,
            seed: 11,
            stop_fallen,
            ..CpbpConfig::default()
        },
        Priors::uniform(1, 3.0, 2.0, 0.5, 4.0),
    );
    let (mut controls, mut shares) = (Vec::new(), Vec::new());
    for _ in 0..20 {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        master.step(&result.control, 0);
        controls.push(result.control.clone());
        shares.push(result.fallen_steps);
    }
    (controls, shares, steps.load(Ordering::SeqCst))
}

#[test]
fn fallen_trajectories_roll_on_until_resampling_drops_them() {
    let (_, shares, simulated) = ride(false);
    assert_eq!(
        simulated,
        20 * PARTICLES * STEPS,
        "every particle step is simulated"
    );
    let mean = shares.iter().sum::<f64>() / shares.len() as f64;
    assert!(mean > 0.0 && mean < 1.0, "some steps follow a fall: {mean}");
}

#[test]
fn stopping_fallen_trajectories_simulates_less_and_plans_the_same() {
    let (rolled, shares, all) = ride(false);
    let (stopped, stopped_shares, fewer) = ride(true);
    assert_eq!(
        stopped, rolled,
        "a final fall's steps cost the same either way"
    );
    assert_eq!(stopped_shares, shares);
    let after = shares.iter().sum::<f64>() * (PARTICLES * STEPS) as f64;
    assert_eq!(
        fewer,
        all - after.round() as usize,
        "only the steps after falls are saved"
    );
}
