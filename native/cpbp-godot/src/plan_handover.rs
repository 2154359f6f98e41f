//! `PlanHandover`: how the planning thread's plans reached the game's control steps, as
//! `BikeSimulation.get_handover_stats()` reports it.

use cpbp_core::control::HandoverStats;
use godot::prelude::*;

/// The hand-overs since the ride was last placed (read-only).
#[derive(GodotClass)]
#[class(no_init, base=RefCounted)]
pub struct PlanHandover {
    /// The game thread's wait at the last control-step boundary (ms).
    #[var(no_set)]
    last_wait_ms: f64,
    /// Its mean wait over the boundaries (ms).
    #[var(no_set)]
    mean_wait_ms: f64,
    /// Its longest wait (ms).
    #[var(no_set)]
    max_wait_ms: f64,
    /// Control-step boundaries counted.
    #[var(no_set)]
    boundaries: i64,
    /// Boundaries with no plan for their step.
    #[var(no_set)]
    late: i64,
}

impl PlanHandover {
    pub fn of(stats: &HandoverStats) -> Gd<Self> {
        Gd::from_object(Self {
            last_wait_ms: stats.last_wait_ms,
            mean_wait_ms: stats.mean_wait_ms(),
            max_wait_ms: stats.max_wait_ms,
            boundaries: stats.boundaries as i64,
            late: stats.late as i64,
        })
    }
}
