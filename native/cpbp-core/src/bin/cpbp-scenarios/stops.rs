//! Stops and hill starts (issue 33): a full brake from speed on flat ground and leaned in
//! a turn, and on slopes a stop, a stand on the brake and a ride off.
//!
//! - `stop10`, `stop25`, `stop40`: full throttle to that speed (8 s), then the full brake
//!   for 5 s: the bike must come to rest and stand. Metric: the stopping distance along
//!   the path (m).
//! - `brake-turn`: 25 km/h in a right turn at 20° of lean, then the full brake with the
//!   stick still in the turn (as the game does, the lean it asks for shrinks with the
//!   speed). Metric: the stopping distance along the path (m).
//! - `slope5`, `slope10`, `slope15`: up a slope of that many degrees at 20 km/h (5 s), the
//!   full brake (4 s), standing on it (3 s), then full throttle with the brake let go at
//!   once (4 s): the hill start. Metric: how far the bike rolled back in the start (m).
//! - `downhill15`: the same facing down a 15° slope. Metric: how far the bike crept while
//!   standing on the brake (m).

use cpbp_core::control::TurnIntent;
use cpbp_core::ride::{Intent, Ride};

use super::{new_ride, Outcome, Rider, STEPS_PER_SECOND};

pub const SCENARIOS: [&str; 8] = [
    "stop10",
    "stop25",
    "stop40",
    "brake-turn",
    "slope5",
    "slope10",
    "slope15",
    "downhill15",
];

pub fn ride(scenario: &str, rider: Rider) -> Outcome {
    let (kmh, lean, slope) = match scenario {
        "stop10" => (10.0, 0.0, 0.0),
        "stop25" => (25.0, 0.0, 0.0),
        "stop40" => (40.0, 0.0, 0.0),
        "brake-turn" => (25.0, 20.0, 0.0),
        "slope5" => (20.0, 0.0, 5.0),
        "slope10" => (20.0, 0.0, 10.0),
        "slope15" => (20.0, 0.0, 15.0),
        _ => (20.0, 0.0, -15.0),
    };
    let mut ride = new_ride(rider, kmh, f64::to_radians(slope));
    let mut planning = Vec::new();
    let cruise = if lean == 0.0 {
        Intent::cruise(kmh)
    } else {
        // The stick that asks for `lean` at `kmh` (eq. 4.4: tan θ = v² κ / g).
        let (speed, g) = (kmh / 3.6, ride.sim().config().gravity.length());
        let curvature = f64::to_radians(lean).tan() * g / (speed * speed);
        Intent {
            lean: None,
            turn: curvature / TurnIntent::default().max_curvature,
            ..Intent::cruise(kmh)
        }
    };
    let mut brake = cruise;
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    // Per phase: the distance ridden along the path (forward positive), and the least it
    // reached (how far back the bike rolled).
    let mut phase = |ride: &mut Ride, intent: Intent, seconds: f64| -> (f64, f64) {
        ride.set_intent(intent);
        let (mut ridden, mut least) = (0.0, 0.0f64);
        for _ in 0..(seconds * STEPS_PER_SECOND).round() as usize {
            ride.step();
            planning.extend(ride.plan().map(|p| p.planning_ms));
            let sim = ride.sim();
            ridden += sim.bike().forward_speed(sim.world(), sim.up()) / STEPS_PER_SECOND;
            least = least.min(ridden);
            if sim.crashed().is_some() {
                break;
            }
        }
        (ridden, least)
    };
    let metric = if slope == 0.0 {
        let before = if lean == 0.0 { 8.0 } else { 5.0 };
        phase(&mut ride, cruise, before);
        phase(&mut ride, brake, 5.0).0
    } else {
        phase(&mut ride, cruise, 5.0);
        phase(&mut ride, brake, 4.0);
        let (crept, _) = phase(&mut ride, brake, 3.0);
        let (_, rolled_back) = phase(&mut ride, cruise, 4.0);
        if slope > 0.0 {
            -rolled_back
        } else {
            crept.abs()
        }
    };
    Outcome::of_ride(&ride, metric, &planning)
}
