//! A deep bend step by step: `cargo run --release --example deep_bend -- [KMH] [LEAN_DEG]
//! [CONTROLLER] [N] [SEED] [--bike FILE] [--rollouts SUBSTEPS,LEAD_STEPS,LEAD_SUBSTEPS]
//! [FIELD=VALUE…]` rides up to KMH (60) upright for 9 s, asks for LEAN_DEG (45) and prints
//! one CSV row per control step of the next 6 s: the frame's roll, the centre of mass's lean
//! over the tyres' contact line (what eq. 4.7 costs), the bar's angle, how fast the tyres
//! slide sideways, the speed, the plan's best cost and how far right of the riding pose the
//! rider's centre of mass sits, until the bike falls. The bend of the `bend45` scenarios,
//! to see how a planner loses it; `--rollouts` plans with another rollout stepping than the
//! physics model's (`RolloutStepping`), FIELD=VALUE changes a field of the bike
//! (`planners_cost_frame_roll=1`).

#[path = "common/bike_args.rs"]
mod bike_args;

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::control::PlanWait;
use cpbp_core::physics::RolloutStepping;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::Simulation;
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};

use bike_args::{bike_config, fail, take_flag};

const TOOL: &str = "deep_bend";

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let config = bike_config(&mut args, TOOL);
    let stepping = take_flag(&mut args, "--rollouts", TOOL).map(|text| {
        let numbers: Vec<usize> = text.split(',').filter_map(|n| n.parse().ok()).collect();
        match numbers[..] {
            [substeps, lead_steps, lead_substeps] if substeps > 0 && lead_substeps > 0 => {
                RolloutStepping {
                    substeps,
                    lead_steps,
                    lead_substeps,
                }
            }
            _ => fail(
                TOOL,
                &format!("--rollouts {text}: SUBSTEPS,LEAD_STEPS,LEAD_SUBSTEPS"),
            ),
        }
    });
    let number = |i: usize, default: f64| {
        args.get(i).map_or(default, |a| {
            a.parse()
                .unwrap_or_else(|_| fail(TOOL, &format!("{a}: not a number")))
        })
    };
    let (kmh, lean_deg) = (number(0, 60.0), number(1, 45.0));
    let (n, seed) = (number(3, 10.0) as usize, number(4, 0.0) as u64);
    let kind = match args.get(2) {
        Some(name) => ControllerKind::from_name(name)
            .unwrap_or_else(|| fail(TOOL, &format!("no controller is called {name}"))),
        None => ControllerKind::OPTIMIZER,
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let mut ride = Ride::new(
        Simulation::new(config, Arc::new(Terrain::flat()), spawn),
        kind,
    );
    ride.planner.planning.trajectories = n;
    ride.planner.planning.seed = seed;
    if let Some(stepping) = stepping {
        ride.planner.planning.rollout_stepping = stepping;
    }
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    let dt = ride.sim().config().control_dt;
    for _ in 0..(9.0 / dt) as usize {
        ride.step();
    }
    ride.set_intent(Intent {
        lean: Some(lean_deg.to_radians()),
        ..Intent::cruise(kmh)
    });
    println!(
        "t,lean_deg,com_lean_deg,steer_deg,side_slide_mps,speed_kmh,best_cost,fell,rider_right_cm"
    );
    for step in 0..(6.0 / dt) as usize {
        ride.step();
        let s = ride.sim();
        let (bike, world, up) = (s.bike(), s.world(), s.up());
        let right = bike.heading(world, up).cross(up);
        let toward = bike.center_of_mass(world) - bike.support_point(world, up);
        let fell = s.crashed().is_some();
        println!(
            "{:.3},{:.2},{:.2},{:.2},{:.3},{:.1},{:.1},{fell},{:.1}",
            (step + 1) as f64 * dt,
            bike.lean(world, up).to_degrees(),
            toward.dot(right).atan2(toward.dot(up)).to_degrees(),
            bike.steering(world).0.to_degrees(),
            bike.tyre_side_slide(world, up),
            bike.forward_speed(world, up) * 3.6,
            ride.plan().map_or(0.0, |p| p.best_cost),
            bike.rider_offset(world).z * 100.0,
        );
        if fell {
            break;
        }
    }
}
