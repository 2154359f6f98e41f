//! The drive's anti-wheelie (`bike::WheelieControl`). Tyres grip with the load their own
//! traction transfers (ODE patch 04), so full throttle lifts the front wheel: launched
//! towards 25 km/h without the control the bike loops over. With it the front stays on
//! the road and the bike still gets going briskly.

mod common;

use cpbp_core::bike::BikeParams;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;
use glam::DVec3;

/// A full-throttle launch towards 25 km/h with arcade for 2 s: the largest frame pitch
/// (degrees, nose up) and the time (s) at which 24 km/h was first reached.
fn launch(bike: BikeParams) -> (f64, Option<f64>) {
    let sim = common::flat_ride_with(SimulationConfig {
        physics: PhysicsModel::Exact,
        bike,
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, ControllerKind::Arcade);
    ride.set_intent(Intent::cruise(25.0));
    let (mut pitch, mut reached) = (f64::MIN, None);
    for step in 0..2 * common::FRAMES_PER_SECOND {
        ride.step();
        let sim = ride.sim();
        let forward = sim.bike().frame_rotation(sim.world()) * DVec3::X;
        pitch = pitch.max(forward.dot(sim.up()).asin().to_degrees());
        let kmh = sim.bike().forward_speed(sim.world(), sim.up()) * 3.6;
        if reached.is_none() && kmh >= 24.0 {
            reached = Some((step + 1) as f64 / common::FRAMES_PER_SECOND as f64);
        }
    }
    (pitch, reached)
}

#[test]
fn full_throttle_from_rest_keeps_the_front_down() {
    let (pitch, reached) = launch(BikeParams::default());
    assert!(pitch < 3.0, "the front rose to {pitch:.1} degrees");
    let seconds = reached.expect("never reached 24 km/h");
    assert!(seconds < 1.6, "24 km/h after {seconds:.2} s");
}

#[test]
fn without_the_control_the_same_launch_loops() {
    let bike = BikeParams {
        wheelie_control: None,
        ..BikeParams::default()
    };
    let (pitch, _) = launch(bike);
    assert!(pitch > 45.0, "the front rose only to {pitch:.1} degrees");
}
