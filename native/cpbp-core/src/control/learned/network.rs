//! The learned controller's network: the policy, a [`Mlp`] from the features to the
//! control entries the planner decides.

use std::path::Path;
use std::sync::OnceLock;

use super::features::{FEATURE_COUNT, FEATURE_NAMES};
use super::mlp::{Mlp, ModelError, NetworkParts, NetworkShape, NonFiniteFeature};
use crate::bike::{CONTROL_DIM, DRIVE_ENTRIES};

/// The `format` a policy file's metadata must name.
pub const MODEL_FORMAT: &str = "counter-steer-policy";
/// How many control entries the network decides: all but the drive's.
pub const OUTPUT_COUNT: usize = CONTROL_DIM - DRIVE_ENTRIES.len();

/// The control entries the network's outputs set, in output order.
pub fn output_entries() -> [usize; OUTPUT_COUNT] {
    let mut entries = [0; OUTPUT_COUNT];
    let decided = (0..CONTROL_DIM).filter(|i| !DRIVE_ENTRIES.contains(i));
    entries.iter_mut().zip(decided).for_each(|(e, i)| *e = i);
    entries
}

/// Names of the outputs, for the metadata of model and data files: the control entries'
/// indices.
pub fn output_names() -> Vec<String> {
    output_entries().iter().map(|i| format!("u{i}")).collect()
}

/// What a policy file holds: the features in, the decided control entries out.
pub fn policy_shape() -> &'static NetworkShape {
    static SHAPE: OnceLock<NetworkShape> = OnceLock::new();
    SHAPE.get_or_init(|| NetworkShape {
        kind: "policy",
        format: MODEL_FORMAT,
        inputs: FEATURE_NAMES.iter().map(|s| s.to_string()).collect(),
        outputs: output_names(),
    })
}

/// The policy network, checked and ready to evaluate.
pub struct PolicyNetwork(Mlp);

impl PolicyNetwork {
    /// Checks the shapes and numbers of `parts`.
    pub fn new(parts: NetworkParts) -> Result<Self, ModelError> {
        Mlp::new(parts, policy_shape()).map(Self)
    }

    /// Reads a model file.
    pub fn load(path: &Path) -> Result<Self, ModelError> {
        Mlp::load(path, policy_shape()).map(Self)
    }

    /// Reads a model from a file's bytes.
    pub fn parse(bytes: &[u8]) -> Result<Self, ModelError> {
        Mlp::parse(bytes, policy_shape()).map(Self)
    }

    /// The model file's bytes: safetensors, with the metadata `parse` checks.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.0.to_bytes(policy_shape())
    }

    pub fn parts(&self) -> &NetworkParts {
        self.0.parts()
    }

    /// The control entries (in [`output_entries`] order) for `features`.
    pub fn evaluate(
        &self,
        features: &[f64; FEATURE_COUNT],
    ) -> Result<[f64; OUTPUT_COUNT], NonFiniteFeature> {
        let mut out = [0.0; OUTPUT_COUNT];
        self.0.evaluate(features, &mut out)?;
        Ok(out)
    }
}
