//! A trajectory count that follows how much the plans disagree (issue 59): C-PBP plans
//! with `agreeing_trajectories` after a plan whose trajectories' first controls agreed
//! (`disagreement` below `agreement`), with all N otherwise; off, every plan has N.

mod common;

use cpbp_core::control::cpbp::{AGREEING_TRAJECTORIES, AGREEMENT, COMBINED, DISAGREEMENT};
use cpbp_core::control::{Goal, PlanningConfig, PlanningSession};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::settings::{SettingValues, Value};

const N: usize = 5;
const PLANS: usize = 30;

/// The trajectory count and disagreement of each of `PLANS` plans from a standing start
/// with `agreeing` trajectories after an agreeing plan (0: off).
fn plans(agreeing: i64, agreement: f64) -> Vec<(usize, f64)> {
    let sim = common::flat_ride_in(PhysicsModel::Exact);
    let mut parameters = SettingValues::holding(COMBINED.parameters.iter().copied());
    parameters
        .set(AGREEING_TRAJECTORIES.name, Value::Int(agreeing))
        .unwrap();
    parameters
        .set(AGREEMENT.name, Value::Float(agreement))
        .unwrap();
    let config = PlanningConfig {
        trajectories: N,
        parameters,
        ..PlanningConfig::default()
    };
    let mut session = PlanningSession::new(&sim, &COMBINED, config);
    (0..PLANS)
        .map(|_| {
            session.controls(&sim, &Goal::default());
            let plan = session.last_plan().expect("a plan");
            let disagreement = plan
                .diagnostics
                .get(DISAGREEMENT)
                .expect("C-PBP says how much its trajectories disagreed");
            (plan.trajectories.len(), disagreement)
        })
        .collect()
}

#[test]
fn after_a_plan_whose_trajectories_agreed_fewer_plan() {
    let off = plans(0, 0.02);
    assert!(off.iter().all(|(n, _)| *n == N), "off: every plan has N");
    // Agreement as wide as the priors' σ: every plan after the first agrees.
    let agreeing = plans(2, 2.0);
    assert_eq!(agreeing[0].0, N, "the first plan has all N");
    assert!(agreeing[1..].iter().all(|(n, _)| *n == 2));
    // At the default agreement each plan has N or 2 as the one before it disagreed.
    let followed = plans(2, AGREEMENT.default_number());
    for pair in followed.windows(2) {
        let expected = if pair[0].1 < AGREEMENT.default_number() {
            2
        } else {
            N
        };
        assert_eq!(pair[1].0, expected, "{followed:?}");
    }
}
