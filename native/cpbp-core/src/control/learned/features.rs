//! What the learned controller sees: one function turns a ride's state and the player's
//! goal into the network's input, used alike by the data generator (labelled by the
//! planner) and by the controller at game time, so the two can never disagree.
//!
//! Values are in SI units (m, m/s, rad, rad/s) in the frame's axes (x forward, y up,
//! z right); the model file carries the mean and spread that normalise them. A change to
//! the list or to how an entry is measured must bump [`FEATURES_VERSION`]: a model trained
//! on the old list is then refused instead of being fed numbers it never saw.

use glam::DVec3;

use crate::bike::{Bike, RIDER_JOINTS};
use crate::control::Goal;
use crate::ode::World;

/// Version of the feature list below; stored in every model and every data shard.
pub const FEATURES_VERSION: u32 = 1;

/// Names of the features, in input order.
pub const FEATURE_NAMES: [&str; FEATURE_COUNT] = [
    "speed",
    "lean",
    "lean_rate",
    "steer",
    "steer_rate",
    "up_x",
    "up_y",
    "up_z",
    "velocity_x",
    "velocity_y",
    "velocity_z",
    "spin_x",
    "spin_y",
    "spin_z",
    "rear_touches",
    "front_touches",
    "rear_compression",
    "front_compression",
    "waist_0",
    "waist_1",
    "waist_2",
    "knee",
    "shoulder_0",
    "shoulder_1",
    "shoulder_2",
    "elbow",
    "wrist_0",
    "wrist_1",
    "wrist_2",
    "rider_offset_x",
    "rider_offset_y",
    "rider_offset_z",
    "goal_lean",
    "goal_lean_error",
    "throttle",
    "brake",
    "speed_error",
    "rider_forward",
    "rider_right",
];

/// How many numbers [`features`] returns.
pub const FEATURE_COUNT: usize = 39;

/// Where the rider's joint angles start in the list.
const RIDER_START: usize = 18;

/// The network's input for the control step about to be taken: the bike's motion and
/// contacts, the rider's pose, and what the player asks (`goal`). `up` points against
/// gravity. A non-finite number in the state comes out as it is: the policy checks
/// (`LearnedPolicy::controls`), since only it knows what to do then.
pub fn features(bike: &Bike, world: &World, goal: &Goal, up: DVec3) -> [f64; FEATURE_COUNT] {
    let to_frame = bike.frame_rotation(world).inverse();
    let frame = bike.body(crate::bike::Part::Frame);
    let speed = bike.forward_speed(world, up);
    let lean = bike.lean(world, up);
    let (steer, steer_rate) = bike.steering(world);
    let up_in_frame = to_frame * up;
    let velocity = to_frame * world.body_linear_velocity(frame);
    let spin = to_frame * world.body_angular_velocity(frame);
    let (rear, front) = bike.wheel_contacts(world);
    let (rear_compression, front_compression) = bike.suspension_compression(world);
    let offset = bike.rider_offset(world);
    let drive = goal.drive.sanitized();
    let (rider, _) = goal.rider.sanitized();
    let mut out = [0.0; FEATURE_COUNT];
    let head = [
        speed,
        lean,
        bike.lean_rate(world, up),
        steer,
        steer_rate,
        up_in_frame.x,
        up_in_frame.y,
        up_in_frame.z,
        velocity.x,
        velocity.y,
        velocity.z,
        spin.x,
        spin.y,
        spin.z,
        f64::from(u8::from(rear)),
        f64::from(u8::from(front)),
        rear_compression,
        front_compression,
    ];
    out[..RIDER_START].copy_from_slice(&head);
    out[RIDER_START..RIDER_START + RIDER_JOINTS].copy_from_slice(&bike.rider_joint_angles(world));
    let tail = [
        offset.x,
        offset.y,
        offset.z,
        goal.lean,
        goal.lean - lean,
        drive.throttle,
        drive.brake,
        drive.max_speed - speed,
        rider.forward,
        rider.right,
    ];
    out[RIDER_START + RIDER_JOINTS..].copy_from_slice(&tail);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_names_match_the_layout() {
        assert_eq!(RIDER_START + RIDER_JOINTS + 10, FEATURE_COUNT);
        assert_eq!(FEATURE_NAMES[RIDER_START], "waist_0");
        assert_eq!(FEATURE_NAMES[RIDER_START + RIDER_JOINTS], "rider_offset_x");
        let mut sorted = FEATURE_NAMES.to_vec();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), FEATURE_COUNT, "every name once");
    }
}
