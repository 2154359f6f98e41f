//! A shortened horizon ended by a cost-to-go (issue 59), on a toy with known dynamics: a
//! point mass pushed towards a target along a line, as in cpbp_planner.rs. The terminal
//! cost is asked once per trajectory, at the last step only; with it a short horizon
//! holds the target where without it the mass overshoots; and a planner asked to record
//! its states says what the rest of the horizon cost from them.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use cpbp_core::control::cpbp::{CpbpConfig, CpbpPlanner, Priors, RolloutSystem, WarmStart};

const DT: f64 = 0.1;
const TARGET: f64 = 1.0;
const PARTICLES: usize = 16;

/// A cost-to-go of (x, v), and a count of the times it was asked.
type CountedValue = (fn(f64, f64) -> f64, Arc<AtomicUsize>);

#[derive(Clone, Default)]
struct PointMass {
    x: f64,
    v: f64,
    /// With this cost-to-go (an oracle: what riding on from here costs), counting the
    /// times it is asked.
    value: Option<CountedValue>,
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
        Some(((self.x - TARGET) / 0.1).powi(2))
    }

    fn terminal_cost(&self) -> Option<f64> {
        let (value, asked) = self.value.as_ref()?;
        asked.fetch_add(1, Ordering::SeqCst);
        Some(value(self.x, self.v))
    }

    fn value_features(&self) -> Vec<f64> {
        vec![self.x, self.v]
    }
}

/// What riding on costs from (x, v): where the mass is heading half a second on, and its
/// speed; a mass arriving at speed overshoots, which a two-step plan cannot see.
fn oracle(x: f64, v: f64) -> f64 {
    10.0 * (((x + 0.5 * v - TARGET) / 0.1).powi(2) + (v / 0.3).powi(2))
}

fn planner(steps: usize, record: Vec<usize>) -> CpbpPlanner {
    CpbpPlanner::new(
        CpbpConfig {
            particles: PARTICLES,
            steps,
            seed: 7,
            record_values_after: record,
            ..CpbpConfig::default()
        },
        Priors::uniform(1, 3.0, 1.0, 0.2, 4.0),
    )
}

/// Rides 60 frames from rest and returns the mean distance from the target over the last
/// 30, and the systems (their counters).
fn ride(steps: usize, value: Option<fn(f64, f64) -> f64>) -> (f64, Arc<AtomicUsize>) {
    let asked = Arc::new(AtomicUsize::new(0));
    let mut master = PointMass::default();
    let mut systems = vec![
        PointMass {
            value: value.map(|v| (v, Arc::clone(&asked))),
            ..PointMass::default()
        };
        PARTICLES
    ];
    let mut planner = planner(steps, Vec::new());
    let mut late = Vec::new();
    for frame in 0..60 {
        let result = planner.plan(&mut systems, &master.save(), WarmStart::Refinement);
        master.step(&result.control, 0);
        if frame >= 30 {
            late.push((master.x - TARGET).abs());
        }
    }
    (late.iter().sum::<f64>() / late.len() as f64, asked)
}

#[test]
fn the_terminal_cost_is_asked_once_a_trajectory_at_the_last_step() {
    let (_, asked) = ride(5, Some(oracle));
    assert_eq!(asked.load(Ordering::SeqCst), 60 * PARTICLES);
}

#[test]
fn with_a_cost_to_go_a_short_horizon_holds_the_target_where_it_overshot() {
    let (short, _) = ride(2, None);
    let (short_with_value, _) = ride(2, Some(oracle));
    let (long, _) = ride(20, None);
    assert!(long < 0.05, "the long horizon holds it: {long}");
    assert!(short > 0.5, "two steps alone overshoot: {short}");
    assert!(
        short_with_value < 0.05,
        "with the cost-to-go two steps hold it too: {short_with_value}"
    );
}

#[test]
fn a_recording_planner_says_what_the_rest_of_the_horizon_cost() {
    let mut planner = planner(10, vec![4, 7]);
    let mut systems = vec![PointMass::default(); PARTICLES];
    let start = (0.0, 0.0);
    let result = planner.plan(&mut systems, &start, WarmStart::Nothing);
    let samples = &result.value_samples;
    assert!(!samples.is_empty() && samples.len() <= 2 * PARTICLES);
    for sample in samples {
        assert!(
            [6, 3].contains(&sample.remaining_steps),
            "{}",
            sample.remaining_steps
        );
        assert_eq!(sample.features.len(), 2);
        assert!(sample.cost_to_go.is_finite() && sample.cost_to_go >= 0.0);
    }
    // The rest of a trajectory costs no more than the whole of it: the cheapest state
    // after 4 steps is on the way of some trajectory whose total is at least that.
    let least = samples
        .iter()
        .filter(|s| s.remaining_steps == 6)
        .map(|s| s.cost_to_go)
        .fold(f64::INFINITY, f64::min);
    let costs: Vec<f64> = result.costs.clone();
    assert!(least <= costs.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
    // Not asked: none recorded, and the plan is the same.
    let mut quiet = planner_without_recording();
    let plain = quiet.plan(
        &mut vec![PointMass::default(); PARTICLES],
        &start,
        WarmStart::Nothing,
    );
    assert!(plain.value_samples.is_empty());
    assert_eq!(plain.sequences, result.sequences);
    assert_eq!(plain.costs, result.costs);
}

fn planner_without_recording() -> CpbpPlanner {
    planner(10, Vec::new())
}

/// A cost-to-go that answers `cost` whatever the state: one linear layer of zero weights
/// whose read-out is ln(1 + cost).
fn constant_value(cost: f64) -> cpbp_core::control::learned::ValueNetwork {
    use cpbp_core::control::learned::{NetworkParts, ValueNetwork, VALUE_INPUT_COUNT};
    ValueNetwork::new(NetworkParts {
        input_mean: vec![0.0; VALUE_INPUT_COUNT],
        input_std: vec![1.0; VALUE_INPUT_COUNT],
        layers: vec![(vec![0.0; VALUE_INPUT_COUNT], vec![0.0])],
        output_mean: vec![cost.ln_1p() as f32],
        output_std: vec![1.0],
        training: "by hand".into(),
        bike: cpbp_core::bike::BikeParams::default().identity(),
    })
    .expect("a cost-to-go")
}

#[test]
fn the_bikes_planners_plan_the_value_horizon_with_the_network_and_the_whole_without() {
    use cpbp_core::bike::{Placement, CONTROL_DIM};
    use cpbp_core::control::cpbp::COMBINED;
    use cpbp_core::control::learned::LoadedValue;
    use cpbp_core::control::{Goal, PlanningConfig, PlanningSession};
    use cpbp_core::physics::PhysicsModel;
    use cpbp_core::simulation::{Simulation, SimulationConfig};
    use cpbp_core::terrain::Terrain;
    use glam::DVec3;

    let network = constant_value(3.5);
    let features = [0.0; cpbp_core::control::learned::FEATURE_COUNT];
    assert!((network.cost_to_go(&features, 0.6).unwrap() - 3.5).abs() < 1e-5);
    let sim = Simulation::new(
        SimulationConfig::default(),
        Arc::new(Terrain::flat()),
        Placement {
            position: DVec3::new(0.0, 0.02, 0.0),
            rotation: glam::DQuat::IDENTITY,
        },
    );
    let planned_steps = |config: PlanningConfig| {
        let mut session = PlanningSession::new(&sim, &COMBINED, config);
        session.controls(&sim, &Goal::default());
        let plan = session.last_plan().expect("a plan");
        (plan.chosen.len() / CONTROL_DIM, plan.best_cost)
    };
    let base = PlanningConfig {
        trajectories: 4,
        terminal_value: true,
        value_horizon: 0.6,
        ..PlanningConfig::default().rolling_out_in(PhysicsModel::Exact)
    };
    let with = PlanningConfig {
        value: LoadedValue::ready(network),
        ..base.clone()
    };
    assert_eq!(with.value_problem(), None);
    let (steps, cost) = planned_steps(with.clone());
    assert_eq!(steps, 18, "0.6 s at 30 Hz");
    assert!(cost >= 3.5, "the rest of the horizon is costed: {cost}");
    let (steps, _) = planned_steps(PlanningConfig {
        terminal_value: false,
        ..with
    });
    assert_eq!(steps, 36, "off: the whole 1.2 s");
    assert!(
        base.value_problem().is_some(),
        "on without the network: it says why"
    );
    let (steps, _) = planned_steps(base);
    assert_eq!(steps, 36, "without the network: the whole 1.2 s");
}
