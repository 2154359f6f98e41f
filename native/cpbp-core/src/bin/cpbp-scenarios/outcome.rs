//! What a ride of a scenario measured, and the helpers each scenario's module reports it
//! with.

use cpbp_core::ride::Ride;

/// What one ride measured: its metric, and what else a scenario reports (printed as the
/// row's `extra` column, `name=value;…`).
pub(crate) struct Outcome {
    pub fell: bool,
    /// What brought the bike down, as the crash report names it (None: it stayed up, or
    /// the scenario judged a fall of its own). Printed, not saved: the rows keep `fell`.
    pub fall_cause: Option<String>,
    pub metric: f64,
    pub planning_ms: f64,
    pub measures: Vec<(&'static str, f64)>,
}

impl Outcome {
    /// The ride as it ended: fallen or not, and why, with `metric` and the mean of its
    /// plans' times; nothing else measured.
    pub(crate) fn of_ride(ride: &Ride, metric: f64, planning: &[f64]) -> Self {
        Self {
            fell: ride.sim().crashed().is_some(),
            fall_cause: fall_cause(ride),
            metric,
            planning_ms: mean_planning_ms(planning),
            measures: Vec::new(),
        }
    }
}

/// What brought the ride's bike down, if it fell (`Outcome::fall_cause`).
pub(crate) fn fall_cause(ride: &Ride) -> Option<String> {
    ride.sim().crashed().map(|crash| crash.describe())
}

/// The mean planning time (ms) of a ride's plans; 0 for a controller that plans nothing
/// (an empty float sum is −0.0, which the rows would print as "-0.000").
pub(crate) fn mean_planning_ms(planning: &[f64]) -> f64 {
    if planning.is_empty() {
        return 0.0;
    }
    planning.iter().sum::<f64>() / planning.len() as f64
}
