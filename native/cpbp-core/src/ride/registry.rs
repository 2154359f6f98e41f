//! Every controller there is, in one list: the menus, the HUD, settings files, the
//! experiment, the scenario tool and the tests all read it (GDScript and the Python tools
//! through the native module). A controller is an entry: its stable name, what menus
//! show, whether players pick it, and how it drives (by itself on the game thread, or a
//! planner on the planning thread). Adding one is its own file with its entry and one
//! line in [`ControllerKind::ALL`].

use std::fmt;
use std::hash::{Hash, Hasher};

use super::controller::{Controller, PlannerSettings};
use super::drivers::{ArcadeDriver, LearnedDriver, ManualDriver, PlannerDriver};
use crate::control::{planner, PlannerSpec};
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
        drives: Drives::Plans(&planner::OPTIMIZER),
    });
    /// C-PBP warm-started with the arcade controller's trajectory.
    pub const COMBINED: Self = Self(&ControllerEntry {
        name: "combined",
        label: "Combined (C-PBP + arcade)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&planner::COMBINED),
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
        drives: Drives::Plans(&planner::SAMPLING),
    });
    /// MPPI (a baseline planner).
    pub const MPPI: Self = Self(&ControllerEntry {
        name: "mppi",
        label: "MPPI (baseline)",
        offered: true,
        uses_network: false,
        drives: Drives::Plans(&planner::MPPI),
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
        drives: Drives::Plans(&planner::GUIDED),
    });
    /// Nobody balances: the bar follows the steering rate input (for inspecting physics).
    pub const MANUAL: Self = Self(&ControllerEntry {
        name: "manual",
        label: "Manual (nobody balances)",
        offered: false,
        uses_network: false,
        drives: Drives::Itself(ManualDriver::boxed),
    });

    /// The registry, in the order the menus list them and the game cycles through them.
    pub const ALL: &'static [Self] = &[
        Self::OPTIMIZER,
        Self::COMBINED,
        Self::ARCADE,
        Self::SAMPLING,
        Self::MPPI,
        Self::LEARNED,
        Self::GUIDED,
        Self::MANUAL,
    ];

    /// The controller `entry` describes (a registry line, or a controller under test).
    pub const fn new(entry: &'static ControllerEntry) -> Self {
        Self(entry)
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
        Self::ALL.iter().copied().find(|k| k.name() == name)
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
