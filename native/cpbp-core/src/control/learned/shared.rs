//! The learned networks as the controllers hold them: loaded once, shared by the ride and
//! every rollout world, or the reason there is none (the `learned` and `guided`
//! controllers then say so and drive as arcade and combined do; a planner without its
//! cost-to-go plans its full horizon).

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use super::{ModelError, NetworkParts, PolicyNetwork, ValueNetwork};
use crate::bike::BikeParams;

/// A kind of learned network the game loads.
pub trait LearnedModel: Sized {
    /// What messages call it ("learned model", "learned cost-to-go").
    const NAME: &'static str;
    fn load(path: &Path) -> Result<Self, ModelError>;
    fn parse(bytes: &[u8]) -> Result<Self, ModelError>;
    fn parts(&self) -> &NetworkParts;
}

impl LearnedModel for PolicyNetwork {
    const NAME: &'static str = "learned model";
    fn load(path: &Path) -> Result<Self, ModelError> {
        PolicyNetwork::load(path)
    }
    fn parse(bytes: &[u8]) -> Result<Self, ModelError> {
        PolicyNetwork::parse(bytes)
    }
    fn parts(&self) -> &NetworkParts {
        PolicyNetwork::parts(self)
    }
}

impl LearnedModel for ValueNetwork {
    const NAME: &'static str = "learned cost-to-go";
    fn load(path: &Path) -> Result<Self, ModelError> {
        ValueNetwork::load(path)
    }
    fn parse(bytes: &[u8]) -> Result<Self, ModelError> {
        ValueNetwork::parse(bytes)
    }
    fn parts(&self) -> &NetworkParts {
        ValueNetwork::parts(self)
    }
}

/// Where a bike's learned model lives in the project, by the bike file's name without
/// `.tres` (`BikeFile::key`; `REFERENCE_BIKE` for the reference bike): a model belongs
/// to the bike it was trained on, so each bike file has its own, and `make train BIKE=`
/// writes it there (`res://` + this in the game; from the repository's root for the
/// tools).
pub fn model_path(bike: &str) -> String {
    format!("models/policy-{bike}.safetensors")
}

/// Where a bike's learned cost-to-go lives in the project, beside its policy
/// (`model_path`).
pub fn value_model_path(bike: &str) -> String {
    format!("models/value-{bike}.safetensors")
}

/// The model file of the bike called `bike` in this source tree: what the headless
/// tools (the scenario tool, the benchmarks, the fingerprint) ride with.
pub fn project_model(bike: &str) -> PathBuf {
    project_file(&model_path(bike))
}

fn project_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path)
}

/// The network of the bike called `bike` (`project_model`), loaded on the first call and
/// shared after; a bike without a model of its own gets the reason, naming the bike.
pub fn project_policy(bike: &str) -> LoadedPolicy {
    static POLICIES: Mutex<Vec<(String, LoadedPolicy)>> = Mutex::new(Vec::new());
    load_once(&POLICIES, bike, &model_path(bike), || {
        no_model_of_its_own(bike)
    })
}

/// The cost-to-go of the bike called `bike` in this source tree (`value_model_path`),
/// loaded on the first call and shared after.
pub fn project_value(bike: &str) -> LoadedValue {
    static VALUES: Mutex<Vec<(String, LoadedValue)>> = Mutex::new(Vec::new());
    let path = value_model_path(bike);
    load_once(&VALUES, bike, &path, || {
        format!(
            "the bike {bike} has no learned cost-to-go ({path} is missing; make train \
             BIKE=<its file> trains one): the planners plan their whole horizon"
        )
    })
}

/// The network at the project's `path` for `bike`, from `cache` or loaded into it; the
/// reason `missing` gives when there is no such file.
fn load_once<N: LearnedModel>(
    cache: &Mutex<Vec<(String, Loaded<N>)>>,
    bike: &str,
    path: &str,
    missing: impl FnOnce() -> String,
) -> Loaded<N> {
    let mut loaded = cache.lock().unwrap_or_else(|p| p.into_inner());
    if let Some((_, network)) = loaded.iter().find(|(name, _)| name == bike) {
        return network.clone();
    }
    let file = project_file(path);
    let network = if file.exists() {
        Loaded::load(&file)
    } else {
        Loaded::missing(missing())
    };
    loaded.push((bike.to_owned(), network.clone()));
    network
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
pub struct Loaded<N>(Result<Arc<N>, Arc<str>>);

/// The policy network, or why there is none.
pub type LoadedPolicy = Loaded<PolicyNetwork>;
/// The cost-to-go network, or why there is none.
pub type LoadedValue = Loaded<ValueNetwork>;

impl<N> Clone for Loaded<N> {
    fn clone(&self) -> Self {
        Self(self.0.clone())
    }
}

impl<N: LearnedModel> Loaded<N> {
    /// A network ready to drive.
    pub fn ready(network: N) -> Self {
        Self(Ok(Arc::new(network)))
    }

    /// No network, for `why`.
    pub fn missing(why: impl Into<String>) -> Self {
        Self(Err(why.into().into()))
    }

    /// The model file's bytes (`source` names it in the reason when they are refused).
    pub fn parse(bytes: &[u8], source: &str) -> Self {
        match N::parse(bytes) {
            Ok(network) => Self::ready(network),
            Err(e) => Self::refused(source, &e),
        }
    }

    /// The model file at `path`.
    pub fn load(path: &Path) -> Self {
        match N::load(path) {
            Ok(network) => Self::ready(network),
            Err(e) => Self::refused(&path.display().to_string(), &e),
        }
    }

    fn refused(source: &str, error: &ModelError) -> Self {
        Self::missing(format!("the {} {source} is unusable: {error}", N::NAME))
    }

    /// The network, if there is one.
    pub fn network(&self) -> Option<&Arc<N>> {
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
                "the {} was trained on another bike ({trained_on}, this one is {}): \
                 it may ride it badly; `make train` trains one for this bike",
                N::NAME,
                bike.identity()
            )
        })
    }
}

impl<N: LearnedModel> Default for Loaded<N> {
    fn default() -> Self {
        Self::missing(format!("no {} was loaded", N::NAME))
    }
}

/// The same network (not an equal copy), or the same reason.
impl<N> PartialEq for Loaded<N> {
    fn eq(&self, other: &Self) -> bool {
        match (&self.0, &other.0) {
            (Ok(a), Ok(b)) => Arc::ptr_eq(a, b),
            (Err(a), Err(b)) => a == b,
            _ => false,
        }
    }
}

impl<N: LearnedModel> fmt::Debug for Loaded<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Ok(network) => write!(f, "Loaded({}: {})", N::NAME, network.parts().training),
            Err(why) => write!(f, "Loaded(no {}: {why})", N::NAME),
        }
    }
}
