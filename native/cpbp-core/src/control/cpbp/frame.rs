//! One frame's particles as they advance step by step, and the record each step leaves:
//! the lineages (control sequences), the drawn paths and the smoothed beliefs of the
//! refinement are all read back from the records by following parents.

use rand::RngExt;
use rand_pcg::Pcg64;

use crate::control::ValueSample;

/// What one particle's step produced.
pub(super) struct Outcome<State> {
    pub state: State,
    pub features: Vec<f64>,
    pub point: Option<[f64; 3]>,
    pub control: Vec<f64>,
    pub state_cost: f64,
    pub control_cost: f64,
    pub blew_up: bool,
    /// Whether its lineage had fallen by the end of the step (`RolloutSystem::fallen`).
    pub fallen: bool,
    /// Whether it had fallen before the step: the step was simulated after a fall.
    pub after_fall: bool,
    /// The state's features for a cost-to-go, after a step that records them (empty
    /// otherwise: `CpbpConfig::record_values_after`).
    pub value_features: Vec<f64>,
}

/// What one particle did in one planning step: the particle (at the step before) it
/// continued from, the control it applied, where it got to (features for the refinement,
/// a point for drawing), its step's ψ and its forward weight after the step
/// (unnormalised).
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct ParticleStep {
    pub parent: usize,
    pub control: Vec<f64>,
    pub features: Vec<f64>,
    pub point: Option<[f64; 3]>,
    pub potential: f64,
    pub weight: f64,
    /// Its lineage's total (state + control) cost after the step.
    pub total: f64,
    /// `Outcome::value_features`.
    pub value_features: Vec<f64>,
}

/// One planning step: every particle's, in particle order.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct StepRecord {
    pub particles: Vec<ParticleStep>,
    pub blowups: usize,
    /// Particles whose lineage had fallen before the step (`Outcome::after_fall`).
    pub after_falls: usize,
    /// Whether the parents were drawn by weight (always at the first step).
    pub resampled: bool,
}

/// One particle between steps.
#[derive(Clone)]
pub(super) struct Particle<State> {
    pub state: State,
    pub weight: f64,
    /// Total (state + control) cost of its lineage so far.
    pub total: f64,
    /// Its last control and the one before: the smoothness priors' inputs.
    pub previous: Vec<f64>,
    pub before_previous: Vec<f64>,
    /// Whether its lineage has fallen (`RolloutSystem::fallen`).
    pub fallen: bool,
}

/// The particles between steps.
pub(super) struct Particles<State> {
    pub all: Vec<Particle<State>>,
}

impl<State> Particles<State> {
    /// Every particle's weight, in order.
    pub fn weights(&self) -> Vec<f64> {
        self.all.iter().map(|p| p.weight).collect()
    }

    /// Normalises the weights (see [`normalise`]) and returns them.
    pub fn normalise_weights(&mut self) -> Vec<f64> {
        let mut weights = self.weights();
        normalise(&mut weights);
        for (particle, &weight) in self.all.iter_mut().zip(&weights) {
            particle.weight = weight;
        }
        weights
    }
}

impl<State: Clone> Particles<State> {
    /// `n` particles at `start`, equally weighted, after the master's last two controls.
    pub fn start(start: &State, n: usize, applied: &[f64], applied_before: &[f64]) -> Self {
        let particle = Particle {
            state: start.clone(),
            weight: 1.0 / n as f64,
            total: 0.0,
            previous: applied.to_vec(),
            before_previous: applied_before.to_vec(),
            fallen: false,
        };
        Self {
            all: vec![particle; n],
        }
    }

    /// Normalises the weights and picks each particle's parent: itself, or, at the first
    /// step and whenever the effective sample size drops below `threshold`·N, one drawn by
    /// weight (particles that replay a sequence keep their own lineage). Returns the
    /// parents and whether the step resampled.
    pub fn choose_parents(
        &mut self,
        k: usize,
        threshold: f64,
        replays: &[bool],
        rng: &mut Pcg64,
    ) -> (Vec<usize>, bool) {
        let n = self.all.len();
        let weights = self.normalise_weights();
        let ess = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
        let resample = k == 0 || ess < threshold * n as f64;
        let parents = (0..n)
            .map(|i| {
                if replays[i] || !resample {
                    i
                } else {
                    draw(&weights, rng)
                }
            })
            .collect();
        (parents, resample)
    }

    /// Takes in the step's outcomes. Every one was computed from its parent's old values;
    /// they replace them only now, all at once, so no particle reads a sibling's new state.
    pub fn advance(
        &mut self,
        parents: Vec<usize>,
        resampled: bool,
        outcomes: Vec<Outcome<State>>,
    ) -> StepRecord {
        let state_costs: Vec<f64> = outcomes.iter().map(|o| o.state_cost).collect();
        let potentials = potentials(&state_costs);
        let mut record = StepRecord {
            particles: Vec::with_capacity(outcomes.len()),
            blowups: 0,
            after_falls: 0,
            resampled,
        };
        let mut next = Vec::with_capacity(outcomes.len());
        for ((outcome, parent), potential) in outcomes.into_iter().zip(parents).zip(potentials) {
            let old = &self.all[parent];
            let weight = if resampled {
                potential
            } else {
                old.weight * potential
            };
            record.blowups += usize::from(outcome.blew_up);
            record.after_falls += usize::from(outcome.after_fall);
            let total = old.total + outcome.state_cost + outcome.control_cost;
            next.push(Particle {
                state: outcome.state,
                weight,
                total,
                previous: outcome.control.clone(),
                before_previous: old.previous.clone(),
                fallen: outcome.fallen,
            });
            record.particles.push(ParticleStep {
                parent,
                control: outcome.control,
                features: outcome.features,
                point: outcome.point,
                potential,
                weight,
                total,
                value_features: outcome.value_features,
            });
        }
        self.all = next;
        record
    }
}

/// The particle that final particle `end` descends from at each step.
pub(super) fn ancestry(records: &[StepRecord], end: usize) -> Vec<usize> {
    let mut indices = vec![0; records.len()];
    let mut i = end;
    for (k, record) in records.iter().enumerate().rev() {
        indices[k] = i;
        i = record.particles[i].parent;
    }
    indices
}

/// Each final particle's control sequence (K·D values) and trace points (empty when the
/// system has none), read along its ancestry.
pub(super) fn lineages(records: &[StepRecord]) -> (Vec<Vec<f64>>, Vec<Vec<[f64; 3]>>) {
    let count = records.last().map_or(0, |r| r.particles.len());
    (0..count)
        .map(|end| {
            let line = ancestry(records, end);
            let steps = records.iter().zip(&line);
            let sequence = steps
                .clone()
                .flat_map(|(record, &i)| record.particles[i].control.iter().copied())
                .collect();
            let path = steps
                .filter_map(|(record, &i)| record.particles[i].point)
                .collect();
            (sequence, path)
        })
        .unzip()
}

/// The states recorded for a cost-to-go (steps whose particles hold value features),
/// each with the least cost a final particle descending from it added after it: the best
/// continuation the frame found from there. A particle no final one descends from was
/// given up by resampling and teaches nothing.
pub(super) fn value_samples(records: &[StepRecord]) -> Vec<ValueSample> {
    let Some(last) = records.last() else {
        return Vec::new();
    };
    let steps = records.len();
    let ancestries: Vec<Vec<usize>> = (0..last.particles.len())
        .map(|end| ancestry(records, end))
        .collect();
    let mut samples = Vec::new();
    for (k, record) in records.iter().enumerate() {
        for (i, step) in record.particles.iter().enumerate() {
            if step.value_features.is_empty() {
                continue;
            }
            let cost_to_go = ancestries
                .iter()
                .zip(&last.particles)
                .filter(|(line, _)| line[k] == i)
                .map(|(_, end)| end.total - step.total)
                .fold(f64::INFINITY, f64::min);
            if cost_to_go.is_finite() {
                samples.push(ValueSample {
                    features: step.value_features.clone(),
                    remaining_steps: steps - k - 1,
                    cost_to_go,
                });
            }
        }
    }
    samples
}

/// The backward pass: β_K = 1/N, β_k(parent) = Σ over its children of ψ·β_{k+1}; the
/// smoothed belief of particle i at step k is its forward weight times β_k(i), so a
/// step's samples count by how well their whole future went, not only their past.
pub(super) fn smoothed_beliefs(records: &[StepRecord]) -> Vec<Vec<f64>> {
    let Some(n) = records.first().map(|r| r.particles.len()) else {
        return Vec::new();
    };
    let mut beliefs = vec![Vec::new(); records.len()];
    let mut backward = vec![1.0 / n as f64; n];
    for (k, record) in records.iter().enumerate().rev() {
        let mut smoothed: Vec<f64> = (0..n)
            .map(|i| record.particles[i].weight * backward[i])
            .collect();
        normalise(&mut smoothed);
        beliefs[k] = smoothed;
        if k > 0 {
            let mut message = vec![0.0; n];
            for (step, b) in record.particles.iter().zip(&backward) {
                message[step.parent] += step.potential * b;
            }
            normalise(&mut message);
            backward = message;
        }
    }
    beliefs
}

/// ψ = exp(−½ c) per particle, with the adaptive temperature of the specification: when
/// even the best step cost exceeds 10, all are scaled by 10 / min so weights never all
/// underflow to zero.
fn potentials(costs: &[f64]) -> Vec<f64> {
    let least = costs.iter().cloned().fold(f64::INFINITY, f64::min);
    let scale = if least > 10.0 { 10.0 / least } else { 1.0 };
    costs.iter().map(|c| (-0.5 * c * scale).exp()).collect()
}

/// Normalises weights to sum 1; NaN, infinite or all-zero weights fall back to uniform.
pub(super) fn normalise(weights: &mut [f64]) {
    let sum: f64 = weights.iter().sum();
    if sum.is_finite() && sum > 0.0 && weights.iter().all(|w| w.is_finite() && *w >= 0.0) {
        weights.iter_mut().for_each(|w| *w /= sum);
    } else {
        let uniform = 1.0 / weights.len() as f64;
        weights.iter_mut().for_each(|w| *w = uniform);
    }
}

/// An index drawn with probability proportional to `weights`.
pub(super) fn draw(weights: &[f64], rng: &mut Pcg64) -> usize {
    let sum: f64 = weights.iter().sum();
    let mut target = rng.random::<f64>() * sum;
    for (i, w) in weights.iter().enumerate() {
        target -= w;
        if target <= 0.0 {
            return i;
        }
    }
    weights.len() - 1
}

/// A seed for one stream: the same (seed, frame, stream) always gives the same draws,
/// whichever thread uses it.
pub(crate) fn mix(seed: u64, frame: u64, stream: u64) -> u64 {
    let mut z = seed
        ^ frame.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ stream.wrapping_mul(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn step(parents: Vec<usize>, controls: &[f64]) -> StepRecord {
        StepRecord {
            particles: parents
                .into_iter()
                .zip(controls)
                .map(|(parent, &u)| ParticleStep {
                    parent,
                    control: vec![u],
                    point: Some([u, 0.0, 0.0]),
                    ..ParticleStep::default()
                })
                .collect(),
            ..StepRecord::default()
        }
    }

    #[test]
    fn lineages_follow_parents_back() {
        // Step 0: particles 0, 1 applied [10], [11]. Step 1: both children of particle 1.
        let records = [
            step(vec![0, 1], &[10.0, 11.0]),
            step(vec![1, 1], &[20.0, 21.0]),
        ];
        let (sequences, paths) = lineages(&records);
        assert_eq!(sequences, [[11.0, 20.0], [11.0, 21.0]]);
        assert_eq!(paths[0], [[11.0, 0.0, 0.0], [20.0, 0.0, 0.0]]);
        assert_eq!(ancestry(&records, 0), [1, 0]);
    }

    #[test]
    fn weights_that_all_underflow_fall_back_to_uniform() {
        let mut weights = [0.0, 0.0, 0.0, 0.0];
        normalise(&mut weights);
        assert_eq!(weights, [0.25; 4]);
        let scaled = potentials(&[1e6, 2e6]);
        assert!(
            scaled[0] > 0.0,
            "the adaptive temperature keeps the best alive"
        );
    }
}
