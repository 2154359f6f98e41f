//! The baseline planners (predictive sampling and MPPI) on the systems C-PBP is tested on:
//! the ODE pendulum, a toy whose rollouts blow up, and the bike in the game's physics.

use crate::common;

use common::pendulum::Pendulum;
use common::{assert_rides_straight_for_20_seconds, ride_in};
use cpbp_core::control::cpbp::{Priors, RolloutSystem};
use cpbp_core::control::sampling::{SamplingConfig, SamplingPlanner, SamplingUpdate};
use cpbp_core::control::PlanResult;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::ControllerKind;

const UPDATES: [SamplingUpdate; 2] = [
    SamplingUpdate::Best,
    SamplingUpdate::Weighted { temperature: 0.1 },
];

fn planner(update: SamplingUpdate, threads: usize) -> SamplingPlanner {
    let config = SamplingConfig {
        samples: 16,
        steps: 24,
        noise: 0.5,
        update,
        seed: 7,
        threads,
        ..SamplingConfig::default()
    };
    SamplingPlanner::new(config, Priors::uniform(1, 2.0, 1.0, 0.2, 4.0))
}

/// A plan and the weights the planner gave its candidates.
type Weighed = (PlanResult, Vec<f64>);

/// Plans and applies `frames` control steps on a pendulum starting at `tilt`; the plans.
fn balance(mut planner: SamplingPlanner, tilt: f64, frames: usize) -> (Pendulum, Vec<Weighed>) {
    let mut master = Pendulum::new(tilt);
    let mut systems: Vec<Pendulum> = (0..16).map(|_| Pendulum::new(tilt)).collect();
    let plans = (0..frames)
        .map(|_| {
            let result = planner.plan(&mut systems, &master.save());
            master.advance(result.control[0]);
            (result, planner.weights.clone())
        })
        .collect();
    (master, plans)
}

#[test]
fn both_planners_bring_the_pendulum_upright_and_keep_it_there() {
    for update in UPDATES {
        let mut master = Pendulum::new(0.3);
        let mut systems: Vec<Pendulum> = (0..16).map(|_| Pendulum::new(0.3)).collect();
        let mut planner = planner(update, 2);
        let mut worst: f64 = 0.0;
        for frame in 0..150 {
            let result = planner.plan(&mut systems, &master.save());
            assert!((-4.0..=4.0).contains(&result.control[0]));
            master.advance(result.control[0]);
            if frame >= 90 {
                worst = worst.max(master.tilt().abs());
            }
        }
        assert!(
            worst < 0.05,
            "{update:?}: worst tilt over the last 2 s {worst} rad"
        );
    }
}

#[test]
fn a_fixed_seed_plans_the_same_on_one_thread_and_on_two() {
    for update in UPDATES {
        let (one, plans_one) = balance(planner(update, 1), 0.2, 20);
        let (two, plans_two) = balance(planner(update, 2), 0.2, 20);
        assert_eq!(plans_one, plans_two, "{update:?}");
        assert_eq!(one.tilt().to_bits(), two.tilt().to_bits());
    }
}

#[test]
fn mppi_applies_the_weighted_average_and_sampling_the_cheapest() {
    let (_, plans) = balance(planner(UPDATES[1], 2), 0.2, 3);
    let (plan, weights) = &plans[2];
    let average: f64 = plan
        .trajectories
        .iter()
        .zip(weights)
        .map(|(t, w)| t.controls[0] * w)
        .sum();
    assert!((plan.control[0] - average).abs() < 1e-12);
    assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    let (_, plans) = balance(planner(UPDATES[0], 2), 0.2, 3);
    let (plan, _) = &plans[2];
    assert_eq!(plan.chosen, plan.trajectories[plan.best].controls);
    assert!(plan.trajectories.iter().all(|t| t.cost >= plan.best_cost));
}

/// A point mass whose simulation "blows up" (returns None) when pushed faster than 1.
#[derive(Default)]
struct Fragile(f64);

impl RolloutSystem for Fragile {
    type State = f64;
    fn save(&self) -> f64 {
        self.0
    }
    fn restore(&mut self, state: &f64) {
        self.0 = *state;
    }
    fn step(&mut self, u: &[f64], _step: usize) -> Option<f64> {
        self.0 += u[0] / 30.0;
        (u[0].abs() <= 1.0).then(|| (self.0 - 1.0).powi(2))
    }
}

#[test]
fn blown_up_rollouts_are_costed_and_never_chosen() {
    for update in UPDATES {
        let config = SamplingConfig {
            samples: 32,
            steps: 10,
            noise: 1.0,
            update,
            ..SamplingConfig::default()
        };
        let mut planner = SamplingPlanner::new(config, Priors::uniform(1, 1.0, 1.0, 0.2, 3.0));
        let mut systems: Vec<Fragile> = (0..32).map(|_| Fragile::default()).collect();
        let result = planner.plan(&mut systems, &0.0);
        assert!(
            result.blowups > 0,
            "{update:?}: noise 1 must push some past 1"
        );
        assert!(result.best_cost < 1e6, "{update:?}: the nominal survives");
        assert!(result
            .chosen
            .iter()
            .all(|u| u.is_finite() && u.abs() <= 3.0));
        for (trajectory, weight) in result.trajectories.iter().zip(&planner.weights) {
            assert!(
                trajectory.cost < 1e6 || *weight < 1e-12,
                "{update:?}: a blow-up has weight"
            );
        }
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "slow in debug builds; make test runs it in release"
)]
fn both_planners_ride_straight_at_15_kmh_in_the_game_physics() {
    for kind in [ControllerKind::SAMPLING, ControllerKind::MPPI] {
        let mut ride = ride_in(PhysicsModel::Exact, kind, 15.0, 10);
        assert_rides_straight_for_20_seconds(&mut ride);
    }
}
