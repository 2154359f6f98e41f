//! The sampling planners the field uses as baselines, over the same rollout systems, cost
//! and priors as C-PBP: a nominal plan (knots, see [`Knots`]) and N − 1 Gaussian
//! perturbations of it, every candidate rolled out from the start state; then either the
//! cheapest candidate becomes the nominal (predictive sampling, Howell et al. 2022) or the
//! cost-weighted average does (MPPI, Williams et al. 2017).

use std::time::Instant;

use rand::SeedableRng;
use rand_distr::StandardNormal;
use rand_pcg::Pcg64;
use rayon::prelude::*;

use super::spline::Knots;
use super::{BASELINE_KNOTS, BASELINE_NOISE};
use crate::control::cpbp::{
    mix, rollout_pool, AppliedControls, Priors, RolloutSystem, DEFAULT_SEED,
};
use crate::control::{Diagnostics, PlanPhases, PlanResult, Trajectory};

/// How a frame's candidates make the next nominal plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SamplingUpdate {
    /// Predictive sampling: the cheapest candidate.
    Best,
    /// MPPI: candidates weighted by exp(−(J − J_min)/λ), λ = `temperature` times the
    /// spread between the median and the cheapest total, so one setting fits costs of
    /// any scale.
    Weighted { temperature: f64 },
}

#[derive(Clone, Debug, PartialEq)]
pub struct SamplingConfig {
    /// N: the nominal plan and N − 1 perturbations of it.
    pub samples: usize,
    /// K: planning steps in the horizon.
    pub steps: usize,
    /// Knots of a plan over the horizon (at least 2).
    pub knots: usize,
    /// A knot's perturbation σ, as a share of the priors' static σ of its dimension.
    pub noise: f64,
    pub update: SamplingUpdate,
    /// Dimensions the planner samples; the others take the system's own prior mean each
    /// step (the bike's pose PD), or the static mean without one. `None`: every planned
    /// dimension of the priors.
    pub sampled: Option<Vec<bool>>,
    /// Cost of a rollout whose simulation blew up (it stops there).
    pub blowup_cost: f64,
    /// Scale of the priors' control cost in a total, as C-PBP's: the same task.
    pub control_cost_weight: f64,
    pub seed: u64,
    /// Worker threads for the rollouts (0: one per core).
    pub threads: usize,
}

/// The diagnostics' names (`SamplingPlanner::diagnostics`).
pub const IMPROVEMENT: &str = "improvement";
pub const EFFECTIVE_SAMPLES: &str = "effective samples";

impl Default for SamplingConfig {
    /// The knots and the noise are the schema's (`BASELINE_KNOTS`, `BASELINE_NOISE`),
    /// which the game and the tools set.
    fn default() -> Self {
        Self {
            samples: 16,
            steps: 36,
            knots: BASELINE_KNOTS.default_number() as usize,
            noise: BASELINE_NOISE.default_number(),
            update: SamplingUpdate::Best,
            sampled: None,
            blowup_cost: 1e6,
            control_cost_weight: 1.0,
            seed: DEFAULT_SEED,
            threads: 0,
        }
    }
}

/// One candidate's rollout, as a record.
struct Rollout {
    /// K·D controls applied (after the pose PD and the bounds).
    controls: Vec<f64>,
    /// One trace point per step, when the system gives them.
    path: Vec<[f64; 3]>,
    total: f64,
    blew_up: bool,
}

/// Predictive sampling or MPPI with its nominal plan between frames.
pub struct SamplingPlanner {
    pub config: SamplingConfig,
    pub priors: Priors,
    pool: rayon::ThreadPool,
    nominal: Option<Knots>,
    applied: AppliedControls,
    frame: u64,
    /// Where the last frame's time went.
    pub phases: PlanPhases,
    /// Each candidate's weight in the last frame's update (MPPI's; the best's alone is 1
    /// for predictive sampling).
    pub weights: Vec<f64>,
}

impl SamplingPlanner {
    pub fn new(config: SamplingConfig, priors: Priors) -> Self {
        Self {
            applied: AppliedControls::at_rest(&priors.mean),
            pool: rollout_pool(config.threads, "sampling"),
            config,
            priors,
            nominal: None,
            frame: 0,
            phases: PlanPhases::default(),
            weights: Vec::new(),
        }
    }

    /// Forgets the nominal plan (after a reset or a teleport).
    pub fn reset(&mut self) {
        self.nominal = None;
        self.applied = AppliedControls::at_rest(&self.priors.mean);
    }

    /// The control really applied, for the smoothness terms of the next frame's cost.
    pub fn note_applied(&mut self, control: &[f64]) {
        self.applied.note(control);
    }

    fn sampled(&self, d: usize) -> bool {
        self.priors.planned[d] && self.config.sampled.as_ref().is_none_or(|s| s[d])
    }

    /// Plans one frame from `start` with one system per candidate (`systems.len()` ≥ N).
    pub fn plan<S: RolloutSystem>(&mut self, systems: &mut [S], start: &S::State) -> PlanResult {
        let started = Instant::now();
        let n = self.config.samples.max(1).min(systems.len());
        let steps = self.config.steps.max(1);
        let nominal = self
            .nominal
            .take()
            .unwrap_or_else(|| Knots::constant(&self.priors.mean, self.config.knots, steps));
        let candidates: Vec<Knots> = (0..n).map(|i| self.candidate(&nominal, i)).collect();
        self.frame += 1;
        let rolling_out = Instant::now();
        let rollouts: Vec<Rollout> = self.pool.install(|| {
            systems[..n]
                .par_iter_mut()
                .zip(&candidates)
                .map(|(system, knots)| self.roll_out(system, start, knots))
                .collect()
        });
        let rolled_out = rolling_out.elapsed();
        let concluding = Instant::now();
        let totals: Vec<f64> = rollouts.iter().map(|r| r.total).collect();
        let best = (0..n)
            .min_by(|a, b| totals[*a].total_cmp(&totals[*b]))
            .unwrap_or(0);
        let weights = self.weights(&rollouts, best);
        let (next, chosen) = match self.config.update {
            SamplingUpdate::Best => (candidates[best].clone(), rollouts[best].controls.clone()),
            SamplingUpdate::Weighted { .. } => {
                let all: Vec<&Knots> = candidates.iter().collect();
                let mut chosen = vec![0.0; rollouts[0].controls.len()];
                for (rollout, &w) in rollouts.iter().zip(&weights) {
                    for (c, u) in chosen.iter_mut().zip(&rollout.controls) {
                        *c += w * u;
                    }
                }
                (Knots::weighted_sum(&all, &weights), chosen)
            }
        };
        self.nominal = Some(next.shifted_one_step());
        let control = chosen[..self.priors.dim()].to_vec();
        self.note_applied(&control);
        self.phases = PlanPhases::measured(started, rolled_out, concluding);
        self.weights = weights;
        let diagnostics = self.diagnostics(&totals, best);
        let blowups = rollouts.iter().filter(|r| r.blew_up).count();
        let trajectories = rollouts
            .into_iter()
            .zip(&totals)
            .map(|(r, &cost)| Trajectory {
                controls: r.controls,
                cost,
                path: r.path,
            })
            .collect();
        PlanResult {
            control,
            chosen,
            best,
            best_cost: totals[best],
            trajectories,
            blowups,
            warm: None,
            diagnostics,
            value_samples: Vec::new(),
        }
    }

    /// What the HUD and the bench show of a plan: how much the best sample bettered the
    /// nominal plan (cost units; 0 when the nominal stayed the best), and for MPPI the
    /// weights' effective sample size, 1/Σw² (1: one sample carried the update; N: all
    /// of them alike, the temperature too high to tell them apart).
    fn diagnostics(&self, totals: &[f64], best: usize) -> Diagnostics {
        let mut named = vec![(IMPROVEMENT, totals[0] - totals[best])];
        if let SamplingUpdate::Weighted { .. } = self.config.update {
            let squares: f64 = self.weights.iter().map(|w| w * w).sum();
            named.push((EFFECTIVE_SAMPLES, 1.0 / squares));
        }
        Diagnostics(named)
    }

    /// Candidate `i`: the nominal itself (i = 0), or the nominal with Gaussian noise on
    /// every sampled dimension of every knot, within the bounds.
    fn candidate(&self, nominal: &Knots, i: usize) -> Knots {
        let mut knots = nominal.clone();
        if i == 0 {
            return knots;
        }
        let mut rng = Pcg64::seed_from_u64(mix(self.config.seed, self.frame, i as u64));
        for j in 0..knots.count() {
            let knot = knots.knot_mut(j);
            for (d, value) in knot.iter_mut().enumerate() {
                if self.sampled(d) {
                    let z: f64 = rand::RngExt::sample(&mut rng, StandardNormal);
                    *value += self.config.noise * self.priors.sigma_static[d] * z;
                }
            }
            self.priors.clamp(knot);
        }
        knots
    }

    /// Rolls one candidate out from `start`: its plan on the sampled dimensions, the
    /// system's own prior mean on the others, costed as C-PBP costs a trajectory.
    fn roll_out<S: RolloutSystem>(
        &self,
        system: &mut S,
        start: &S::State,
        knots: &Knots,
    ) -> Rollout {
        let (dim, steps) = (self.priors.dim(), self.config.steps.max(1));
        system.restore(start);
        let (mut previous, mut before) = (self.applied.last.clone(), self.applied.before.clone());
        let mut rollout = Rollout {
            controls: Vec::with_capacity(steps * dim),
            path: Vec::with_capacity(steps),
            total: 0.0,
            blew_up: false,
        };
        let mut u = vec![0.0; dim];
        for k in 0..steps {
            knots.at(k as f64, &mut u);
            if !rollout.blew_up {
                self.follow_system(system, &mut u);
            }
            self.priors.clamp(&mut u);
            if !rollout.blew_up {
                match system.step(&u, k) {
                    Some(cost) if cost.is_finite() => {
                        let control = self.priors.cost(&u, &previous, &before);
                        rollout.total += cost + self.config.control_cost_weight * control;
                    }
                    _ => {
                        // Stop here; the system goes back to a sane state, the path
                        // stays where the rollout last was.
                        rollout.blew_up = true;
                        rollout.total += self.config.blowup_cost;
                        system.restore(start);
                    }
                }
            }
            let point = match rollout.blew_up {
                false => system.trace_point(),
                true => rollout.path.last().copied(),
            };
            rollout.path.extend(point);
            rollout.controls.extend_from_slice(&u);
            before = std::mem::replace(&mut previous, u.clone());
        }
        // A shortened horizon is costed with the rest of the longer one, as C-PBP's.
        if !rollout.blew_up {
            if let Some(rest) = system.terminal_cost().filter(|c| c.is_finite()) {
                rollout.total += rest;
            }
        }
        rollout
    }

    /// The dimensions this planner does not sample take the system's prior mean (the
    /// pose PD), where it says something.
    fn follow_system<S: RolloutSystem>(&self, system: &S, u: &mut [f64]) {
        let Some((mean, sigma)) = system.client_prior() else {
            return;
        };
        for d in (0..u.len()).filter(|&d| !self.sampled(d)) {
            if sigma[d].is_finite() && mean[d].is_finite() {
                u[d] = mean[d];
            }
        }
    }

    /// Each candidate's belief: all on the cheapest (predictive sampling) or MPPI's
    /// exponential weights over the candidates that did not blow up (a blow-up's cost is
    /// a stand-in, not a cost to average with).
    fn weights(&self, rollouts: &[Rollout], best: usize) -> Vec<f64> {
        let one_hot = || (0..rollouts.len()).map(|i| f64::from(i == best)).collect();
        let SamplingUpdate::Weighted { temperature } = self.config.update else {
            return one_hot();
        };
        let mut alive: Vec<f64> = rollouts
            .iter()
            .filter(|r| !r.blew_up)
            .map(|r| r.total)
            .collect();
        if alive.is_empty() {
            return one_hot();
        }
        alive.sort_by(f64::total_cmp);
        let (cheapest, median) = (alive[0], alive[alive.len() / 2]);
        let lambda = (temperature * (median - cheapest)).max(1e-9);
        let raw: Vec<f64> = rollouts
            .iter()
            .map(|r| match r.blew_up {
                true => 0.0,
                false => (-(r.total - cheapest) / lambda).exp(),
            })
            .collect();
        let sum: f64 = raw.iter().sum();
        raw.iter().map(|w| w / sum).collect()
    }
}
