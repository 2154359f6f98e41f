//! Every controller there is, in one list: the menus, the HUD, settings files, the
//! experiment, the scenario tool and the tests all read it (GDScript and the Python tools
//! through the native module). A controller is an entry: its stable name, what menus
//! show, whether players pick it, and how it drives (by itself on the game thread, or a
//! planner on the planning thread). Adding one is its own file (a planner: its own
//! folder, `control/<planner>/`) with its entry and one line in
//! [`ControllerKind::BUILT_IN`]; a mod, or a test, registers its own at run time
//! ([`ControllerKind::register`]) and it then reaches every reader as a built-in does,
//! its planner's parameters included (`ride::schema`).

use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::{PoisonError, RwLock};

use super::controller::Controller;
use super::drivers::{ArcadeDriver, LearnedDriver, ManualDriver, PlannerDriver};
use super::schema;
use super::PlannerSettings;
use crate::control::{cpbp, mppi, sampling, PlannerSpec};
use crate::settings::Setting;
use crate::simulation::Simulation;

/// A controller's entry in the registry.
#[derive(Debug)]
pub struct ControllerEntry {
    /// What settings files, the experiment's CSV and the command line call it.
    pub name: &'static str,
    /// What menus show.
    pub label: &'static str,
    /// Whether players pick it (menus, the game's cycle); manual is for tests and tools.
    pub offered: bool,
    /// Whether it drives with the learned network (and needs its model file).
    pub uses_network: bool,
    pub drives: Drives,
}

/// How a controller drives.
#[derive(Debug)]
pub enum Drives {
    /// By itself, on the game thread, once per control step.
    Itself(fn() -> Box<dyn Controller>),
    /// By planning trajectories on the planning thread (and so has plans to draw and
    /// time).
    Plans(&'static PlannerSpec),
}

/// A controller of the registry (compared by name).
#[derive(Clone, Copy)]
pub struct ControllerKind(&'static ControllerEntry);

impl ControllerKind {
    /// C-PBP alone (thesis §4.3).
    pub const OPTIMIZER: Self = Self(&ControllerEntry {
        name: "optimizer",
        label: "Optimizer (C-PBP)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&cpbp::OPTIMIZER),
    });
    /// C-PBP warm-started with the arcade controller's trajectory.
    pub const COMBINED: Self = Self(&ControllerEntry {
        name: "combined",
        label: "Combined (C-PBP + arcade)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&cpbp::COMBINED),
    });
    /// The PD controller on the steering of the thesis (§4.3.2).
    pub const ARCADE: Self = Self(&ControllerEntry {
        name: "arcade",
        label: "Arcade (PD)",
        offered: true,
        uses_network: false,
        drives: Drives::Itself(ArcadeDriver::boxed),
    });
    /// MuJoCo MPC's predictive sampling (a baseline planner).
    pub const SAMPLING: Self = Self(&ControllerEntry {
        name: "sampling",
        label: "Predictive sampling (baseline)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&sampling::SAMPLING),
    });
    /// MPPI (a baseline planner).
    pub const MPPI: Self = Self(&ControllerEntry {
        name: "mppi",
        label: "MPPI (baseline)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&mppi::MPPI),
    });
    /// The network distilled from the planner (issue 34): the planner's skill at the
    /// cost of a few matrix products.
    pub const LEARNED: Self = Self(&ControllerEntry {
        name: "learned",
        label: "Learned (network)",
        offered: true,
        uses_network: true,
        drives: Drives::Itself(LearnedDriver::boxed),
    });
    /// C-PBP whose trajectory 1 follows the learned network: the network proposes, a
    /// few trajectories check and refine.
    pub const GUIDED: Self = Self(&ControllerEntry {
        name: "guided",
        label: "Guided (C-PBP + network)",
        offered: true,
        uses_network: true,
        drives: Drives::Plans(&cpbp::GUIDED),
    });
    /// Nobody balances: the bar follows the steering rate input (for inspecting physics).
    pub const MANUAL: Self = Self(&ControllerEntry {
        name: "manual",
        label: "Manual (nobody balances)",
        offered: false,
        uses_network: false,
        drives: Drives::Itself(ManualDriver::boxed),
    });

    /// The built-in controllers, in the order the menus list them and the game cycles
    /// through them.
    pub const BUILT_IN: &'static [Self] = &[
        Self::OPTIMIZER,
        Self::COMBINED,
        Self::ARCADE,
        Self::SAMPLING,
        Self::MPPI,
        Self::LEARNED,
        Self::GUIDED,
        Self::MANUAL,
    ];

    /// The controller `entry` describes (a registry line, or a controller under test
    /// that rides without being registered).
    pub const fn new(entry: &'static ControllerEntry) -> Self {
        Self(entry)
    }

    /// The registry: the built-in controllers, then those registered at run time.
    pub fn all() -> Vec<Self> {
        let registered = REGISTERED.read().unwrap_or_else(PoisonError::into_inner);
        Self::BUILT_IN
            .iter()
            .chain(registered.iter())
            .copied()
            .collect()
    }

    /// Adds `entry` to the registry for the rest of the process: menus, settings files,
    /// the tools and `from_name` then have it, and its planner's parameters join the
    /// settings schema. Refused when its name is taken, or a parameter's name is another
    /// setting's.
    pub fn register(entry: &'static ControllerEntry) -> Result<Self, String> {
        let kind = Self(entry);
        if Self::from_name(entry.name).is_some() {
            return Err(format!("a controller is already called {}", entry.name));
        }
        let parameters = kind.planner().map_or(&[][..], |spec| spec.parameters);
        for parameter in parameters {
            match schema::find(parameter.name) {
                Some(known) if known != *parameter => {
                    return Err(format!(
                        "{}: its parameter {} is another setting's name",
                        entry.name, parameter.name
                    ))
                }
                _ => schema::check_entry(parameter)
                    .map_err(|why| format!("{}: {why}", entry.name))?,
            }
        }
        REGISTERED
            .write()
            .unwrap_or_else(PoisonError::into_inner)
            .push(kind);
        Ok(kind)
    }

    /// Every parameter of the registered planners, each once, in the registry's order.
    pub fn planner_parameters() -> Vec<Setting> {
        let mut all: Vec<Setting> = Vec::new();
        let specs = Self::all().into_iter().filter_map(|k| k.planner());
        for setting in specs.flat_map(|spec| spec.parameters) {
            if all.iter().all(|s| s.name != setting.name) {
                all.push(*setting);
            }
        }
        all
    }

    /// The name settings files, the experiment's CSV and the command line use.
    pub fn name(self) -> &'static str {
        self.0.name
    }

    /// What menus show.
    pub fn label(self) -> &'static str {
        self.0.label
    }

    /// The registered controller named `name`, if there is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::all().into_iter().find(|k| k.name() == name)
    }

    /// Whether players pick it (menus, the game's cycle); manual is for tests and tools.
    pub fn offered(self) -> bool {
        self.0.offered
    }

    /// Whether it drives with the learned network (and needs its model file).
    pub fn uses_network(self) -> bool {
        self.0.uses_network
    }

    /// Whether it plans with trajectories (and so has plans to draw and time).
    pub fn plans(self) -> bool {
        self.planner().is_some()
    }

    /// The planner behind a planning controller.
    pub fn planner(self) -> Option<&'static PlannerSpec> {
        match self.0.drives {
            Drives::Plans(spec) => Some(spec),
            Drives::Itself(_) => None,
        }
    }

    /// A new controller of this kind for `sim`.
    pub fn build(self, sim: &Simulation, planner: &PlannerSettings) -> Box<dyn Controller> {
        match self.0.drives {
            Drives::Itself(build) => build(),
            Drives::Plans(spec) => Box::new(PlannerDriver::new(sim, spec, planner)),
        }
    }
}

/// Controllers registered at run time (`ControllerKind::register`).
static REGISTERED: RwLock<Vec<ControllerKind>> = RwLock::new(Vec::new());

impl PartialEq for ControllerKind {
    fn eq(&self, other: &Self) -> bool {
        self.name() == other.name()
    }
}

impl Eq for ControllerKind {}

impl Hash for ControllerKind {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.name().hash(state);
    }
}

impl fmt::Debug for ControllerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for ControllerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
