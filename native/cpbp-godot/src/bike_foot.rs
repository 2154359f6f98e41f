//! `BikeFoot`: one of the rider's feet as `BikeSimulation.get_feet()` reports it.

use cpbp_core::bike::FootState;
use godot::prelude::*;

use crate::convert::vector3;

/// One of the rider's feet in the last control step (read-only).
#[derive(GodotClass)]
#[class(no_init, base=RefCounted)]
pub struct BikeFoot {
    /// Put down: below walking pace with the throttle closed.
    #[var(no_set)]
    down: bool,
    /// Stood on the ground in the last step.
    #[var(no_set)]
    on_ground: bool,
    /// The sole's centre in the frame body's frame: `get_body_transform(FRAME) * on_frame`
    /// is where it is.
    #[var(no_set)]
    on_frame: Vector3,
}

impl BikeFoot {
    pub fn of(foot: &FootState) -> Gd<Self> {
        Gd::from_object(Self {
            down: foot.down,
            on_ground: foot.on_ground,
            on_frame: vector3(foot.on_frame),
        })
    }
}
