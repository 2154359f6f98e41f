//! Stop and pull away across a slope (issue 68). On a road falling 8° to one side the
//! street bike's stiff feet stand it leaned far downhill (the uphill foot touches with
//! the weight already downhill, the bike rolls off it onto the downhill foot) and pulling
//! away from there falls; with legs that reach (`Feet::reach`) the foot it leans to holds
//! it 2.5° from upright, the uphill leg bent or the downhill one stretched, on either side,
//! and it rides off.

use std::sync::Arc;

use crate::common;

use cpbp_core::bike::{field, BikeParams, Feet, Placement};
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DMat3, DQuat, DVec3};

/// The street bike with legs that reach `reach` m, the sole built at the peg; with 0,
/// the stiff legs and soles every bike had before.
fn street_bike_reaching(reach: f64) -> BikeParams {
    let mut bike = common::street_bike();
    if reach == 0.0 {
        bike.feet = Some(Feet::default());
        return bike;
    }
    for (name, value) in [("feet/y", 0.25), ("feet/reach", reach)] {
        field(name).unwrap().apply(&mut bike, value).unwrap();
    }
    bike
}

/// How a stop on a road falling `degrees` to the right (negative: to the left) ended.
struct Stand {
    /// Lean from upright (°, positive downhill) at the end of 3 s standing.
    downhill_lean: f64,
    on_a_foot: bool,
    /// The largest lean from upright (°) riding off, or how it fell.
    riding_off: Result<f64, String>,
}

/// `kind` rides `bike` across a road falling `degrees` to the right at 10 km/h, brakes
/// to a stop, stands 3 s and rides off (4 s).
fn stop_across(bike: BikeParams, kind: ControllerKind, degrees: f64) -> Stand {
    let plane = DQuat::from_rotation_y(0.3) * DQuat::from_rotation_x(degrees.to_radians());
    let normal = plane * DVec3::Y;
    let forward = plane * DVec3::X;
    let upright = (DVec3::Y - forward * forward.y).normalize();
    let spawn = Placement {
        position: normal * 0.02,
        rotation: DQuat::from_mat3(&DMat3::from_cols(forward, upright, forward.cross(upright))),
    };
    let terrain = Terrain::new(vec![TerrainPiece::ground_through_origin("camber", normal)]);
    let config = SimulationConfig {
        bike,
        ..SimulationConfig::default()
    };
    let sim = Simulation::new(config, Arc::new(terrain.unwrap()), spawn);
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = 5;
    ride.planner.wait = PlanWait::EveryPlan;
    let cruise = Intent::cruise(10.0);
    let mut brake = cruise;
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    let downhill = degrees.signum();
    // Rides a phase: the lean (°, positive downhill) at its end and its largest from
    // upright, or how it fell.
    let phase = |ride: &mut Ride, intent: Intent, seconds: f64| -> Result<(f64, f64), String> {
        ride.set_intent(intent);
        let mut largest = 0f64;
        for _ in 0..(seconds * common::FRAMES_PER_SECOND as f64) as usize {
            ride.step();
            if let Some(crash) = ride.sim().crashed() {
                return Err(crash.describe());
            }
            largest = largest.max(common::lean(ride).abs().to_degrees());
        }
        Ok((common::lean(ride).to_degrees() * downhill, largest))
    };
    phase(&mut ride, cruise, 5.0).expect("rode across the slope");
    phase(&mut ride, brake, 4.0).expect("stopped");
    let (downhill_lean, _) = phase(&mut ride, brake, 3.0).expect("stood");
    let sim = ride.sim();
    let on_a_foot = sim.bike().feet(sim.world()).iter().any(|f| f.on_ground);
    let riding_off = phase(&mut ride, cruise, 4.0).map(|(_, largest)| largest);
    Stand {
        downhill_lean,
        on_a_foot,
        riding_off,
    }
}

#[test]
fn on_a_camber_stiff_feet_stand_the_bike_far_downhill_and_riding_off_falls() {
    for degrees in [8.0, -8.0] {
        let stand = stop_across(street_bike_reaching(0.0), ControllerKind::ARCADE, degrees);
        assert!(
            stand.downhill_lean > 9.0,
            "stood {:.1}°",
            stand.downhill_lean
        );
        assert!(stand.riding_off.is_err(), "rode off a {degrees}° camber");
    }
}

#[test]
fn on_a_camber_legs_that_reach_stand_the_bike_near_upright_and_it_rides_off() {
    for degrees in [8.0, -8.0] {
        let stand = stop_across(street_bike_reaching(0.35), ControllerKind::ARCADE, degrees);
        let lean = stand.downhill_lean;
        assert!(
            (2.0..5.0).contains(&lean.abs()),
            "stood {lean:.1}° on {degrees}°"
        );
        assert!(stand.on_a_foot, "stood without a foot down on {degrees}°");
        let riding_off = stand.riding_off.expect("rode off");
        assert!(
            riding_off < 10.0,
            "leaned {riding_off:.1}° riding off {degrees}°"
        );
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_planners_stop_and_ride_off_a_10_degree_camber_on_legs_that_reach() {
    for kind in [ControllerKind::COMBINED, ControllerKind::OPTIMIZER] {
        for degrees in [10.0, -10.0] {
            // On a road turned 0.3 rad from the world's axes the pyramid of world-axis
            // friction lets the optimizer's tyres slide out riding off; the planners
            // stand and ride off on tyres whose friction follows the wheel.
            let mut bike = street_bike_reaching(0.35);
            bike.tyre_friction_follows_wheel = true;
            let stand = stop_across(bike, kind, degrees);
            let lean = stand.downhill_lean;
            assert!(lean.abs() < 5.0, "{kind:?} stood {lean:.1}° on {degrees}°");
            let riding_off = stand.riding_off.expect("rode off");
            assert!(
                riding_off < 20.0,
                "{kind:?} leaned {riding_off:.1}° riding off"
            );
        }
    }
}
