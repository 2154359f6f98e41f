//! What the game's sound hears of the tyres and the ground (`Bike::rear_rim_speed`,
//! `Bike::tyre_slip`, `Simulation::ground_blow`): a tyre rolling along does not slide and
//! its rim turns at the road's speed, braking hard makes the tyres slide, and a landing's
//! blows add up to the momentum the ground took out of the fall.

use crate::common;

use cpbp_core::bike::DriveInput;
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent};

#[test]
fn a_landing_blows_as_hard_as_the_fall_and_falling_blows_nothing() {
    let mut sim = common::exact_sim_on(Vec::new(), 0.6);
    let up = sim.up();
    let mut fall_momentum = 0.0_f64;
    let mut blows = Vec::new();
    for _ in 0..common::FRAMES_PER_SECOND {
        let touching = {
            let (rear, front) = sim.bike().wheel_contacts(sim.world());
            rear || front
        };
        if !touching && blows.is_empty() {
            fall_momentum = -sim.bike().momentum(sim.world()).dot(up);
        }
        sim.step();
        let (rear, front) = sim.bike().wheel_contacts(sim.world());
        if rear || front || !blows.is_empty() {
            blows.push(sim.ground_blow());
        } else {
            assert_eq!(sim.ground_blow(), 0.0, "in the air nothing pushes");
        }
    }
    let hardest = blows.iter().cloned().fold(0.0, f64::max);
    let total: f64 = blows.iter().take(10).sum();
    assert!(fall_momentum > 300.0, "falling at {fall_momentum:.0} N·s");
    assert!(hardest > 60.0, "hardest blow {hardest:.0} N·s");
    assert!(
        (total / fall_momentum - 1.0).abs() < 0.35,
        "the ground took {total:.0} N·s out of {fall_momentum:.0}"
    );
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with a controller: run in release (tools/test.sh does)"
)]
fn rolling_tyres_do_not_slide_and_hard_braking_makes_them() {
    let mut ride = common::ride_in(PhysicsModel::Exact, ControllerKind::ARCADE, 15.0, 1);
    common::ride(&mut ride, 4.0, 0.0);
    let sim = ride.sim();
    let (rear, front) = sim.bike().tyre_slip(sim.world(), sim.up());
    let speed = sim.bike().forward_speed(sim.world(), sim.up());
    let rim = sim.bike().rear_rim_speed(sim.world());
    assert!(
        rear < 0.3 && front < 0.3,
        "rolling: slips {rear:.2}, {front:.2} m/s"
    );
    assert!(
        (rim / speed - 1.0).abs() < 0.05,
        "rim {rim:.2} m/s, road {speed:.2} m/s"
    );
    assert!(
        sim.ground_blow() < 10.0,
        "rolling on flat: {:.1} N·s",
        sim.ground_blow()
    );
    ride.set_intent(Intent {
        drive: DriveInput {
            throttle: 0.0,
            brake: 1.0,
            max_speed: 15.0 / 3.6,
        },
        ..*ride.intent()
    });
    let mut most = 0.0_f64;
    for _ in 0..common::FRAMES_PER_SECOND {
        ride.step();
        let sim = ride.sim();
        let (rear, front) = sim.bike().tyre_slip(sim.world(), sim.up());
        most = most.max(rear.max(front));
    }
    assert!(
        most > 1.0,
        "full brake: the tyres slid at most {most:.2} m/s"
    );
}
