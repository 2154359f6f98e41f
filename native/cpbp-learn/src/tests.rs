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
fn a_log_episode_rides_straight_at_one_speed_over_the_test_levels_logs() {
    let settings = ExpertSettings {
        family: Family::Logs,
        ..ExpertSettings::default()
    };
    let episode = Episode::draw(200_001, &settings);
    assert_eq!(episode, Episode::draw(200_001, &settings));
    let Ground::Logs(fields) = episode.ground else {
        panic!("not a log field: {:?}", episode.ground);
    };
    assert_eq!(episode.segments.len(), 1, "one request for the whole ride");
    let segment = episode.segments[0];
    assert_eq!(
        (segment.stick, segment.lean, segment.push),
        (0.0, None, 0.0)
    );
    assert!((6.0..25.0).contains(&(segment.drive.max_speed * 3.6)));
    let heading = glam::DQuat::from_rotation_y(episode.heading);
    let terrain = super::grounds::log_field(episode.seed, heading, fields);
    let per_field = cpbp_core::grounds::LogField::test_level().count;
    assert!((2..=4).contains(&fields));
    assert_eq!(
        terrain.len(),
        fields * per_field + 1,
        "the logs and the ground"
    );
    assert!(
        episode
            .simulation(&cpbp_core::bike::BikeParams::default())
            .crashed()
            .is_none(),
        "it starts upright, clear of logs"
    );
    // The mixed family's draws are the ones the committed data was made from.
    assert_ne!(
        Episode::draw(7, &ExpertSettings::default()).ground,
        episode.ground
    );
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
fn a_carving_episode_turns_hard_and_long_at_speed() {
    let settings = ExpertSettings {
        family: Family::Carving,
        ..ExpertSettings::default()
    };
    for seed in [1, 2, 3, 70_001] {
        let episode = Episode::draw(seed, &settings);
        assert_eq!(episode, Episode::draw(seed, &settings));
        assert!(matches!(episode.ground, Ground::Flat | Ground::Bumps(_)));
        let first = episode.segments[0];
        assert_eq!((first.start, first.stick), (0, 0.0), "up to speed first");
        let kmh = first.drive.max_speed * 3.6;
        assert!((20.0..40.0).contains(&kmh) && first.drive.throttle >= 0.2);
        let ends = episode.segments.iter().skip(1).map(|s| s.start);
        let turns: Vec<usize> = episode
            .segments
            .iter()
            .zip(ends.chain([episode.steps]))
            .filter(|(s, _)| s.stick != 0.0)
            .map(|(s, end)| {
                assert!((0.3..1.0).contains(&s.stick.abs()), "{}", s.stick);
                assert_eq!(s.drive, first.drive, "one speed all the way");
                end - s.start
            })
            .collect();
        assert!(!turns.is_empty() && turns[0] >= 90, "{turns:?}");
        assert!(episode
            .simulation(&cpbp_core::bike::BikeParams::default())
            .crashed()
            .is_none());
    }
}

#[test]
fn adding_a_family_leaves_the_others_draws_as_they_were() {
    // Pinned from the draws the committed model's data was made from.
    let mixed = Episode::draw(7, &ExpertSettings::default());
    let logs = ExpertSettings {
        family: Family::Logs,
        ..ExpertSettings::default()
    };
    let logs = Episode::draw(50_002, &logs);
    assert_eq!((mixed.ground, mixed.segments.len()), (Ground::Flat, 7));
    assert!((mixed.heading - 2.876966).abs() < 1e-6, "{}", mixed.heading);
    // The log episodes ride the level's own fields since issue 55 (the committed model's
    // drew 44 logs of the trainer's own description here); the draws around it are kept.
    assert_eq!(logs.ground, Ground::Logs(3));
    assert!((logs.segments[0].drive.max_speed - 6.056304).abs() < 1e-6);
    assert!((logs.heading - 3.349467).abs() < 1e-6, "{}", logs.heading);
    let carving = ExpertSettings {
        family: Family::Carving,
        ..ExpertSettings::default()
    };
    let carving = Episode::draw(70_002, &carving);
    assert!(matches!(carving.ground, Ground::Bumps(h) if (h - 0.040545).abs() < 1e-6));
    assert_eq!(carving.segments.len(), 4);
    assert!(
        (carving.heading - 3.452051).abs() < 1e-6,
        "{}",
        carving.heading
    );
    let drive = carving.segments[0].drive;
    assert!((drive.max_speed - 7.641776).abs() < 1e-6 && (drive.throttle - 0.667289).abs() < 1e-6);
}

#[test]
fn a_shoves_episode_shoves_hard_and_often_at_a_riding_speed() {
    let settings = ExpertSettings {
        family: Family::Shoves,
        ..ExpertSettings::default()
    };
    for seed in [1, 2, 3, 80_001] {
        let episode = Episode::draw(seed, &settings);
        assert_eq!(episode, Episode::draw(seed, &settings));
        let first = episode.segments[0];
        assert_eq!((first.start, first.push), (0, 0.0), "up to speed first");
        let kmh = first.drive.max_speed * 3.6;
        assert!((8.0..35.0).contains(&kmh) && first.drive.throttle >= 0.6);
        let shoves = &episode.segments[1..];
        assert!(shoves.len() >= 2, "{} shoves", shoves.len());
        for pair in shoves.windows(2) {
            let gap = pair[1].start - pair[0].start;
            assert!((60..120).contains(&gap), "{gap} steps between shoves");
        }
        for shove in shoves {
            assert!((60.0..260.0).contains(&shove.push.abs()), "{}", shove.push);
            assert!(shove.stick.abs() < 0.4 && shove.lean.is_none());
            assert_eq!(shove.drive, first.drive, "one speed all the way");
        }
        assert!(episode
            .simulation(&cpbp_core::bike::BikeParams::default())
            .crashed()
            .is_none());
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

#[test]
fn a_braking_episode_speeds_up_then_brakes_to_a_stand_and_again() {
    let settings = ExpertSettings {
        family: Family::Braking,
        seconds: 24.0,
        ..ExpertSettings::default()
    };
    for seed in [1, 2, 3, 90_001] {
        let episode = Episode::draw(seed, &settings);
        assert_eq!(episode, Episode::draw(seed, &settings));
        match episode.ground {
            Ground::Flat => {}
            Ground::Slope(angle) => assert!(angle.abs() <= 15f64.to_radians(), "{angle}"),
            other => panic!("{other:?}"),
        }
        let first = episode.segments[0];
        let kmh = first.drive.max_speed * 3.6;
        assert!(
            (45.0..90.0).contains(&kmh) && first.drive.throttle >= 0.6,
            "{kmh}"
        );
        let brakes: Vec<_> = episode
            .segments
            .iter()
            .filter(|s| s.drive.brake > 0.0)
            .collect();
        assert!(brakes.len() >= 2, "{} brakes in 24 s", brakes.len());
        assert!((300..420).contains(&brakes[0].start), "{}", brakes[0].start);
        for brake in &brakes {
            assert!(brake.drive.throttle == 0.0 && (0.5..=1.0).contains(&brake.drive.brake));
            assert!(brake.stick.abs() < 0.15 && brake.lean.is_none());
        }
    }
    // A short episode still brakes, halfway through.
    let short = Episode::draw(
        1,
        &ExpertSettings {
            seconds: 12.0,
            ..settings
        },
    );
    assert!(short
        .segments
        .iter()
        .any(|s| s.drive.brake > 0.0 && s.start == 180));
}
