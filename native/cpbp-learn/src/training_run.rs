//! `cpbp-learn train` and `train-value`: a network trained on every shard in the folders
//! given (episodes whose seed ends in 0 held out), each epoch's losses printed (and saved
//! as CSV), the model written aside and renamed into place. `train` fits the policy to
//! the expert's controls (the last second before a crash left out: by then the fall could
//! not be stopped, and what the expert did is no lesson); `train-value` fits the
//! cost-to-go to what the rest of the expert's horizon cost from the states its
//! trajectories reached, the falls included (they are the costly states it must know).

use std::path::PathBuf;

use cpbp_core::control::learned::{
    PolicyNetwork, ValueNetwork, FEATURE_COUNT, OUTPUT_COUNT, VALUE_INPUT_COUNT,
};

use crate::shard::{self, ShardRows};
use crate::train::{self, Dataset, TrainSettings};

/// Control steps before a crash left out of the policy's training (one second).
const FALL_STEPS: usize = 30;

/// Which network a run trains.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Policy,
    Value,
}

impl Kind {
    fn dataset(self) -> Dataset {
        match self {
            Kind::Policy => Dataset::new(FEATURE_COUNT, OUTPUT_COUNT),
            Kind::Value => Dataset::new(VALUE_INPUT_COUNT, 1),
        }
    }

    /// The rows of `shard` this network learns from, into `set`.
    fn take(self, shard: ShardRows, set: &mut Dataset) {
        match self {
            Kind::Policy => {
                let shard = shard.without_the_fall(FALL_STEPS);
                set.extend(&shard.features, &shard.labels);
            }
            Kind::Value => set.extend(&shard.value_inputs, &shard.value_targets),
        }
    }

    /// The model file's bytes for trained `parts`, checked as the game checks them.
    fn model_bytes(
        self,
        parts: cpbp_core::control::learned::NetworkParts,
    ) -> Result<Vec<u8>, String> {
        match self {
            Kind::Policy => PolicyNetwork::new(parts).map(|n| n.to_bytes()),
            Kind::Value => ValueNetwork::new(parts).map(|n| n.to_bytes()),
        }
        .map_err(|e| e.to_string())
    }

    fn command(self) -> &'static str {
        match self {
            Kind::Policy => "train",
            Kind::Value => "train-value",
        }
    }
}

/// `train|train-value --data DIR[,DIR…] --model FILE [--losses CSV] [--epochs E]
/// [--seed S] [--hidden W,W…] [--weight-decay D]`.
pub fn train_command(arguments: &[String], kind: Kind) -> Result<(), String> {
    let (data, model, losses_path, settings) = parse(arguments)?;
    let (mut fit, mut held_out) = (kind.dataset(), kind.dataset());
    let mut episodes = 0;
    // One network is one bike's: the shards must all have ridden the same one.
    let mut bike: Option<(String, PathBuf)> = None;
    for dir in &data {
        for path in shard::shard_paths(dir)? {
            let shard = shard::read(&path)?;
            match &bike {
                Some((first, from)) if *first != shard.bike => {
                    return Err(format!(
                        "{} rode another bike ({}) than {} ({first}): train one bike's \
                         episodes at a time",
                        path.display(),
                        shard.bike,
                        from.display()
                    ));
                }
                Some(_) => {}
                None => bike = Some((shard.bike.clone(), path.clone())),
            }
            let seed = shard::seed_of(&path)
                .ok_or_else(|| format!("{}: no seed in its name", path.display()))?;
            kind.take(
                shard,
                if seed % 10 == 0 {
                    &mut held_out
                } else {
                    &mut fit
                },
            );
            episodes += 1;
        }
    }
    if kind == Kind::Value && fit.rows() == 0 {
        return Err(
            "the episodes recorded no cost-to-go samples: generate them with --values".into(),
        );
    }
    println!(
        "{episodes} episodes: {} rows to train on, {} held out",
        fit.rows(),
        held_out.rows()
    );
    let folders: Vec<String> = data
        .iter()
        .filter_map(|d| d.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    let description = format!(
        "cpbp-learn {}: {episodes} episodes ({}), {} rows, hidden {:?}, {} epochs, batch {}, \
         AdamW lr {}, seed {}",
        kind.command(),
        folders.join(" + "),
        fit.rows(),
        settings.hidden,
        settings.epochs,
        settings.batch,
        settings.learning_rate,
        settings.seed
    );
    let mut losses = String::from("epoch,train,held_out\n");
    let bike = bike.map(|(identity, _)| identity).unwrap_or_default();
    let parts = train::train(
        &fit,
        &held_out,
        &settings,
        &description,
        &bike,
        |epoch, loss| {
            println!(
                "epoch {epoch:>3}: train {:.4} · held out {:.4}",
                loss.train, loss.validation
            );
            losses += &format!("{epoch},{:.6},{:.6}\n", loss.train, loss.validation);
        },
    )?;
    let bytes = kind.model_bytes(parts)?;
    if let Some(path) = losses_path {
        std::fs::write(&path, losses).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let aside = model.with_extension("partial");
    std::fs::write(&aside, bytes).map_err(|e| format!("{}: {e}", aside.display()))?;
    std::fs::rename(&aside, &model).map_err(|e| format!("{}: {e}", model.display()))?;
    println!("model written to {}", model.display());
    Ok(())
}

type Parsed = (Vec<PathBuf>, PathBuf, Option<PathBuf>, TrainSettings);

fn parse(arguments: &[String]) -> Result<Parsed, String> {
    let (mut data, mut model, mut settings) = (Vec::new(), None, TrainSettings::default());
    let mut losses_path = None;
    for pair in arguments.chunks(2) {
        let [flag, value] = pair else {
            return Err(format!("{} needs a value", pair[0]));
        };
        let count = || {
            value
                .parse::<usize>()
                .map_err(|_| format!("{flag}: bad number '{value}'"))
        };
        match flag.as_str() {
            "--data" => data.extend(value.split(',').map(PathBuf::from)),
            "--model" => model = Some(PathBuf::from(value)),
            "--losses" => losses_path = Some(PathBuf::from(value)),
            "--epochs" => settings.epochs = count()?,
            "--seed" => settings.seed = count()? as u64,
            "--hidden" => {
                settings.hidden = value
                    .split(',')
                    .map(|w| w.parse::<usize>().ok().filter(|&w| w > 0))
                    .collect::<Option<_>>()
                    .ok_or_else(|| format!("--hidden is widths like 128,128, not '{value}'"))?;
            }
            "--weight-decay" => {
                settings.weight_decay = value
                    .parse::<f64>()
                    .ok()
                    .filter(|w| w.is_finite() && *w >= 0.0)
                    .ok_or_else(|| format!("--weight-decay must be a number ≥ 0, not '{value}'"))?;
            }
            other => return Err(format!("unknown option '{other}'")),
        }
    }
    let model = model.ok_or("--model is required")?;
    if data.is_empty() {
        return Err("--data is required".into());
    }
    Ok((data, model, losses_path, settings))
}
