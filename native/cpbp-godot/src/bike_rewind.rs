//! `BikeSimulation`'s rewind: the ride put back up to `rewind_seconds`, exactly
//! (`cpbp_core::ride`'s history), for the game's rewind button.

use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

/// Why a node whose ride is not built yet cannot rewind.
const NOT_STARTED: &str = "the ride has not started";

#[godot_api(secondary)]
impl BikeSimulation {
    /// Puts the ride back `seconds` (as far as its history goes, when that is shorter):
    /// `rewound` says how far it went (0: not at all), `why` why not ("nothing to rewind
    /// yet: ride first").
    #[func]
    fn rewind(&mut self, seconds: f64) -> VarDictionary {
        let outcome = match self.ride.as_mut() {
            Some(ride) => ride.rewind(seconds).map_err(|refusal| refusal.to_string()),
            None => Err(NOT_STARTED.to_owned()),
        };
        if outcome.is_ok() {
            // Drawn from here: no blend from the moment the rewind left.
            self.remember_poses();
        }
        let (rewound, why) = match outcome {
            Ok(rewound) => (rewound, String::new()),
            Err(why) => (0.0, why),
        };
        vdict! { "rewound" => rewound, "why" => why.as_str() }
    }

    /// Why a rewind would do nothing now ("": it would go back), in the player's words.
    #[func]
    fn get_rewind_refusal(&self) -> GString {
        match self.ride.as_ref() {
            Some(ride) => ride
                .rewind_refusal()
                .map_or_else(GString::new, |refusal| refusal.to_string().as_str().into()),
            None => NOT_STARTED.into(),
        }
    }

    /// How far back (s) a rewind can go now.
    #[func]
    fn get_rewindable(&self) -> f64 {
        self.ride.as_ref().map_or(0.0, |ride| ride.rewindable())
    }
}
