//! The bike as a system the C-PBP planner branches (thesis §4.3.1): each particle owns a
//! world built like the master's; a planning step applies a control vector for one
//! control period and costs the squared lean error of eq. 4.7, plus the rider-position
//! error when the player holds the rider's weight somewhere. In a wheelie the lean is
//! measured against the lifted support point, so the balance point costs nothing. A bike
//! with `planners_cost_frame_roll` has its frame's roll costed instead, and one with a
//! `planners_slide_tolerance` its tyres' sideways slide too; one with a
//! `planners_grip_share` asks no deeper lean than that share of its tyres' grip holds, one
//! with `planners_lean_reference` asks it on the way from the plan's start, one with
//! `planners_lean_lookahead` costs the lean its roll is heading for, and one with
//! `planners_rider_hold` keeps the rider's weight near the riding pose unasked.

use std::sync::Arc;

use glam::DVec3;

use super::arcade::ArcadeController;
use super::cpbp::{Priors, RolloutSystem};
use super::lean::{
    current_lean_vector, desired_lean_vector, fall_time_scale, frame_roll_cost, grip_lean_limit,
    lean_ahead, lean_cost, lean_on_the_way, roll_lean_cost,
};
use super::learned::{self, PolicyNetwork, ValueNetwork};
use super::Goal;
use crate::bike::{
    index, rider_position_cost, Bike, Controls, ForceClass, CONTROL_DIM, DRIVE_ENTRIES,
    FORCE_TUNINGS, LOWER, POSE_GAIN, UPPER,
};
use crate::ode::{World, WorldState};
use crate::physics::RolloutStepping;
use crate::settings;

/// How strictly the cost holds each part of the goal: the error that costs as much as
/// one unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CostTolerances {
    /// Eq. 4.7's s (rad).
    pub lean: f64,
    /// The rider's centre of mass from where the player asks (m).
    pub rider: f64,
}

impl Default for CostTolerances {
    fn default() -> Self {
        Self {
            lean: settings::LEAN_TOLERANCE_DEG.default_number().to_radians(),
            rider: settings::RIDER_TOLERANCE_CM.default_number() / 100.0,
        }
    }
}

/// Cost added for every step in which a part other than a wheel touches the ground.
const CRASH_COST: f64 = 400.0;

/// One particle's world and what it needs to step and cost it.
pub struct BikeRollout {
    pub world: World,
    pub bike: Bike,
    pub gravity: DVec3,
    /// Against gravity.
    pub up: DVec3,
    /// One planning step (s), and the ODE steps each planning step of the horizon takes.
    pub step_dt: f64,
    pub stepping: RolloutStepping,
    /// What the player asks during the plan; throttle and brake go to the rear wheel
    /// directly, not through the planner.
    pub goal: Goal,
    pub tolerances: CostTolerances,
    /// The controller this particle follows (combined and guided modes' particle 1).
    pub policy: Option<RolloutPolicy>,
    /// Where the plan starts, read at its first step on a bike with
    /// `planners_lean_reference`: the lean goal approaches the asked lean from there.
    pub start: PlanStart,
    /// The learned cost-to-go that ends a shortened horizon, if the plan's is.
    pub value: Option<TerminalValue>,
    /// Whether its last step ended with a part other than the wheels and feet on the
    /// ground (`RolloutSystem::fallen`).
    pub fallen: bool,
}

/// A learned cost-to-go standing for the seconds a shortened horizon leaves out.
#[derive(Clone)]
pub struct TerminalValue {
    pub network: Arc<ValueNetwork>,
    /// The full horizon less the planned one (s).
    pub remaining_s: f64,
}

/// The costed lean where a plan starts and the time scale of the bike's fall from it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanStart {
    /// Rad, positive right.
    pub lean: f64,
    /// `lean::fall_time_scale` of the centre of mass's height over the contact line (s).
    pub fall_time: f64,
}

/// A controller a particle follows live.
#[derive(Clone)]
pub enum RolloutPolicy {
    /// The arcade controller, with its memory as it was on the master at the start of
    /// the plan.
    Arcade(ArcadeController),
    /// The learned network (it remembers nothing).
    Network(Arc<PolicyNetwork>),
}

impl BikeRollout {
    /// The control vector the planner's `u` stands for: sanitised, with the rear wheel
    /// entries taken from the player's throttle and brake.
    pub fn controls_for(&self, u: &[f64]) -> Controls {
        let mut raw = [0.0; CONTROL_DIM];
        raw.copy_from_slice(&u[..CONTROL_DIM]);
        let (mut controls, _) = Controls::sanitized(&raw);
        self.goal
            .drive
            .apply(self.bike.params().wheel_radius, &mut controls);
        controls
    }

    /// The lean the cost holds now (the frame's roll, or eq. 4.7's centre of mass over the
    /// tyres' contact line, signed about the heading) and how fast the bike falls from it:
    /// where a plan starts, or where a step that looks ahead sets off from.
    fn costed_lean(&self) -> PlanStart {
        let toward =
            self.bike.center_of_mass(&self.world) - self.bike.support_point(&self.world, self.up);
        let lean = if self.bike.params().planners_cost_frame_roll {
            self.bike.lean(&self.world, self.up)
        } else {
            let right = self.bike.heading(&self.world, self.up).cross(self.up);
            toward.dot(right).atan2(toward.dot(self.up))
        };
        PlanStart {
            lean,
            fall_time: fall_time_scale(toward.length(), self.gravity.length()),
        }
    }

    /// The lean the cost asks `step` steps into the plan: the player's, held to the bike's
    /// share of its grip, and on the way to it from the plan's start at the pace the bike
    /// falls by itself (`BikeParams::planners_lean_reference`).
    fn goal_lean(&self, step: usize) -> f64 {
        let params = self.bike.params();
        let asked = match grip_lean_limit(params.tyre_friction, params.planners_grip_share) {
            Some(limit) => self.goal.lean.clamp(-limit, limit),
            None => self.goal.lean,
        };
        if !params.planners_lean_reference {
            return asked;
        }
        let t = (step + 1) as f64 * self.step_dt;
        lean_on_the_way(self.start.lean, asked, t, self.start.fall_time)
    }

    /// The lean cost of a bike whose planners look ahead (`BikeParams::
    /// planners_lean_lookahead`): the costed lean carried on by the frame's roll rate for
    /// the time scale of the bike's fall, against the goal. The frame's rate stands for
    /// the centre of mass's: with the rider held (`planners_rider_hold`) they differ little.
    fn lean_ahead_cost(&self, lean_goal: f64) -> f64 {
        let now = self.costed_lean();
        let rate = self.bike.lean_rate(&self.world, self.up);
        let ahead = lean_ahead(now.lean, rate, now.fall_time);
        frame_roll_cost(ahead, lean_goal, self.tolerances.lean)
    }
}

impl RolloutSystem for BikeRollout {
    type State = WorldState;

    fn save(&self) -> WorldState {
        self.world.snapshot()
    }

    fn restore(&mut self, state: &WorldState) {
        self.world
            .restore(state)
            .expect("every rollout world is built like the master");
    }

    fn step(&mut self, u: &[f64], step: usize) -> Option<f64> {
        let controls = self.controls_for(u);
        if step == 0 && self.bike.params().planners_lean_reference {
            self.start = self.costed_lean();
        }
        let asked = self.goal.pitch_request();
        let period = self.stepping.ode_steps_at(step, self.step_dt);
        let bike = &self.bike;
        let mut crash = 0.0;
        let mut watch = |world: &World, _dt: f64| {
            if bike.part_touching_ground(world).is_some() {
                crash = CRASH_COST;
            }
        };
        let held = bike
            .step_control_period(
                &mut self.world,
                &controls,
                asked,
                self.up,
                period,
                &mut watch,
            )
            .ok()?;
        let params = self.bike.params();
        let lean_goal = self.goal_lean(step);
        let pitching = held.lift > 0.0 || held.air != 0.0 || held.stoppie > 0.0;
        let lean = if params.planners_lean_lookahead && !pitching {
            self.lean_ahead_cost(lean_goal)
        } else if params.planners_cost_frame_roll {
            // The frame's roll is about the heading: a wheelie's pitch never enters it.
            let roll = self.bike.lean(&self.world, self.up);
            frame_roll_cost(roll, lean_goal, self.tolerances.lean)
        } else {
            let heading = self.bike.heading(&self.world, self.up);
            let desired = desired_lean_vector(heading, self.up, lean_goal);
            let current = current_lean_vector(
                self.bike.center_of_mass(&self.world),
                self.bike
                    .support_point_lifted(&self.world, self.up, held.lift - held.stoppie),
            );
            // Pitching on request (a wheelie, a turn in the air), the pitch is the bike's
            // to hold: the planners answer for the roll alone.
            if pitching {
                roll_lean_cost(desired, current, heading, self.tolerances.lean)
            } else {
                lean_cost(desired, current, self.tolerances.lean)
            }
        };
        // Only when asked or held: measuring the rider costs a little in every step.
        let hold = if params.planners_rider_hold > 0.0 {
            params.planners_rider_hold_at(self.bike.forward_speed(&self.world, self.up))
        } else {
            0.0
        };
        let rider = if self.goal.rider.engagement() > 0.0 || hold > 0.0 {
            rider_position_cost(
                &self.goal.rider,
                self.bike.rider_offset(&self.world),
                self.tolerances.rider,
                hold,
            )
        } else {
            0.0
        };
        // Only on a bike that asks: the reference plans as the thesis did.
        let slide_tolerance = params.planners_slide_tolerance;
        let slide = if slide_tolerance > 0.0 {
            (self.bike.tyre_side_slide(&self.world, self.up) / slide_tolerance).powi(2)
        } else {
            0.0
        };
        self.fallen = crash > 0.0;
        Some(lean + rider + crash + slide)
    }

    fn fallen(&self) -> bool {
        self.fallen
    }

    /// Lean, lean rate, steering angle and rate, in units of roughly what one control
    /// step changes (0.1 rad, 1 rad/s): the state the lean cost depends on.
    fn features(&self) -> Vec<f64> {
        let (steer, steer_rate) = self.bike.steering(&self.world);
        vec![
            self.bike.lean(&self.world, self.up) / 0.1,
            self.bike.lean_rate(&self.world, self.up),
            steer / 0.1,
            steer_rate,
        ]
    }

    fn policy(&mut self, _step: usize) -> Option<Vec<f64>> {
        let controls = match self.policy.as_mut()? {
            RolloutPolicy::Arcade(controller) => controller.controls(
                &self.bike,
                &self.world,
                &self.goal,
                self.gravity,
                self.step_dt,
            ),
            // A state the network cannot read (non-finite) is one the particle's cost
            // already condemns: the prior's mean steps it on.
            RolloutPolicy::Network(network) => network
                .controls(&self.bike, &self.world, &self.goal, self.up)
                .ok()?,
        };
        Some(controls.values().to_vec())
    }

    fn trace_point(&self) -> Option<[f64; 3]> {
        Some(self.bike.center_of_mass(&self.world).to_array())
    }

    /// The learned cost-to-go of the rest of the full horizon, when the plan's is
    /// shortened (`BikeRollout::value`); a state it cannot read (non-finite) gets none:
    /// its steps' costs already condemn it. Nor does a plan made while the rider asks for
    /// a wheelie or a stoppie (the goal, so every trajectory of the plan alike): with the
    /// street 390's network the bot's wheelie onto the skate park's platform lifted the
    /// front 12° instead of 19° and the rear wheel did not climb, with or without wheelies
    /// in its training, where the same short plan without it lifts 18° and climbs.
    fn terminal_cost(&self) -> Option<f64> {
        let value = self.value.as_ref()?;
        let asked = self.goal.pitch_request();
        if asked.lift > 0.0 || asked.stoppie > 0.0 {
            return None;
        }
        let seen = learned::features(&self.bike, &self.world, &self.goal, self.up);
        value.network.cost_to_go(&seen, value.remaining_s).ok()
    }

    fn value_features(&self) -> Vec<f64> {
        learned::features(&self.bike, &self.world, &self.goal, self.up).to_vec()
    }

    /// The pose prior (thesis §4.3.1): rider joints towards the riding pose (offset where
    /// the player holds the rider's weight), the steering around its current velocity so
    /// the plan does not jerk the bar.
    fn client_prior(&self) -> Option<(Vec<f64>, Vec<f64>)> {
        let mut mean = vec![0.0; CONTROL_DIM];
        let mut sigma = vec![f64::INFINITY; CONTROL_DIM];
        let (_, steer_rate) = self.bike.steering(&self.world);
        mean[index::STEER] = steer_rate;
        sigma[index::STEER] = 1.5;
        let pose = self.goal.rider.pose();
        for (i, angle) in self
            .bike
            .rider_joint_angles(&self.world)
            .into_iter()
            .enumerate()
        {
            mean[index::WAIST + i] = -POSE_GAIN * (angle - pose[i]);
            sigma[index::WAIST + i] = 0.5;
        }
        Some((mean, sigma))
    }
}

/// Priors for sampling the bike's controls: joint velocities around zero, steering more
/// freely than the rider's joints, force tunings near full strength. C-PBP mutates the
/// sequences it follows by its own scale of σ0 (`cpbp::MUTATION_SCALE`); until it sets
/// one, σm = σ0.
pub fn bike_priors() -> Priors {
    let mut mean = vec![0.0; CONTROL_DIM];
    let mut sigma_static = vec![1.0; CONTROL_DIM];
    let mut sigma_smooth1 = vec![0.5; CONTROL_DIM];
    let mut sigma_smooth2 = vec![0.5; CONTROL_DIM];
    sigma_static[index::STEER] = 4.0;
    sigma_smooth1[index::STEER] = 4.0;
    sigma_smooth2[index::STEER] = 4.0;
    // The force tunings: near full strength, but the rear wheel's, which rolls freely
    // unless the throttle or brake says otherwise.
    for class in 0..FORCE_TUNINGS {
        let i = index::FORCE + class;
        mean[i] = if class == ForceClass::RearWheel as usize {
            0.0
        } else {
            0.9
        };
        sigma_static[i] = 0.2;
        sigma_smooth1[i] = 0.1;
        sigma_smooth2[i] = 0.1;
    }
    // Throttle and brake set the rear wheel: the planner leaves those entries alone.
    let mut planned = vec![true; CONTROL_DIM];
    DRIVE_ENTRIES.iter().for_each(|&i| planned[i] = false);
    Priors {
        mean,
        sigma_static,
        sigma_smooth1,
        sigma_smooth2,
        mutation_scale: 1.0,
        lower: LOWER.to_vec(),
        upper: UPPER.to_vec(),
        planned,
    }
}

#[cfg(test)]
mod tests;
