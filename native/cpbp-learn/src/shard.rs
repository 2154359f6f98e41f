//! An episode's records on disk: one safetensors file per episode (`features` and
//! `labels`, float32, one row per control step, and when the episode recorded them the
//! cost-to-go's `value_inputs` and `value_targets`) whose metadata says what made it, so
//! a trainer can refuse data of another feature list. A file is written whole or not at
//! all (written aside, synced, renamed), so a killed generator leaves no half file and
//! its next run rides only the episodes missing.

use std::collections::HashMap;
use std::io::Write;
use std::path::{Path, PathBuf};

use cpbp_core::bike::BikeParams;
use cpbp_core::control::learned::{
    f32_bytes, f32_values, output_names, FEATURES_VERSION, FEATURE_COUNT, FEATURE_NAMES,
    OUTPUT_COUNT, VALUE_INPUT_COUNT,
};
use safetensors::tensor::TensorView;
use safetensors::{Dtype, SafeTensors};

use crate::episode::{Episode, ExpertSettings, Records};

/// The `format` every shard's metadata names.
pub const SHARD_FORMAT: &str = "counter-steer-expert-data";

/// Where episode `seed`'s records go in `dir`.
pub fn shard_path(dir: &Path, seed: u64) -> PathBuf {
    dir.join(format!("episode-{seed:07}.safetensors"))
}

/// Writes an episode's records.
pub fn write(
    dir: &Path,
    episode: &Episode,
    settings: &ExpertSettings,
    records: &Records,
) -> std::io::Result<()> {
    let rows = records.features.len();
    let features = f32_bytes(records.features.as_flattened());
    let labels = f32_bytes(records.labels.as_flattened());
    let value_rows = records.value_targets.len();
    let value_inputs = f32_bytes(records.value_inputs.as_flattened());
    let value_targets = f32_bytes(&records.value_targets);
    let mut views = vec![
        (
            "features",
            TensorView::new(Dtype::F32, vec![rows, FEATURE_COUNT], &features),
        ),
        (
            "labels",
            TensorView::new(Dtype::F32, vec![rows, OUTPUT_COUNT], &labels),
        ),
    ];
    if value_rows > 0 {
        views.push((
            "value_inputs",
            TensorView::new(
                Dtype::F32,
                vec![value_rows, VALUE_INPUT_COUNT],
                &value_inputs,
            ),
        ));
        views.push((
            "value_targets",
            TensorView::new(Dtype::F32, vec![value_rows, 1], &value_targets),
        ));
    }
    let views = views
        .into_iter()
        .map(|(name, view)| (name, view.expect("rows of fixed width")));
    let meta = HashMap::from([
        ("format".to_string(), SHARD_FORMAT.to_string()),
        ("features_version".into(), FEATURES_VERSION.to_string()),
        ("features".into(), FEATURE_NAMES.join(",")),
        ("outputs".into(), output_names().join(",")),
        ("seed".into(), episode.seed.to_string()),
        ("ground".into(), episode.ground.label()),
        (
            "expert".into(),
            format!("combined N={} exact", settings.trajectories),
        ),
        ("noise".into(), settings.noise.to_string()),
        ("family".into(), settings.family.name().to_string()),
        ("driver".into(), records.driver.clone()),
        ("crashed".into(), records.crashed.to_string()),
        ("bike".into(), settings.bike.identity()),
    ]);
    let bytes = cpbp_core::control::learned::serialize_sorted(views, meta)
        .map_err(std::io::Error::other)?;
    let path = shard_path(dir, episode.seed);
    let aside = path.with_extension("partial");
    let mut file = std::fs::File::create(&aside)?;
    file.write_all(&bytes)?;
    file.sync_all()?;
    std::fs::rename(&aside, &path)
}

/// An episode's rows as read back.
pub struct ShardRows {
    pub features: Vec<f32>,
    pub labels: Vec<f32>,
    pub rows: usize,
    /// The cost-to-go's rows (none when the episode did not record them).
    pub value_inputs: Vec<f32>,
    pub value_targets: Vec<f32>,
    /// Whether the episode ended in a crash.
    pub crashed: bool,
    /// The identity of the bike it rode (`BikeParams::identity`).
    pub bike: String,
}

impl ShardRows {
    /// Leaves out the last `steps` rows of an episode that crashed: by then the fall
    /// could not be stopped, and what the expert did is no lesson.
    pub fn without_the_fall(mut self, steps: usize) -> Self {
        if self.crashed {
            self.rows = self.rows.saturating_sub(steps);
            self.features.truncate(self.rows * FEATURE_COUNT);
            self.labels.truncate(self.rows * OUTPUT_COUNT);
        }
        self
    }
}

/// A shard's rows, checked against this build's feature list.
pub fn read(path: &Path) -> Result<ShardRows, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let fail = |why: String| format!("{}: {why}", path.display());
    let (_, header) = SafeTensors::read_metadata(&bytes).map_err(|e| fail(e.to_string()))?;
    let meta = header.metadata().clone().unwrap_or_default();
    let field = |key: &str| meta.get(key).cloned().unwrap_or_default();
    if field("format") != SHARD_FORMAT {
        return Err(fail("not expert data".into()));
    }
    if field("features") != FEATURE_NAMES.join(",") {
        return Err(fail(format!(
            "made with feature list version {}, this build has {FEATURES_VERSION}: generate again",
            field("features_version")
        )));
    }
    let file = SafeTensors::deserialize(&bytes).map_err(|e| fail(e.to_string()))?;
    let floats = |name: &str, width: usize| -> Result<(Vec<f32>, usize), String> {
        let view = file.tensor(name).map_err(|e| fail(e.to_string()))?;
        if view.dtype() != Dtype::F32 || view.shape().len() != 2 || view.shape()[1] != width {
            return Err(fail(format!("'{name}' is not float32 rows of {width}")));
        }
        Ok((f32_values(view.data()), view.shape()[0]))
    };
    let (features, rows) = floats("features", FEATURE_COUNT)?;
    let (labels, label_rows) = floats("labels", OUTPUT_COUNT)?;
    if rows != label_rows {
        return Err(fail("features and labels differ in length".into()));
    }
    let (value_inputs, value_targets) = if file.names().contains(&"value_targets") {
        let (inputs, input_rows) = floats("value_inputs", VALUE_INPUT_COUNT)?;
        let (targets, target_rows) = floats("value_targets", 1)?;
        if input_rows != target_rows {
            return Err(fail("value inputs and targets differ in length".into()));
        }
        (inputs, targets)
    } else {
        (Vec::new(), Vec::new())
    };
    Ok(ShardRows {
        features,
        labels,
        rows,
        value_inputs,
        value_targets,
        crashed: field("crashed") == "true",
        // Shards from before bikes were recorded rode the reference bike.
        bike: meta
            .get("bike")
            .cloned()
            .unwrap_or_else(|| BikeParams::default().identity()),
    })
}

/// The shards in `dir` and the folders in it (one a DAgger round), in path order.
pub fn shard_paths(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut paths = Vec::new();
    for entry in
        std::fs::read_dir(dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?
    {
        let path = entry
            .map_err(|e| format!("cannot read {}: {e}", dir.display()))?
            .path();
        if path.is_dir() {
            paths.extend(shard_paths(&path)?);
        } else if path.extension().is_some_and(|x| x == "safetensors") {
            paths.push(path);
        }
    }
    paths.sort();
    Ok(paths)
}

/// The episode seed a shard's name carries.
pub fn seed_of(path: &Path) -> Option<u64> {
    path.file_stem()?
        .to_str()?
        .strip_prefix("episode-")?
        .parse()
        .ok()
}
