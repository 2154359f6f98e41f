//! The rider's weight on the right stick: every controller moves the rider's centre of
//! mass where the player asks, keeps the bike up while it does, and lets go when the
//! stick is released.

use crate::common;

use cpbp_core::bike::{RiderPosition, COM_REACH_FORWARD, COM_REACH_RIGHT};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use glam::DVec3;

/// Rides `seconds` asking for `position`; returns the rider's mean offset over the last
/// second (frame axes, m) and the largest lean (rad) seen. With the weight back the
/// throttle is closed (the weight back with the throttle open asks for a wheelie, which
/// `wheelie_control.rs` tests); nothing slows the bike, so it rolls on at its speed.
fn hold(ride: &mut Ride, position: RiderPosition, seconds: f64) -> (DVec3, f64) {
    let mut drive = ride.intent().drive;
    drive.throttle = if position.forward < 0.0 { 0.0 } else { 1.0 };
    ride.set_intent(Intent {
        rider: position,
        drive,
        ..*ride.intent()
    });
    let steps = (seconds * common::FRAMES_PER_SECOND as f64) as usize;
    let (mut sum, mut max_lean) = (DVec3::ZERO, 0f64);
    for step in 0..steps {
        let events = ride.step();
        assert!(events.crashed.is_none(), "crashed: {:?}", events.crashed);
        max_lean = max_lean.max(common::lean(ride).abs());
        if step + common::FRAMES_PER_SECOND >= steps {
            let sim = ride.sim();
            sum += sim.bike().rider_offset(sim.world());
        }
    }
    (sum / common::FRAMES_PER_SECOND as f64, max_lean)
}

const FORWARD: RiderPosition = RiderPosition {
    forward: 1.0,
    right: 0.0,
};
const BACK: RiderPosition = RiderPosition {
    forward: -1.0,
    right: 0.0,
};
const RIGHT: RiderPosition = RiderPosition {
    forward: 0.0,
    right: 1.0,
};
const LEFT: RiderPosition = RiderPosition {
    forward: 0.0,
    right: -1.0,
};

/// Each full-stick direction in turn, then released, at 15 km/h in the game's physics:
/// the offsets reached, in order forward, back, right, left, released. Forward straight to
/// back: where the rider ends up must not depend on where he came from.
fn ride_every_direction(kind: ControllerKind) -> Vec<DVec3> {
    let mut ride = common::ride_in(PhysicsModel::Exact, kind, 15.0, 10);
    let (at_rest, _) = hold(&mut ride, RiderPosition::NEUTRAL, 2.0);
    assert!(at_rest.length() < 0.02, "{kind:?} before: {at_rest:?}");
    [FORWARD, BACK, RIGHT, LEFT, RiderPosition::NEUTRAL]
        .into_iter()
        .map(|position| {
            // Released, nothing in the cost holds the rider: only the pose prior brings
            // him back, which takes longer than a push to where the stick asks.
            let seconds = if position == RiderPosition::NEUTRAL {
                4.0
            } else {
                2.5
            };
            let (offset, lean) = hold(&mut ride, position, seconds);
            assert!(
                lean < 10f64.to_radians(),
                "{kind:?} {position:?}: leaned {:.1}°",
                lean.to_degrees()
            );
            offset
        })
        .collect()
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_arcade_controllers_pose_hold_moves_the_weight_where_the_stick_asks() {
    let [forward, back, right, left, released] = ride_every_direction(ControllerKind::ARCADE)[..]
    else {
        unreachable!()
    };
    assert!(forward.x > 0.8 * COM_REACH_FORWARD, "{forward:?}");
    assert!(back.x < -0.8 * COM_REACH_FORWARD, "{back:?}");
    assert!(right.z > 0.8 * COM_REACH_RIGHT, "{right:?}");
    assert!(left.z < -0.8 * COM_REACH_RIGHT, "{left:?}");
    assert!(released.length() < 0.01, "released: {released:?}");
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn the_planners_put_the_weight_where_the_stick_asks() {
    for kind in [ControllerKind::COMBINED, ControllerKind::OPTIMIZER] {
        let [forward, back, right, left, released] = ride_every_direction(kind)[..] else {
            unreachable!()
        };
        assert!(forward.x > 0.8 * COM_REACH_FORWARD, "{kind:?} {forward:?}");
        assert!(back.x < -0.8 * COM_REACH_FORWARD, "{kind:?} {back:?}");
        assert!(right.z > 0.8 * COM_REACH_RIGHT, "{kind:?} {right:?}");
        assert!(left.z < -0.8 * COM_REACH_RIGHT, "{kind:?} {left:?}");
        // Released, the rider is free again: back near the riding pose.
        assert!(
            released.x.abs() < 0.03 && released.z.abs() < 0.03,
            "{kind:?} {released:?}"
        );
    }
}
