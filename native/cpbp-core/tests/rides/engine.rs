//! The engine and the rear brake as bike data (`bike::RearWheelDrive`): a power limit
//! leaves the pull from a stop as it was and caps the pull at speed at the power, energy
//! for energy; a weaker rear brake stops the bike no harder than its torque allows.

use crate::common;

use cpbp_core::bike::{BikeParams, GRAVITY};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;

fn arcade_ride(bike: BikeParams) -> Ride {
    let sim = common::flat_ride_with(SimulationConfig {
        physics: PhysicsModel::Exact,
        bike,
        ..SimulationConfig::default()
    });
    Ride::new(sim, ControllerKind::ARCADE)
}

fn speed(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().forward_speed(sim.world(), sim.up())
}

fn mass(ride: &Ride) -> f64 {
    ride.sim().bike().mass(ride.sim().world())
}

/// Full throttle towards 90 km/h for 15 s: the time (s) each of `marks` (m/s) was first
/// reached, None where it was not.
fn launch(ride: &mut Ride, marks: &[f64]) -> Vec<Option<f64>> {
    ride.set_intent(Intent::cruise(90.0));
    let mut reached = vec![None; marks.len()];
    for step in 0..15 * common::FRAMES_PER_SECOND {
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "fell at full throttle");
        let t = (step + 1) as f64 / common::FRAMES_PER_SECOND as f64;
        for (mark, time) in marks.iter().zip(reached.iter_mut()) {
            if time.is_none() && speed(ride) >= *mark {
                *time = Some(t);
            }
        }
    }
    reached
}

#[test]
fn a_power_limit_leaves_the_launch_as_it_was_and_caps_the_pull_at_speed_at_the_power() {
    let unlimited = common::street_bike();
    let mut limited = unlimited.clone();
    limited.rear_drive.max_power_kw = 20.0;
    // 20 kW at 700 N·m: full torque until 8.6 m/s (31 km/h) on the 0.30 m wheel.
    let full_until = limited.rear_drive.full_torque_until(limited.wheel_radius);
    assert!((full_until - 8.57).abs() < 0.01, "{full_until}");

    let (slow, fast) = (6.0, [14.0, 23.0]);
    let marks = [slow, fast[0], fast[1]];
    let mut free = arcade_ride(unlimited);
    let free_times = launch(&mut free, &marks);
    let mut capped = arcade_ride(limited);
    let capped_times = launch(&mut capped, &marks);
    let time = |times: &[Option<f64>], i: usize| times[i].expect("reached every mark");
    println!("to 6, 14, 23 m/s: without a limit {free_times:?}, with 20 kW {capped_times:?}");

    // Below the limit's speed the anti-wheelie and the tyre decide, not the engine.
    assert!((time(&capped_times, 0) - time(&free_times, 0)).abs() <= 2.0 / 30.0);
    // Above it, the kinetic energy gained is at most the power's work, and most of it:
    // the rest goes to tyre slip and the suspension's damping.
    let gained = 0.5 * mass(&capped) * (fast[1] * fast[1] - fast[0] * fast[0]);
    let work = 20_000.0 * (time(&capped_times, 2) - time(&capped_times, 1));
    println!("14 → 23 m/s with 20 kW: gained {gained:.0} J of {work:.0} J of work");
    assert!(gained <= work * 1.01, "more energy than the power gave");
    assert!(gained >= work * 0.8, "the power did not reach the road");
    // Without the limit the same stretch took 1.3 s, about 30 kW: the anti-wheelie's.
    let stretch = |times: &[Option<f64>]| time(times, 2) - time(times, 1);
    assert!(stretch(&capped_times) > stretch(&free_times) * 1.3);
}

/// A stop from 30 km/h on the rear brake alone (a bike without a front brake): the mean
/// deceleration (g) from the trigger.
fn rear_brake_stop(brake_torque: f64) -> f64 {
    let mut bike = common::street_bike();
    bike.front_brake = None;
    bike.rear_drive.brake_torque = brake_torque;
    let mut ride = arcade_ride(bike);
    ride.set_intent(Intent::cruise(30.0));
    common::ride(&mut ride, 6.0, 0.0);
    let dt = ride.sim().config().control_dt;
    let start = speed(&ride);
    common::full_brake(&mut ride);
    let (mut distance, mut last) = (0.0, start);
    while last > 0.05 {
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "fell braking");
        let v = speed(&ride);
        distance += (last + v.max(0.0)) / 2.0 * dt;
        last = v;
    }
    start * start / (2.0 * distance) / GRAVITY
}

#[test]
fn the_rear_brake_stops_no_harder_than_its_torque_allows() {
    let weak = rear_brake_stop(150.0);
    let strong = rear_brake_stop(700.0);
    println!("rear brake alone from 30 km/h: 150 N·m {weak:.3} g, 700 N·m {strong:.3} g");
    // 150 N·m on the 0.30 m wheel is 500 N on the road, on about 230 kg.
    let bike = common::street_bike();
    let total = bike.bike_mass() + bike.rider_mass();
    let allowed = 150.0 / bike.wheel_radius / total / GRAVITY;
    assert!(
        weak <= allowed * 1.05,
        "{weak} g from a brake that allows {allowed} g"
    );
    assert!(
        weak >= allowed * 0.8,
        "{weak} g: the brake did not reach the road"
    );
    assert!(strong > weak * 1.5);
}
