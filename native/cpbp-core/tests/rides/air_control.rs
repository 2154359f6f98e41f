//! Air control: in a jump the rider's weight turns the bike's nose (thesis §6.4: "in air
//! this extra control could be used to adjust the bike's lean under the biker to match
//! incoming slopes"). Weight back spins the rear wheel up and its reaction lifts the nose;
//! weight forward brakes it and the nose drops, as riders use throttle and rear brake in
//! the air. The rider's body alone turns the bike only about 3°, and the other way.

use crate::common;

use cpbp_core::bike::{Part, RiderPosition};
use cpbp_core::ride::{ControllerKind, Intent};
use glam::DVec3;

/// The frame's pitch (degrees, nose up) 0.67 s into a jump: the bike thrown level at
/// 8 m/s from 3 m up, wheels turning with the ground speed, the rider's weight at
/// `forward` (−1 back to 1 forward), no triggers.
fn pitch_after_a_jump(kind: ControllerKind, forward: f64) -> f64 {
    let mut sim = common::exact_sim_on(Vec::new(), 3.0);
    let bike = sim.bike().clone();
    let speed = 8.0;
    for part in Part::ALL {
        let body = bike.body(part);
        sim.world_mut()
            .set_body_linear_velocity(body, DVec3::new(speed, 0.0, 0.0));
    }
    let spin = -speed / bike.params().wheel_radius;
    for wheel in [Part::RearWheel, Part::FrontWheel] {
        sim.world_mut()
            .set_body_angular_velocity(bike.body(wheel), DVec3::new(0.0, 0.0, spin));
    }
    let mut ride = common::planned_ride(sim, kind);
    ride.set_intent(Intent {
        lean: Some(0.0),
        rider: RiderPosition {
            forward,
            right: 0.0,
        },
        ..Intent::default()
    });
    for _ in 0..20 {
        ride.step();
        let sim = ride.sim();
        assert_eq!(sim.bike().wheel_contacts(sim.world()), (false, false));
    }
    common::pitch(&ride)
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_riders_weight_turns_the_nose_in_the_air() {
    for kind in [ControllerKind::ARCADE, ControllerKind::COMBINED] {
        let level = pitch_after_a_jump(kind, 0.0);
        let back = pitch_after_a_jump(kind, -1.0);
        let forward = pitch_after_a_jump(kind, 1.0);
        assert!(level.abs() < 1.5, "{kind:?} released: {level:.1}°");
        assert!(back > 6.0, "{kind:?} weight back: {back:.1}°");
        assert!(forward < -6.0, "{kind:?} weight forward: {forward:.1}°");
    }
}
