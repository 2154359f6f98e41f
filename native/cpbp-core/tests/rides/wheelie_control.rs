//! The drive's wheelie control (`bike::WheelieControl`). Tyres grip with the load their
//! own traction transfers (ODE patch 04), so full throttle lifts the front wheel: launched
//! towards 25 km/h without the control the bike loops over. With it the front stays on
//! the road and the bike still gets going briskly. Asked for a wheelie (the rider's weight
//! back, throttle open) it holds the front up near the balance point instead, the
//! planners keep the bike upright on its rear wheel, and every controller comes down
//! safely when the wheelie topples or the stick is released.

use crate::common;

use common::pitch;
use cpbp_core::bike::{BikeParams, Part, Placement, RiderPosition};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::simulation::SimulationConfig;
use cpbp_core::terrain::{TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

/// A full-throttle launch towards 25 km/h with arcade for 2 s: the largest frame pitch
/// (degrees, nose up) and the time (s) at which 24 km/h was first reached.
fn launch(bike: BikeParams) -> (f64, Option<f64>) {
    let sim = common::flat_ride_with(SimulationConfig {
        physics: PhysicsModel::Exact,
        bike,
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, ControllerKind::ARCADE);
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

/// Holds the rider's weight `back` (0–1) with full throttle.
fn ask_wheelie(ride: &mut Ride, back: f64) {
    ride.set_intent(Intent {
        rider: RiderPosition {
            forward: -back,
            right: 0.0,
        },
        ..*ride.intent()
    });
}

/// What a wheelie asked for at 12 km/h did over `seconds` with planner seed `seed`: the
/// time (s) the front wheel stayed above 40° of pitch, and the highest pitch (degrees).
/// The ride must not crash.
fn wheelie(kind: ControllerKind, seconds: f64, seed: u64) -> (f64, f64) {
    let mut ride = common::ride_in(PhysicsModel::Exact, kind, 12.0, 10);
    ride.planner.planning.seed = seed;
    common::ride(&mut ride, 2.0, 0.0);
    ask_wheelie(&mut ride, 1.0);
    let (mut up, mut highest) = (0.0, f64::MIN);
    for _ in 0..(seconds * common::FRAMES_PER_SECOND as f64) as usize {
        ride.step();
        assert_eq!(
            ride.sim().crashed(),
            None,
            "{kind:?} crashed in the wheelie"
        );
        highest = highest.max(pitch(&ride));
        if pitch(&ride) > 40.0 {
            up += 1.0 / common::FRAMES_PER_SECOND as f64;
        }
    }
    (up, highest)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_planner_holds_a_wheelie_near_the_balance_point() {
    // The balance point of this bike with the rider back is about 58° of pitch. How long
    // one wheelie lasts depends on the planner's draws (0.6–4.4 s above 40° over seeds
    // 1–6, 2.4 s on average; 0.7–3.9 s and 2.1 s before the arcade controller's horizon
    // shortened with speed), so the hold is judged over six seeds.
    let rides: Vec<(f64, f64)> = (1..=6)
        .map(|seed| wheelie(ControllerKind::COMBINED, 6.0, seed))
        .collect();
    let mean_up = rides.iter().map(|(up, _)| up).sum::<f64>() / rides.len() as f64;
    assert!(
        mean_up > 1.5,
        "above 40° for {mean_up:.2} s on average: {rides:?}"
    );
    for (_, highest) in rides {
        assert!(
            highest < 65.0,
            "pitched to {highest:.1}°: past the balance point"
        );
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn every_controller_lifts_the_front_and_comes_down_safely() {
    for kind in [ControllerKind::ARCADE, ControllerKind::OPTIMIZER] {
        let (_, highest) = wheelie(kind, 6.0, 2015);
        assert!(
            highest > 40.0,
            "{kind:?} lifted the front only to {highest:.1}°"
        );
    }
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn releasing_the_stick_puts_the_front_down() {
    let mut ride = common::ride_in(PhysicsModel::Exact, ControllerKind::COMBINED, 12.0, 10);
    common::ride(&mut ride, 2.0, 0.0);
    ask_wheelie(&mut ride, 1.0);
    common::ride(&mut ride, 1.0, 0.0);
    assert!(
        pitch(&ride) > 30.0,
        "the front rose only to {:.1}°",
        pitch(&ride)
    );
    ask_wheelie(&mut ride, 0.0);
    common::ride(&mut ride, 2.0, 0.0);
    assert_eq!(ride.sim().crashed(), None);
    assert!(pitch(&ride).abs() < 3.0, "still at {:.1}°", pitch(&ride));
}

/// Where the platform's edge is (m along +x from the spawn) and how high it is: nearly
/// the wheel's radius, so a wheel rolled into it stops dead (the thesis's Figure 4.7).
const PLATFORM_EDGE: f64 = 8.0;
const PLATFORM_HEIGHT: f64 = 0.28;

/// A `kind` ride at 10 km/h at a platform; with `wheelie`, the rider's weight goes back
/// from 2 m before the edge until the front wheel is over it. Where the rear wheel's
/// centre is after 3.5 s (x forward, y up), on the 6 m platform if it climbed.
fn ride_at_a_platform(kind: ControllerKind, wheelie: bool) -> DVec3 {
    let platform = TerrainPiece {
        source: "platform".into(),
        shape: TerrainShape::Cuboid {
            size: DVec3::new(6.0, PLATFORM_HEIGHT, 2.0),
        },
        placement: Placement {
            position: DVec3::new(PLATFORM_EDGE + 3.0, PLATFORM_HEIGHT / 2.0, 0.0),
            rotation: DQuat::IDENTITY,
        },
    };
    let mut ride = common::planned_ride(common::exact_sim_on(vec![platform], 0.02), kind);
    ride.set_intent(Intent::cruise(10.0));
    let centre = |ride: &Ride, part| {
        let sim = ride.sim();
        sim.world().body_position(sim.bike().body(part))
    };
    for _ in 0..(3.5 * common::FRAMES_PER_SECOND as f64) as usize {
        let front = centre(&ride, Part::FrontWheel).x;
        let lifting = wheelie && front > PLATFORM_EDGE - 2.0 && front < PLATFORM_EDGE + 0.2;
        ask_wheelie(&mut ride, if lifting { 1.0 } else { 0.0 });
        ride.step();
        assert_eq!(ride.sim().crashed(), None, "{kind:?} crashed");
    }
    centre(&ride, Part::RearWheel)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn a_wheelie_lifts_the_bike_onto_a_platform_a_wheel_rolled_into_stops_at() {
    let on_top = PLATFORM_HEIGHT + BikeParams::default().wheel_radius;
    for kind in [ControllerKind::COMBINED, ControllerKind::ARCADE] {
        let rear = ride_at_a_platform(kind, true);
        assert!(
            rear.x > PLATFORM_EDGE + 0.5 && (rear.y - on_top).abs() < 0.03,
            "{kind:?}: the rear wheel is at {rear}, not on the platform"
        );
    }
    let rear = ride_at_a_platform(ControllerKind::COMBINED, false);
    assert!(
        rear.x < PLATFORM_EDGE,
        "rolled onto it without a wheelie: {rear}"
    );
}
