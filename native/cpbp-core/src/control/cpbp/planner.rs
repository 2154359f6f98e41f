//! One C-PBP planning step ("frame") over N particles and K planning steps.

use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;
use rand_pcg::Pcg64;
use rayon::prelude::*;

use super::priors::Priors;
use super::refinement::{refine, StepSamples};
use super::sequences::{lineages, shift_one_step};

/// A simulated system the planner can branch: one instance per particle, all built alike.
/// Instances are stepped on several threads at once, each by one thread at a time.
pub trait RolloutSystem: Send {
    /// Everything needed to put an instance back into a state (a world snapshot).
    type State: Clone + Send + Sync;
    fn save(&self) -> Self::State;
    fn restore(&mut self, state: &Self::State);
    /// Applies control `u` for planning step `step` and simulates it; returns the step's
    /// state cost (squared, tolerance-scaled), or `None` when the simulation blew up.
    fn step(&mut self, u: &[f64], step: usize) -> Option<f64>;
    /// A prior that depends on the current state (the thesis's pose prior): per dimension
    /// a mean and a standard deviation (infinite for dimensions it says nothing about).
    fn client_prior(&self) -> Option<(Vec<f64>, Vec<f64>)> {
        None
    }
    /// A few numbers describing the state, scaled to about unit size, that the local
    /// refinement regresses controls on. None (the default): no refinement.
    fn features(&self) -> Vec<f64> {
        Vec::new()
    }
    /// The control the system's own controller would choose now (for the combined mode's
    /// arcade controller), when it has one: particle 1 follows it live when the planner
    /// is configured with `policy_warm_start`.
    fn policy(&mut self, _step: usize) -> Option<Vec<f64>> {
        None
    }
    /// A point to draw the trajectory through (the bike's centre of mass), if any.
    fn trace_point(&self) -> Option<[f64; 3]> {
        None
    }
}

/// Sizes and tuning of the planner; defaults are the specification's.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannerConfig {
    /// N, the number of trajectories.
    pub particles: usize,
    /// K, the planning steps (horizon / step length).
    pub steps: usize,
    /// Share of particles that follow no previous sequence (explore from the priors).
    pub uniform_bias: f64,
    /// Resample when the effective sample size drops below this share of N.
    pub resample_threshold: f64,
    /// Cost given to a rollout whose simulation blew up.
    pub blowup_cost: f64,
    /// Seed of every random draw; the same seed and inputs give the same plan, whatever
    /// the number of threads.
    pub seed: u64,
    /// Worker threads for the rollouts (0: one per core).
    pub threads: usize,
    /// Compute the local refinement (Gaussian back-propagation) each frame; particle 1
    /// replays it next frame unless the caller supplies its own warm start.
    pub refine: bool,
    /// Particle 1 follows the system's policy (`RolloutSystem::policy`) step by step: the
    /// same trajectory as replaying that controller's rollout, without simulating it
    /// first on one thread while the others wait.
    pub policy_warm_start: bool,
    /// Ridge λ of the refinement's regression (absolute: features are unit-scaled).
    pub ridge: f64,
    /// Scale of the control (prior) cost in a trajectory's total. With many controlled
    /// dimensions and one costed state feature, the prior terms can outweigh the state
    /// cost that the choice of the best trajectory is about.
    pub control_cost_weight: f64,
}

impl Default for PlannerConfig {
    fn default() -> Self {
        Self {
            particles: 32,
            steps: 36,
            uniform_bias: 0.2,
            resample_threshold: 0.5,
            blowup_cost: 1e6,
            seed: 2015,
            threads: 0,
            refine: true,
            policy_warm_start: false,
            ridge: 1e-3,
            control_cost_weight: 1.0,
        }
    }
}

/// What a frame found.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanResult {
    /// The best trajectory's first control: apply it now.
    pub control: Vec<f64>,
    /// Total (state + control) cost of the best trajectory.
    pub best_cost: f64,
    /// Index of the best particle.
    pub best: usize,
    /// Each final particle's control sequence (K·D values) and total cost.
    pub sequences: Vec<Vec<f64>>,
    pub costs: Vec<f64>,
    /// How many of the K steps resampled.
    pub resamples: usize,
    /// Rollouts that blew up (restored and given `blowup_cost`).
    pub blowups: usize,
    /// The refined sequence (K·D values, within bounds), when the system has features.
    pub refined: Option<Vec<f64>>,
    /// Each final particle's belief (weights of next frame's choice of sequences).
    pub beliefs: Vec<f64>,
    /// Each final particle's trace points, one per step, when the system gives them.
    pub paths: Vec<Vec<[f64; 3]>>,
    /// Whether particle 1 replayed a warm start (the caller's or the refinement).
    pub warm_started: bool,
}

/// Carried from one frame to the next.
#[derive(Clone, Debug)]
struct Memory {
    sequences: Vec<Vec<f64>>,
    beliefs: Vec<f64>,
    best: Vec<f64>,
    refined: Option<Vec<f64>>,
}

/// The planner with its memory of the last frame.
pub struct Planner {
    pub config: PlannerConfig,
    pub priors: Priors,
    pool: rayon::ThreadPool,
    memory: Option<Memory>,
    applied: Vec<f64>,
    applied_before: Vec<f64>,
    frame: u64,
}

impl Planner {
    pub fn new(config: PlannerConfig, priors: Priors) -> Self {
        let rest = priors.mean.clone();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(config.threads)
            .thread_name(|i| format!("cpbp-rollout-{i}"))
            .build()
            .expect("the rollout threads could not start");
        Self {
            config,
            priors,
            pool,
            memory: None,
            applied: rest.clone(),
            applied_before: rest,
            frame: 0,
        }
    }

    /// Forgets the previous frames (after a reset or a teleport).
    pub fn reset(&mut self) {
        self.memory = None;
        self.applied = self.priors.mean.clone();
        self.applied_before = self.priors.mean.clone();
    }

    /// Tells the planner which control was really applied (when something else than its
    /// own result was), so the next frame's smoothness priors start from it.
    pub fn note_applied(&mut self, control: &[f64]) {
        self.applied_before = std::mem::replace(&mut self.applied, control.to_vec());
        self.applied_before.truncate(self.priors.dim());
    }

    /// Plans one frame from `start` with one system per particle (`systems.len()` ≥ N).
    /// `warm` is particle 1's sequence (the arcade rollout or a refinement), replayed as is.
    pub fn plan<S: RolloutSystem>(
        &mut self,
        systems: &mut [S],
        start: &S::State,
        warm: Option<&[f64]>,
    ) -> PlanResult {
        let n = self.config.particles.max(1).min(systems.len());
        let (k_steps, dim) = (self.config.steps.max(1), self.priors.dim());
        let mut resampler = Pcg64::seed_from_u64(mix(self.config.seed, self.frame, u64::MAX));
        let mut rngs: Vec<Pcg64> = (0..n)
            .map(|i| Pcg64::seed_from_u64(mix(self.config.seed, self.frame, i as u64)))
            .collect();
        self.frame += 1;

        let (guides, replays) = self.choose_guides(n, warm, &mut resampler);
        // Features feed only the refinement: skip them (a hot path) when it is off.
        let start_features = if self.config.refine {
            systems[0].restore(start);
            systems[0].features()
        } else {
            Vec::new()
        };
        let mut states: Vec<S::State> = vec![start.clone(); n];
        let mut weights = vec![1.0 / n as f64; n];
        let mut totals = vec![0.0; n];
        let mut previous: Vec<Vec<f64>> = vec![self.applied.clone(); n];
        let mut before_previous: Vec<Vec<f64>> = vec![self.applied_before.clone(); n];
        let mut parents_per_step = Vec::with_capacity(k_steps);
        let mut controls_per_step = Vec::with_capacity(k_steps);
        let mut features_per_step: Vec<Vec<Vec<f64>>> = Vec::with_capacity(k_steps);
        let mut potentials_per_step = Vec::with_capacity(k_steps);
        let mut weights_per_step = Vec::with_capacity(k_steps);
        let mut points_per_step: Vec<Vec<Option<[f64; 3]>>> = Vec::with_capacity(k_steps);
        let (mut resamples, mut blowups) = (0, 0);

        for k in 0..k_steps {
            normalise(&mut weights);
            let ess = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
            let resample = k == 0 || ess < self.config.resample_threshold * n as f64;
            resamples += usize::from(resample && k > 0);
            let parents: Vec<usize> = (0..n)
                .map(|i| {
                    if replays[i] || !resample {
                        i
                    } else {
                        draw(&weights, &mut resampler)
                    }
                })
                .collect();

            // Every particle restores its parent's state into its own world, samples, steps
            // and saves, independently of the others: run them across the worker threads.
            let (states_ref, previous_ref, before_ref, guides_ref) =
                (&states, &previous, &before_previous, &guides);
            let (parents_ref, replays_ref, this) = (&parents, &replays, &*self);
            let outcomes: Vec<Outcome<S::State>> = self.pool.install(|| {
                systems[..n]
                    .par_iter_mut()
                    .zip(rngs.par_iter_mut())
                    .enumerate()
                    .map(|(i, (system, rng))| {
                        let p = parents_ref[i];
                        let guide = guides_ref[i].as_ref().map(|g| &g[k * dim..(k + 1) * dim]);
                        this.rollout_step(
                            system,
                            rng,
                            &states_ref[p],
                            &previous_ref[p],
                            &before_ref[p],
                            guide,
                            replays_ref[i],
                            k,
                        )
                    })
                    .collect()
            });
            let mut new_states = Vec::with_capacity(n);
            let mut new_totals = Vec::with_capacity(n);
            let mut controls = Vec::with_capacity(n);
            let mut state_costs = Vec::with_capacity(n);
            let mut features = Vec::with_capacity(n);
            let mut points = Vec::with_capacity(n);
            for (i, outcome) in outcomes.into_iter().enumerate() {
                features.push(outcome.features);
                points.push(outcome.point);
                blowups += usize::from(outcome.blew_up);
                new_totals.push(totals[parents[i]] + outcome.state_cost + outcome.control_cost);
                state_costs.push(outcome.state_cost);
                new_states.push(outcome.state);
                controls.push(outcome.control);
            }
            // Every new value above was computed from the parents' old ones; replace them
            // only now, all at once, so no particle reads a sibling's new state.
            totals = new_totals;
            before_previous = parents.iter().map(|&p| previous[p].clone()).collect();
            previous = controls.clone();
            let potentials = potentials(&state_costs);
            let old_weights = weights.clone();
            for i in 0..n {
                weights[i] = if resample {
                    potentials[i]
                } else {
                    old_weights[parents[i]] * potentials[i]
                };
            }
            states = new_states;
            parents_per_step.push(parents);
            controls_per_step.push(controls);
            features_per_step.push(features);
            points_per_step.push(points);
            potentials_per_step.push(potentials);
            weights_per_step.push(weights.clone());
        }

        normalise(&mut weights);
        let sequences = lineages(&parents_per_step, &controls_per_step);
        let best = (0..n)
            .min_by(|a, b| totals[*a].total_cmp(&totals[*b]))
            .unwrap_or(0);
        let control = sequences[best][..dim].to_vec();
        let refined = if self.config.refine {
            let smoothed =
                smoothed_beliefs(&weights_per_step, &potentials_per_step, &parents_per_step);
            let steps: Vec<StepSamples> = (0..k_steps)
                .map(|k| StepSamples {
                    before: parents_per_step[k]
                        .iter()
                        .map(|&p| {
                            if k == 0 {
                                start_features.as_slice()
                            } else {
                                features_per_step[k - 1][p].as_slice()
                            }
                        })
                        .collect(),
                    controls: &controls_per_step[k],
                    after: &features_per_step[k],
                    weights: &smoothed[k],
                })
                .collect();
            refine(&steps, &weights, &self.priors, self.config.ridge)
        } else {
            None
        };
        self.remember(&sequences, &weights, best, refined.clone(), dim);
        self.note_applied(&control);
        PlanResult {
            control,
            best_cost: totals[best],
            best,
            sequences,
            costs: totals,
            resamples,
            blowups,
            refined,
            beliefs: weights,
            paths: trace_paths(&parents_per_step, &points_per_step),
            warm_started: replays.get(1).copied().unwrap_or(false),
        }
    }

    /// One particle's step: restore the parent's state, choose a control, simulate.
    #[allow(clippy::too_many_arguments)]
    fn rollout_step<S: RolloutSystem>(
        &self,
        system: &mut S,
        rng: &mut Pcg64,
        parent_state: &S::State,
        previous: &[f64],
        before_previous: &[f64],
        guide: Option<&[f64]>,
        replay: bool,
        k: usize,
    ) -> Outcome<S::State> {
        system.restore(parent_state);
        let control = if replay {
            let mut u = match guide {
                Some(sequence) => sequence.to_vec(),
                None => system.policy(k).unwrap_or_else(|| self.priors.mean.clone()),
            };
            self.priors.clamp(&mut u);
            u
        } else {
            self.sample(previous, before_previous, guide, system.client_prior(), rng)
        };
        let (state_cost, blew_up) = match system.step(&control, k) {
            Some(c) if c.is_finite() => (c, false),
            _ => {
                system.restore(parent_state);
                (self.config.blowup_cost, true)
            }
        };
        Outcome {
            control_cost: self.config.control_cost_weight
                * self.priors.cost(&control, previous, before_previous),
            features: if self.config.refine {
                system.features()
            } else {
                Vec::new()
            },
            point: system.trace_point(),
            state: system.save(),
            control,
            state_cost,
            blew_up,
        }
    }

    /// Which previous sequence each particle follows (shifted one step), and which
    /// particles replay theirs exactly: particle 0 the last best, particle 1 `warm` or,
    /// without one, the last refinement.
    fn choose_guides(
        &self,
        n: usize,
        warm: Option<&[f64]>,
        rng: &mut Pcg64,
    ) -> (Vec<Option<Vec<f64>>>, Vec<bool>) {
        let mut guides = vec![None; n];
        let mut replays = vec![false; n];
        if let Some(memory) = &self.memory {
            guides[0] = Some(memory.best.clone());
            replays[0] = true;
            for guide in guides.iter_mut().skip(2) {
                if rng.random::<f64>() >= self.config.uniform_bias {
                    *guide = Some(memory.sequences[draw(&memory.beliefs, rng)].clone());
                }
            }
        }
        let refined = self.memory.as_ref().and_then(|m| m.refined.as_deref());
        if self.config.policy_warm_start && n > 1 {
            guides[1] = None;
            replays[1] = true;
        } else if let Some(sequence) = warm.or(refined).filter(|_| n > 1) {
            let expected = self.config.steps.max(1) * self.priors.dim();
            if sequence.len() == expected {
                guides[1] = Some(sequence.to_vec());
                replays[1] = true;
            }
        }
        (guides, replays)
    }

    /// A control drawn from the product of the priors (and the system's own prior, if it
    /// has one), clamped to the bounds.
    fn sample(
        &self,
        previous: &[f64],
        before_previous: &[f64],
        guide: Option<&[f64]>,
        client: Option<(Vec<f64>, Vec<f64>)>,
        rng: &mut Pcg64,
    ) -> Vec<f64> {
        let mut u: Vec<f64> = (0..self.priors.dim())
            .map(|d| {
                let guided = guide.map(|g| g[d]);
                let mut prior = self
                    .priors
                    .product(d, previous[d], before_previous[d], guided);
                if let Some((client_mean, client_sigma)) = &client {
                    prior = combine(prior, (client_mean[d], client_sigma[d]));
                }
                prior.0 + prior.1 * rng.sample::<f64, _>(StandardNormal)
            })
            .collect();
        self.priors.clamp(&mut u);
        u
    }

    /// Keeps this frame's sequences, shifted one step, for the next frame.
    fn remember(
        &mut self,
        sequences: &[Vec<f64>],
        beliefs: &[f64],
        best: usize,
        mut refined: Option<Vec<f64>>,
        dim: usize,
    ) {
        let mut shifted: Vec<Vec<f64>> = sequences.to_vec();
        for sequence in shifted.iter_mut().chain(refined.iter_mut()) {
            shift_one_step(sequence, dim);
        }
        self.memory = Some(Memory {
            refined,
            best: shifted[best].clone(),
            sequences: shifted,
            beliefs: beliefs.to_vec(),
        });
    }
}

/// What one particle's step produced.
struct Outcome<State> {
    state: State,
    features: Vec<f64>,
    point: Option<[f64; 3]>,
    control: Vec<f64>,
    state_cost: f64,
    control_cost: f64,
    blew_up: bool,
}

/// Each final particle's trace points, step by step, found by following its parents back;
/// empty when the system has none.
fn trace_paths(parents: &[Vec<usize>], points: &[Vec<Option<[f64; 3]>>]) -> Vec<Vec<[f64; 3]>> {
    let Some(last) = points.last() else {
        return Vec::new();
    };
    (0..last.len())
        .map(|end| {
            let mut path = Vec::with_capacity(points.len());
            let mut i = end;
            for k in (0..points.len()).rev() {
                if let Some(p) = points[k][i] {
                    path.push(p);
                }
                i = parents[k][i];
            }
            path.reverse();
            path
        })
        .collect()
}

/// The backward pass: β_K = 1/N, β_k(parent) = Σ over its children of ψ·β_{k+1}; the
/// smoothed belief of particle i at step k is its forward weight times β_k(i), so a
/// step's samples count by how well their whole future went, not only their past.
fn smoothed_beliefs(
    forward: &[Vec<f64>],
    potentials: &[Vec<f64>],
    parents: &[Vec<usize>],
) -> Vec<Vec<f64>> {
    let steps = forward.len();
    let Some(n) = forward.first().map(Vec::len) else {
        return Vec::new();
    };
    let mut beliefs = vec![Vec::new(); steps];
    let mut backward = vec![1.0 / n as f64; n];
    for k in (0..steps).rev() {
        let mut smoothed: Vec<f64> = (0..n).map(|i| forward[k][i] * backward[i]).collect();
        normalise(&mut smoothed);
        beliefs[k] = smoothed;
        if k > 0 {
            let mut message = vec![0.0; n];
            for i in 0..n {
                message[parents[k][i]] += potentials[k][i] * backward[i];
            }
            normalise(&mut message);
            backward = message;
        }
    }
    beliefs
}

/// Product of two Gaussians (mean, σ): precision-weighted; an infinite σ adds nothing.
fn combine(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    if !b.1.is_finite() || !b.0.is_finite() {
        return a;
    }
    let (pa, pb) = (1.0 / (a.1 * a.1), 1.0 / (b.1 * b.1));
    ((a.0 * pa + b.0 * pb) / (pa + pb), (pa + pb).recip().sqrt())
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
fn normalise(weights: &mut [f64]) {
    let sum: f64 = weights.iter().sum();
    if sum.is_finite() && sum > 0.0 && weights.iter().all(|w| w.is_finite() && *w >= 0.0) {
        weights.iter_mut().for_each(|w| *w /= sum);
    } else {
        let uniform = 1.0 / weights.len() as f64;
        weights.iter_mut().for_each(|w| *w = uniform);
    }
}

/// An index drawn with probability proportional to `weights`.
fn draw(weights: &[f64], rng: &mut Pcg64) -> usize {
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
fn mix(seed: u64, frame: u64, stream: u64) -> u64 {
    let mut z = seed
        ^ frame.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ stream.wrapping_mul(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
