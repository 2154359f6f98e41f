//! What a ride's steps tell the scene: crashes, landings and recoveries as signals, and a
//! controller that failed, reported once with an error.

use cpbp_core::ride::Ride;
use cpbp_core::simulation::StepEvents;
use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

impl BikeSimulation {
    /// Emits the signals for a step's events.
    pub(crate) fn emit(&mut self, events: StepEvents) {
        if let Some(cause) = events.crashed {
            self.signals()
                .crashed()
                .emit(&GString::from(cause.describe().as_str()));
        }
        if events.landed {
            self.signals().landed().emit();
        }
        if let Some(reason) = events.recovered_from {
            godot_warn!("BikeSimulation: the physics blew up ({reason})");
            self.signals()
                .recovered()
                .emit(&GString::from(reason.as_str()));
            self.remember_poses();
        }
    }

    /// Reports a controller failure once, when it happens.
    pub(crate) fn report_failure(&mut self) {
        let failure = self
            .ride
            .as_ref()
            .and_then(Ride::failure)
            .map(str::to_owned);
        if failure.is_some() == self.failure_reported {
            return;
        }
        self.failure_reported = failure.is_some();
        if let Some(reason) = failure {
            let label = self.controller_kind().label();
            if self.ride.as_ref().is_some_and(Ride::controller_died) {
                godot_error!(
                    "BikeSimulation: the {label} controller cannot drive as itself: {reason}"
                );
            } else {
                // Known and shown on the HUD (a missing model was warned of as it loaded).
                godot_print!(
                    "BikeSimulation: the {label} controller cannot drive as itself: {reason}"
                );
            }
            self.signals()
                .controller_failed()
                .emit(&GString::from(reason.as_str()));
        }
    }
}
