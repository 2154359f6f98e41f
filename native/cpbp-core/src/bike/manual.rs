//! Driving without a balance controller (the registry's `manual`, for inspecting the
//! physics in tests and tools): the rider holds the riding pose, the triggers drive the
//! rear wheel, and the steering follows a rate input and springs back to centre when it
//! is released.

use super::controls::{index, Controls};
use super::drive::DriveInput;
use super::model::Bike;
use crate::ode::World;

/// Rider pose servo gain (1/s).
pub const POSE_GAIN: f64 = 5.0;
/// How fast (1/s) released steering returns to centre.
const STEER_RETURN: f64 = 4.0;

/// Controls for one step of manual driving; `steer_rate` in rad/s, positive to the left.
pub fn manual_controls(
    bike: &Bike,
    world: &World,
    drive: &DriveInput,
    steer_rate: f64,
) -> Controls {
    let mut controls = Controls::default();
    bike.pose_hold(world, POSE_GAIN, &mut controls);
    drive.apply(bike.params().wheel_radius, &mut controls);
    let rate = if steer_rate.is_finite() {
        steer_rate
    } else {
        0.0
    };
    let (angle, _) = bike.steering(world);
    let steer = if rate == 0.0 {
        -STEER_RETURN * angle
    } else {
        rate
    };
    controls.set(index::STEER, steer);
    controls
}
