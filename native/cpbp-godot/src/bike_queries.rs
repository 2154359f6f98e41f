//! `BikeSimulation`'s read-only side for GDScript: the controller registry, the plans and
//! hand-over statistics, the ride's state, and the bodies and shapes the views draw.

use cpbp_core::bike::Part;
use cpbp_core::ride::{ControllerKind, Ride};
use cpbp_core::simulation::Simulation;
use glam::{DQuat, DVec3};
use godot::prelude::*;

use crate::bike_foot::BikeFoot;
use crate::bike_shape::BikeShape;
use crate::bike_simulation::BikeSimulation;
use crate::convert::{transform, vector3};
use crate::plan_handover::PlanHandover;
use crate::{controller_choice, physics_choice};

#[godot_api(secondary)]
impl BikeSimulation {
    // The bodies, by index (`get_body_transform`, `get_shapes`' `body`): cpbp_core's
    // `Part` order, the one definition.
    #[constant]
    const REAR_WHEEL: i64 = Part::RearWheel as i64;
    #[constant]
    const FRONT_WHEEL: i64 = Part::FrontWheel as i64;
    #[constant]
    const FORK: i64 = Part::Fork as i64;
    #[constant]
    const FRAME: i64 = Part::Frame as i64;
    #[constant]
    const FORK_LOWER: i64 = Part::ForkLower as i64;
    #[constant]
    const SWINGARM: i64 = Part::Swingarm as i64;
    #[constant]
    const LOWER_LEG: i64 = Part::LowerLeg as i64;
    #[constant]
    const UPPER_LEG: i64 = Part::UpperLeg as i64;
    #[constant]
    const TORSO: i64 = Part::Torso as i64;
    #[constant]
    const UPPER_ARM: i64 = Part::UpperArm as i64;
    #[constant]
    const LOWER_ARM: i64 = Part::LowerArm as i64;
    /// Numbers per body in `get_pose_frame`.
    #[constant]
    const POSE_FLOATS: i64 = 7;

    /// The controllers players pick, by name, in the order menus list them and the game
    /// cycles through them (the one list: `cpbp_core::ride::ControllerKind::all`).
    #[func]
    fn controller_names() -> PackedStringArray {
        controller_choice::offered_names()
    }

    /// The controllers players may pick for this bike, in the menus' order: every one
    /// `controller_names` lists, but `learned` (the network alone) only when the bike has
    /// a learned model (`policy_model`, or the bike's own).
    #[func]
    fn get_offered_controller_names(&self) -> PackedStringArray {
        let has_network = self.policy().network().is_some();
        controller_choice::offered_names_where(|k| has_network || !k.uses_network() || k.plans())
    }

    /// The model file the learned controllers read: `policy_model`, or the bike's own;
    /// empty, for a bike without one.
    #[func]
    fn get_policy_model_path(&self) -> GString {
        if !self.policy_model.is_empty() {
            return self.policy_model.clone();
        }
        crate::policy_model::bike_model(self.bike.as_ref()).unwrap_or_default()
    }

    /// Control steps simulated since the bike was built or last placed.
    #[func]
    fn get_step_count(&self) -> i64 {
        self.ride.as_ref().map_or(0, |r| r.steps() as i64)
    }

    /// Length of one control step (s): the rate poses change at.
    #[func]
    fn get_control_dt(&self) -> f64 {
        self.sim().map_or(
            cpbp_core::simulation::SimulationConfig::default().control_dt,
            |s| s.config().control_dt,
        )
    }

    /// Control steps since the bike was last placed at which a planner drove without a
    /// plan for that step (a late plan, or none): 0 for a ride that repeats exactly.
    #[func]
    fn get_late_plan_count(&self) -> i64 {
        self.ride.as_ref().map_or(0, |r| r.late_plans() as i64)
    }

    /// The physics models, by name (`cpbp_core::physics::PhysicsModel::ALL`).
    #[func]
    fn physics_names() -> PackedStringArray {
        physics_choice::names()
    }

    /// The fewest (x) and most (y) trajectories a planner may simulate per control step
    /// (the core's limit).
    #[func]
    fn trajectory_limits() -> Vector2i {
        let limit = cpbp_core::ride::limits::TRAJECTORIES;
        Vector2i::new(limit.min as i32, limit.max as i32)
    }

    /// The fewest (x) and most (y) trajectories the automatic choice moves between.
    #[func]
    fn auto_trajectory_limits() -> Vector2i {
        let limit = cpbp_core::ride::limits::AUTO_TRAJECTORIES;
        Vector2i::new(limit.min as i32, limit.max as i32)
    }

    /// Trajectories the active planner plans with now (the automatic choice's, or
    /// `trajectories`); 0 while no planner drives.
    #[func]
    fn get_trajectories_in_use(&self) -> i64 {
        let n = self.ride.as_ref().and_then(|r| r.trajectories());
        n.map_or(0, |n| n as i64)
    }

    /// What menus show for controller `name` (empty for an unknown name).
    #[func]
    fn controller_label(name: GString) -> GString {
        controller_choice::kind_named(&name).map_or(GString::new(), |k| GString::from(k.label()))
    }

    /// Whether controller `name` plans with trajectories (and so has plans to draw and
    /// time); false for an unknown name.
    #[func]
    fn controller_plans(name: GString) -> bool {
        controller_choice::kind_named(&name).is_some_and(ControllerKind::plans)
    }

    /// The registry's name of the active controller ("arcade", "combined", …).
    #[func]
    fn get_controller_name(&self) -> GString {
        GString::from(self.controller_kind().name())
    }

    /// Why the controller no longer drives as itself (its planning thread died and the
    /// arcade controller stands in until the ride is placed anew), or "" when it does.
    #[func]
    fn get_controller_failure(&self) -> GString {
        let failure = self.ride.as_ref().and_then(|r| r.failure());
        GString::from(failure.unwrap_or_default())
    }

    /// Milliseconds the planning thread took for the last plan taken over (0 when the
    /// optimizer is not driving).
    #[func]
    fn get_planning_ms(&self) -> f64 {
        self.current_plan().map_or(0.0, |p| p.planning_ms)
    }

    /// Total cost of the best trajectory of the last plan taken over.
    #[func]
    fn get_best_cost(&self) -> f64 {
        self.current_plan().map_or(0.0, |p| p.best_cost)
    }

    /// The running planner's own numbers about the last plan taken over, by name (C-PBP:
    /// its resamplings; predictive sampling: how much the samples bettered the nominal;
    /// MPPI: that and its weights' effective sample size); empty while nothing plans.
    #[func]
    fn get_plan_diagnostics(&self) -> Dictionary<GString, f64> {
        let mut named = Dictionary::new();
        for (name, value) in self
            .current_plan()
            .map_or(&[][..], |p| &p.diagnostics.0[..])
        {
            named.set(&GString::from(*name), *value);
        }
        named
    }

    /// How the planning thread's plans reached the control steps since the ride was last
    /// placed (all zero for a controller that does not plan).
    #[func]
    fn get_handover_stats(&self) -> Gd<PlanHandover> {
        let stats = self.ride.as_ref().and_then(Ride::handover);
        PlanHandover::of(&stats.unwrap_or_default())
    }

    /// The last plan's trajectories as centre-of-mass paths (one point per planning
    /// step), for drawing: `get_best_trajectory` and `get_warm_trajectory` index it.
    #[func]
    fn get_trajectory_paths(&self) -> Array<PackedVector3Array> {
        let mut paths = Array::new();
        for path in self.current_plan().map_or(&[][..], |p| &p.paths[..]) {
            let points: PackedVector3Array = path.iter().map(|p| vector3(*p)).collect();
            paths.push(&points);
        }
        paths
    }

    /// Index of the best trajectory in `get_trajectory_paths` (−1 without a plan).
    #[func]
    fn get_best_trajectory(&self) -> i64 {
        self.current_plan().map_or(-1, |p| p.best as i64)
    }

    /// Index of the refined (optimizer) or arcade (combined) trajectory, −1 if none.
    #[func]
    fn get_warm_trajectory(&self) -> i64 {
        self.current_plan()
            .and_then(|p| p.warm)
            .map_or(-1, |w| w as i64)
    }

    /// True while the bike stands waiting for the first throttle (`wait_for_throttle`).
    #[func]
    fn is_waiting_for_throttle(&self) -> bool {
        self.ride
            .as_ref()
            .is_some_and(Ride::is_waiting_for_throttle)
    }

    /// True once the simulation runs (the terrain was read and the bike built).
    #[func]
    fn is_running(&self) -> bool {
        self.ride.is_some()
    }

    /// Forward speed in m/s.
    #[func]
    fn get_speed(&self) -> f64 {
        self.sim()
            .map_or(0.0, |s| s.bike().forward_speed(s.world(), s.up()))
    }

    /// Lean angle in radians, positive to the right.
    #[func]
    fn get_lean(&self) -> f64 {
        self.sim().map_or(0.0, |s| s.bike().lean(s.world(), s.up()))
    }

    /// How far the fork (x) and the rear wheel (y) have compressed from full extension
    /// (m): about 39 mm each at rest with the rider aboard, 130 mm bottomed out.
    #[func]
    fn get_suspension_compression(&self) -> Vector2 {
        self.sim().map_or(Vector2::ZERO, |s| {
            let (front, rear) = s.bike().suspension_compression(s.world());
            Vector2::new(front as f32, rear as f32)
        })
    }

    /// Steering angle in radians, positive to the left.
    #[func]
    fn get_steering_angle(&self) -> f64 {
        self.sim().map_or(0.0, |s| s.bike().steering(s.world()).0)
    }

    #[func]
    fn is_rear_wheel_grounded(&self) -> bool {
        self.sim()
            .is_some_and(|s| s.bike().wheel_contacts(s.world()).0)
    }

    #[func]
    fn is_front_wheel_grounded(&self) -> bool {
        self.sim()
            .is_some_and(|s| s.bike().wheel_contacts(s.world()).1)
    }

    /// The rider's feet, left then right (none on the classic physics' rigid bike).
    #[func]
    fn get_feet(&self) -> Array<Gd<BikeFoot>> {
        let Some(sim) = self.sim() else {
            return Array::new();
        };
        sim.bike()
            .feet(sim.world())
            .iter()
            .map(BikeFoot::of)
            .collect()
    }

    /// True after a crash, until the next reset or lift.
    #[func]
    fn is_crashed(&self) -> bool {
        self.sim().is_some_and(|s| s.crashed().is_some())
    }

    /// Whether the rider is on the bike: after a crash the rider falls off (a ragdoll of
    /// the same bodies) until the next reset or lift.
    #[func]
    fn is_rider_on(&self) -> bool {
        self.sim().is_some_and(Simulation::rider_is_on)
    }

    /// Centre of mass of bike and rider.
    #[func]
    fn get_center_of_mass(&self) -> Vector3 {
        self.sim().map_or(Vector3::ZERO, |s| {
            vector3(s.bike().center_of_mass(s.world()))
        })
    }

    /// Radius of the wheels, tyre included (m): the drawing sizes its wheels by it.
    #[func]
    fn get_wheel_radius(&self) -> f64 {
        self.sim().map_or(0.0, |s| s.config().bike.wheel_radius)
    }

    /// Number of rigid bodies of the bike and rider (`Part::ALL`).
    #[func]
    fn get_body_count(&self) -> i64 {
        Part::ALL.len() as i64
    }

    /// Name of body `index` (`rear_wheel`, `frame`, `torso`, …).
    #[func]
    fn get_body_name(&self, index: i64) -> GString {
        part(index).map_or(GString::new(), |p| GString::from(p.name()))
    }

    /// Global transform of body `index`, interpolated between the last two steps.
    #[func]
    fn get_body_transform(&self, index: i64) -> Transform3D {
        let (Some(sim), Some(part)) = (self.sim(), part(index)) else {
            return Transform3D::IDENTITY;
        };
        let now = pose_of(sim, part);
        let (before_position, before_rotation) = self
            .previous_poses
            .get(part as usize)
            .copied()
            .unwrap_or(now);
        let alpha = (self.accumulator / sim.config().control_dt).clamp(0.0, 1.0);
        transform(
            before_position.lerp(now.0, alpha),
            before_rotation.slerp(now.1, alpha),
        )
    }

    /// Every body's pose at the last control step (not interpolated), for recording
    /// ghosts and replays: per body in `Part` order, position x, y, z then rotation
    /// x, y, z, w (`POSE_FLOATS` numbers a body).
    #[func]
    fn get_pose_frame(&self) -> PackedFloat32Array {
        let Some(sim) = self.sim() else {
            return PackedFloat32Array::new();
        };
        Part::ALL
            .iter()
            .flat_map(|part| {
                let (p, q) = pose_of(sim, *part);
                [p.x, p.y, p.z, q.x, q.y, q.z, q.w].map(|v| v as f32)
            })
            .collect()
    }

    /// The collision shapes of every body, for drawing the physical model.
    #[func]
    fn get_shapes(&self) -> Array<Gd<BikeShape>> {
        self.sim().map_or_else(Array::new, |sim| {
            sim.bike().shapes().iter().map(BikeShape::of).collect()
        })
    }
}

fn part(index: i64) -> Option<Part> {
    usize::try_from(index)
        .ok()
        .and_then(|i| Part::ALL.get(i).copied())
}

/// Where body `part` is now: position and rotation.
pub(crate) fn pose_of(sim: &Simulation, part: Part) -> (DVec3, DQuat) {
    let body = sim.bike().body(part);
    (
        sim.world().body_position(body),
        sim.world().body_quaternion(body),
    )
}
