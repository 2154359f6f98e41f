//! Trajectories that have fallen (issue 59): C-PBP counts the particle steps it simulates
//! after a lineage fell (the plans' "fallen steps" share), what stopping them could save.

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
const FRAMES: usize = 20;

/// A mass moved along a line by its control, which falls for good past the edge; it
/// counts the steps it is simulated from over the edge.
#[derive(Clone, Default)]
struct Ledge {
    x: f64,
    over: bool,
    steps_after_falls: Arc<AtomicUsize>,
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
        if self.over {
            self.steps_after_falls.fetch_add(1, Ordering::SeqCst);
            return Some(FALLEN_COST);
        }
        self.x += u[0] * DT;
        self.over = self.x > EDGE;
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

#[test]
fn a_plan_says_what_share_of_its_steps_rolled_on_after_falls() {
    let steps_after_falls = Arc::new(AtomicUsize::new(0));
    let system = Ledge {
        steps_after_falls: Arc::clone(&steps_after_falls),
        ..Ledge::default()
    };
    let mut systems = vec![system; PARTICLES];
    let mut master = Ledge::default();
    let mut planner = CpbpPlanner::new(
        CpbpConfig {
            particles: PARTICLES,
            steps: STEPS,
            seed: 11,
            ..CpbpConfig::default()
        },
        Priors::uniform(1, 3.0, 2.0, 0.5, 4.0),
    );
    let mut shares = 0.0;
    for _ in 0..FRAMES {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        master.step(&result.control, 0);
        shares += result.fallen_steps;
    }
    let counted = steps_after_falls.load(Ordering::SeqCst);
    assert!(
        counted > 0,
        "fallen trajectories roll on until resampling drops them"
    );
    assert!(!master.over, "the plans keep the master back from the edge");
    let reported = shares * (PARTICLES * STEPS) as f64;
    assert!(
        (reported - counted as f64).abs() < 1e-6,
        "the share is of the steps simulated after a fall: {reported} against {counted}"
    );
}
