//! A full brake from speed as a curve: `cargo run --release --example brake_curve
//! [KMH] [CONTROLLER]` prints one CSV row per control step of the stop (time, speed,
//! deceleration, pitch, rear and front suspension compression, wheel contacts).

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kmh: f64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(60.0);
    let kind = args
        .get(1)
        .and_then(|n| ControllerKind::from_name(n))
        .unwrap_or(ControllerKind::from_name("arcade").unwrap());
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::IDENTITY,
    };
    let sim = Simulation::new(
        SimulationConfig::default(),
        Arc::new(Terrain::flat()),
        spawn,
    );
    let mut ride = Ride::new(sim, kind);
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    let dt = 1.0 / 30.0;
    for _ in 0..(kmh / 3.6 / 2.0 / dt) as usize + 90 {
        ride.step();
    }
    let mut brake = Intent::cruise(kmh);
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    ride.set_intent(brake);
    println!("t,speed_kmh,decel_g,pitch_deg,rear_mm,front_mm,front_contact,rear_contact,fell");
    let speed = |r: &Ride| {
        let s = r.sim();
        s.bike().forward_speed(s.world(), s.up())
    };
    let mut last = speed(&ride);
    for step in 0..(8.0 / dt) as usize {
        ride.step();
        let s = ride.sim();
        let v = speed(&ride);
        let forward = s.bike().frame_rotation(s.world()) * DVec3::X;
        let pitch = forward.dot(s.up()).asin().to_degrees();
        let (front, rear) = s.bike().suspension_compression(s.world());
        let (fc, rc) = s.bike().wheel_contacts(s.world());
        println!(
            "{:.3},{:.2},{:.3},{:.2},{:.1},{:.1},{},{},{}",
            step as f64 * dt,
            v * 3.6,
            (last - v) / dt / 9.81,
            pitch,
            rear * 1000.0,
            front * 1000.0,
            fc,
            rc,
            s.crashed().is_some()
        );
        last = v;
        if v < 0.05 {
            break;
        }
    }
}
