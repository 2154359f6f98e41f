//! The policy network as the controllers hold it: loaded once, shared by the ride and
//! every rollout world, or the reason there is none (the `learned` and `guided`
//! controllers then say so and drive as arcade and combined do).

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

use super::{ModelError, PolicyNetwork};
use crate::bike::BikeParams;

/// Where the model lives in the project (`res://` in the game; from the repository's
/// root for the tools). `make train` writes it there.
pub const MODEL_PATH: &str = "models/policy.safetensors";

/// The model file in this source tree: what the headless tools (the scenario tool, the
/// benchmarks, the fingerprint) ride with; the game reads `res://` + [`MODEL_PATH`].
pub fn project_model() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(MODEL_PATH)
}

/// The network in [`project_model`], loaded on the first call and shared after.
pub fn project_policy() -> LoadedPolicy {
    static POLICY: OnceLock<LoadedPolicy> = OnceLock::new();
    POLICY
        .get_or_init(|| LoadedPolicy::load(&project_model()))
        .clone()
}

/// A loaded network, or why none could be.
#[derive(Clone)]
pub struct LoadedPolicy(Result<Arc<PolicyNetwork>, Arc<str>>);

impl LoadedPolicy {
    /// A network ready to drive.
    pub fn ready(network: PolicyNetwork) -> Self {
        Self(Ok(Arc::new(network)))
    }

    /// No network, for `why`.
    pub fn missing(why: impl Into<String>) -> Self {
        Self(Err(why.into().into()))
    }

    /// The model file's bytes (`source` names it in the reason when they are refused).
    pub fn parse(bytes: &[u8], source: &str) -> Self {
        match PolicyNetwork::parse(bytes) {
            Ok(network) => Self::ready(network),
            Err(e) => Self::refused(source, &e),
        }
    }

    /// The model file at `path`.
    pub fn load(path: &Path) -> Self {
        match PolicyNetwork::load(path) {
            Ok(network) => Self::ready(network),
            Err(e) => Self::refused(&path.display().to_string(), &e),
        }
    }

    fn refused(source: &str, error: &ModelError) -> Self {
        Self::missing(format!("the learned model {source} is unusable: {error}"))
    }

    /// The network, if there is one.
    pub fn network(&self) -> Option<&Arc<PolicyNetwork>> {
        self.0.as_ref().ok()
    }

    /// Why there is no network, if there is none.
    pub fn problem(&self) -> Option<&str> {
        self.0.as_ref().err().map(|why| &**why)
    }

    /// What to tell the player when the network was trained on another bike than `bike`
    /// (it drives it all the same, as a controller tuned on one bike drives another).
    pub fn other_bike(&self, bike: &BikeParams) -> Option<String> {
        let network = self.network()?;
        let trained_on = &network.parts().bike;
        (*trained_on != bike.identity()).then(|| {
            format!(
                "the learned model was trained on another bike ({trained_on}, this one is {}): \
                 it may ride it badly; `make train` trains one for this bike",
                bike.identity()
            )
        })
    }
}

impl Default for LoadedPolicy {
    fn default() -> Self {
        Self::missing("no learned model was loaded")
    }
}

/// The same network (not an equal copy), or the same reason.
impl PartialEq for LoadedPolicy {
    fn eq(&self, other: &Self) -> bool {
        match (&self.0, &other.0) {
            (Ok(a), Ok(b)) => Arc::ptr_eq(a, b),
            (Err(a), Err(b)) => a == b,
            _ => false,
        }
    }
}

impl fmt::Debug for LoadedPolicy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Ok(network) => write!(f, "LoadedPolicy({})", network.parts().training),
            Err(why) => write!(f, "LoadedPolicy(none: {why})"),
        }
    }
}
