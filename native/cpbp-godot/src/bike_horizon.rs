//! How far the node's planners look, and whether the bike has the learned cost-to-go that
//! lets them look less far (issue 59): what the HUD shows and what the game asks for.

use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

#[godot_api(secondary)]
impl BikeSimulation {
    /// How far ahead the planners simulate (s): the value horizon while the learned
    /// cost-to-go ends their plans (`is_horizon_ended_by_value`), the whole horizon else.
    #[func]
    fn get_planned_horizon(&self) -> f64 {
        self.ride
            .as_ref()
            .map_or(0.0, |r| r.planner.planning.planned().0)
    }

    /// Whether the learned cost-to-go costs the rest of the horizon after the plans.
    #[func]
    fn is_horizon_ended_by_value(&self) -> bool {
        self.ride
            .as_ref()
            .is_some_and(|r| r.planner.planning.planned().1.is_some())
    }

    /// Whether the bike has a cost-to-go file of its own (models/value-<bike>), readable
    /// or not: the game turns `terminal_value` on only for such a bike, so a bike without
    /// one plans its whole horizon with nothing to report, while a file that cannot be
    /// read is reported as the node reports it.
    #[func]
    fn has_learned_cost_to_go(&self) -> bool {
        crate::policy_model::bike_value(self.bike.as_ref())
            .is_ok_and(|path| godot::classes::FileAccess::file_exists(&path))
    }
}
