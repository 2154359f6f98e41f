//! The learned networks at game time: small multilayer perceptrons read from safetensors
//! files and evaluated in plain Rust. Training happens elsewhere (a machine-learning
//! library, offline); the game needs only a few dense layers, so it links no such
//! library. Every kind of network the game runs (the policy, the cost-to-go) is one of
//! these with a [`NetworkShape`] of its own: the file names its format, the inputs and
//! outputs it was trained with and how it was made, and a file of another kind or for
//! another input list is refused with a message saying why.

use std::collections::HashMap;
use std::fmt;
use std::path::Path;

use safetensors::{Dtype, SafeTensors};

use super::features::FEATURES_VERSION;

/// Version of the file layout below (every kind's).
pub const MODEL_FORMAT_VERSION: u32 = 1;
/// Normalised inputs are held to this many spreads from the training mean: a state far
/// outside what the network saw gets the answer for the nearest state it did see.
const INPUT_LIMIT: f32 = 8.0;

/// What a kind of network file holds.
#[derive(Clone, Debug, PartialEq)]
pub struct NetworkShape {
    /// What a user calls it ("policy", "cost-to-go"), in messages.
    pub kind: &'static str,
    /// The `format` its metadata names.
    pub format: &'static str,
    /// Its inputs' names, in order: the metadata's `features`.
    pub inputs: Vec<String>,
    /// Its outputs' names, in order: the metadata's `outputs`.
    pub outputs: Vec<String>,
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
    /// Not a file of this kind (the kind, then why).
    NotAModel(&'static str, String),
    Mismatch(String),
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unreadable(why) => write!(f, "the model file cannot be read: {why}"),
            Self::NotAModel(kind, why) => {
                write!(f, "the file is not a Counter-Steer {kind}: {why}")
            }
            Self::Mismatch(why) => write!(f, "the model does not fit this build: {why}"),
        }
    }
}

impl std::error::Error for ModelError {}

/// An input was not a finite number: the network is not asked.
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

/// A network of some shape, checked and ready to evaluate.
pub struct Mlp {
    parts: NetworkParts,
    layers: Vec<Dense>,
}

impl Mlp {
    /// Checks the shapes and numbers of `parts` against `shape`.
    pub fn new(parts: NetworkParts, shape: &NetworkShape) -> Result<Self, ModelError> {
        let bad = |why: String| Err(ModelError::NotAModel(shape.kind, why));
        let positive = |v: &[f32]| v.iter().all(|x| x.is_finite() && *x > 0.0);
        let finite = |v: &[f32]| v.iter().all(|x| x.is_finite());
        let (inputs, outputs) = (shape.inputs.len(), shape.outputs.len());
        if parts.input_mean.len() != inputs || parts.input_std.len() != inputs {
            return bad(format!("input normalisation is not {inputs} long"));
        }
        if parts.output_mean.len() != outputs || parts.output_std.len() != outputs {
            return bad(format!("output normalisation is not {outputs} long"));
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
        let mut width = inputs;
        for (i, (weight, bias)) in parts.layers.iter().enumerate() {
            if bias.is_empty() || weight.len() != bias.len() * width {
                return bad(format!("layer {i} does not take {width} inputs"));
            }
            if !finite(weight) || !finite(bias) {
                return bad(format!("layer {i} has a weight that is not finite"));
            }
            width = bias.len();
        }
        if width != outputs {
            return bad(format!("it gives {width} outputs, not {outputs}"));
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

    /// Reads a model file of `shape`.
    pub fn load(path: &Path, shape: &NetworkShape) -> Result<Self, ModelError> {
        let bytes = std::fs::read(path)
            .map_err(|e| ModelError::Unreadable(format!("{}: {e}", path.display())))?;
        Self::parse(&bytes, shape)
    }

    /// Reads a model of `shape` from a file's bytes.
    pub fn parse(bytes: &[u8], shape: &NetworkShape) -> Result<Self, ModelError> {
        let not_a_model = |why: String| ModelError::NotAModel(shape.kind, why);
        let (_, header) =
            SafeTensors::read_metadata(bytes).map_err(|e| not_a_model(e.to_string()))?;
        let file = SafeTensors::deserialize(bytes).map_err(|e| not_a_model(e.to_string()))?;
        let meta = header.metadata().clone().unwrap_or_default();
        let field = |key: &str| meta.get(key).map(String::as_str).unwrap_or("");
        if field("format") != shape.format {
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
        expect("features", shape.inputs.join(","))?;
        expect("outputs", shape.outputs.join(","))?;
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
        let parts = NetworkParts {
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
        };
        Self::new(parts, shape)
    }

    /// The model file's bytes: safetensors, with the metadata `parse` checks.
    pub fn to_bytes(&self, shape: &NetworkShape) -> Vec<u8> {
        let p = &self.parts;
        let (inputs, outputs) = (shape.inputs.len(), shape.outputs.len());
        let mut tensors: Vec<(String, Vec<usize>, &[f32])> = vec![
            ("input.mean".into(), vec![inputs], &p.input_mean),
            ("input.std".into(), vec![inputs], &p.input_std),
            ("output.mean".into(), vec![outputs], &p.output_mean),
            ("output.std".into(), vec![outputs], &p.output_std),
        ];
        for (i, (weight, bias)) in p.layers.iter().enumerate() {
            let layer_shape = vec![bias.len(), weight.len() / bias.len()];
            tensors.push((format!("layer{i}.weight"), layer_shape, weight));
            tensors.push((format!("layer{i}.bias"), vec![bias.len()], bias));
        }
        let bytes: Vec<(String, Vec<usize>, Vec<u8>)> = tensors
            .into_iter()
            .map(|(name, dims, values)| (name, dims, f32_bytes(values)))
            .collect();
        let views = bytes.iter().map(|(name, dims, data)| {
            let view = safetensors::tensor::TensorView::new(Dtype::F32, dims.clone(), data)
                .expect("shapes come from the data");
            (name.clone(), view)
        });
        let meta = HashMap::from([
            ("format".to_string(), shape.format.to_string()),
            ("format_version".into(), MODEL_FORMAT_VERSION.to_string()),
            ("features_version".into(), FEATURES_VERSION.to_string()),
            ("features".into(), shape.inputs.join(",")),
            ("outputs".into(), shape.outputs.join(",")),
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

    /// The outputs for `inputs` (as many as the shape's), into `outputs`.
    pub fn evaluate(&self, inputs: &[f64], outputs: &mut [f64]) -> Result<(), NonFiniteFeature> {
        if let Some(i) = inputs.iter().position(|f| !f.is_finite()) {
            return Err(NonFiniteFeature(i));
        }
        let p = &self.parts;
        let mut input: Vec<f32> = inputs
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                let x = (x as f32 - p.input_mean[i]) / p.input_std[i];
                x.clamp(-INPUT_LIMIT, INPUT_LIMIT)
            })
            .collect();
        let mut output = Vec::new();
        let last = self.layers.len() - 1;
        for (i, layer) in self.layers.iter().enumerate() {
            layer.apply(&input, &mut output, i < last);
            std::mem::swap(&mut input, &mut output);
        }
        for (o, value) in outputs.iter_mut().enumerate() {
            *value = f64::from(p.output_mean[o] + input[o] * p.output_std[o]);
        }
        Ok(())
    }
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
