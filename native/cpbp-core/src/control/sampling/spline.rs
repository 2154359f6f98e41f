//! A control sequence over the horizon as a few knots with straight lines between them
//! (MuJoCo MPC's linear spline policy): the sampling planners perturb knots, not every
//! step, so a candidate is a smooth plan instead of white noise.

/// `knots` control vectors of `dim` values, evenly spread from planning step 0 to the last
/// planning step `steps − 1`.
#[derive(Clone, Debug, PartialEq)]
pub struct Knots {
    values: Vec<f64>,
    dim: usize,
    steps: usize,
}

impl Knots {
    /// Every knot at `value` (at least two knots; one step when `steps` is 0).
    pub fn constant(value: &[f64], knots: usize, steps: usize) -> Self {
        Self {
            values: value.repeat(knots.max(2)),
            dim: value.len(),
            steps: steps.max(1),
        }
    }

    pub fn count(&self) -> usize {
        self.values.len() / self.dim.max(1)
    }

    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Knot `j`'s control vector, to perturb or average.
    pub fn knot_mut(&mut self, j: usize) -> &mut [f64] {
        &mut self.values[j * self.dim..(j + 1) * self.dim]
    }

    pub fn knot(&self, j: usize) -> &[f64] {
        &self.values[j * self.dim..(j + 1) * self.dim]
    }

    /// Planning step (fractional) at which knot `j` sits.
    fn time_of(&self, j: usize) -> f64 {
        (self.steps - 1) as f64 * j as f64 / (self.count() - 1) as f64
    }

    /// The control at planning step `t` (fractional): linear between the knots around it,
    /// the end knots held beyond the ends.
    pub fn at(&self, t: f64, out: &mut [f64]) {
        let last = self.count() - 1;
        let span = (self.steps - 1).max(1) as f64 / last as f64;
        let position = (t / span).clamp(0.0, last as f64);
        let j = (position.floor() as usize).min(last - 1);
        let f = position - j as f64;
        let (a, b) = (self.knot(j), self.knot(j + 1));
        for (d, value) in out.iter_mut().enumerate().take(self.dim) {
            *value = a[d] + (b[d] - a[d]) * f;
        }
    }

    /// The same plan seen one planning step later: each knot takes the value the plan had
    /// one step after the knot's time (the end held), as MuJoCo MPC re-samples its nominal
    /// policy at the new knot times.
    pub fn shifted_one_step(&self) -> Self {
        let mut shifted = self.clone();
        let mut value = vec![0.0; self.dim];
        for j in 0..self.count() {
            self.at(self.time_of(j) + 1.0, &mut value);
            shifted.knot_mut(j).copy_from_slice(&value);
        }
        shifted
    }

    /// Σ wᵢ·knotsᵢ for weights that sum to one (MPPI's update), knot by knot.
    pub fn weighted_sum(all: &[&Knots], weights: &[f64]) -> Self {
        let mut sum = all[0].clone();
        sum.values.iter_mut().for_each(|v| *v = 0.0);
        for (knots, &w) in all.iter().zip(weights) {
            for (s, v) in sum.values.iter_mut().zip(&knots.values) {
                *s += w * v;
            }
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two dimensions, knots at steps 0, 5 and 10: (0, 10) (1, 20) (3, 30).
    fn knots() -> Knots {
        let mut k = Knots::constant(&[0.0, 0.0], 3, 11);
        k.knot_mut(0).copy_from_slice(&[0.0, 10.0]);
        k.knot_mut(1).copy_from_slice(&[1.0, 20.0]);
        k.knot_mut(2).copy_from_slice(&[3.0, 30.0]);
        k
    }

    #[test]
    fn between_knots_the_plan_is_a_straight_line_and_beyond_them_it_holds() {
        let mut u = [0.0; 2];
        knots().at(2.5, &mut u);
        assert_eq!(u, [0.5, 15.0]);
        knots().at(7.5, &mut u);
        assert_eq!(u, [2.0, 25.0]);
        knots().at(14.0, &mut u);
        assert_eq!(u, [3.0, 30.0]);
        knots().at(-1.0, &mut u);
        assert_eq!(u, [0.0, 10.0]);
    }

    #[test]
    fn a_shift_reads_the_plan_one_step_later_and_holds_the_end() {
        let shifted = knots().shifted_one_step();
        assert_eq!(shifted.knot(0), &[0.2, 12.0]);
        assert_eq!(shifted.knot(1), &[1.4, 22.0]);
        assert_eq!(shifted.knot(2), &[3.0, 30.0]);
    }

    #[test]
    fn the_weighted_sum_averages_knot_by_knot() {
        let a = knots();
        let b = Knots::constant(&[1.0, 0.0], 3, 11);
        let sum = Knots::weighted_sum(&[&a, &b], &[0.5, 0.5]);
        assert_eq!(sum.knot(2), &[2.0, 15.0]);
    }
}
