//! One frame's particles as they advance step by step, and the record each step leaves:
//! the lineages (control sequences), the drawn paths and the smoothed beliefs of the
//! refinement are all read back from the records by following parents.

use rand::RngExt;
use rand_pcg::Pcg64;

/// What one particle's step produced.
pub(super) struct Outcome<State> {
    pub state: State,
    pub features: Vec<f64>,
    pub point: Option<[f64; 3]>,
    pub control: Vec<f64>,
    pub state_cost: f64,
    pub control_cost: f64,
    pub blew_up: bool,
}

/// One planning step, per particle i: `parents[i]` is the particle (at the step before)
/// that particle i continued from, `controls[i]` what it applied, `features[i]` and
/// `points[i]` where it got to, `potentials[i]` its step's ψ and `weights[i]` its forward
/// weight after the step (unnormalised).
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct StepRecord {
    pub parents: Vec<usize>,
    pub controls: Vec<Vec<f64>>,
    pub features: Vec<Vec<f64>>,
    pub potentials: Vec<f64>,
    pub weights: Vec<f64>,
    pub points: Vec<Option<[f64; 3]>>,
    pub blowups: usize,
    /// Whether the parents were drawn by weight (always at the first step).
    pub resampled: bool,
}

/// The particles between steps.
pub(super) struct Particles<State> {
    pub states: Vec<State>,
    pub weights: Vec<f64>,
    /// Total (state + control) cost of each particle's lineage so far.
    pub totals: Vec<f64>,
    /// Each particle's last control and the one before: the smoothness priors' inputs.
    pub previous: Vec<Vec<f64>>,
    pub before_previous: Vec<Vec<f64>>,
}

impl<State: Clone> Particles<State> {
    /// `n` particles at `start`, equally weighted, after the master's last two controls.
    pub fn start(start: &State, n: usize, applied: &[f64], applied_before: &[f64]) -> Self {
        Self {
            states: vec![start.clone(); n],
            weights: vec![1.0 / n as f64; n],
            totals: vec![0.0; n],
            previous: vec![applied.to_vec(); n],
            before_previous: vec![applied_before.to_vec(); n],
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
        let n = self.weights.len();
        normalise(&mut self.weights);
        let ess = 1.0 / self.weights.iter().map(|w| w * w).sum::<f64>();
        let resample = k == 0 || ess < threshold * n as f64;
        let parents = (0..n)
            .map(|i| {
                if replays[i] || !resample {
                    i
                } else {
                    draw(&self.weights, rng)
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
        let mut record = StepRecord::default();
        let mut state_costs = Vec::with_capacity(outcomes.len());
        let mut totals = Vec::with_capacity(outcomes.len());
        let mut states = Vec::with_capacity(outcomes.len());
        for (outcome, &parent) in outcomes.into_iter().zip(&parents) {
            record.features.push(outcome.features);
            record.points.push(outcome.point);
            record.blowups += usize::from(outcome.blew_up);
            totals.push(self.totals[parent] + outcome.state_cost + outcome.control_cost);
            state_costs.push(outcome.state_cost);
            states.push(outcome.state);
            record.controls.push(outcome.control);
        }
        self.totals = totals;
        self.states = states;
        self.before_previous = parents.iter().map(|&p| self.previous[p].clone()).collect();
        self.previous = record.controls.clone();
        record.potentials = potentials(&state_costs);
        self.weights = parents
            .iter()
            .zip(&record.potentials)
            .map(|(&parent, &potential)| {
                if resampled {
                    potential
                } else {
                    self.weights[parent] * potential
                }
            })
            .collect();
        record.weights = self.weights.clone();
        record.parents = parents;
        record.resampled = resampled;
        record
    }
}

/// The particle that final particle `end` descends from at each step.
pub(super) fn ancestry(records: &[StepRecord], end: usize) -> Vec<usize> {
    let mut indices = vec![0; records.len()];
    let mut i = end;
    for (k, record) in records.iter().enumerate().rev() {
        indices[k] = i;
        i = record.parents[i];
    }
    indices
}

/// Each final particle's control sequence (K·D values) and trace points (empty when the
/// system has none), read along its ancestry.
pub(super) fn lineages(records: &[StepRecord]) -> (Vec<Vec<f64>>, Vec<Vec<[f64; 3]>>) {
    let count = records.last().map_or(0, |r| r.parents.len());
    (0..count)
        .map(|end| {
            let line = ancestry(records, end);
            let steps = records.iter().zip(&line);
            let sequence = steps
                .clone()
                .flat_map(|(record, &i)| record.controls[i].iter().copied())
                .collect();
            let path = steps.filter_map(|(record, &i)| record.points[i]).collect();
            (sequence, path)
        })
        .unzip()
}

/// The backward pass: β_K = 1/N, β_k(parent) = Σ over its children of ψ·β_{k+1}; the
/// smoothed belief of particle i at step k is its forward weight times β_k(i), so a
/// step's samples count by how well their whole future went, not only their past.
pub(super) fn smoothed_beliefs(records: &[StepRecord]) -> Vec<Vec<f64>> {
    let Some(n) = records.first().map(|r| r.weights.len()) else {
        return Vec::new();
    };
    let mut beliefs = vec![Vec::new(); records.len()];
    let mut backward = vec![1.0 / n as f64; n];
    for (k, record) in records.iter().enumerate().rev() {
        let mut smoothed: Vec<f64> = (0..n).map(|i| record.weights[i] * backward[i]).collect();
        normalise(&mut smoothed);
        beliefs[k] = smoothed;
        if k > 0 {
            let mut message = vec![0.0; n];
            for i in 0..n {
                message[record.parents[i]] += record.potentials[i] * backward[i];
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
            points: controls.iter().map(|&u| Some([u, 0.0, 0.0])).collect(),
            controls: controls.iter().map(|&u| vec![u]).collect(),
            parents,
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
