//! Advancing every particle one planning step: each restores its parent's state, takes a
//! control (replayed, drawn from the priors, or its system's own policy) and steps, the
//! particles split in runs over the rollout threads.

use rand::RngExt;
use rand_distr::StandardNormal;
use rand_pcg::Pcg64;
use rayon::prelude::*;

use super::super::frame::{Outcome, Particle, Particles};
use super::super::rollout::RolloutSystem;
use super::{CpbpPlanner, Guide};

impl CpbpPlanner {
    /// Every particle restores its parent's state, chooses a control, steps and saves,
    /// independently of the others: run them across the worker threads.
    pub(super) fn step_all<S: RolloutSystem>(
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
                .flat_map_iter(|(r, (systems, rngs))| {
                    let first = r * run;
                    self.step_run(systems, rngs, first, particles, parents, guides, k)
                })
                .collect()
        })
    }

    /// One thread's run of particles, from `first` on, stepped in one world that stays
    /// warm in the thread's cache (restoring each particle's parent state into it, as
    /// every step does anyway): with a world per particle, a thread stepping 64 particles
    /// visited 64 cold worlds a step, 12 % of a plan at N = 128 on two threads. A policy
    /// particle keeps its own system: its controller remembers between steps.
    #[allow(clippy::too_many_arguments)]
    fn step_run<S: RolloutSystem>(
        &self,
        systems: &mut [S],
        rngs: &mut [Pcg64],
        first: usize,
        particles: &Particles<S::State>,
        parents: &[usize],
        guides: &[Guide],
        k: usize,
    ) -> Vec<Outcome<S::State>> {
        let follows_policy = |j: usize| matches!(guides[first + j], Guide::Policy);
        let shared = (0..systems.len())
            .find(|&j| !follows_policy(j))
            .unwrap_or(0);
        (0..systems.len())
            .map(|j| {
                let system = &mut systems[if follows_policy(j) { j } else { shared }];
                let from = &particles.all[parents[first + j]];
                let parent = (&from.previous[..], &from.before_previous[..]);
                system.restore(&from.state);
                let guide = &guides[first + j];
                let control = self.choose_control(system, &mut rngs[j], parent, guide, k);
                self.simulate(system, from, control, parent, k)
            })
            .collect()
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
        from: &Particle<S::State>,
        control: Vec<f64>,
        (previous, before_previous): (&[f64], &[f64]),
        k: usize,
    ) -> Outcome<S::State> {
        let (mut state_cost, blew_up) = match system.step(&control, k) {
            Some(c) if c.is_finite() => (c, false),
            _ => {
                system.restore(&from.state);
                (self.config.blowup_cost, true)
            }
        };
        // A shortened horizon's last step is costed with the rest of the longer one.
        if k + 1 == self.config.steps.max(1) && !blew_up {
            if let Some(rest) = system.terminal_cost().filter(|c| c.is_finite()) {
                state_cost += rest;
            }
        }
        let value_features = if self.config.record_values_after.contains(&(k + 1)) && !blew_up {
            system.value_features()
        } else {
            Vec::new()
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
            fallen: from.fallen || (!blew_up && system.fallen()),
            after_fall: from.fallen,
            value_features,
        }
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
}

/// Product of two Gaussians (mean, σ): precision-weighted; an infinite σ adds nothing.
fn combine(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    if !b.1.is_finite() || !b.0.is_finite() {
        return a;
    }
    let (pa, pb) = (1.0 / (a.1 * a.1), 1.0 / (b.1 * b.1));
    ((a.0 * pa + b.0 * pb) / (pa + pb), (pa + pb).recip().sqrt())
}
