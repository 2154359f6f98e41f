//! Deep bends (issue 68): the bike leaned as far as its tyres grip, at three headings
//! (grip must not depend on which way the road runs), and a bend asked beyond the grip,
//! which must end in a low-side, the tyres sliding out, not another kind of fall.
//!
//! - `bend45-h0`, `bend45-h22`, `bend45-h45`: 60 km/h heading 0°, 22.5° or 45° from the
//!   world's x axis, then 45° of right lean asked for 6 s, or the bike's deepest lean
//!   (`max_lean_deg`) where that is less: a bike on knobblies is asked as far as its own
//!   tyres hold, not into a low-side. Metric: the RMS error from the lean asked over the
//!   last 3 s (°). Also reported: the mean lean then, the radius ridden
//!   (the mean speed over the mean yaw rate: the mean of their ratio runs to kilometres
//!   when a wobble stops the yaw for an instant) and the one eq. 4.3 gives that lean at that speed
//!   (r = v² / (g tan θ)).
//! - `lowside-wet`: on a wet road (the tyres' friction 0.5: a lean past tan⁻¹ 0.5 ≈ 27°
//!   slides them out), 60 km/h, then the bike's deepest lean asked (its `max_lean_deg`;
//!   a lean request is held to it). Metric: 1 when it fell in a low-side, 0 for a fall of
//!   another kind or none (it should fall: `fell` is true).

use cpbp_core::bike::{Fall, Part, Placement};
use cpbp_core::ride::{Intent, Ride};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};

use super::{
    fall_cause, mean_planning_ms, ridden_bike, ride_bike_on, Outcome, Rider, STEPS_PER_SECOND,
};

pub const SCENARIOS: [&str; 4] = ["bend45-h0", "bend45-h22", "bend45-h45", "lowside-wet"];

const KMH: f64 = 60.0;
/// The deep bends' lean: street tyres' limit (issue 68).
const DEEP_BEND_DEG: f64 = 45.0;
/// Wet asphalt's grip, about half of dry (road-safety tables give 0.4–0.6).
const WET: f64 = 0.5;

pub fn ride(scenario: &str, rider: Rider) -> Outcome {
    let mut bike = ridden_bike();
    let deep = DEEP_BEND_DEG.min(bike.max_lean.to_degrees());
    let (heading_deg, lean_deg) = match scenario {
        "bend45-h0" => (0.0, deep),
        "bend45-h22" => (22.5, deep),
        "bend45-h45" => (45.0, deep),
        _ => {
            bike.tyre_friction = WET;
            (0.0, bike.max_lean.to_degrees())
        }
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(f64::to_radians(heading_deg)),
    };
    let mut ride = ride_bike_on(rider, KMH, Terrain::flat(), spawn, bike);
    let mut planning = Vec::new();
    let mut step = |ride: &mut Ride| -> bool {
        ride.step();
        planning.extend(ride.plan().map(|p| p.planning_ms));
        ride.sim().crashed().is_none()
    };
    // Up to speed (about 7 s from a standstill), upright.
    for _ in 0..(9.0 * STEPS_PER_SECOND) as usize {
        if !step(&mut ride) {
            break;
        }
    }
    let want = f64::to_radians(lean_deg);
    ride.set_intent(Intent {
        lean: Some(want),
        ..Intent::cruise(KMH)
    });
    let (mut errors, mut leans, mut yaws) = (Vec::new(), Vec::new(), Vec::new());
    let (mut speeds, mut stayed_up) = (Vec::new(), true);
    for i in 0..(6.0 * STEPS_PER_SECOND) as usize {
        if !step(&mut ride) {
            stayed_up = false;
            break;
        }
        if i >= (3.0 * STEPS_PER_SECOND) as usize {
            let sim = ride.sim();
            let (bike, world, up) = (sim.bike(), sim.world(), sim.up());
            let lean = bike.lean(world, up);
            let speed = bike.forward_speed(world, up);
            let yaw = world.body_angular_velocity(bike.body(Part::Frame)).dot(up);
            errors.push(lean - want);
            leans.push(lean);
            speeds.push(speed);
            yaws.push(yaw.abs());
        }
    }
    let crash = ride.sim().crashed();
    if scenario == "lowside-wet" {
        let low_side = crash.as_ref().and_then(|c| c.fall) == Some(Fall::LowSide);
        return Outcome {
            fell: crash.is_some(),
            fall_cause: fall_cause(&ride),
            metric: f64::from(u8::from(low_side)),
            planning_ms: mean_planning_ms(&planning),
            measures: Vec::new(),
        };
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    let (lean, speed) = (mean(&leans), mean(&speeds));
    let g = ride.sim().config().gravity.length();
    Outcome {
        fell: !stayed_up || crash.is_some(),
        fall_cause: fall_cause(&ride),
        metric: (mean(&errors.iter().map(|e| e * e).collect::<Vec<_>>()))
            .sqrt()
            .to_degrees(),
        planning_ms: mean_planning_ms(&planning),
        measures: vec![
            ("lean_deg", lean.to_degrees()),
            ("radius_m", speed / mean(&yaws).max(1e-6)),
            ("radius_eq43_m", speed * speed / (g * lean.abs().tan())),
        ],
    }
}
