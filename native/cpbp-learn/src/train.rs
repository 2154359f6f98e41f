//! Training a network on the recorded episodes with candle: a tanh MLP on normalised
//! inputs regressing normalised targets (mean squared error, AdamW): the policy the
//! planner's controls from the features, the cost-to-go the log of what the rest of the
//! planner's horizon cost from the features and the time left. Weights start from a seeded generator and batches are drawn from it,
//! on one thread, so a run repeats exactly. Episodes whose seed is a multiple of ten are
//! held out for validation, never trained on.

use candle_core::{DType, Device, Tensor, Var};
use candle_nn::{AdamW, Optimizer, ParamsAdamW};
use cpbp_core::control::learned::{NetworkParts, FEATURE_COUNT, OUTPUT_COUNT};
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

/// How a network is trained.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainSettings {
    pub hidden: Vec<usize>,
    pub epochs: usize,
    pub batch: usize,
    pub learning_rate: f64,
    pub weight_decay: f64,
    pub seed: u64,
}

impl Default for TrainSettings {
    fn default() -> Self {
        Self {
            hidden: vec![128, 128],
            epochs: 40,
            batch: 256,
            learning_rate: 1e-3,
            weight_decay: 1e-4,
            seed: 1,
        }
    }
}

/// Rows of inputs (`features`) and targets (`labels`), flattened, `inputs` and `outputs`
/// wide.
#[derive(Clone, Debug)]
pub struct Dataset {
    pub inputs: usize,
    pub outputs: usize,
    pub features: Vec<f32>,
    pub labels: Vec<f32>,
}

/// The policy's rows: the features, the planner's controls.
impl Default for Dataset {
    fn default() -> Self {
        Self::new(FEATURE_COUNT, OUTPUT_COUNT)
    }
}

impl Dataset {
    /// No rows yet, of `inputs` inputs and `outputs` targets.
    pub fn new(inputs: usize, outputs: usize) -> Self {
        Self {
            inputs,
            outputs,
            features: Vec::new(),
            labels: Vec::new(),
        }
    }

    pub fn rows(&self) -> usize {
        self.features.len() / self.inputs
    }

    pub fn extend(&mut self, features: &[f32], labels: &[f32]) {
        self.features.extend_from_slice(features);
        self.labels.extend_from_slice(labels);
    }
}

/// One epoch's mean losses (normalised units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EpochLoss {
    pub train: f64,
    pub validation: f64,
}

/// Mean and spread of each column; a spread under `floor` counts as `floor`, so a
/// column that never moved is passed through instead of blown up.
fn moments(values: &[f32], width: usize, floor: f32) -> (Vec<f32>, Vec<f32>) {
    let rows = (values.len() / width).max(1) as f64;
    let mut mean = vec![0.0f64; width];
    let mut square = vec![0.0f64; width];
    for row in values.chunks_exact(width) {
        for (c, &v) in row.iter().enumerate() {
            mean[c] += f64::from(v) / rows;
            square[c] += f64::from(v).powi(2) / rows;
        }
    }
    let spread = mean
        .iter()
        .zip(&square)
        .map(|(m, s)| ((s - m * m).max(0.0).sqrt() as f32).max(floor))
        .collect();
    (mean.into_iter().map(|m| m as f32).collect(), spread)
}

fn normalised(values: &[f32], mean: &[f32], spread: &[f32]) -> Vec<f32> {
    let width = mean.len();
    values
        .iter()
        .enumerate()
        .map(|(i, v)| (v - mean[i % width]) / spread[i % width])
        .collect()
}

/// Each layer's weights and biases as plain numbers (the model file's layout).
type Weights = Vec<(Vec<f32>, Vec<f32>)>;

/// The network's weights as candle variables.
pub(crate) struct Layers {
    vars: Vec<(Var, Var)>,
}

impl Layers {
    /// Glorot-uniform weights from `rng`, zero biases.
    fn new(widths: &[usize], rng: &mut Pcg64, device: &Device) -> candle_core::Result<Self> {
        let vars = widths
            .windows(2)
            .map(|w| {
                let (inputs, outputs) = (w[0], w[1]);
                let limit = (6.0 / (inputs + outputs) as f64).sqrt();
                let weight: Vec<f32> = (0..inputs * outputs)
                    .map(|_| rng.random_range(-limit..limit) as f32)
                    .collect();
                Ok((
                    Var::from_tensor(&Tensor::from_vec(weight, (outputs, inputs), device)?)?,
                    Var::zeros(outputs, DType::F32, device)?,
                ))
            })
            .collect::<candle_core::Result<_>>()?;
        Ok(Self { vars })
    }

    /// The layers of a trained network, as candle variables again.
    #[cfg(test)]
    pub(crate) fn from_parts(parts: &NetworkParts, device: &Device) -> candle_core::Result<Self> {
        let vars = parts
            .layers
            .iter()
            .map(|(weight, bias)| {
                let shape = (bias.len(), weight.len() / bias.len());
                Ok((
                    Var::from_tensor(&Tensor::from_slice(weight, shape, device)?)?,
                    Var::from_tensor(&Tensor::from_slice(bias, bias.len(), device)?)?,
                ))
            })
            .collect::<candle_core::Result<_>>()?;
        Ok(Self { vars })
    }

    pub(crate) fn forward(&self, input: &Tensor) -> candle_core::Result<Tensor> {
        let last = self.vars.len() - 1;
        let mut x = input.clone();
        for (i, (weight, bias)) in self.vars.iter().enumerate() {
            x = x
                .matmul(&weight.as_tensor().t()?)?
                .broadcast_add(bias.as_tensor())?;
            if i < last {
                x = x.tanh()?;
            }
        }
        Ok(x)
    }

    /// Each layer's weights (row-major, rows are outputs) and biases, as the model file
    /// stores them.
    fn weights(&self) -> candle_core::Result<Weights> {
        self.vars
            .iter()
            .map(|(weight, bias)| {
                Ok((
                    weight.as_tensor().flatten_all()?.to_vec1::<f32>()?,
                    bias.as_tensor().to_vec1::<f32>()?,
                ))
            })
            .collect()
    }

    fn all(&self) -> Vec<Var> {
        self.vars
            .iter()
            .flat_map(|(w, b)| [w.clone(), b.clone()])
            .collect()
    }
}

/// Mean squared error of `layers` over normalised rows `inputs` and `outputs` wide.
fn loss(
    layers: &Layers,
    (x, inputs): (&[f32], usize),
    (y, outputs): (&[f32], usize),
    device: &Device,
) -> candle_core::Result<Tensor> {
    let rows = x.len() / inputs;
    let x = Tensor::from_slice(x, (rows, inputs), device)?;
    let y = Tensor::from_slice(y, (rows, outputs), device)?;
    (layers.forward(&x)? - y)?.sqr()?.mean_all()
}

/// Trains on `train`, reporting each epoch's losses to `report`; returns the parts of the
/// network of the epoch that did best on `validation` (the last epoch's when there is
/// none), for the caller to check as the kind of network it trained.
pub fn train(
    train: &Dataset,
    validation: &Dataset,
    settings: &TrainSettings,
    description: &str,
    bike: &str,
    mut report: impl FnMut(usize, EpochLoss),
) -> Result<NetworkParts, String> {
    let fail = |e: candle_core::Error| e.to_string();
    if train.rows() == 0 {
        return Err("no training rows".into());
    }
    let (inputs, outputs) = (train.inputs, train.outputs);
    let device = Device::Cpu;
    let (in_mean, in_std) = moments(&train.features, inputs, 1e-3);
    let (out_mean, out_std) = moments(&train.labels, outputs, 1e-3);
    let x = normalised(&train.features, &in_mean, &in_std);
    let y = normalised(&train.labels, &out_mean, &out_std);
    let vx = normalised(&validation.features, &in_mean, &in_std);
    let vy = normalised(&validation.labels, &out_mean, &out_std);
    let mut rng = Pcg64::seed_from_u64(settings.seed);
    let widths: Vec<usize> = std::iter::once(inputs)
        .chain(settings.hidden.iter().copied())
        .chain(std::iter::once(outputs))
        .collect();
    let layers = Layers::new(&widths, &mut rng, &device).map_err(fail)?;
    let params = ParamsAdamW {
        lr: settings.learning_rate,
        weight_decay: settings.weight_decay,
        ..ParamsAdamW::default()
    };
    let mut optimizer = AdamW::new(layers.all(), params).map_err(fail)?;
    let mut order: Vec<usize> = (0..train.rows()).collect();
    let (mut bx, mut by) = (Vec::new(), Vec::new());
    let mut best: Option<(usize, f64, Weights)> = None;
    for epoch in 0..settings.epochs {
        order.shuffle(&mut rng);
        let (mut total, mut batches) = (0.0, 0);
        for chunk in order.chunks(settings.batch.max(1)) {
            bx.clear();
            by.clear();
            for &r in chunk {
                bx.extend_from_slice(&x[r * inputs..(r + 1) * inputs]);
                by.extend_from_slice(&y[r * outputs..(r + 1) * outputs]);
            }
            let batch_loss = loss(&layers, (&bx, inputs), (&by, outputs), &device).map_err(fail)?;
            optimizer.backward_step(&batch_loss).map_err(fail)?;
            total += f64::from(batch_loss.to_scalar::<f32>().map_err(fail)?);
            batches += 1;
        }
        let validation = if vx.is_empty() {
            f64::NAN
        } else {
            let v = loss(&layers, (&vx, inputs), (&vy, outputs), &device).map_err(fail)?;
            f64::from(v.to_scalar::<f32>().map_err(fail)?)
        };
        report(
            epoch,
            EpochLoss {
                train: total / f64::from(batches.max(1)),
                validation,
            },
        );
        // Early stopping: the weights of the epoch that did best on the held-out
        // episodes are the ones kept.
        if validation.is_finite() && best.as_ref().is_none_or(|(_, loss, _)| validation < *loss) {
            best = Some((epoch, validation, layers.weights().map_err(fail)?));
        }
    }
    let (best_epoch, parts_layers) = match best {
        Some((epoch, _, weights)) => (epoch, weights),
        None => (
            settings.epochs.saturating_sub(1),
            layers.weights().map_err(fail)?,
        ),
    };
    Ok(NetworkParts {
        input_mean: in_mean,
        input_std: in_std,
        layers: parts_layers,
        output_mean: out_mean,
        output_std: out_std,
        training: format!("{description}, weights of epoch {best_epoch}"),
        bike: bike.to_owned(),
    })
}
