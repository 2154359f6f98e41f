//! The generator's contract: an episode is a function of its seed, a shard holds exactly
//! what was ridden, and data of another feature list is refused.

use super::episode::{ride, Episode, ExpertSettings, Ground};
use super::shard;
use cpbp_core::bike::{LOWER, UPPER};
use cpbp_core::control::learned::{output_entries, OUTPUT_COUNT};

fn short() -> ExpertSettings {
    ExpertSettings {
        trajectories: 4,
        seconds: 1.0,
        noise: 0.05,
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
    let records = ride(&episode, &settings);
    assert_eq!(records.features.len(), 30);
    assert_eq!(
        ride(&episode, &settings),
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
    let (features, labels, rows) = shard::read(&path).unwrap();
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
