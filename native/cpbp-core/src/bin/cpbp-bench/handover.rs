//! The hand-over: whether plans made on the planning thread arrive by the control step
//! that needs them, the game loop paced in real time (issue 59 asks it of the shorter
//! horizons at N ≥ 32 too).

use std::sync::Arc;
use std::time::{Duration, Instant};

use cpbp_core::bike::DriveInput;
use cpbp_core::control::{PlanWait, PlanningConfig};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::terrain::Terrain;

use super::rolling_bike;

/// Prints one row per N: the combined planner's time, the game loop's waits and the
/// share of late control steps, its settings `adjust`ed (`what` names how, if at all).
pub fn handover_table(
    what: &str,
    counts: impl IntoIterator<Item = usize>,
    adjust: impl Fn(&mut PlanningConfig),
) {
    println!();
    println!(
        "Hand-over ({} physics{what}): planning thread, game loop paced at 30 control steps/s, 6 s riding:",
        PhysicsModel::default().name()
    );
    println!(
        "{:<14} {:>14} {:>14} {:>14} {:>10}",
        "trajectories", "plan (ms)", "mean wait", "max wait", "late"
    );
    for n in counts {
        let h = handover(n, &adjust);
        println!(
            "{n:<14} {:>14.1} {:>11.2} ms {:>11.2} ms {:>9.0}%",
            h.0,
            h.1,
            h.2,
            h.3 * 100.0
        );
    }
}

/// Rides 6 s in real time on flat ground with the planner on its own thread, waiting at
/// most 10 ms at a boundary, the planner's settings `adjust`ed: (mean planning ms, mean
/// wait ms, max wait ms, share of late boundaries).
fn handover(n: usize, adjust: &dyn Fn(&mut PlanningConfig)) -> (f64, f64, f64, f64) {
    // The game's ride: the combined controller behind the one controller interface.
    let mut ride = Ride::new(
        rolling_bike(Arc::new(Terrain::flat()), PhysicsModel::default()),
        ControllerKind::COMBINED,
    );
    ride.planner.planning.trajectories = n;
    adjust(&mut ride.planner.planning);
    // At this N throughout: the automatic choice would move it.
    ride.planner.auto_trajectories = false;
    ride.planner.wait = PlanWait::AtMost(Duration::from_millis(10));
    ride.set_intent(Intent {
        drive: DriveInput {
            throttle: 1.0,
            brake: 0.0,
            max_speed: 15.0 / 3.6,
        },
        ..Intent::default()
    });
    let period = Duration::from_secs_f64(1.0 / 30.0);
    let mut boundary = Instant::now();
    let (mut planning, mut plans, mut last_plan_step) = (0.0, 0, None);
    for _ in 0..180 {
        ride.step();
        if let Some(plan) = ride.plan() {
            if last_plan_step != Some(plan.step) {
                last_plan_step = Some(plan.step);
                planning += plan.planning_ms;
                plans += 1;
            }
        }
        boundary += period;
        std::thread::sleep(boundary.saturating_duration_since(Instant::now()));
    }
    let stats = ride.handover().unwrap_or_default();
    (
        planning / plans.max(1) as f64,
        stats.mean_wait_ms(),
        stats.max_wait_ms,
        stats.late as f64 / stats.boundaries.max(1) as f64,
    )
}
