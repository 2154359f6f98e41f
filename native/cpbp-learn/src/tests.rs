//! The generator's contract: an episode is a function of its seed, a shard holds exactly
//! what was ridden, and data of another feature list is refused.

use candle_core::{Device, Tensor};

use super::episode::{ride, Episode, ExpertSettings, Family, Ground};
use super::shard;
use super::train::{train, Dataset, Layers, TrainSettings};
use cpbp_core::bike::{read_bike_file, BikeParams, LOWER, UPPER};
use cpbp_core::control::learned::{output_entries, PolicyNetwork, FEATURE_COUNT, OUTPUT_COUNT};

pub(crate) fn short() -> ExpertSettings {
    ExpertSettings {
        trajectories: 4,
        seconds: 1.0,
        noise: 0.05,
        family: Family::Mixed,
        bike: BikeParams::default(),
        values: false,
        short_planner: None,
    }
}

#[test]
fn an_episode_is_drawn_from_its_seed_alone() {
    let settings = ExpertSettings::default();
    assert_eq!(Episode::draw(7, &settings), Episode::draw(7, &settings));
    assert_ne!(Episode::draw(7, &settings), Episode::draw(8, &settings));
    let episode = Episode::draw(7, &settings);
    assert_eq!(episode.segments[0].start, 0);
    assert_eq!(episode.steps, 360);
    let grounds: Vec<Ground> = (0..40)
        .map(|s| Episode::draw(s, &settings).ground)
        .collect();
    assert!(grounds.contains(&Ground::Flat));
    assert!(grounds.iter().any(|g| matches!(g, Ground::Slope(_))));
    assert!(grounds.iter().any(|g| matches!(g, Ground::Bumps(_))));
}

#[test]
fn a_ridden_episode_repeats_and_reads_back_from_its_shard() {
    let settings = short();
    let episode = Episode::draw(3, &settings);
    let records = ride(&episode, &settings, None);
    assert_eq!(records.features.len(), 30);
    assert_eq!(
        ride(&episode, &settings, None),
        records,
        "the same seed rides the same"
    );
    for label in &records.labels {
        for (o, &entry) in output_entries().iter().enumerate() {
            let value = f64::from(label[o]);
            assert!(value >= LOWER[entry] - 1e-6 && value <= UPPER[entry] + 1e-6);
        }
    }
    let dir = std::env::temp_dir().join(format!("cpbp-learn-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    shard::write(&dir, &episode, &settings, &records).unwrap();
    let path = shard::shard_path(&dir, 3);
    let shard::ShardRows {
        features,
        labels,
        rows,
        crashed,
        bike,
        ..
    } = shard::read(&path).unwrap();
    assert_eq!(crashed, records.crashed);
    assert_eq!(bike, BikeParams::default().identity());
    assert_eq!(rows, 30);
    assert_eq!(
        &features[..records.features[0].len()],
        &records.features[0][..]
    );
    assert_eq!(labels.len(), rows * OUTPUT_COUNT);
    assert_eq!(
        &labels[labels.len() - OUTPUT_COUNT..],
        &records.labels[29][..]
    );
    assert!(!path.with_extension("partial").exists());
    std::fs::write(&path, b"garbage").unwrap();
    assert!(shard::read(&path).is_err());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Rides a few short episodes as the expert and trains on them: the whole pipeline,
/// small (make test holds it under two minutes).
fn tiny_run() -> (PolicyNetwork, Dataset) {
    let settings = short();
    let mut data = Dataset::default();
    for seed in 1..=3 {
        let records = ride(&Episode::draw(seed, &settings), &settings, None);
        data.extend(
            records.features.as_flattened(),
            records.labels.as_flattened(),
        );
    }
    let training = TrainSettings {
        hidden: vec![16, 16],
        epochs: 3,
        batch: 32,
        ..TrainSettings::default()
    };
    let parts = train(
        &data,
        &Dataset::default(),
        &training,
        "a test's",
        &BikeParams::default().identity(),
        |_, loss| {
            assert!(loss.train.is_finite());
        },
    )
    .expect("it trains");
    (PolicyNetwork::new(parts).expect("a policy"), data)
}

#[test]
fn a_tiny_generation_and_training_run_completes_and_repeats() {
    let (network, data) = tiny_run();
    let (again, data_again) = tiny_run();
    assert_eq!(data.features, data_again.features);
    // Parts, not bytes: the file's metadata is a map whose order safetensors leaves free.
    assert_eq!(
        network.parts(),
        again.parts(),
        "the same seed trains the same"
    );
    let back = PolicyNetwork::parse(&network.to_bytes()).expect("the model reads back");
    assert_eq!(back.parts().layers, network.parts().layers);
}

#[test]
fn the_game_computes_what_training_computed() {
    let (network, data) = tiny_run();
    let parts = network.parts();
    let device = Device::Cpu;
    let layers = Layers::from_parts(parts, &device).unwrap();
    for row in data.features.chunks_exact(FEATURE_COUNT).step_by(7) {
        let normalised: Vec<f32> = row
            .iter()
            .enumerate()
            .map(|(i, x)| (x - parts.input_mean[i]) / parts.input_std[i])
            .collect();
        let input = Tensor::from_slice(&normalised, (1, FEATURE_COUNT), &device).unwrap();
        let trained: Vec<f32> = layers
            .forward(&input)
            .unwrap()
            .flatten_all()
            .unwrap()
            .to_vec1()
            .unwrap();
        let features: [f64; FEATURE_COUNT] = std::array::from_fn(|i| f64::from(row[i]));
        let game = network.evaluate(&features).unwrap();
        for o in 0..OUTPUT_COUNT {
            let expected = parts.output_mean[o] + trained[o] * parts.output_std[o];
            assert!(
                (f64::from(expected) - game[o]).abs() <= 1e-5,
                "output {o}: training {expected}, game {}",
                game[o]
            );
        }
    }
}

#[test]
fn episodes_ride_the_bike_asked_and_a_network_is_one_bikes() {
    let fixture = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/fixtures/bikes/pit_bike.tres"
    );
    let pit_bike = read_bike_file(std::path::Path::new(fixture)).expect("the fixture reads");
    let root = std::env::temp_dir().join(format!("cpbp-learn-bikes-{}", std::process::id()));
    let ride_into = |dir: &str, bike: &BikeParams| {
        let settings = ExpertSettings {
            bike: bike.clone(),
            ..short()
        };
        let episode = Episode::draw(5, &settings);
        let records = ride(&episode, &settings, None);
        std::fs::create_dir_all(root.join(dir)).unwrap();
        shard::write(&root.join(dir), &episode, &settings, &records).unwrap();
        shard::read(&shard::shard_path(&root.join(dir), 5)).unwrap()
    };
    let pit = ride_into("pit", &pit_bike.params);
    let street = ride_into("street", &BikeParams::default());
    assert_eq!(pit.bike, pit_bike.params.identity());
    assert_ne!(pit.features, street.features, "another bike, another ride");
    let arguments = |data: &str| -> Vec<String> {
        let model = root.join("model.safetensors");
        [
            "--data",
            data,
            "--model",
            &model.to_string_lossy(),
            "--epochs",
            "1",
            "--hidden",
            "8",
        ]
        .map(String::from)
        .to_vec()
    };
    let both = format!(
        "{},{}",
        root.join("pit").display(),
        root.join("street").display()
    );
    let refused =
        super::training_run::train_command(&arguments(&both), super::training_run::Kind::Policy)
            .unwrap_err();
    assert!(refused.contains("another bike"), "{refused}");
    super::training_run::train_command(
        &arguments(&root.join("pit").to_string_lossy()),
        super::training_run::Kind::Policy,
    )
    .unwrap();
    let model = PolicyNetwork::load(&root.join("model.safetensors")).unwrap();
    assert_eq!(model.parts().bike, pit_bike.params.identity());
    std::fs::remove_dir_all(&root).unwrap();
}
