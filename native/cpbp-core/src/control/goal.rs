//! What the player asks of one control step, in the form every controller reads it: the
//! lean the turn command asks for, throttle and brake, and where the rider's weight goes.

use crate::bike::{pitch_request, DriveInput, PitchRequest, RiderPosition};

#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Goal {
    /// Lean (rad, positive right): the turn command's at the current speed (eq. 4.4).
    pub lean: f64,
    /// Throttle and brake go to the rear wheel directly, not through a planner.
    pub drive: DriveInput,
    /// The rider's weight: the waist pose every controller holds, and the planners' cost
    /// on the rider's centre of mass.
    pub rider: RiderPosition,
}

impl Goal {
    /// A lean and a drive, the rider in the riding pose.
    pub fn riding(lean: f64, drive: DriveInput) -> Self {
        Self {
            lean,
            drive,
            rider: RiderPosition::NEUTRAL,
        }
    }

    /// The pitch the rider's weight asks for: a wheelie, a turn in the air
    /// (`bike::PitchRequest`).
    pub fn pitch_request(&self) -> PitchRequest {
        pitch_request(&self.rider, &self.drive)
    }
}
