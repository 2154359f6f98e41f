//! The learned controller (thesis §6.3's future work): a network distilled from the
//! planner's choices, cheap enough for any machine, alone (`learned`) or as the particle
//! the planner follows (`guided`). This module holds what the game and the data
//! generator share: the features the network sees and the network itself.

mod features;
mod mlp;
mod network;
mod shared;
mod sorted_header;
#[cfg(test)]
mod tests;
mod trim;
mod value;

pub use features::{features, FEATURES_VERSION, FEATURE_COUNT, FEATURE_NAMES};
pub use mlp::{
    f32_bytes, f32_values, Mlp, ModelError, NetworkParts, NetworkShape, NonFiniteFeature,
    MODEL_FORMAT_VERSION,
};
pub use network::{
    output_entries, output_names, policy_shape, PolicyNetwork, MODEL_FORMAT, OUTPUT_COUNT,
};
pub use shared::{
    model_path, no_model_of_its_own, project_model, project_policy, project_value,
    value_model_path, LearnedModel, Loaded, LoadedPolicy, LoadedValue,
};
pub use sorted_header::{serialize_sorted, sort_header};
pub use trim::{LeanTrim, TRIM_GAIN, TRIM_LIMIT, TRIM_MIN_SPEED, TRIM_WINDOW};
pub use value::{
    value_shape, value_target, ValueNetwork, REMAINING_INPUT, VALUE_FORMAT, VALUE_INPUT_COUNT,
};

use glam::DVec3;

use crate::bike::{Bike, Controls};
use crate::control::Goal;
use crate::ode::World;

impl PolicyNetwork {
    /// The controls the network chooses for the next step of `bike` towards `goal`, the
    /// rear wheel's entries set by the player's throttle and brake as for every
    /// controller. A non-finite feature (a state already broken) is reported instead.
    pub fn controls(
        &self,
        bike: &Bike,
        world: &World,
        goal: &Goal,
        up: DVec3,
    ) -> Result<Controls, NonFiniteFeature> {
        let outputs = self.evaluate(&features(bike, world, goal, up))?;
        let mut controls = Controls::default();
        for (&entry, &value) in output_entries().iter().zip(&outputs) {
            controls.set(entry, value);
        }
        goal.drive.apply(bike.params().wheel_radius, &mut controls);
        Ok(controls)
    }
}
