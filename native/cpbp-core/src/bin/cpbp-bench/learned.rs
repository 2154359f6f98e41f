//! The learned controller's cost (issue 34): one control step's features and network
//! against a plan's, with the bike's own model as `make train` left it.

use cpbp_core::control::learned::features;
use cpbp_core::ride::ControllerKind;
use cpbp_core::simulation::Simulation;

use super::planning::planning_ms;
use super::{median, time_per_call};

/// Prints the network's cost per control step and what the planners cost against it.
pub fn inference_cost(sim: &Simulation, row: impl Fn(&str, String)) {
    let policy = super::bike_policy();
    let Some(network) = policy.network() else {
        row(
            "learned controller: one control step",
            format!("none: {}", policy.problem().unwrap_or_default()),
        );
        return;
    };
    let goal = super::cruising_goal();
    let step_us = median(|| {
        time_per_call(20_000, || {
            std::hint::black_box(network.controls(sim.bike(), sim.world(), &goal, sim.up())).ok();
        })
    });
    row(
        "learned controller: features + network, one control step",
        format!("{step_us:.2} µs"),
    );
    let features_us = median(|| {
        time_per_call(20_000, || {
            std::hint::black_box(features(sim.bike(), sim.world(), &goal, sim.up()));
        })
    });
    row("  of which the features", format!("{features_us:.2} µs"));
    let combined_ms = planning_ms(sim, ControllerKind::COMBINED, 15, 2).ms;
    row(
        "  combined N = 15 (2 threads) ÷ learned, per control step",
        format!("{:.0}×", combined_ms * 1000.0 / step_us),
    );
    // The guided planner's target is a third of combined-15's cost: N = 5 and below.
    for n in [3, 4, 5] {
        let guided_ms = planning_ms(sim, ControllerKind::GUIDED, n, 2).ms;
        row(
            &format!("  guided N = {n} (2 threads): ÷ learned; ÷ combined N = 15"),
            format!(
                "{:.0}×; {:.2}",
                guided_ms * 1000.0 / step_us,
                guided_ms / combined_ms
            ),
        );
    }
}
