//! The game picks N: the number of trajectories a planner simulates is moved, while the
//! player rides, to what this machine plans in time. Games lower their detail when frames
//! come late; here a plan that misses its control step is what comes late, so the rule
//! watches the planning thread's times and the hand-over's late steps:
//!
//! - down at once when plans run long (smoothed over a few plans, above `SLOW` of the
//!   control period) or `LATE_STEPS` hand-overs within `WINDOW` steps were late, to what
//!   the measured time per trajectory affords within `TARGET` of the period;
//! - up only after a calm spell (no late step, plans below `FAST` of the period), by at
//!   most a quarter; the spell it waits doubles each time going up made plans late again,
//!   so a machine on the edge does not see-saw.
//!
//! Only plans made with the N in use count: the ones in flight when N changed were made
//! with the old one. Everything here is pure bookkeeping on numbers it is given, so the
//! rule is tested with made-up timings; `make bench` rides it under load
//! (`src/bin/cpbp-bench/auto_n.rs`).

use super::limits::AUTO_TRAJECTORIES;

/// Plans should take this share of the control period: the rest is slack for the
/// master's step, the drawing and the spread between plans.
const TARGET: f64 = 0.7;
/// Smoothed plans longer than this share of the period: fewer trajectories.
const SLOW: f64 = 0.9;
/// Smoothed plans shorter than this share of a period, for a calm spell: more.
const FAST: f64 = 0.55;
/// Weight of the newest plan in the smoothed planning time.
const SMOOTHING: f64 = 0.25;
/// Plans at this N before its time counts as measured.
const MEASURED_AFTER: usize = 3;
/// Control steps of calm before N goes up (1 s at 30 steps/s), and the most it waits
/// after going up made plans late.
const CALM_STEPS: u64 = 30;
const LONGEST_CALM_STEPS: u64 = 16 * CALM_STEPS;
/// Growth per step up, at most.
const MOST_GROWTH: f64 = 1.25;

/// The automatic choice of N for one planner.
#[derive(Clone, Debug, PartialEq)]
pub struct AutoTrajectories {
    n: usize,
    period_ms: f64,
    /// Smoothed milliseconds per plan made with `n`.
    smoothed_ms: Option<f64>,
    plans_at_n: usize,
    /// One bit per control step at this N, newest lowest: set where the step was late.
    late_bits: u32,
    steps_at_n: u64,
    calm_needed: u64,
    /// Whether the last change was up (a slow spell right after it was its fault).
    went_up: bool,
}

impl AutoTrajectories {
    /// Late hand-overs among the last `WINDOW` steps at this N that lower it: one alone
    /// is let pass (a frame's stall, the scheduler's slice).
    pub const LATE_STEPS: u32 = 2;
    pub const WINDOW: u32 = 30;

    /// Starts from `start` (within the automatic range) for control steps of `period_s`.
    pub fn new(start: usize, period_s: f64) -> Self {
        Self {
            n: AUTO_TRAJECTORIES.clamp_count(start as i64),
            period_ms: period_s * 1000.0,
            smoothed_ms: None,
            plans_at_n: 0,
            late_bits: 0,
            steps_at_n: 0,
            calm_needed: CALM_STEPS,
            went_up: false,
        }
    }

    /// The N to plan with now.
    pub fn trajectories(&self) -> usize {
        self.n
    }

    /// A plan arrived that took `planning_ms` with `trajectories`.
    pub fn note_plan(&mut self, planning_ms: f64, trajectories: usize) {
        if trajectories != self.n || !planning_ms.is_finite() {
            return;
        }
        self.smoothed_ms = Some(match self.smoothed_ms {
            Some(s) => s + SMOOTHING * (planning_ms - s),
            None => planning_ms,
        });
        self.plans_at_n += 1;
    }

    /// A control step passed (`late`: its plan was not ready); returns the N to plan
    /// with from here on.
    pub fn note_step(&mut self, late: bool) -> usize {
        self.late_bits = (self.late_bits << 1) | u32::from(late);
        self.steps_at_n += 1;
        let late_steps = (self.late_bits & ((1 << Self::WINDOW) - 1)).count_ones();
        let measured = self
            .smoothed_ms
            .filter(|_| self.plans_at_n >= MEASURED_AFTER);
        if late_steps >= Self::LATE_STEPS || measured.is_some_and(|ms| ms > SLOW * self.period_ms) {
            self.go_down(measured);
        } else if late_steps == 0
            && self.steps_at_n >= self.calm_needed
            && measured.is_some_and(|ms| ms < FAST * self.period_ms)
        {
            self.go_up(measured.unwrap_or(self.period_ms));
        } else if self.steps_at_n >= LONGEST_CALM_STEPS {
            // Long at one N without trouble: the machine's hiccups were passing.
            self.calm_needed = CALM_STEPS;
        }
        self.n
    }

    fn go_down(&mut self, measured_ms: Option<f64>) {
        if self.went_up {
            self.calm_needed = (self.calm_needed * 2).min(LONGEST_CALM_STEPS);
        }
        // Late without a measured time (plans so slow none came back yet): a sixth off.
        let afforded = measured_ms.map_or(self.n as f64 * 5.0 / 6.0, |ms| {
            self.n as f64 * TARGET * self.period_ms / ms
        });
        let lower = (afforded.floor() as usize).min(self.n.saturating_sub(1));
        self.change_to(lower, false);
    }

    fn go_up(&mut self, measured_ms: f64) {
        let afforded = self.n as f64 * TARGET * self.period_ms / measured_ms;
        let capped = afforded.min(self.n as f64 * MOST_GROWTH).floor() as usize;
        self.change_to(capped.max(self.n + 1), true);
    }

    fn change_to(&mut self, n: usize, up: bool) {
        let n = AUTO_TRAJECTORIES.clamp_count(n as i64);
        if n == self.n {
            // At a bound: start a new spell so the same verdict is not repeated every step.
            self.steps_at_n = 0;
            self.late_bits = 0;
            return;
        }
        *self = Self {
            n,
            went_up: up,
            smoothed_ms: None,
            plans_at_n: 0,
            late_bits: 0,
            steps_at_n: 0,
            ..self.clone()
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PERIOD: f64 = 1.0 / 30.0;

    /// Rides `steps` control steps on a machine where a plan costs `ms_per_trajectory`
    /// per trajectory and is late whenever it takes longer than the period.
    fn ride(auto: &mut AutoTrajectories, steps: usize, ms_per_trajectory: f64) {
        for _ in 0..steps {
            let ms = auto.trajectories() as f64 * ms_per_trajectory;
            auto.note_plan(ms, auto.trajectories());
            auto.note_step(ms > PERIOD * 1000.0);
        }
    }

    #[test]
    fn a_slow_machine_lowers_n_until_plans_fit_and_a_fast_one_raises_it() {
        let mut auto = AutoTrajectories::new(64, PERIOD);
        ride(&mut auto, 60, 2.0);
        let n = auto.trajectories();
        assert!(
            (5..=12).contains(&n),
            "2 ms a trajectory affords about 11: got {n}"
        );
        assert!(n as f64 * 2.0 < PERIOD * 1000.0);
        ride(&mut auto, 300, 0.5);
        assert!(auto.trajectories() >= 32, "got {}", auto.trajectories());
        assert!(auto.trajectories() as f64 * 0.5 <= TARGET * PERIOD * 1000.0 + 1.0);
    }

    #[test]
    fn n_holds_inside_the_band() {
        let mut auto = AutoTrajectories::new(20, PERIOD);
        // 20 × 1.2 ms = 24 ms: between FAST (18 ms) and SLOW (30 ms).
        ride(&mut auto, 600, 1.2);
        assert_eq!(auto.trajectories(), 20);
    }

    #[test]
    fn it_stays_within_the_automatic_range() {
        let mut auto = AutoTrajectories::new(500, PERIOD);
        assert_eq!(auto.trajectories(), AUTO_TRAJECTORIES.max as usize);
        ride(&mut auto, 300, 50.0);
        assert_eq!(auto.trajectories(), AUTO_TRAJECTORIES.min as usize);
        ride(&mut auto, 3_000, 0.01);
        assert_eq!(auto.trajectories(), AUTO_TRAJECTORIES.max as usize);
    }

    #[test]
    fn late_steps_lower_n_even_when_plans_look_fast() {
        // A frame that stalls the game loop makes hand-overs late whatever the plan took.
        let mut auto = AutoTrajectories::new(30, PERIOD);
        auto.note_plan(5.0, 30);
        assert_eq!(auto.note_step(true), 30, "one late step is a hiccup");
        assert_eq!(auto.note_step(true), 25, "two: a sixth fewer");
    }

    #[test]
    fn plans_made_with_another_n_do_not_count() {
        let mut auto = AutoTrajectories::new(30, PERIOD);
        for _ in 0..10 {
            auto.note_plan(90.0, 64);
            auto.note_plan(f64::NAN, 30);
            auto.note_step(false);
        }
        assert_eq!(auto.trajectories(), 30);
    }

    #[test]
    fn going_up_into_trouble_makes_the_next_climb_wait_longer() {
        let mut auto = AutoTrajectories::new(10, PERIOD);
        // 1.4 ms a trajectory: N = 14 plans in 19.6 ms (calm), N = 17 in 23.8 ms; make the
        // machine late above 15 as a neighbour's load would.
        let mut changes = Vec::new();
        for _ in 0..3_000 {
            let n = auto.trajectories();
            auto.note_plan(n as f64 * 1.4, n);
            let after = auto.note_step(n > 15);
            if after != n {
                changes.push(after);
            }
        }
        let climbs = changes.windows(2).filter(|w| w[1] > w[0]).count();
        assert!(climbs <= 6, "it see-sawed: {changes:?}");
    }
}
