//! The manoeuvres, on flat ground at a riding speed, the stick moved as a player would:
//!
//! - `turn`: 3 s straight at 20 km/h, then 15° right; the RMS lean error over the last 5 s.
//! - `carve`: as a player carves a long bend: part throttle towards 40 km/h for 3–5 s,
//!   then the stick 0.3–0.7 over for 8 s, asking the 30° limit, with a sideways knock of
//!   20–80 N·s 3 s in; the RMS error from the lean asked over the last 6 s.
//! - `slalom`: 20 km/h, ±15° every 2 s for 12 s; RMS over the last 10 s.
//! - `reversals`: 25 km/h, ±15° every 2 s for 12 s; the settled error: RMS over the second
//!   second of each gate after the first, once the lean has swung over.
//! - `push`: 15 km/h, a sideways shove of 100–250 N·s at 3 s; the largest lean in the 5 s
//!   after it.
//! - `walk`: 8 km/h for 20 s; the mean speed over the last 10 s (km/h).

use cpbp_core::bike::DriveInput;
use cpbp_core::ride::{Intent, Ride};
use glam::DVec3;

use super::{draw, new_ride, Outcome, Rider, STEPS_PER_SECOND};

pub const SCENARIOS: [&str; 6] = ["turn", "carve", "slalom", "reversals", "push", "walk"];

/// Rides manoeuvre `scenario` (one of `SCENARIOS`).
pub fn ride(scenario: &str, rider: Rider) -> Outcome {
    let kmh = match scenario {
        "walk" => 8.0,
        "push" => 15.0,
        "reversals" => 25.0,
        "carve" => 40.0,
        _ => 20.0,
    };
    let mut ride = new_ride(rider, kmh, 0.0);
    let mut planning = Vec::new();
    let mut run = |ride: &mut Ride, seconds: f64, lean: f64, each: &mut dyn FnMut(&Ride)| {
        ride.set_intent(Intent {
            lean: Some(lean),
            ..*ride.intent()
        });
        for _ in 0..(seconds * STEPS_PER_SECOND).round() as usize {
            ride.step();
            planning.extend(ride.plan().map(|p| p.planning_ms));
            each(ride);
        }
    };
    let lean_of = |ride: &Ride| {
        let sim = ride.sim();
        sim.bike().lean(sim.world(), sim.up())
    };
    let mut samples = Vec::new();
    let want = 15f64.to_radians();
    match scenario {
        "turn" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            run(&mut ride, 2.0, want, &mut |_| {});
            run(&mut ride, 5.0, want, &mut |r| {
                samples.push(lean_of(r) - want)
            });
        }
        "carve" => {
            // As the game's player rides it: the trigger at 50–100 % of the default motor
            // share (0.6) towards the 40 km/h setting, then after 3–5 s the stick 0.3–0.7
            // over, which asks for the 30° limit from about 25 km/h on.
            ride.set_intent(Intent {
                drive: DriveInput {
                    throttle: 0.6 * (0.5 + 0.5 * draw(rider.seed, 2)),
                    ..ride.intent().drive
                },
                ..*ride.intent()
            });
            run(&mut ride, 3.0 + 2.0 * draw(rider.seed, 3), 0.0, &mut |_| {});
            let side = if draw(rider.seed, 1) < 0.5 { 1.0 } else { -1.0 };
            ride.set_intent(Intent {
                lean: None,
                turn: (0.3 + 0.4 * draw(rider.seed, 4)) * side,
                ..*ride.intent()
            });
            // The track's rollers and kerbs, as a sideways knock 3 s into the turn.
            let knock = (3.0 * STEPS_PER_SECOND) as usize;
            for step in 0..(8.0 * STEPS_PER_SECOND) as usize {
                if step == knock {
                    let sim = ride.sim();
                    let forward = sim.bike().frame_rotation(sim.world()) * DVec3::X;
                    let side = forward.cross(sim.up()).normalize_or_zero();
                    let sign = if draw(rider.seed, 5) < 0.5 { 1.0 } else { -1.0 };
                    ride.push(side * sign * (20.0 + 60.0 * draw(rider.seed, 6)));
                }
                ride.step();
                planning.extend(ride.plan().map(|p| p.planning_ms));
                if step >= (2.0 * STEPS_PER_SECOND) as usize {
                    samples.push(lean_of(&ride) - ride.desired_lean());
                }
            }
        }
        "slalom" | "reversals" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            let first = if draw(rider.seed, 1) < 0.5 { 1.0 } else { -1.0 };
            // The slalom counts every step of a gate, the swing over included; the
            // reversals only the steps after the gate's first second.
            let settle = if scenario == "reversals" { 1.0 } else { 0.0 };
            let settled_from = (settle * STEPS_PER_SECOND).round() as usize;
            for gate in 0..6 {
                let target = want * if gate % 2 == 0 { first } else { -first };
                let mut step = 0;
                run(&mut ride, 2.0, target, &mut |r| {
                    if gate > 0 && step >= settled_from {
                        samples.push(lean_of(r) - target);
                    }
                    step += 1;
                });
            }
        }
        "push" => {
            run(&mut ride, 3.0, 0.0, &mut |_| {});
            let sim = ride.sim();
            let forward = sim.bike().frame_rotation(sim.world()) * DVec3::X;
            let side = forward.cross(sim.up()).normalize_or_zero();
            let sign = if draw(rider.seed, 2) < 0.5 { 1.0 } else { -1.0 };
            ride.push(side * sign * (100.0 + 150.0 * draw(rider.seed, 3)));
            run(&mut ride, 5.0, 0.0, &mut |r| samples.push(lean_of(r)));
        }
        _ => {
            run(&mut ride, 10.0, 0.0, &mut |_| {});
            run(&mut ride, 10.0, 0.0, &mut |r| {
                let sim = r.sim();
                samples.push(sim.bike().forward_speed(sim.world(), sim.up()) * 3.6);
            });
        }
    }
    let metric = match scenario {
        "turn" | "carve" | "slalom" | "reversals" => (samples.iter().map(|e| e * e).sum::<f64>()
            / samples.len() as f64)
            .sqrt()
            .to_degrees(),
        "push" => samples
            .iter()
            .fold(0.0, |m: f64, l| m.max(l.abs()))
            .to_degrees(),
        _ => samples.iter().sum::<f64>() / samples.len() as f64,
    };
    Outcome::of_ride(&ride, metric, &planning)
}
