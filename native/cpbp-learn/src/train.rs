//! Training the policy network on the recorded episodes with candle: a tanh MLP on
//! normalised features regressing the planner's normalised controls (mean squared
//! error, AdamW). Weights start from a seeded generator and batches are drawn from it,
//! on one thread, so a run repeats exactly. Episodes whose seed is a multiple of ten are
//! held out for validation, never trained on.

use candle_core::{DType, Device, Tensor, Var};
use candle_nn::{AdamW, Optimizer, ParamsAdamW};
use cpbp_core::control::learned::{NetworkParts, PolicyNetwork, FEATURE_COUNT, OUTPUT_COUNT};
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

/// Rows of features and labels, flattened.
#[derive(Clone, Debug, Default)]
pub struct Dataset {
    pub features: Vec<f32>,
    pub labels: Vec<f32>,
}

impl Dataset {
    pub fn rows(&self) -> usize {
        self.features.len() / FEATURE_COUNT
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

/// Mean squared error of `layers` over `rows` normalised rows.
fn loss(layers: &Layers, x: &[f32], y: &[f32], device: &Device) -> candle_core::Result<Tensor> {
    let rows = x.len() / FEATURE_COUNT;
    let x = Tensor::from_slice(x, (rows, FEATURE_COUNT), device)?;
    let y = Tensor::from_slice(y, (rows, OUTPUT_COUNT), device)?;
    (layers.forward(&x)? - y)?.sqr()?.mean_all()
}

/// Trains on `train`, reporting each epoch's losses to `report`; returns the network of
/// the epoch that did best on `validation` (the last epoch's when there is none).
pub fn train(
    train: &Dataset,
    validation: &Dataset,
    settings: &TrainSettings,
    description: &str,
    bike: &str,
    mut report: impl FnMut(usize, EpochLoss),
) -> Result<PolicyNetwork, String> {
    let fail = |e: candle_core::Error| e.to_string();
    if train.rows() == 0 {
        return Err("no training rows".into());
    }
    let device = Device::Cpu;
    let (in_mean, in_std) = moments(&train.features, FEATURE_COUNT, 1e-3);
    let (out_mean, out_std) = moments(&train.labels, OUTPUT_COUNT, 1e-3);
    let x = normalised(&train.features, &in_mean, &in_std);
    let y = normalised(&train.labels, &out_mean, &out_std);
    let vx = normalised(&validation.features, &in_mean, &in_std);
    let vy = normalised(&validation.labels, &out_mean, &out_std);
    let mut rng = Pcg64::seed_from_u64(settings.seed);
    let widths: Vec<usize> = std::iter::once(FEATURE_COUNT)
        .chain(settings.hidden.iter().copied())
        .chain(std::iter::once(OUTPUT_COUNT))
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
                bx.extend_from_slice(&x[r * FEATURE_COUNT..(r + 1) * FEATURE_COUNT]);
                by.extend_from_slice(&y[r * OUTPUT_COUNT..(r + 1) * OUTPUT_COUNT]);
            }
            let batch_loss = loss(&layers, &bx, &by, &device).map_err(fail)?;
            optimizer.backward_step(&batch_loss).map_err(fail)?;
            total += f64::from(batch_loss.to_scalar::<f32>().map_err(fail)?);
            batches += 1;
        }
        let validation = if vx.is_empty() {
            f64::NAN
        } else {
            let v = loss(&layers, &vx, &vy, &device).map_err(fail)?;
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
    PolicyNetwork::new(NetworkParts {
        input_mean: in_mean,
        input_std: in_std,
        layers: parts_layers,
        output_mean: out_mean,
        output_std: out_std,
        training: format!("{description}, weights of epoch {best_epoch}"),
        bike: bike.to_owned(),
    })
    .map_err(|e| e.to_string())
}
