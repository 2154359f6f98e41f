//! Stop anywhere (issue 33): a full brake from the game's top speed ends with the bike
//! standing on a foot, and on a 15° slope the brake holds the bike and a hill start rides
//! off without rolling back. The scenario tool (`cpbp-scenarios`, docs/scenarios) rides the
//! same manoeuvres over many seeds; these are the checks `make test` keeps.

use crate::common;

use std::sync::Arc;

use cpbp_core::bike::{DriveInput, Placement};
use cpbp_core::control::PlanWait;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DQuat, DVec3};

const FULL_BRAKE: DriveInput = DriveInput {
    throttle: 0.0,
    brake: 1.0,
    max_speed: 40.0 / 3.6,
};

/// Rides `seconds` with `drive`; returns the least distance reached along the path from
/// where it began (m: negative when the bike rolled back). The bike must stay up.
fn ride_for(ride: &mut Ride, drive: DriveInput, seconds: f64, what: &str) -> f64 {
    ride.set_intent(Intent {
        drive,
        ..*ride.intent()
    });
    let (mut ridden, mut least) = (0.0, 0.0f64);
    let per_step = 1.0 / common::FRAMES_PER_SECOND as f64;
    for _ in 0..(seconds / per_step).round() as usize {
        ride.step();
        let sim = ride.sim();
        assert_eq!(sim.crashed(), None, "{:?} fell {what}", ride.controller());
        ridden += sim.bike().forward_speed(sim.world(), sim.up()) * per_step;
        least = least.min(ridden);
    }
    least
}

fn speed(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().forward_speed(sim.world(), sim.up())
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn a_full_brake_from_40_kmh_ends_standing_on_a_foot() {
    let kinds = [
        ControllerKind::ARCADE,
        ControllerKind::COMBINED,
        ControllerKind::OPTIMIZER,
    ];
    for kind in kinds {
        let mut ride = common::ride_in(PhysicsModel::Exact, kind, 40.0, 5);
        ride_for(&mut ride, common::auto_throttle(40.0), 8.0, "riding");
        assert!(
            speed(&ride) > 10.0,
            "{kind:?} reached only {:.1} m/s",
            speed(&ride)
        );
        ride_for(&mut ride, FULL_BRAKE, 5.0, "braking");
        let sim = ride.sim();
        assert!(speed(&ride).abs() < 0.05, "{kind:?} still moving");
        let (left, right) = sim.bike().feet_on_ground(sim.world());
        assert!(left || right, "{kind:?} stands on no foot");
        let lean = common::lean(&ride).to_degrees();
        assert!(lean.abs() < 10.0, "{kind:?} stands at {lean:.1}°");
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn on_a_15_degree_slope_the_brake_holds_and_a_hill_start_does_not_roll_back() {
    let slope = 15f64.to_radians();
    let rotation = DQuat::from_rotation_y(0.3) * DQuat::from_rotation_z(slope);
    let normal = rotation * DVec3::Y;
    let ground = TerrainPiece::ground_through_origin("15° slope", normal);
    let terrain = Arc::new(Terrain::new(vec![ground]).expect("a plane"));
    // The optimizer left the bar at full lock standing, leaned onto the foot and fell
    // setting off, until the rider sat still on a foot (`Feet::straighten_rate`).
    let kinds = [
        ControllerKind::ARCADE,
        ControllerKind::COMBINED,
        ControllerKind::OPTIMIZER,
    ];
    for kind in kinds {
        let spawn = Placement {
            position: normal * 0.02,
            rotation,
        };
        let sim = Simulation::new(SimulationConfig::default(), terrain.clone(), spawn);
        let mut ride = Ride::new(sim, kind);
        ride.planner.planning.trajectories = 5;
        ride.planner.wait = PlanWait::EveryPlan;
        ride.set_intent(Intent::cruise(20.0));
        ride_for(&mut ride, common::auto_throttle(20.0), 5.0, "riding uphill");
        ride_for(&mut ride, FULL_BRAKE, 4.0, "stopping uphill");
        let held = ride_for(&mut ride, FULL_BRAKE, 3.0, "standing on the brake");
        assert!(
            held > -0.02,
            "{kind:?} crept back {:.3} m on the brake",
            -held
        );
        let back = ride_for(&mut ride, common::auto_throttle(20.0), 4.0, "pulling away");
        assert!(back > -0.3, "{kind:?} rolled back {:.2} m", -back);
        assert!(
            speed(&ride) > 3.0,
            "{kind:?} did not ride off ({:.1} m/s)",
            speed(&ride)
        );
    }
}
