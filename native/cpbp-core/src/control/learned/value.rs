//! The learned cost-to-go (issue 59): a [`Mlp`] V(state, goal, remaining) estimating the
//! cost a planner's trajectory adds over the `remaining` seconds of the full horizon
//! after a shortened one ends, so that a rollout stopped early is costed as if it went
//! on ("Plan Online, Learn Offline", Lowrey et al. 2019; TD-MPC, Hansen et al. 2022). It
//! sees what the policy sees and the time left; it answers the cost's logarithm
//! (`value_target`), because the costs span orders of magnitude: a few units riding on,
//! hundreds a step once a part other than a wheel touches the ground.

use std::path::Path;
use std::sync::OnceLock;

use super::features::{FEATURE_COUNT, FEATURE_NAMES};
use super::mlp::{Mlp, ModelError, NetworkParts, NetworkShape, NonFiniteFeature};

/// The `format` a cost-to-go file's metadata must name.
pub const VALUE_FORMAT: &str = "counter-steer-value";
/// Its inputs: the policy's features, then the seconds of horizon left.
pub const VALUE_INPUT_COUNT: usize = FEATURE_COUNT + 1;
/// The name of its last input.
pub const REMAINING_INPUT: &str = "remaining_s";

/// What a cost-to-go file holds: the features and the time left in, the cost's log out.
pub fn value_shape() -> &'static NetworkShape {
    static SHAPE: OnceLock<NetworkShape> = OnceLock::new();
    SHAPE.get_or_init(|| NetworkShape {
        kind: "cost-to-go",
        format: VALUE_FORMAT,
        inputs: FEATURE_NAMES
            .iter()
            .chain(&[REMAINING_INPUT])
            .map(|s| s.to_string())
            .collect(),
        outputs: vec!["log_cost_to_go".into()],
    })
}

/// What the network learns to answer for a cost-to-go `cost`: ln(1 + cost).
pub fn value_target(cost: f64) -> f32 {
    cost.max(0.0).ln_1p() as f32
}

/// The cost-to-go network, checked and ready to evaluate.
pub struct ValueNetwork(Mlp);

impl ValueNetwork {
    /// Checks the shapes and numbers of `parts`.
    pub fn new(parts: NetworkParts) -> Result<Self, ModelError> {
        Mlp::new(parts, value_shape()).map(Self)
    }

    /// Reads a model file.
    pub fn load(path: &Path) -> Result<Self, ModelError> {
        Mlp::load(path, value_shape()).map(Self)
    }

    /// Reads a model from a file's bytes.
    pub fn parse(bytes: &[u8]) -> Result<Self, ModelError> {
        Mlp::parse(bytes, value_shape()).map(Self)
    }

    /// The model file's bytes: safetensors, with the metadata `parse` checks.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.0.to_bytes(value_shape())
    }

    pub fn parts(&self) -> &NetworkParts {
        self.0.parts()
    }

    /// The cost a planner's trajectory adds over `remaining_s` more seconds from the state
    /// `features` describe (never below 0).
    pub fn cost_to_go(
        &self,
        features: &[f64; FEATURE_COUNT],
        remaining_s: f64,
    ) -> Result<f64, NonFiniteFeature> {
        let mut inputs = [0.0; VALUE_INPUT_COUNT];
        inputs[..FEATURE_COUNT].copy_from_slice(features);
        inputs[FEATURE_COUNT] = remaining_s;
        let mut log_cost = [0.0];
        self.0.evaluate(&inputs, &mut log_cost)?;
        Ok(log_cost[0].exp_m1().max(0.0))
    }
}
