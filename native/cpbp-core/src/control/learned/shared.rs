//! The policy network as the controllers hold it: loaded once, shared by the ride and
//! every rollout world, or the reason there is none (the `learned` and `guided`
//! controllers then say so and drive as arcade and combined do).

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use super::{ModelError, PolicyNetwork};
use crate::bike::BikeParams;

/// Where a bike's learned model lives in the project, by the bike file's name without
/// `.tres` (`BikeFile::key`; `REFERENCE_BIKE` for the reference bike): a model belongs
/// to the bike it was trained on, so each bike file has its own, and `make train BIKE=`
/// writes it there (`res://` + this in the game; from the repository's root for the
/// tools).
pub fn model_path(bike: &str) -> String {
    format!("models/policy-{bike}.safetensors")
}

/// The model file of the bike called `bike` in this source tree: what the headless
/// tools (the scenario tool, the benchmarks, the fingerprint) ride with.
pub fn project_model(bike: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(model_path(bike))
}

/// The network of the bike called `bike` (`project_model`), loaded on the first call and
/// shared after; a bike without a model of its own gets the reason, naming the bike.
pub fn project_policy(bike: &str) -> LoadedPolicy {
    static POLICIES: Mutex<Vec<(String, LoadedPolicy)>> = Mutex::new(Vec::new());
    let mut loaded = POLICIES.lock().unwrap_or_else(|p| p.into_inner());
    if let Some((_, policy)) = loaded.iter().find(|(name, _)| name == bike) {
        return policy.clone();
    }
    let path = project_model(bike);
    let policy = if path.exists() {
        LoadedPolicy::load(&path)
    } else {
        LoadedPolicy::missing(no_model_of_its_own(bike))
    };
    loaded.push((bike.to_owned(), policy.clone()));
    policy
}

/// What a bike without a model of its own is told, where the game and the tools load it.
pub fn no_model_of_its_own(bike: &str) -> String {
    format!(
        "the bike {bike} has no learned model of its own ({} is missing; make train \
         BIKE=<its file> trains one): guided plans without it and learned is not offered",
        model_path(bike)
    )
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
