//! Local refinement by Gaussian back-propagation (the C-PBP paper's Algorithm 2): from
//! where the particles ended up, walk back through the steps, and at each one ask the
//! particles' own samples "which state and control led here?" by fitting a Gaussian to
//! (state before, control, state after) and conditioning it on the state after. The
//! answer is a control sequence that blends the good particles smoothly instead of
//! picking one; the next frame replays it as a warm start.

use nalgebra::{DMatrix, DVector};

use super::priors::Priors;

/// One planning step's samples: per particle the features before and after the step (of
/// the particle's parent and of the particle), the control it applied, and its weight.
pub struct StepSamples<'a> {
    pub before: Vec<&'a [f64]>,
    pub controls: Vec<&'a [f64]>,
    pub after: Vec<&'a [f64]>,
    pub weights: &'a [f64],
}

/// The refined control sequence (K·D values), clamped to the priors' bounds, or `None`
/// when the system has no features. `end_weights` pick the final state to start from.
pub fn refine(
    steps: &[StepSamples],
    end_weights: &[f64],
    priors: &Priors,
    ridge: f64,
) -> Option<Vec<f64>> {
    let last = steps.last()?;
    let features = last.after.first()?.len();
    if features == 0 {
        return None;
    }
    let planned: Vec<usize> = (0..priors.dim()).filter(|&d| priors.planned[d]).collect();
    let mut target = weighted_mean(last.after.iter().copied(), end_weights, features);
    let mut sequence = vec![0.0; steps.len() * priors.dim()];
    for (k, step) in steps.iter().enumerate().rev() {
        let rows: Vec<DVector<f64>> = (0..step.weights.len())
            .map(|i| {
                let mut z = Vec::with_capacity(2 * features + planned.len());
                z.extend_from_slice(step.before[i]);
                z.extend(planned.iter().map(|&d| step.controls[i][d]));
                z.extend_from_slice(step.after[i]);
                DVector::from_vec(z)
            })
            .collect();
        let inferred = condition_on_last(&rows, step.weights, &target, ridge);
        let control = &mut sequence[k * priors.dim()..(k + 1) * priors.dim()];
        control.copy_from_slice(&priors.mean);
        for (slot, &d) in planned.iter().enumerate() {
            let value = inferred[features + slot];
            control[d] = if value.is_finite() {
                value
            } else {
                priors.mean[d]
            };
        }
        priors.clamp(control);
        target = (0..features)
            .map(|f| inferred[f])
            .map(|v| if v.is_finite() { v } else { 0.0 })
            .collect();
    }
    Some(sequence)
}

/// Fits a weighted Gaussian to `rows` (each [a, b], b the last `target.len()` entries) and
/// returns the conditional mean of a given b = target, with ridge `λ` on b's covariance.
fn condition_on_last(
    rows: &[DVector<f64>],
    weights: &[f64],
    target: &[f64],
    ridge: f64,
) -> DVector<f64> {
    let dim = rows[0].len();
    let nb = target.len();
    let na = dim - nb;
    let total: f64 = weights.iter().sum();
    let uniform = !(total.is_finite() && total > 0.0);
    let weight = |i: usize| {
        if uniform {
            1.0 / rows.len() as f64
        } else {
            weights[i] / total
        }
    };
    let mut mean = DVector::zeros(dim);
    for (i, row) in rows.iter().enumerate() {
        mean += row * weight(i);
    }
    let mut covariance = DMatrix::zeros(dim, dim);
    for (i, row) in rows.iter().enumerate() {
        let centred = row - &mean;
        covariance += &centred * centred.transpose() * weight(i);
    }
    let s_ab = covariance.view((0, na), (na, nb));
    let s_bb = covariance.view((na, na), (nb, nb)) + DMatrix::identity(nb, nb) * ridge;
    let b = DVector::from_column_slice(target);
    let offset = &b - mean.rows(na, nb);
    let solved = s_bb
        .clone()
        .cholesky()
        .map(|c| c.solve(&offset))
        .unwrap_or_else(|| DVector::zeros(nb));
    mean.rows(0, na) + s_ab * solved
}

fn weighted_mean<'a>(
    rows: impl Iterator<Item = &'a [f64]>,
    weights: &[f64],
    dim: usize,
) -> Vec<f64> {
    let mut mean = vec![0.0; dim];
    let mut total = 0.0;
    for (row, &w) in rows.zip(weights) {
        if w.is_finite() && w > 0.0 {
            mean.iter_mut().zip(row).for_each(|(m, x)| *m += w * x);
            total += w;
        }
    }
    if total > 0.0 {
        mean.iter_mut().for_each(|m| *m /= total);
    }
    mean
}

#[cfg(test)]
mod tests {
    use super::*;

    fn priors(dim: usize) -> Priors {
        Priors::uniform(dim, 1.0, 1.0, 0.2, 1.0)
    }

    #[test]
    fn conditioning_recovers_a_linear_relation() {
        // x' = x + u with x = 0: the weighted samples say u = x'; ask for x' = 0.3.
        let rows: Vec<DVector<f64>> = [-0.5, -0.2, 0.1, 0.4, 0.6]
            .iter()
            .map(|&u| DVector::from_vec(vec![0.0, u, u]))
            .collect();
        let inferred = condition_on_last(&rows, &[1.0; 5], &[0.3], 1e-9);
        assert!((inferred[1] - 0.3).abs() < 1e-6, "{inferred}");
    }

    #[test]
    fn refined_controls_stay_within_bounds_even_when_the_fit_asks_for_more() {
        // The samples imply u = x' / 10, and the best particles ended far away: the
        // regression wants controls far outside [-1, 1].
        let before = vec![vec![0.0]; 4];
        let controls = [vec![0.5], vec![0.9], vec![1.0], vec![0.95]];
        let after: Vec<Vec<f64>> = controls.iter().map(|u| vec![u[0] * 10.0 + 50.0]).collect();
        let step = StepSamples {
            before: before.iter().map(Vec::as_slice).collect(),
            controls: controls.iter().map(Vec::as_slice).collect(),
            after: after.iter().map(Vec::as_slice).collect(),
            weights: &[0.1, 0.2, 0.3, 0.4],
        };
        let sequence = refine(&[step], &[0.0, 0.0, 0.0, 1.0], &priors(1), 0.001).unwrap();
        assert!(
            sequence.iter().all(|u| (-1.0..=1.0).contains(u)),
            "{sequence:?}"
        );
    }

    #[test]
    fn no_features_means_no_refinement() {
        let before: Vec<Vec<f64>> = vec![vec![]; 2];
        let controls = [vec![0.1], vec![0.2]];
        let after: Vec<Vec<f64>> = vec![vec![]; 2];
        let step = StepSamples {
            before: before.iter().map(Vec::as_slice).collect(),
            controls: controls.iter().map(Vec::as_slice).collect(),
            after: after.iter().map(Vec::as_slice).collect(),
            weights: &[0.5, 0.5],
        };
        assert_eq!(refine(&[step], &[0.5, 0.5], &priors(1), 0.001), None);
    }
}
