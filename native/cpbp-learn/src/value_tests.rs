//! The cost-to-go's data and training: recording it leaves the expert's plans as they
//! were, the samples say what the rest of the horizon cost, they read back from the
//! shard, and the game's network computes what training made.

use cpbp_core::bike::BikeParams;
use cpbp_core::control::learned::{value_target, ValueNetwork, FEATURE_COUNT, VALUE_INPUT_COUNT};

use super::episode::{
    ride, Episode, ExpertSettings, Records, VALUE_SAMPLES_PER_STEP, VALUE_SPLITS,
};
use super::shard;
use super::tests::short;
use super::train::{train, Dataset, TrainSettings};

fn with_values() -> ExpertSettings {
    ExpertSettings {
        values: true,
        ..short()
    }
}

fn ridden(seed: u64) -> Records {
    let settings = with_values();
    ride(&Episode::draw(seed, &settings), &settings, None)
}

#[test]
fn recording_the_cost_to_go_leaves_the_experts_plans_as_they_were() {
    let settings = short();
    let without = ride(&Episode::draw(3, &settings), &settings, None);
    let with = ridden(3);
    assert_eq!(with.features, without.features);
    assert_eq!(with.labels, without.labels);
    assert!(without.value_targets.is_empty());
    assert_eq!(with, ridden(3), "the same seed keeps the same samples");
}

#[test]
fn each_step_keeps_a_few_states_with_the_time_left_and_a_cost_of_at_least_nothing() {
    let records = ridden(3);
    let steps = records.features.len();
    let samples = records.value_targets.len();
    assert_eq!(records.value_inputs.len(), samples);
    // Four trajectories recorded at three splits: up to 12 a plan, of which those a
    // final trajectory descends from count (resampling drops some), 2 kept.
    assert!(samples <= steps * VALUE_SAMPLES_PER_STEP, "{samples}");
    assert!(
        samples >= steps * VALUE_SAMPLES_PER_STEP * 9 / 10,
        "{samples}"
    );
    let dt = 1.0 / 30.0;
    let left: Vec<f32> = VALUE_SPLITS
        .iter()
        .map(|&k| ((36 - k) as f64 * dt) as f32)
        .collect();
    for (inputs, &target) in records.value_inputs.iter().zip(&records.value_targets) {
        assert!(
            left.contains(&inputs[FEATURE_COUNT]),
            "{}",
            inputs[FEATURE_COUNT]
        );
        assert!(target.is_finite() && target >= 0.0, "{target}");
    }
    // Riding on from a state costs more the longer it rides: the mean log cost with 0.8 s
    // left is above the mean with 0.3 s.
    let mean_at = |seconds: f32| {
        let picked: Vec<f32> = records
            .value_inputs
            .iter()
            .zip(&records.value_targets)
            .filter(|(i, _)| i[FEATURE_COUNT] == seconds)
            .map(|(_, &t)| t)
            .collect();
        picked.iter().sum::<f32>() / picked.len().max(1) as f32
    };
    assert!(
        mean_at(left[0]) > mean_at(left[2]),
        "{} vs {}",
        mean_at(left[0]),
        mean_at(left[2])
    );
}

#[test]
fn the_samples_read_back_from_the_shard_and_a_shard_without_them_has_none() {
    let settings = with_values();
    let episode = Episode::draw(4, &settings);
    let records = ride(&episode, &settings, None);
    let dir = std::env::temp_dir().join(format!("cpbp-learn-values-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    shard::write(&dir, &episode, &settings, &records).unwrap();
    let back = shard::read(&shard::shard_path(&dir, 4)).unwrap();
    assert_eq!(back.value_inputs, records.value_inputs.as_flattened());
    assert_eq!(back.value_targets, records.value_targets);
    let plain = Records {
        value_inputs: Vec::new(),
        value_targets: Vec::new(),
        ..records
    };
    shard::write(&dir, &episode, &settings, &plain).unwrap();
    assert!(shard::read(&shard::shard_path(&dir, 4))
        .unwrap()
        .value_targets
        .is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_game_computes_the_cost_to_go_training_made() {
    let mut data = Dataset::new(VALUE_INPUT_COUNT, 1);
    for seed in 1..=2 {
        let records = ridden(seed);
        data.extend(records.value_inputs.as_flattened(), &records.value_targets);
    }
    let training = TrainSettings {
        hidden: vec![8],
        epochs: 3,
        batch: 16,
        ..TrainSettings::default()
    };
    let identity = BikeParams::default().identity();
    let parts = train(
        &data,
        &Dataset::new(VALUE_INPUT_COUNT, 1),
        &training,
        "a test's",
        &identity,
        |_, loss| {
            assert!(loss.train.is_finite());
        },
    )
    .expect("it trains");
    let network = ValueNetwork::new(parts).expect("a cost-to-go");
    let back = ValueNetwork::parse(&network.to_bytes()).expect("it reads back");
    assert_eq!(back.parts(), network.parts());
    for row in data.features.chunks_exact(VALUE_INPUT_COUNT).step_by(5) {
        let features: [f64; FEATURE_COUNT] = std::array::from_fn(|i| f64::from(row[i]));
        let cost = network
            .cost_to_go(&features, f64::from(row[FEATURE_COUNT]))
            .unwrap();
        assert!(cost.is_finite() && cost >= 0.0);
        // The answer is the cost itself, the inverse of the target's logarithm.
        let log = f64::from(value_target(cost));
        assert!((log - cost.ln_1p()).abs() < 1e-5);
    }
}

#[test]
fn a_short_planner_with_a_cost_to_go_drives_while_the_expert_labels() {
    use super::episode::ShortPlanner;
    use cpbp_core::control::learned::{LoadedValue, NetworkParts};

    let constant = ValueNetwork::new(NetworkParts {
        input_mean: vec![0.0; VALUE_INPUT_COUNT],
        input_std: vec![1.0; VALUE_INPUT_COUNT],
        layers: vec![(vec![0.0; VALUE_INPUT_COUNT], vec![0.0])],
        output_mean: vec![2.0],
        output_std: vec![1.0],
        training: "by hand".into(),
        bike: BikeParams::default().identity(),
    })
    .unwrap();
    let settings = ExpertSettings {
        short_planner: Some(ShortPlanner {
            value: LoadedValue::ready(constant),
            horizon: 0.4,
        }),
        ..with_values()
    };
    let episode = Episode::draw(3, &settings);
    let driven = ride(&episode, &settings, None);
    assert!(
        driven.driver.starts_with("short planner"),
        "{}",
        driven.driver
    );
    assert!(
        driven.driver.contains("0.4 s + cost-to-go"),
        "{}",
        driven.driver
    );
    let expert = ridden(3);
    assert_eq!(driven.features[0], expert.features[0], "the same start");
    assert_ne!(
        driven.features, expert.features,
        "another driver, other states"
    );
    assert!(
        !driven.value_targets.is_empty(),
        "the expert's plans still recorded"
    );
}
