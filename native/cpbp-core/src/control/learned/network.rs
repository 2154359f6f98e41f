//! The learned controller's network at game time: a small multilayer perceptron read
//! from a safetensors file and evaluated in plain Rust. Training happens elsewhere (a
//! machine-learning library, offline); the game needs only a few dense layers, so it
//! links no such library. The file names its format, the feature list it was trained
//! on and how it was made; anything else is refused with a message saying why.

use std::collections::HashMap;
use std::fmt;
use std::path::Path;

use safetensors::{Dtype, SafeTensors};

use super::features::{FEATURES_VERSION, FEATURE_COUNT, FEATURE_NAMES};
use crate::bike::{CONTROL_DIM, DRIVE_ENTRIES};

/// The `format` a model file's metadata must name.
pub const MODEL_FORMAT: &str = "counter-steer-policy";
/// Version of the file layout below.
pub const MODEL_FORMAT_VERSION: u32 = 1;
/// How many control entries the network decides: all but the drive's.
pub const OUTPUT_COUNT: usize = CONTROL_DIM - DRIVE_ENTRIES.len();
/// Normalised inputs are held to this many spreads from the training mean: a state far
/// outside what the network saw gets the answer for the nearest state it did see.
const INPUT_LIMIT: f32 = 8.0;

/// The control entries the network's outputs set, in output order.
pub fn output_entries() -> [usize; OUTPUT_COUNT] {
    let mut entries = [0; OUTPUT_COUNT];
    let decided = (0..CONTROL_DIM).filter(|i| !DRIVE_ENTRIES.contains(i));
    entries.iter_mut().zip(decided).for_each(|(e, i)| *e = i);
    entries
}

/// What a model file holds, as plain numbers (the trainer fills it from its tensors).
/// Hidden layers use tanh; the last layer is linear. Weights are row-major, one row per
/// output.
#[derive(Clone, Debug, PartialEq)]
pub struct NetworkParts {
    pub input_mean: Vec<f32>,
    pub input_std: Vec<f32>,
    pub layers: Vec<(Vec<f32>, Vec<f32>)>,
    pub output_mean: Vec<f32>,
    pub output_std: Vec<f32>,
    /// How the model was made: the training run, data, seed (free text, shown to users).
    pub training: String,
    /// The bike it was trained on (`BikeParams::identity`); models written before bikes
    /// were recorded name none and were all trained on the reference bike.
    pub bike: String,
}

/// Why a model file was refused.
#[derive(Debug)]
pub enum ModelError {
    Unreadable(String),
    NotAModel(String),
    Mismatch(String),
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unreadable(why) => write!(f, "the model file cannot be read: {why}"),
            Self::NotAModel(why) => write!(f, "the file is not a Counter-Steer policy: {why}"),
            Self::Mismatch(why) => write!(f, "the model does not fit this build: {why}"),
        }
    }
}

impl std::error::Error for ModelError {}

/// A feature was not a finite number: the network is not asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NonFiniteFeature(pub usize);

struct Dense {
    weight: Vec<f32>,
    bias: Vec<f32>,
}

impl Dense {
    fn apply(&self, input: &[f32], output: &mut Vec<f32>, squash: bool) {
        output.clear();
        let inputs = input.len();
        for (row, &bias) in self.weight.chunks_exact(inputs).zip(&self.bias) {
            let sum = bias + row.iter().zip(input).map(|(w, x)| w * x).sum::<f32>();
            output.push(if squash { sum.tanh() } else { sum });
        }
    }
}

/// The network, checked and ready to evaluate.
pub struct PolicyNetwork {
    parts: NetworkParts,
    layers: Vec<Dense>,
}

impl PolicyNetwork {
    /// Checks the shapes and numbers of `parts`.
    pub fn new(parts: NetworkParts) -> Result<Self, ModelError> {
        let bad = |why: String| Err(ModelError::NotAModel(why));
        let positive = |v: &[f32]| v.iter().all(|x| x.is_finite() && *x > 0.0);
        let finite = |v: &[f32]| v.iter().all(|x| x.is_finite());
        if parts.input_mean.len() != FEATURE_COUNT || parts.input_std.len() != FEATURE_COUNT {
            return bad(format!("input normalisation is not {FEATURE_COUNT} long"));
        }
        if parts.output_mean.len() != OUTPUT_COUNT || parts.output_std.len() != OUTPUT_COUNT {
            return bad(format!("output normalisation is not {OUTPUT_COUNT} long"));
        }
        if !finite(&parts.input_mean) || !finite(&parts.output_mean) {
            return bad("a normalisation mean is not finite".into());
        }
        if !positive(&parts.input_std) || !positive(&parts.output_std) {
            return bad("a normalisation spread is not a positive number".into());
        }
        if parts.layers.is_empty() {
            return bad("it has no layers".into());
        }
        let mut width = FEATURE_COUNT;
        for (i, (weight, bias)) in parts.layers.iter().enumerate() {
            if bias.is_empty() || weight.len() != bias.len() * width {
                return bad(format!("layer {i} does not take {width} inputs"));
            }
            if !finite(weight) || !finite(bias) {
                return bad(format!("layer {i} has a weight that is not finite"));
            }
            width = bias.len();
        }
        if width != OUTPUT_COUNT {
            return bad(format!("it gives {width} outputs, not {OUTPUT_COUNT}"));
        }
        let layers = parts
            .layers
            .iter()
            .map(|(weight, bias)| Dense {
                weight: weight.clone(),
                bias: bias.clone(),
            })
            .collect();
        Ok(Self { parts, layers })
    }

    /// Reads a model file.
    pub fn load(path: &Path) -> Result<Self, ModelError> {
        let bytes = std::fs::read(path)
            .map_err(|e| ModelError::Unreadable(format!("{}: {e}", path.display())))?;
        Self::parse(&bytes)
    }

    /// Reads a model from a file's bytes.
    pub fn parse(bytes: &[u8]) -> Result<Self, ModelError> {
        let not_a_model = |why: String| ModelError::NotAModel(why);
        let (_, header) =
            SafeTensors::read_metadata(bytes).map_err(|e| not_a_model(e.to_string()))?;
        let file = SafeTensors::deserialize(bytes).map_err(|e| not_a_model(e.to_string()))?;
        let meta = header.metadata().clone().unwrap_or_default();
        let field = |key: &str| meta.get(key).map(String::as_str).unwrap_or("");
        if field("format") != MODEL_FORMAT {
            return Err(not_a_model(format!("its format is '{}'", field("format"))));
        }
        let expect = |key: &str, wanted: String| {
            let found = field(key);
            if found == wanted {
                Ok(())
            } else {
                Err(ModelError::Mismatch(format!(
                    "its {key} is '{found}', this build needs '{wanted}' (retrain with `make train`)"
                )))
            }
        };
        expect("format_version", MODEL_FORMAT_VERSION.to_string())?;
        expect("features_version", FEATURES_VERSION.to_string())?;
        expect("features", FEATURE_NAMES.join(","))?;
        expect("outputs", output_names().join(","))?;
        let tensor = |name: &str| -> Result<Vec<f32>, ModelError> {
            let view = file
                .tensor(name)
                .map_err(|_| not_a_model(format!("it has no tensor '{name}'")))?;
            if view.dtype() != Dtype::F32 {
                return Err(not_a_model(format!("'{name}' is not float32")));
            }
            Ok(f32_values(view.data()))
        };
        let count: usize = field("layers")
            .parse()
            .map_err(|_| not_a_model("it does not say how many layers it has".into()))?;
        let layers = (0..count.min(64))
            .map(|i| {
                Ok((
                    tensor(&format!("layer{i}.weight"))?,
                    tensor(&format!("layer{i}.bias"))?,
                ))
            })
            .collect::<Result<Vec<_>, ModelError>>()?;
        Self::new(NetworkParts {
            input_mean: tensor("input.mean")?,
            input_std: tensor("input.std")?,
            layers,
            output_mean: tensor("output.mean")?,
            output_std: tensor("output.std")?,
            training: field("training").to_string(),
            bike: match field("bike") {
                "" => crate::bike::BikeParams::default().identity(),
                bike => bike.to_string(),
            },
        })
    }

    /// The model file's bytes: safetensors, with the metadata `parse` checks.
    pub fn to_bytes(&self) -> Vec<u8> {
        let p = &self.parts;
        let mut tensors: Vec<(String, Vec<usize>, &[f32])> = vec![
            ("input.mean".into(), vec![FEATURE_COUNT], &p.input_mean),
            ("input.std".into(), vec![FEATURE_COUNT], &p.input_std),
            ("output.mean".into(), vec![OUTPUT_COUNT], &p.output_mean),
            ("output.std".into(), vec![OUTPUT_COUNT], &p.output_std),
        ];
        for (i, (weight, bias)) in p.layers.iter().enumerate() {
            let shape = vec![bias.len(), weight.len() / bias.len()];
            tensors.push((format!("layer{i}.weight"), shape, weight));
            tensors.push((format!("layer{i}.bias"), vec![bias.len()], bias));
        }
        let bytes: Vec<(String, Vec<usize>, Vec<u8>)> = tensors
            .into_iter()
            .map(|(name, shape, values)| (name, shape, f32_bytes(values)))
            .collect();
        let views = bytes.iter().map(|(name, shape, data)| {
            let view = safetensors::tensor::TensorView::new(Dtype::F32, shape.clone(), data)
                .expect("shapes come from the data");
            (name.clone(), view)
        });
        let meta = HashMap::from([
            ("format".to_string(), MODEL_FORMAT.to_string()),
            ("format_version".into(), MODEL_FORMAT_VERSION.to_string()),
            ("features_version".into(), FEATURES_VERSION.to_string()),
            ("features".into(), FEATURE_NAMES.join(",")),
            ("outputs".into(), output_names().join(",")),
            ("layers".into(), p.layers.len().to_string()),
            ("activation".into(), "tanh".into()),
            ("training".into(), p.training.clone()),
            ("bike".into(), p.bike.clone()),
        ]);
        super::serialize_sorted(views, meta).expect("checked shapes serialise")
    }

    pub fn parts(&self) -> &NetworkParts {
        &self.parts
    }

    /// The control entries (in [`output_entries`] order) for `features`.
    pub fn evaluate(
        &self,
        features: &[f64; FEATURE_COUNT],
    ) -> Result<[f64; OUTPUT_COUNT], NonFiniteFeature> {
        if let Some(i) = features.iter().position(|f| !f.is_finite()) {
            return Err(NonFiniteFeature(i));
        }
        let p = &self.parts;
        let mut input: Vec<f32> = (0..FEATURE_COUNT)
            .map(|i| {
                let x = (features[i] as f32 - p.input_mean[i]) / p.input_std[i];
                x.clamp(-INPUT_LIMIT, INPUT_LIMIT)
            })
            .collect();
        let mut output = Vec::new();
        let last = self.layers.len() - 1;
        for (i, layer) in self.layers.iter().enumerate() {
            layer.apply(&input, &mut output, i < last);
            std::mem::swap(&mut input, &mut output);
        }
        let mut out = [0.0; OUTPUT_COUNT];
        for (o, value) in out.iter_mut().enumerate() {
            *value = f64::from(p.output_mean[o] + input[o] * p.output_std[o]);
        }
        Ok(out)
    }
}

/// Names of the outputs, for the metadata of model and data files: the control entries'
/// indices.
pub fn output_names() -> Vec<String> {
    output_entries().iter().map(|i| format!("u{i}")).collect()
}

/// Float32 values as safetensors stores them (little-endian bytes).
pub fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// The float32 values of safetensors bytes.
pub fn f32_values(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}
