//! A full brake from speed as a curve: `cargo run --release --example brake_curve --
//! [KMH] [CONTROLLER] [--bike FILE] [--heading DEG] [FIELD=VALUE…]` prints one CSV row per control step
//! of the stop (time, speed, deceleration, pitch, rear and front suspension compression,
//! wheel contacts, how high the rear tyre is off the road, lean, steering). `--bike` rides
//! a bike file (the reference bike without it); FIELD=VALUE sets one of its fields
//! (`front_brake/tipping_share=0.95`) to try a change.

#[path = "common/bike_args.rs"]
mod bike_args;

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::Simulation;
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};

use bike_args::{bike_config, take_flag};

const TOOL: &str = "brake_curve";

fn fail(why: &str) -> ! {
    bike_args::fail(TOOL, why)
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let config = bike_config(&mut args, TOOL);
    let heading = take_flag(&mut args, "--heading", TOOL).map_or(0.0, |degrees| {
        degrees
            .parse::<f64>()
            .unwrap_or_else(|_| fail(&format!("--heading {degrees}: not degrees")))
    });
    let kmh: f64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(60.0);
    let kind = match args.get(1) {
        Some(name) => ControllerKind::from_name(name)
            .unwrap_or_else(|| fail(&format!("no controller is called {name}"))),
        None => ControllerKind::ARCADE,
    };
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: DQuat::from_rotation_y(heading.to_radians()),
    };
    let sim = Simulation::new(config, Arc::new(Terrain::flat()), spawn);
    let mut ride = Ride::new(sim, kind);
    ride.planner.wait = PlanWait::EveryPlan;
    ride.set_intent(Intent::cruise(kmh));
    let dt = ride.sim().config().control_dt;
    for _ in 0..(kmh / 3.6 / 2.0 / dt) as usize + 90 {
        ride.step();
    }
    let mut brake = Intent::cruise(kmh);
    brake.drive.throttle = 0.0;
    brake.drive.brake = 1.0;
    ride.set_intent(brake);
    println!(
        "t,speed_kmh,decel_g,pitch_deg,rear_mm,front_mm,rear_contact,front_contact,fell,\
         rear_lift_mm,lean_deg,steer_deg"
    );
    let speed = |r: &Ride| {
        let s = r.sim();
        s.bike().forward_speed(s.world(), s.up())
    };
    let mut last = speed(&ride);
    for step in 0..(8.0 / dt) as usize {
        ride.step();
        let s = ride.sim();
        let (bike, world, up) = (s.bike(), s.world(), s.up());
        let v = speed(&ride);
        let forward = bike.frame_rotation(world) * DVec3::X;
        let pitch = forward.dot(up).asin().to_degrees();
        let (front, rear) = bike.suspension_compression(world);
        let (rear_down, front_down) = bike.wheel_contacts(world);
        // The road is flat at height 0: the rear tyre's lowest point's height is its lift.
        let rear_lift = bike.tyre_contacts(world, up).0.dot(up);
        println!(
            "{:.3},{:.2},{:.3},{:.2},{:.1},{:.1},{rear_down},{front_down},{},{:.1},{:.2},{:.2}",
            (step + 1) as f64 * dt,
            v * 3.6,
            (last - v) / dt / 9.81,
            pitch,
            rear * 1000.0,
            front * 1000.0,
            s.crashed().is_some(),
            rear_lift * 1000.0,
            bike.lean(world, up).to_degrees(),
            bike.steering(world).0.to_degrees(),
        );
        last = v;
        if v < 0.05 {
            break;
        }
    }
}
