//! Stop and pull away across a slope (issue 68): on a road falling to one side (a camber)
//! the rider stops, stands and rides off again, where a foot that does not reach the road
//! stood the bike leaned far downhill and the ride off fell.
//!
//! - `camber5-left`, `camber5-right`, `camber8-…`, `camber10-…`: the road falls that many
//!   degrees to the bike's left or right. `slope10-across45`: a 10° slope crossed at 45°
//!   (uphill to the left: falling 7.1° across and climbing 7.1°).
//! - 10 km/h for 5 s, the full brake for 4 s, standing on it for 3 s, then the throttle
//!   towards 10 km/h with the brake let go (4 s). Metric: the largest lean from upright
//!   (against gravity, degrees) while standing and pulling away. Also reported: the lean
//!   it stood at (signed: positive towards the side the road falls to) and whether a
//!   foot stood on the road at the end of the stand.

use cpbp_core::ride::{Intent, Ride};
use glam::{DMat3, DQuat, DVec3};

use super::{
    fall_cause, heading_of, mean_planning_ms, new_ride_on_plane, Outcome, Rider, STEPS_PER_SECOND,
};

pub const SCENARIOS: [&str; 7] = [
    "camber5-left",
    "camber5-right",
    "camber8-left",
    "camber8-right",
    "camber10-left",
    "camber10-right",
    "slope10-across45",
];

const KMH: f64 = 10.0;

/// The road's tilt in the bike's own axes (x forward, y up, z right) for `scenario`: a
/// turn about the heading (the road falling to the right is a turn from y towards z).
fn tilt(scenario: &str) -> DQuat {
    if scenario == "slope10-across45" {
        // The fall line 45° off the heading, to the back right: the road rises ahead left.
        let axis = DVec3::new(1.0, 0.0, -1.0).normalize();
        return DQuat::from_axis_angle(axis, 10f64.to_radians());
    }
    let (degrees, side) = scenario
        .trim_start_matches("camber")
        .split_once('-')
        .expect("a camber scenario is cambern-side");
    let degrees: f64 = degrees.parse().expect("the camber's degrees");
    let falls_right = if side == "right" { 1.0 } else { -1.0 };
    DQuat::from_rotation_x(falls_right * degrees.to_radians())
}

/// The bike's turn on a plane turned by `plane`: facing along the plane's x axis (in the
/// plane), upright against gravity as a rider rides across a slope.
fn upright_on(plane: DQuat) -> DQuat {
    let forward = plane * DVec3::X;
    let up = (DVec3::Y - forward * forward.y).normalize();
    DQuat::from_mat3(&DMat3::from_cols(forward, up, forward.cross(up)))
}

pub fn ride(scenario: &str, rider: Rider) -> Outcome {
    let tilt = tilt(scenario);
    let plane = heading_of(rider.seed) * tilt;
    let mut ride = new_ride_on_plane(rider, KMH, plane, upright_on(plane));
    // The downhill side (+1 right): the road's normal leans towards where it falls.
    let downhill = (tilt * DVec3::Y).z.signum();
    let mut planning = Vec::new();
    let cruise = Intent::cruise(KMH);
    let mut brake = cruise;
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    let mut largest = 0f64;
    let mut phase = |ride: &mut Ride, intent: Intent, seconds: f64, watched: bool| -> f64 {
        ride.set_intent(intent);
        let mut lean = 0.0;
        for _ in 0..(seconds * STEPS_PER_SECOND).round() as usize {
            ride.step();
            planning.extend(ride.plan().map(|p| p.planning_ms));
            let sim = ride.sim();
            lean = sim.bike().lean(sim.world(), sim.up());
            if watched {
                largest = largest.max(lean.abs());
            }
            if sim.crashed().is_some() {
                break;
            }
        }
        lean
    };
    phase(&mut ride, cruise, 5.0, false);
    phase(&mut ride, brake, 4.0, false);
    let stood = phase(&mut ride, brake, 3.0, true);
    let sim = ride.sim();
    let on_a_foot = sim.bike().feet(sim.world()).iter().any(|f| f.on_ground);
    phase(&mut ride, cruise, 4.0, true);
    Outcome {
        fell: ride.sim().crashed().is_some(),
        fall_cause: fall_cause(&ride),
        metric: largest.to_degrees(),
        planning_ms: mean_planning_ms(&planning),
        measures: vec![
            ("stood_downhill_deg", (stood * downhill).to_degrees()),
            ("on_a_foot", f64::from(u8::from(on_a_foot))),
        ],
    }
}
