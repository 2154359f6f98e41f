//! One C-PBP planning step ("frame") over N particles and K planning steps, in three
//! phases: choose what each particle follows, advance all particles step by step (each
//! step leaves a record), and read the plan back from the records.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

use std::sync::Arc;
use std::time::{Duration, Instant};

use super::config::{CpbpConfig, FrameResult, WarmStart};
use super::frame::{draw, lineages, mix, smoothed_beliefs, value_samples};
use super::frame::{Particles, StepRecord};
use super::priors::{AppliedControls, Priors};
use super::refinement::{refine, StepSamples};
use super::rollout::RolloutSystem;
use super::sequences::shift_one_step;
use crate::control::PlanPhases;

mod stepping;

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
pub struct CpbpPlanner {
    pub config: CpbpConfig,
    pub priors: Priors,
    pool: Arc<rayon::ThreadPool>,
    memory: Option<Memory>,
    applied: AppliedControls,
    frame: u64,
    /// Where the last frame's time went.
    pub phases: PlanPhases,
}

impl CpbpPlanner {
    pub fn new(config: CpbpConfig, priors: Priors) -> Self {
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
    ) -> FrameResult {
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
    ) -> FrameResult {
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

    /// Reads the plan back from the step records: each final particle's sequence and path
    /// along its ancestry, the cheapest, and the refinement; remembers them for next frame.
    fn conclude<State>(
        &mut self,
        records: Vec<StepRecord>,
        mut particles: Particles<State>,
        start_features: &[f64],
        warm_started: bool,
    ) -> FrameResult {
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
        let disagreement = self
            .priors
            .disagreement(sequences.iter().map(|s| &s[..dim]));
        self.remember(&sequences, &end_weights, best, refined.clone(), dim);
        self.note_applied(&control);
        FrameResult {
            control,
            best_cost: totals[best],
            best,
            chosen: sequences[best].clone(),
            sequences,
            costs: totals,
            resamples: records.iter().skip(1).filter(|r| r.resampled).count(),
            blowups: records.iter().map(|r| r.blowups).sum(),
            fallen_steps: records.iter().map(|r| r.after_falls).sum::<usize>() as f64
                / records
                    .iter()
                    .map(|r| r.particles.len())
                    .sum::<usize>()
                    .max(1) as f64,
            disagreement,
            refined,
            beliefs: end_weights,
            paths,
            warm_started,
            value_samples: if self.config.record_values_after.is_empty() {
                Vec::new()
            } else {
                value_samples(&records)
            },
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

/// The worker threads a planner rolls out on (`threads` = 0: one per core), named
/// `{planner}-rollout-i` in profilers and debuggers.
pub(crate) fn rollout_pool(threads: usize, planner: &'static str) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(move |i| format!("{planner}-rollout-{i}"))
        .build()
        .expect("the rollout threads could not start")
}
