//! One C-PBP planning step ("frame") over N particles and K planning steps, in three
//! phases: choose what each particle follows, advance all particles step by step (each
//! step leaves a record), and read the plan back from the records.

use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;
use rand_pcg::Pcg64;
use rayon::prelude::*;

use std::sync::Arc;
use std::time::{Duration, Instant};

use super::config::{PlanPhases, PlanResult, PlannerConfig, WarmStart};
use super::frame::{draw, lineages, mix, smoothed_beliefs};
use super::frame::{Outcome, Particles, StepRecord};
use super::priors::{AppliedControls, Priors};
use super::refinement::{refine, StepSamples};
use super::rollout::RolloutSystem;
use super::sequences::shift_one_step;

/// Carried from one frame to the next.
#[derive(Clone, Debug)]
struct Memory {
    sequences: Vec<Vec<f64>>,
    beliefs: Vec<f64>,
    best: Vec<f64>,
    refined: Option<Vec<f64>>,
}

/// What a particle does for its controls during a frame.
#[derive(Clone, Debug, PartialEq)]
enum Guide {
    /// Samples from the priors alone (the uniform-bias share).
    Explore,
    /// Samples around a previous sequence (shifted one step).
    Follow(Vec<f64>),
    /// Applies a sequence exactly: particle 0 the last best, particle 1 a warm start.
    Replay(Vec<f64>),
    /// Applies the system's own controller step by step.
    Policy,
}

impl Guide {
    fn replays(&self) -> bool {
        matches!(self, Self::Replay(_) | Self::Policy)
    }
}

/// The planner with its memory of the last frame.
pub struct Planner {
    pub config: PlannerConfig,
    pub priors: Priors,
    pool: Arc<rayon::ThreadPool>,
    memory: Option<Memory>,
    applied: AppliedControls,
    frame: u64,
    /// Where the last frame's time went.
    pub phases: PlanPhases,
}

impl Planner {
    pub fn new(config: PlannerConfig, priors: Priors) -> Self {
        Self {
            applied: AppliedControls::at_rest(&priors.mean),
            pool: Arc::new(rollout_pool(config.threads, "cpbp")),
            config,
            priors,
            memory: None,
            frame: 0,
            phases: PlanPhases::default(),
        }
    }

    /// Forgets the previous frames (after a reset or a teleport).
    pub fn reset(&mut self) {
        self.memory = None;
        self.applied = AppliedControls::at_rest(&self.priors.mean);
    }

    /// Tells the planner which control was really applied (when something else than its
    /// own result was), so the next frame's smoothness priors start from it.
    pub fn note_applied(&mut self, control: &[f64]) {
        self.applied.note(control);
    }

    /// Plans one frame from `start` with one system per particle (`systems.len()` ≥ N);
    /// `warm` says what particle 1 replays.
    pub fn plan<S: RolloutSystem>(
        &mut self,
        systems: &mut [S],
        start: &S::State,
        warm: WarmStart<'_>,
    ) -> PlanResult {
        // The whole frame runs on the rollout threads: handing each of its K steps from the
        // caller's thread to the pool and back put the kernel's scheduler in every step.
        let pool = Arc::clone(&self.pool);
        pool.install(|| self.plan_on_pool(systems, start, warm))
    }

    fn plan_on_pool<S: RolloutSystem>(
        &mut self,
        systems: &mut [S],
        start: &S::State,
        warm: WarmStart<'_>,
    ) -> PlanResult {
        let started = Instant::now();
        let mut rolling_out = Duration::ZERO;
        let n = self.config.particles.max(1).min(systems.len());
        let mut resampler = Pcg64::seed_from_u64(mix(self.config.seed, self.frame, u64::MAX));
        let mut rngs: Vec<Pcg64> = (0..n)
            .map(|i| Pcg64::seed_from_u64(mix(self.config.seed, self.frame, i as u64)))
            .collect();
        self.frame += 1;

        let guides = self.choose_guides(n, warm, &mut resampler);
        let replays: Vec<bool> = guides.iter().map(Guide::replays).collect();
        // Features feed only the refinement: skip them (a hot path) when it is off.
        let start_features = if self.config.refine {
            systems[0].restore(start);
            systems[0].features()
        } else {
            Vec::new()
        };
        let mut particles = Particles::start(start, n, &self.applied.last, &self.applied.before);
        let records: Vec<StepRecord> = (0..self.config.steps.max(1))
            .map(|k| {
                let threshold = self.config.resample_threshold;
                let (parents, resampled) =
                    particles.choose_parents(k, threshold, &replays, &mut resampler);
                let stepping = Instant::now();
                let outcomes = self.step_all(systems, &particles, &parents, &guides, &mut rngs, k);
                rolling_out += stepping.elapsed();
                particles.advance(parents, resampled, outcomes)
            })
            .collect();
        let concluding = Instant::now();
        let warm_started = replays.get(1) == Some(&true);
        let result = self.conclude(records, particles, &start_features, warm_started);
        self.phases = PlanPhases::measured(started, rolling_out, concluding);
        result
    }

    /// Every particle restores its parent's state into its own world, chooses a control,
    /// steps and saves, independently of the others: run them across the worker threads.
    fn step_all<S: RolloutSystem>(
        &self,
        systems: &mut [S],
        particles: &Particles<S::State>,
        parents: &[usize],
        guides: &[Guide],
        rngs: &mut [Pcg64],
        k: usize,
    ) -> Vec<Outcome<S::State>> {
        let n = parents.len();
        // One run of particles per thread, the calling thread taking the first: it starts
        // at once while the others wake, and it carries the largest share when N does not
        // divide evenly, so waking never adds to the step's critical path.
        let run = n.div_ceil(self.pool.current_num_threads().max(1));
        self.pool.install(|| {
            systems[..n]
                .par_chunks_mut(run)
                .zip(rngs[..n].par_chunks_mut(run))
                .enumerate()
                .flat_map_iter(|(c, (systems, rngs))| {
                    (c * run..).zip(systems.iter_mut().zip(rngs.iter_mut()))
                })
                .map(|(i, (system, rng))| {
                    let from = &particles.all[parents[i]];
                    let parent = (&from.previous[..], &from.before_previous[..]);
                    system.restore(&from.state);
                    let control = self.choose_control(system, rng, parent, &guides[i], k);
                    self.simulate(system, &from.state, control, parent, k)
                })
                .collect()
        })
    }

    /// A particle's control at step `k`: replayed exactly, or sampled around what it
    /// follows.
    fn choose_control<S: RolloutSystem>(
        &self,
        system: &mut S,
        rng: &mut Pcg64,
        (previous, before_previous): (&[f64], &[f64]),
        guide: &Guide,
        k: usize,
    ) -> Vec<f64> {
        let dim = self.priors.dim();
        let at_step = |sequence: &[f64]| sequence[k * dim..(k + 1) * dim].to_vec();
        let mut u = match guide {
            Guide::Replay(sequence) => at_step(sequence),
            Guide::Policy => system.policy(k).unwrap_or_else(|| self.priors.mean.clone()),
            Guide::Follow(sequence) => {
                let followed = at_step(sequence);
                let client = system.client_prior();
                return self.sample(previous, before_previous, Some(&followed), client, rng);
            }
            Guide::Explore => {
                let client = system.client_prior();
                return self.sample(previous, before_previous, None, client, rng);
            }
        };
        self.priors.clamp(&mut u);
        u
    }

    /// Applies `control` at step `k` and simulates; a blow-up restores the parent's state
    /// and costs `blowup_cost`.
    fn simulate<S: RolloutSystem>(
        &self,
        system: &mut S,
        parent_state: &S::State,
        control: Vec<f64>,
        (previous, before_previous): (&[f64], &[f64]),
        k: usize,
    ) -> Outcome<S::State> {
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

    /// Reads the plan back from the step records: each final particle's sequence and path
    /// along its ancestry, the cheapest, and the refinement; remembers them for next frame.
    fn conclude<State>(
        &mut self,
        records: Vec<StepRecord>,
        mut particles: Particles<State>,
        start_features: &[f64],
        warm_started: bool,
    ) -> PlanResult {
        let dim = self.priors.dim();
        let (sequences, paths) = lineages(&records);
        let end_weights = particles.normalise_weights();
        let totals: Vec<f64> = particles.all.iter().map(|p| p.total).collect();
        let best = (0..totals.len())
            .min_by(|a, b| totals[*a].total_cmp(&totals[*b]))
            .unwrap_or(0);
        let control = sequences[best][..dim].to_vec();
        let refined = if self.config.refine {
            self.refinement(&records, &end_weights, start_features)
        } else {
            None
        };
        self.remember(&sequences, &end_weights, best, refined.clone(), dim);
        self.note_applied(&control);
        PlanResult {
            control,
            best_cost: totals[best],
            best,
            chosen: sequences[best].clone(),
            sequences,
            costs: totals,
            resamples: records.iter().skip(1).filter(|r| r.resampled).count(),
            blowups: records.iter().map(|r| r.blowups).sum(),
            refined,
            beliefs: end_weights,
            paths,
            warm_started,
        }
    }

    /// The local refinement over this frame's samples, weighted by the smoothed beliefs.
    fn refinement(
        &self,
        records: &[StepRecord],
        end_weights: &[f64],
        start_features: &[f64],
    ) -> Option<Vec<f64>> {
        let smoothed = smoothed_beliefs(records);
        let steps: Vec<StepSamples> = records
            .iter()
            .enumerate()
            .map(|(k, record)| StepSamples {
                before: record
                    .particles
                    .iter()
                    .map(|step| match k {
                        0 => start_features,
                        _ => records[k - 1].particles[step.parent].features.as_slice(),
                    })
                    .collect(),
                controls: record
                    .particles
                    .iter()
                    .map(|s| s.control.as_slice())
                    .collect(),
                after: record
                    .particles
                    .iter()
                    .map(|s| s.features.as_slice())
                    .collect(),
                weights: &smoothed[k],
            })
            .collect();
        refine(&steps, end_weights, &self.priors, self.config.ridge)
    }

    /// What each particle follows this frame (a previous sequence, shifted one step, or
    /// nothing), and what particles 0 (the last best) and 1 (the warm start) replay.
    fn choose_guides(&self, n: usize, warm: WarmStart<'_>, rng: &mut Pcg64) -> Vec<Guide> {
        let mut guides = vec![Guide::Explore; n];
        if let Some(memory) = &self.memory {
            guides[0] = Guide::Replay(memory.best.clone());
            for guide in guides.iter_mut().skip(2) {
                if rng.random::<f64>() >= self.config.uniform_bias {
                    *guide = Guide::Follow(memory.sequences[draw(&memory.beliefs, rng)].clone());
                }
            }
        }
        let expected = self.config.steps.max(1) * self.priors.dim();
        let refined = self.memory.as_ref().and_then(|m| m.refined.as_deref());
        let sequence = match warm {
            WarmStart::Sequence(sequence) => Some(sequence),
            WarmStart::Refinement => refined,
            WarmStart::Nothing | WarmStart::Policy => None,
        };
        if n > 1 && warm == WarmStart::Policy {
            guides[1] = Guide::Policy;
        } else if let Some(sequence) = sequence.filter(|s| n > 1 && s.len() == expected) {
            guides[1] = Guide::Replay(sequence.to_vec());
        }
        guides
    }

    /// A control drawn from the product of the priors (and the system's own prior, if it
    /// has one), clamped to the bounds.
    fn sample(
        &self,
        previous: &[f64],
        before_previous: &[f64],
        followed: Option<&[f64]>,
        client: Option<(Vec<f64>, Vec<f64>)>,
        rng: &mut Pcg64,
    ) -> Vec<f64> {
        let mut u: Vec<f64> = (0..self.priors.dim())
            .map(|d| {
                let guided = followed.map(|g| g[d]);
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

/// Product of two Gaussians (mean, σ): precision-weighted; an infinite σ adds nothing.
fn combine(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    if !b.1.is_finite() || !b.0.is_finite() {
        return a;
    }
    let (pa, pb) = (1.0 / (a.1 * a.1), 1.0 / (b.1 * b.1));
    ((a.0 * pa + b.0 * pb) / (pa + pb), (pa + pb).recip().sqrt())
}

/// The worker threads a planner rolls out on (`threads` = 0: one per core), named
/// `{planner}-rollout-i` in profilers and debuggers.
pub(crate) fn rollout_pool(threads: usize, planner: &'static str) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(move |i| format!("{planner}-rollout-{i}"))
        .build()
        .expect("the rollout threads could not start")
}
