//! The node's settings as the ride's: which controller drives, how the planners
//! plan and what the pedals drive. GDScript and the inspector may change them at any
//! time, in any order; before every physics tick they are read, clamped to the core's
//! limits, and handed to the ride when they differ from what it has.

use cpbp_core::control::learned::{LoadedPolicy, LoadedValue};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::ride::PlannerSettings;
use cpbp_core::settings::{ABS, LEAN_SHARE, TERMINAL_VALUE, WAIT_FOR_THROTTLE};

use godot::global::godot_warn;

use crate::bike_simulation::BikeSimulation;

impl BikeSimulation {
    /// The exports, as the ride's settings: GDScript may change them at any time.
    pub(crate) fn sync_settings(&mut self) {
        let kind = self.controller_kind();
        let planner = self.planner_settings();
        if kind.uses_network() && !self.told_other_bike {
            let other = self
                .sim()
                .and_then(|sim| planner.network.other_bike(&sim.config().bike));
            if let Some(why) = other {
                godot_warn!("BikeSimulation: {why}");
                self.told_other_bike = true;
            }
        }
        if let Some(drive) = self.drive().filter(|d| *d != self.intent.drive) {
            self.intent.drive = drive;
            self.apply_intent();
        }
        if let Some(ride) = &mut self.ride {
            if ride.controller() != kind {
                ride.set_controller(kind);
            }
            if ride.planner != planner {
                ride.planner = planner;
            }
            ride.wait_for_throttle = self.settings.flag(&WAIT_FOR_THROTTLE);
            ride.set_aids(self.settings.flag(&ABS), self.settings.number(&LEAN_SHARE));
        }
    }

    /// The learned network the controllers ride with: the file `policy_model` names, or
    /// the bike's own (none, with the reason, for a bike without one).
    pub(crate) fn policy(&self) -> LoadedPolicy {
        if !self.policy_model.is_empty() {
            return crate::policy_model::policy_at(&self.policy_model);
        }
        match crate::policy_model::bike_model(self.bike.as_ref()) {
            Ok(path) => crate::policy_model::policy_at(&path),
            Err(why) => LoadedPolicy::missing(why),
        }
    }

    /// The bike's learned cost-to-go, read only while the settings ask the planners to
    /// end their plans with it (`terminal_value`).
    fn value(&self) -> LoadedValue {
        if !self.settings.flag(&TERMINAL_VALUE) {
            return LoadedValue::default();
        }
        match crate::policy_model::bike_value(self.bike.as_ref()) {
            Ok(path) => crate::policy_model::value_at(&path),
            Err(why) => LoadedValue::missing(why),
        }
    }

    /// The planners' settings the node's settings ask for, rolling out in the built
    /// ride's physics (a change of the export waits for the next build).
    fn planner_settings(&self) -> PlannerSettings {
        let physics = self
            .sim()
            .map_or(PhysicsModel::from(self.physics), |sim| sim.config().physics);
        PlannerSettings::from_values(&self.settings, physics, self.policy(), self.value())
    }
}
