//! The Gaussian priors a C-PBP particle samples its controls from (per dimension), and
//! the control cost they imply.

/// Standard deviations of the priors and the control bounds, per dimension.
#[derive(Clone, Debug, PartialEq)]
pub struct Priors {
    /// Static prior N(μ0, σ0²): typical control magnitude.
    pub mean: Vec<f64>,
    pub sigma_static: Vec<f64>,
    /// First-difference smoothness N(u_prev, σ1²).
    pub sigma_smooth1: Vec<f64>,
    /// Second-difference smoothness N(2u_prev − u_prevprev, σ2²).
    pub sigma_smooth2: Vec<f64>,
    /// Mutation around the followed sequence: σm = `mutation_scale` · σ0.
    pub mutation_scale: f64,
    pub lower: Vec<f64>,
    pub upper: Vec<f64>,
    /// Dimensions the planner chooses; the others are set by someone else (the player's
    /// throttle, say): they are neither sampled (they take the static mean) nor costed.
    pub planned: Vec<bool>,
}

impl Priors {
    /// The same priors for every one of `dim` dimensions, all planned, zero-mean, within
    /// ±`bound`, with both smoothness priors at `sigma_smooth` (for toy systems).
    pub fn uniform(
        dim: usize,
        sigma_static: f64,
        sigma_smooth: f64,
        mutation_scale: f64,
        bound: f64,
    ) -> Self {
        Self {
            mean: vec![0.0; dim],
            sigma_static: vec![sigma_static; dim],
            sigma_smooth1: vec![sigma_smooth; dim],
            sigma_smooth2: vec![sigma_smooth; dim],
            mutation_scale,
            lower: vec![-bound; dim],
            upper: vec![bound; dim],
            planned: vec![true; dim],
        }
    }

    pub fn dim(&self) -> usize {
        self.mean.len()
    }

    /// Mean and standard deviation of the product of the priors for dimension `d`: the
    /// precision-weighted mean and the combined variance. `guide` is the followed
    /// sequence's value, if the particle follows one.
    pub fn product(
        &self,
        d: usize,
        previous: f64,
        before_previous: f64,
        guide: Option<f64>,
    ) -> (f64, f64) {
        if !self.planned[d] {
            return (self.mean[d], 0.0);
        }
        let mut terms = vec![
            (self.mean[d], self.sigma_static[d]),
            (previous, self.sigma_smooth1[d]),
            (2.0 * previous - before_previous, self.sigma_smooth2[d]),
        ];
        if let Some(g) = guide {
            terms.push((g, self.mutation_scale * self.sigma_static[d]));
        }
        let (weighted, precision) = terms.iter().fold((0.0, 0.0), |(sum, prec), (mean, sigma)| {
            let p = 1.0 / (sigma * sigma);
            (sum + mean * p, prec + p)
        });
        (weighted / precision, precision.recip().sqrt())
    }

    /// Control cost Σ over dimensions of the static and smoothness prior terms,
    /// ((u − μ)/σ)² each: what the chosen control costs in the trajectory's total.
    pub fn cost(&self, u: &[f64], previous: &[f64], before_previous: &[f64]) -> f64 {
        (0..self.dim())
            .filter(|&d| self.planned[d])
            .map(|d| {
                let z0 = (u[d] - self.mean[d]) / self.sigma_static[d];
                let z1 = (u[d] - previous[d]) / self.sigma_smooth1[d];
                let z2 = (u[d] - (2.0 * previous[d] - before_previous[d])) / self.sigma_smooth2[d];
                z0 * z0 + z1 * z1 + z2 * z2
            })
            .sum()
    }

    /// How much a plan's trajectories disagree on what to do now: over the planned
    /// dimensions, the largest standard deviation of their first controls in units of the
    /// static prior's σ (0 when they all begin alike, or there is one).
    pub fn disagreement<'a>(&self, first_controls: impl Iterator<Item = &'a [f64]> + Clone) -> f64 {
        let n = first_controls.clone().count() as f64;
        if n < 2.0 {
            return 0.0;
        }
        (0..self.dim())
            .filter(|&d| self.planned[d])
            .map(|d| {
                let mean = first_controls.clone().map(|u| u[d]).sum::<f64>() / n;
                let variance = first_controls
                    .clone()
                    .map(|u| (u[d] - mean).powi(2))
                    .sum::<f64>()
                    / n;
                variance.sqrt() / self.sigma_static[d]
            })
            .fold(0.0, f64::max)
    }

    /// `u` clamped to the bounds, non-finite entries replaced by the static mean.
    pub fn clamp(&self, u: &mut [f64]) {
        for (d, value) in u.iter_mut().enumerate().take(self.dim()) {
            let v = if value.is_finite() {
                *value
            } else {
                self.mean[d]
            };
            *value = v.clamp(self.lower[d], self.upper[d]);
        }
    }
}

/// The controls the master really applied in the last two control steps: where a plan's
/// smoothness terms start from. Both C-PBP and the baseline planners keep one.
#[derive(Clone, Debug, PartialEq)]
pub struct AppliedControls {
    pub last: Vec<f64>,
    pub before: Vec<f64>,
}

impl AppliedControls {
    /// As if `rest` had been applied for ever (a new or reset planner).
    pub fn at_rest(rest: &[f64]) -> Self {
        Self {
            last: rest.to_vec(),
            before: rest.to_vec(),
        }
    }

    /// `control` was applied: it becomes the last, the last the one before.
    pub fn note(&mut self, control: &[f64]) {
        let dim = self.last.len();
        self.before = std::mem::replace(&mut self.last, control.to_vec());
        self.before.truncate(dim);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn priors() -> Priors {
        Priors::uniform(1, 2.0, 1.0, 0.5, 3.0)
    }

    #[test]
    fn the_product_is_the_precision_weighted_mean() {
        // Static N(0, 4), smooth1 N(1, 1), smooth2 N(2·1 − 1, 1) = N(1, 1), guide N(2, 1):
        // precisions 0.25, 1, 1, 1 → mean (0 + 1 + 1 + 2)/3.25, variance 1/3.25.
        let (mean, sigma) = priors().product(0, 1.0, 1.0, Some(2.0));
        assert!((mean - 4.0 / 3.25).abs() < 1e-12);
        assert!((sigma - (1.0f64 / 3.25).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn the_control_cost_adds_the_prior_terms() {
        // u = 2, previous 1, before 1: (2/2)² + (1/1)² + (1/1)² = 3.
        assert!((priors().cost(&[2.0], &[1.0], &[1.0]) - 3.0).abs() < 1e-12);
    }

    #[test]
    fn unplanned_dimensions_are_neither_sampled_nor_costed() {
        let priors = Priors {
            planned: vec![false],
            ..priors()
        };
        assert_eq!(priors.product(0, 1.0, 1.0, Some(2.0)), (0.0, 0.0));
        assert_eq!(priors.cost(&[2.5], &[1.0], &[1.0]), 0.0);
    }

    #[test]
    fn disagreement_is_the_widest_spread_of_the_first_controls_in_prior_sigmas() {
        let priors = Priors {
            planned: vec![true, true, false],
            ..Priors::uniform(3, 2.0, 1.0, 0.5, 3.0)
        };
        // Dimension 0 alike, dimension 1 at ±1 (σ 1, half the prior's 2), dimension 2
        // far apart but not planned.
        let firsts = [[0.5, 1.0, -3.0], [0.5, -1.0, 3.0]];
        let spread = priors.disagreement(firsts.iter().map(|u| u.as_slice()));
        assert!((spread - 0.5).abs() < 1e-12);
        assert_eq!(
            priors.disagreement(firsts[..1].iter().map(|u| u.as_slice())),
            0.0
        );
    }

    #[test]
    fn clamping_respects_bounds_and_replaces_nan() {
        let mut u = [7.0];
        priors().clamp(&mut u);
        assert_eq!(u, [3.0]);
        let mut u = [f64::NAN];
        priors().clamp(&mut u);
        assert_eq!(u, [0.0]);
    }
}
