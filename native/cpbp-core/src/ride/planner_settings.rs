//! How the planners plan, and how the settings schema's values say it: the game's node
//! and the headless tools build the planners' settings through one mapping
//! (`PlannerSettings::from_values`), so a setting given to a tool (`cpbp-scenarios --set
//! horizon=0.6`) plans as it plans in the game.

use std::time::Duration;

use crate::control::learned::{LoadedPolicy, LoadedValue};
use crate::control::{CostTolerances, PlanWait, PlanningConfig};
use crate::physics::{PhysicsModel, RolloutStepping};
use crate::settings::{self, SettingValues};

/// How the planners plan: the planning settings, the learned network and how long the
/// ride waits for a plan.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannerSettings {
    /// Every planner's settings; `planning.trajectories` is N, or where the automatic
    /// choice starts from.
    pub planning: PlanningConfig,
    /// The learned network: the learned controller drives with it, and the ride hands it
    /// to a planner that follows it (guided mode).
    pub network: LoadedPolicy,
    pub wait: PlanWait,
    /// Move N while riding to what this machine plans in time (`AutoTrajectories`).
    /// Only where the ride waits at most a while for a plan: a ride that waits for every
    /// plan is never late, and must repeat exactly whatever the machine.
    pub auto_trajectories: bool,
}

impl PlannerSettings {
    /// Whether N moves with the machine's speed.
    pub fn picks_trajectories(&self) -> bool {
        self.auto_trajectories && matches!(self.wait, PlanWait::AtMost(_))
    }

    /// The planners' settings `values` ask for (each already within its range:
    /// `SettingValues` clamps what is set), rolling out as `physics` prescribes unless
    /// the rollout substeps are set, with `network` for the controllers that follow one
    /// and `value` to end the plans with when the settings ask (`terminal_value`). A
    /// setting `values` does not hold plans at its default.
    pub fn from_values(
        values: &SettingValues,
        physics: PhysicsModel,
        network: LoadedPolicy,
        value: LoadedValue,
    ) -> Self {
        let mut planning = PlanningConfig {
            trajectories: values.count(&settings::TRAJECTORIES),
            horizon: values.number(&settings::HORIZON_S),
            tolerances: CostTolerances {
                lean: values.number(&settings::LEAN_TOLERANCE_DEG).to_radians(),
                rider: values.number(&settings::RIDER_TOLERANCE_CM) / 100.0,
            },
            threads: values.count(&settings::PLANNING_THREADS),
            seed: values.integer(&settings::PLANNER_SEED) as u64,
            parameters: values.clone(),
            terminal_value: values.flag(&settings::TERMINAL_VALUE),
            value_horizon: values.number(&settings::VALUE_HORIZON_S),
            value,
            ..PlanningConfig::default()
        }
        .rolling_out_in(physics);
        let rollout_substeps = values.count(&settings::ROLLOUT_SUBSTEPS);
        if rollout_substeps > 0 {
            planning.rollout_stepping = RolloutStepping::uniform(rollout_substeps);
        }
        Self {
            planning,
            network,
            auto_trajectories: values.flag(&settings::AUTO_TRAJECTORIES),
            wait: if values.flag(&settings::WAIT_FOR_EVERY_PLAN) {
                PlanWait::EveryPlan
            } else {
                let wait_ms = values.number(&settings::PLAN_WAIT_MS);
                PlanWait::AtMost(Duration::from_secs_f64(wait_ms / 1000.0))
            },
        }
    }
}

/// Longest the game waits at a control step for a plan: a frame of 60 Hz less what
/// the step itself and the drawing need, so a slow plan never stalls the game.
pub const GAME_PLAN_WAIT: Duration =
    Duration::from_millis(settings::PLAN_WAIT_MS.default_number() as u64);

impl Default for PlannerSettings {
    /// The game's: the planners' defaults, no network, waiting at most `GAME_PLAN_WAIT`
    /// at a step.
    fn default() -> Self {
        Self {
            planning: PlanningConfig::default(),
            network: LoadedPolicy::default(),
            wait: PlanWait::AtMost(GAME_PLAN_WAIT),
            auto_trajectories: settings::AUTO_TRAJECTORIES.default_number() != 0.0,
        }
    }
}
