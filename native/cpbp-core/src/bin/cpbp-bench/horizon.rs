//! What a shorter horizon saves (issue 59): combined and guided planning 1.2, 0.9, 0.6
//! and 0.4 s ahead, alone and ended by the bike's learned cost-to-go, each against
//! combined N = 5 over the whole 1.2 s in the same run; whether the hand-over keeps up
//! at N = 24–48 at each shorter horizon; and what one evaluation of the cost-to-go costs
//! (it runs once per trajectory per plan).

use cpbp_core::control::learned::features;
use cpbp_core::control::PlanningConfig;
use cpbp_core::ride::ControllerKind;
use cpbp_core::settings::HORIZON_S;
use cpbp_core::simulation::Simulation;

use super::planning::planning_ms_with;
use super::{median, time_per_call};

/// The horizons measured (s).
const HORIZONS: [f64; 4] = [1.2, 0.9, 0.6, 0.4];
/// The trajectory counts whose hand-over the issue asks about at a shorter horizon (it
/// keeps up at the whole horizon up to N = 15 on this 2-core VM).
const HANDOVER_COUNTS: [usize; 3] = [24, 32, 48];
/// The planners and trajectory counts whose cost the targets name.
const RIDERS: [(ControllerKind, usize); 5] = [
    (ControllerKind::COMBINED, 5),
    (ControllerKind::GUIDED, 5),
    (ControllerKind::COMBINED, 15),
    // Four split evenly over two threads where five leave one thread a third of a plan
    // alone: the count to try next at the short horizons.
    (ControllerKind::COMBINED, 4),
    (ControllerKind::GUIDED, 4),
];

/// Prints the table: ms per control step on 2 threads and, in brackets, over combined
/// N = 5 at the whole horizon.
pub fn horizon_table(sim: &Simulation, row: impl Fn(&str, String)) {
    let value = super::bike_value();
    let full = HORIZON_S.default_number();
    let time = |kind, n, adjust: &dyn Fn(&mut PlanningConfig)| {
        planning_ms_with(sim, kind, n, 2, |c| adjust(c)).ms
    };
    println!();
    println!(
        "Horizons ({} physics, 2 threads, 15 km/h): ms per control step (÷ combined N = 5 over {full} s):",
        sim.config().physics.name()
    );
    let heads: Vec<String> = RIDERS
        .iter()
        .map(|(kind, n)| format!("{:>18}", format!("{}-{n}", kind.name())))
        .collect();
    println!("{:<26} {}", "horizon", heads.join(" "));
    // The first cell, combined N = 5 over the whole horizon, is what the others are over.
    let mut reference = None;
    let mut cell = |ms: f64| {
        let over = *reference.get_or_insert(ms);
        format!("{:>18}", format!("{ms:.1} ({:.2})", ms / over))
    };
    for horizon in HORIZONS {
        let alone: Vec<String> = RIDERS
            .iter()
            .map(|&(kind, n)| cell(time(kind, n, &|c| c.horizon = horizon)))
            .collect();
        println!("{:<26} {}", format!("{horizon} s"), alone.join(" "));
        if horizon >= full || value.network().is_none() {
            continue;
        }
        let ended: Vec<String> = RIDERS
            .iter()
            .map(|&(kind, n)| {
                cell(time(kind, n, &|c| {
                    c.terminal_value = true;
                    c.value_horizon = horizon;
                    c.value = value.clone();
                }))
            })
            .collect();
        println!(
            "{:<26} {}",
            format!("{horizon} s + cost-to-go"),
            ended.join(" ")
        );
    }
    // Whether the plans still arrive in time with many trajectories, the horizon shorter.
    for horizon in HORIZONS.into_iter().filter(|&h| h < full) {
        super::handover::handover_table(&format!(", {horizon} s alone"), HANDOVER_COUNTS, |c| {
            c.horizon = horizon
        });
        if value.network().is_some() {
            super::handover::handover_table(
                &format!(", {horizon} s + cost-to-go"),
                HANDOVER_COUNTS,
                |c| {
                    c.terminal_value = true;
                    c.value_horizon = horizon;
                    c.value = value.clone();
                },
            );
        }
    }
    let Some(network) = value.network() else {
        row(
            "learned cost-to-go: one evaluation",
            format!("none: {}", value.problem().unwrap_or_default()),
        );
        return;
    };
    let goal = super::cruising_goal();
    let us = median(|| {
        time_per_call(20_000, || {
            let seen = features(sim.bike(), sim.world(), &goal, sim.up());
            std::hint::black_box(network.cost_to_go(&seen, 0.6)).ok();
        })
    });
    row(
        "learned cost-to-go: features + network, one trajectory's end",
        format!("{us:.2} µs"),
    );
}
