//! The C-PBP planner on a toy system with known dynamics: a point mass pushed towards a
//! target along a line.

use std::sync::{Arc, Mutex};

use cpbp_core::control::cpbp::{CpbpConfig, CpbpPlanner, Priors, RolloutSystem, WarmStart};

const DT: f64 = 0.1;
const TARGET: f64 = 1.0;

#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct PointMass {
    x: f64,
    v: f64,
    /// Positions beyond this "blow up" (the step reports failure).
    explodes_beyond: f64,
}

impl RolloutSystem for PointMass {
    type State = (f64, f64);

    fn save(&self) -> (f64, f64) {
        (self.x, self.v)
    }

    fn restore(&mut self, state: &(f64, f64)) {
        (self.x, self.v) = *state;
    }

    fn step(&mut self, u: &[f64], _step: usize) -> Option<f64> {
        self.v += u[0] * DT;
        self.x += self.v * DT;
        if self.x > self.explodes_beyond {
            return None;
        }
        Some(((self.x - TARGET) / 0.1).powi(2) + (self.v / 2.0).powi(2))
    }
}

fn planner(seed: u64) -> CpbpPlanner {
    planner_on_threads(seed, 0)
}

fn planner_on_threads(seed: u64, threads: usize) -> CpbpPlanner {
    let priors = Priors::uniform(1, 3.0, 1.0, 0.2, 4.0);
    CpbpPlanner::new(
        CpbpConfig {
            particles: 16,
            steps: 20,
            seed,
            threads,
            ..CpbpConfig::default()
        },
        priors,
    )
}

/// Runs `frames` frames: plan from the master, apply the first control to it. Returns the
/// master, the applied controls, the blow-ups, and the positions after each frame.
fn ride(
    planner: &mut CpbpPlanner,
    frames: usize,
    explodes_beyond: f64,
) -> (PointMass, Vec<f64>, usize) {
    let (master, applied, blowups, _) = ride_tracking(planner, frames, explodes_beyond);
    (master, applied, blowups)
}

fn ride_tracking(
    planner: &mut CpbpPlanner,
    frames: usize,
    explodes_beyond: f64,
) -> (PointMass, Vec<f64>, usize, Vec<f64>) {
    let mut master = PointMass {
        explodes_beyond,
        ..PointMass::default()
    };
    let mut systems = vec![master; 16];
    let (mut applied, mut blowups, mut positions) = (Vec::new(), 0, Vec::new());
    for _ in 0..frames {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        assert!(
            result.control[0] >= -4.0 && result.control[0] <= 4.0,
            "out of bounds: {:?}",
            result.control
        );
        blowups += result.blowups;
        master.step(&result.control, 0);
        applied.push(result.control[0]);
        positions.push(master.x);
    }
    (master, applied, blowups, positions)
}

/// Over the second half of a ride the mass stays near the target on average.
fn assert_holds_the_target(positions: &[f64]) {
    let last = &positions[positions.len() / 2..];
    let mean_error = last.iter().map(|x| (x - TARGET).abs()).sum::<f64>() / last.len() as f64;
    assert!(
        mean_error < 0.05,
        "mean distance from the target {mean_error}"
    );
}

#[test]
fn it_brings_the_mass_to_the_target_and_holds_it() {
    // 6 s from rest; over the last 3 s the mass stays near the target (sampling noise
    // keeps it moving a little, which the smoothness priors make worth tolerating).
    let (_, _, _, positions) = ride_tracking(&mut planner(7), 60, f64::INFINITY);
    assert_holds_the_target(&positions);
}

#[test]
fn a_fixed_seed_reproduces_the_plan_exactly() {
    let (_, first, _) = ride(&mut planner(42), 30, f64::INFINITY);
    let (_, second, _) = ride(&mut planner(42), 30, f64::INFINITY);
    let (_, other, _) = ride(&mut planner(43), 30, f64::INFINITY);
    assert_eq!(first, second);
    assert_ne!(first, other, "another seed explores differently");
}

#[test]
fn one_thread_and_two_threads_plan_identically() {
    let (_, one, _) = ride(&mut planner_on_threads(11, 1), 20, f64::INFINITY);
    let (_, two, _) = ride(&mut planner_on_threads(11, 2), 20, f64::INFINITY);
    assert_eq!(one, two);
}

#[test]
fn blown_up_rollouts_are_absorbed_without_poisoning_the_rest() {
    // Overshooting the target by 0.3 "explodes". The fast approach makes many sampled
    // rollouts do so; they are cut (restored, huge cost) and the master never crosses.
    let line = TARGET + 0.3;
    let (_, _, blowups, positions) = ride_tracking(&mut planner(7), 60, line);
    assert!(blowups > 0, "the test should provoke blow-ups");
    let furthest = positions.iter().cloned().fold(f64::MIN, f64::max);
    assert!(furthest < line, "the master reached {furthest}");
    assert_holds_the_target(&positions);
}

#[test]
fn the_warm_start_particle_replays_its_sequence() {
    let mut planner = planner(3);
    let mut systems = vec![
        PointMass {
            explodes_beyond: f64::INFINITY,
            ..PointMass::default()
        };
        16
    ];
    let warm: Vec<f64> = (0..20).map(|k| if k < 5 { 2.0 } else { -0.5 }).collect();
    let result = planner.plan(&mut systems, &(0.0, 0.0), WarmStart::Sequence(&warm));
    assert_eq!(result.sequences[1], warm);
}

#[test]
fn each_warm_start_route_decides_what_particle_1_replays() {
    let free = PointMass {
        explodes_beyond: f64::INFINITY,
        ..PointMass::default()
    };
    // The policy route: particle 1 follows the system's controller step by step.
    let mut systems = vec![ObservedPointMass(free); 16];
    let result = planner(4).plan(&mut systems, &(0.0, 0.0), WarmStart::Policy);
    let mut replay = ObservedPointMass(free);
    let expected: Vec<f64> = (0..20)
        .flat_map(|k| {
            let u = replay.policy(k).unwrap();
            replay.step(&u, k);
            u
        })
        .collect();
    assert!(result.warm_started);
    assert_eq!(result.sequences[1], expected);
    // A sequence of the wrong length, or none: particle 1 samples like the others.
    let mut systems = vec![free; 16];
    for warm in [WarmStart::Sequence(&[1.0; 7]), WarmStart::Nothing] {
        let result = planner(4).plan(&mut systems, &(0.0, 0.0), warm);
        assert!(!result.warm_started, "{warm:?}");
    }
    // The refinement route replays nothing while there is no refinement (a system
    // without features never has one).
    let mut planner = planner(4);
    let first = planner.plan(&mut systems, &(0.0, 0.0), WarmStart::Refinement);
    assert!(
        !first.warm_started && first.refined.is_none(),
        "no features, no refinement"
    );
}

/// A system that notes every control given at the first planning step, in a list all its
/// clones share (the planner may step several particles in one system).
#[derive(Clone, Debug, Default)]
struct FirstStepRecorder {
    firsts: Arc<Mutex<Vec<f64>>>,
}

impl RolloutSystem for FirstStepRecorder {
    type State = ();

    fn save(&self) {}

    fn restore(&mut self, _state: &()) {}

    /// Only the first control costs anything: any lineage that survives to the end should
    /// descend from a cheap first step.
    fn step(&mut self, u: &[f64], step: usize) -> Option<f64> {
        if step == 0 {
            self.firsts.lock().expect("not poisoned").push(u[0]);
            return Some((u[0] / 0.1).powi(2));
        }
        Some(0.0)
    }
}

#[test]
fn resampling_keeps_the_low_cost_lineages() {
    let mut planner = planner(5);
    let recorder = FirstStepRecorder::default();
    let mut systems = vec![recorder.clone(); 16];
    let result = planner.plan(&mut systems, &(), WarmStart::Refinement);
    let sampled = recorder.firsts.lock().expect("not poisoned").clone();
    assert_eq!(sampled.len(), 16, "one first step per particle");
    let survived: Vec<f64> = result.sequences.iter().map(|s| s[0]).collect();
    assert!(
        result.resamples > 0,
        "the first step's costs should force a resample"
    );
    assert!(survived.iter().all(|u| sampled.contains(u)));
    let mean_abs = |v: &[f64]| v.iter().map(|u| u.abs()).sum::<f64>() / v.len() as f64;
    assert!(
        mean_abs(&survived) < 0.5 * mean_abs(&sampled),
        "survivors {survived:?} of {sampled:?}"
    );
    let distinct = survived
        .iter()
        .filter(|u| survived.iter().filter(|v| v == u).count() > 1)
        .count();
    assert!(distinct > 0, "low-cost first steps should be forked");
}

/// A point mass that tells the refinement its position and velocity, with a controller of
/// its own (a PD towards the target) for the policy warm start.
#[derive(Clone, Copy, Debug, Default)]
struct ObservedPointMass(PointMass);

impl RolloutSystem for ObservedPointMass {
    type State = (f64, f64);

    fn save(&self) -> (f64, f64) {
        self.0.save()
    }

    fn restore(&mut self, state: &(f64, f64)) {
        self.0.restore(state)
    }

    fn step(&mut self, u: &[f64], step: usize) -> Option<f64> {
        self.0.step(u, step)
    }

    fn policy(&mut self, _step: usize) -> Option<Vec<f64>> {
        Some(vec![
            (2.0 * (TARGET - self.0.x) - 1.5 * self.0.v).clamp(-3.0, 3.0)
        ])
    }

    fn features(&self) -> Vec<f64> {
        vec![self.0.x, self.0.v]
    }
}

#[test]
fn the_refinement_stays_in_bounds_and_is_replayed_by_particle_1_next_frame() {
    let mut planner = planner(9);
    let mass = PointMass {
        explodes_beyond: f64::INFINITY,
        ..PointMass::default()
    };
    let mut systems = vec![ObservedPointMass(mass); 16];
    let first = planner.plan(&mut systems, &(0.0, 0.0), WarmStart::Refinement);
    let refined = first.refined.expect("a system with features is refined");
    assert_eq!(refined.len(), 20);
    assert!(
        refined.iter().all(|u| (-4.0..=4.0).contains(u)),
        "{refined:?}"
    );
    // It heads for the target like the particles did: push forward first.
    assert!(refined[0] > 0.0, "{refined:?}");
    let second = planner.plan(&mut systems, &(0.0, 0.0), WarmStart::Refinement);
    let mut shifted = refined.clone();
    cpbp_core::control::cpbp::shift_one_step(&mut shifted, 1);
    assert_eq!(second.sequences[1], shifted);
}

#[test]
fn a_single_trajectory_still_plans_even_with_a_warm_start() {
    let mut planner = planner(4);
    planner.config.particles = 1;
    let mass = PointMass {
        explodes_beyond: f64::INFINITY,
        ..PointMass::default()
    };
    let mut systems = vec![mass; 1];
    let warm = vec![1.0; 20];
    for _ in 0..3 {
        let result = planner.plan(&mut systems, &(0.0, 0.0), WarmStart::Sequence(&warm));
        assert_eq!(result.sequences.len(), 1);
        assert!(!result.warm_started);
        assert!(result.best_cost.is_finite());
    }
}
