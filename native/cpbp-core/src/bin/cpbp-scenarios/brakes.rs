//! Full brakes as a road test measures them (issue 67): from 60 and 90 km/h on the level,
//! and in a 25 m bend at 25° of lean.
//!
//! - `brake60`, `brake90`: full throttle towards that speed, then the full brake until the
//!   bike has stood 2 s. Metric: the mean deceleration from the trigger to rest, v₀²/2d
//!   (g), the measure of a braking distance.
//! - `brake-bend`: round a bend of 25 m radius at 25° of lean (38.5 km/h: tan θ = v²/rg),
//!   then the full brake with the stick still in the bend (as the game does, the lean it
//!   asks for shrinks with the speed). Metric: the same.
//!
//! Each also reports its distance (m), the largest 0.1 s mean deceleration (g), the least
//! deceleration of a control step while moving (g; negative: a step sped the bike up), the
//! most nose-down pitch (°), the highest the rear tyre rose off the road while braking
//! (mm), the same once a foot is down at the end, and the share of control steps the rear
//! tyre touched the road (its contact flickers at the few tens of newtons it carries near
//! the limit, so this counts a tyre skimming the road by tenths of a millimetre as off it).

use cpbp_core::control::TurnIntent;
use cpbp_core::ride::{Intent, Ride};

use super::{fall_cause, mean_planning_ms, new_ride, Outcome, Rider, STEPS_PER_SECOND};

pub const SCENARIOS: [&str; 3] = ["brake60", "brake90", "brake-bend"];

/// The bend's radius (m) and lean (°).
const BEND: (f64, f64) = (25.0, 25.0);
/// Forward speed (m/s) below which the bike counts as at rest.
const AT_REST: f64 = 0.05;

pub fn ride(scenario: &str, rider: Rider) -> Outcome {
    let (kmh, turn) = match scenario {
        "brake60" => (60.0, 0.0),
        "brake90" => (90.0, 0.0),
        _ => {
            let (radius, lean) = BEND;
            let speed = (f64::to_radians(lean).tan() * radius * 9.81).sqrt();
            (
                speed * 3.6,
                1.0 / radius / TurnIntent::default().max_curvature,
            )
        }
    };
    let mut ride = new_ride(rider, kmh, 0.0);
    let mut planning = Vec::new();
    let cruise = Intent {
        turn,
        ..Intent::cruise(kmh)
    };
    ride.set_intent(cruise);
    // Long enough to reach the speed: the top of the drive is approached slowly.
    for _ in 0..((kmh / 5.0 + 4.0) * STEPS_PER_SECOND).round() as usize {
        ride.step();
        planning.extend(ride.plan().map(|p| p.planning_ms));
        if ride.sim().crashed().is_some() {
            return fell(&planning, fall_cause(&ride));
        }
    }
    let mut brake = cruise;
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    ride.set_intent(brake);
    let measured = measure_stop(&mut ride, &mut planning);
    // Standing 2 s after.
    for _ in 0..(2.0 * STEPS_PER_SECOND) as usize {
        ride.step();
    }
    let fell = ride.sim().crashed().is_some() || measured.is_none();
    let Some(stop) = measured.filter(|_| !fell) else {
        return self::fell(&planning, fall_cause(&ride));
    };
    Outcome {
        fell,
        fall_cause: None,
        metric: stop.mean_g,
        planning_ms: mean_planning_ms(&planning),
        measures: vec![
            ("distance_m", stop.distance),
            ("peak_g", stop.peak_g),
            ("least_step_g", stop.least_step_g),
            ("pitch_deg", stop.pitch_deg),
            ("rear_lift_mm", stop.rear_lift * 1000.0),
            ("foot_lift_mm", stop.foot_lift * 1000.0),
            ("rear_on_road", stop.rear_on_road),
        ],
    }
}

fn fell(planning: &[f64], fall_cause: Option<String>) -> Outcome {
    Outcome {
        fell: true,
        fall_cause,
        metric: f64::NAN,
        planning_ms: mean_planning_ms(planning),
        measures: Vec::new(),
    }
}

struct Stop {
    distance: f64,
    mean_g: f64,
    peak_g: f64,
    least_step_g: f64,
    pitch_deg: f64,
    rear_lift: f64,
    foot_lift: f64,
    rear_on_road: f64,
}

/// Brakes `ride` to rest (at most 10 s): what the stop measured, none if the bike fell
/// or did not stop.
fn measure_stop(ride: &mut Ride, planning: &mut Vec<f64>) -> Option<Stop> {
    let g = ride.sim().config().gravity.length();
    let dt = 1.0 / STEPS_PER_SECOND;
    let speed = |ride: &Ride| {
        let sim = ride.sim();
        sim.bike().forward_speed(sim.world(), sim.up())
    };
    let start = speed(ride);
    let mut stop = Stop {
        distance: 0.0,
        mean_g: 0.0,
        peak_g: 0.0,
        least_step_g: f64::INFINITY,
        pitch_deg: 0.0,
        rear_lift: 0.0,
        foot_lift: 0.0,
        rear_on_road: 0.0,
    };
    let (mut last, mut steps, mut touching) = (start, 0, 0);
    let mut decelerations = Vec::new();
    while last > AT_REST {
        if steps as f64 * dt > 10.0 {
            return None;
        }
        ride.step();
        planning.extend(ride.plan().map(|p| p.planning_ms));
        let sim = ride.sim();
        if sim.crashed().is_some() {
            return None;
        }
        let (bike, world, up) = (sim.bike(), sim.world(), sim.up());
        let v = speed(ride);
        stop.distance += (last + v.max(0.0)) / 2.0 * dt;
        decelerations.push((last - v) / dt / g);
        let nose = (bike.frame_rotation(world) * glam::DVec3::X).dot(up).asin();
        stop.pitch_deg = stop.pitch_deg.max(-nose.to_degrees());
        // The rear tyre's lowest point: on the flat ground these rides use, its height.
        let (rear, _) = bike.tyre_contacts(world, up);
        // Until the feet come down; the hop as a foot takes the bike's weight at rest (a
        // leaning bike levered up on its stiff leg) is the feet's, counted apart.
        if bike.feet(world).iter().any(|foot| foot.down) {
            stop.foot_lift = stop.foot_lift.max(rear.dot(up));
        } else {
            stop.rear_lift = stop.rear_lift.max(rear.dot(up));
        }
        touching += usize::from(bike.wheel_contacts(world).0);
        steps += 1;
        last = v;
    }
    let moving = &decelerations[..decelerations.len().saturating_sub(1)];
    stop.least_step_g = moving.iter().copied().fold(f64::INFINITY, f64::min);
    stop.peak_g = decelerations
        .windows(3)
        .map(|w| w.iter().sum::<f64>() / 3.0)
        .fold(0.0, f64::max);
    stop.mean_g = start * start / (2.0 * stop.distance) / g;
    stop.rear_on_road = touching as f64 / steps.max(1) as f64;
    Some(stop)
}
