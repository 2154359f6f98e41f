//! `BikeSimulation`: the ODE bike and rider in a Godot scene.

use std::sync::Arc;
use std::time::Duration;

use cpbp_core::bike::{
    from_quat, manual_controls, Controls, CrashCause, DriveInput, Part, Shape, CONTROL_DIM,
};
use cpbp_core::control::{
    AnytimeOptimizer, ArcadeController, OptimizerConfig, OptimizerMode, PlanWait, TurnIntent,
};
use cpbp_core::simulation::{Simulation, SimulationConfig, StepEvents};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};
use godot::classes::{INode3D, Node3D};
use godot::prelude::*;

use crate::convert::{basis, placement, transform, vector3};
use crate::terrain_import;

/// Simulates the bike and its rider with ODE on the level's static collision shapes.
///
/// It builds at its own global transform (facing −z) when it enters the tree, steps one
/// control period (1/30 s) at a time from `_physics_process`, so pausing the tree pauses
/// it, and interpolates body transforms between steps for smooth visuals.
#[derive(GodotClass)]
#[class(base=Node3D)]
pub struct BikeSimulation {
    /// Node whose descendants' static collision shapes form the terrain.
    #[export]
    terrain_root: NodePath,
    /// Speed (km/h) full throttle drives towards.
    #[export(range = (1.0, 90.0))]
    max_speed_kmh: f64,
    /// Share of the rear motor's torque (700 N·m) that full throttle or brake uses.
    #[export(range = (0.1, 1.0, 0.05))]
    motor_force: f64,
    /// ODE steps per control step (more: stiffer joints, slower).
    #[export(range = (1.0, 16.0))]
    substeps: i32,
    /// Who balances and steers: `arcade` (the PD controller of the thesis, §4.3.2),
    /// `manual` (nobody: the bar follows `set_steer_rate`, for inspecting the physics),
    /// `optimizer` (C-PBP) or `combined` (C-PBP warm-started with the arcade controller).
    #[export(enum = (Arcade = 0, Manual = 1, Optimizer = 2, Combined = 3))]
    controller: i32,
    /// Trajectories the optimizer simulates each control step (N).
    #[export(range = (1.0, 256.0))]
    trajectories: i32,
    /// How far ahead the optimizer plans (s); the thesis used 1.2 s.
    #[export(range = (0.2, 3.0, 0.1, suffix = "s"))]
    horizon: f64,
    /// Lean error (degrees) that costs as much as one unit (eq. 4.7's s): smaller tracks
    /// the requested lean more strictly.
    #[export(range = (1.0, 30.0, 0.5, suffix = "°"))]
    lean_tolerance_deg: f64,
    /// ODE steps per planning step in the rollouts: 4 is the master's own physics; fewer
    /// plan faster but predict a different bike.
    #[export(range = (1.0, 8.0))]
    rollout_substeps: i32,
    /// Longest the game waits at a control step for the planning thread (ms); a later
    /// plan is taken over at a later step while the last best trajectory plays on.
    #[export(range = (0.0, 1000.0, 1.0, suffix = "ms"))]
    plan_wait_ms: f64,
    /// Wait at every control step until its plan comes, however long that takes (headless
    /// tests and experiments): no step uses a late plan, so a ride repeats exactly for its
    /// seed on a loaded machine too. Off in the game, where a slow plan must not stall.
    #[export]
    wait_for_every_plan: bool,
    /// Threads that simulate the optimizer's trajectories (0: one per core). The
    /// experiment runs one bike per core with one thread each.
    #[export(range = (0.0, 64.0))]
    planning_threads: i32,
    /// Seed of the optimizer's random draws: the same seed, start and inputs give the same
    /// ride.
    #[export]
    planner_seed: i64,
    /// Hold the bike still where it was placed until the first throttle (and again after
    /// each reset): standing still, no steering can balance a bike, so the ride starts
    /// when the player does.
    #[export]
    wait_for_throttle: bool,
    started: bool,
    steps_since_reset: u64,
    late_plans_since_reset: u64,
    sim: Option<Simulation>,
    accumulator: f64,
    previous_poses: Vec<(DVec3, DQuat)>,
    drive: DriveInput,
    steer_rate: f64,
    turn: f64,
    arcade: ArcadeController,
    optimizer: Option<AnytimeOptimizer>,
    planning: bool,
    raw_controls: Option<Controls>,
    base: Base<Node3D>,
}

#[godot_api]
impl INode3D for BikeSimulation {
    fn init(base: Base<Node3D>) -> Self {
        Self {
            terrain_root: NodePath::from(".."),
            max_speed_kmh: 25.0,
            motor_force: 1.0,
            substeps: 4,
            controller: 0,
            trajectories: 15,
            horizon: 1.2,
            lean_tolerance_deg: 5.0,
            rollout_substeps: 4,
            plan_wait_ms: 12.0,
            wait_for_every_plan: false,
            planning_threads: 0,
            planner_seed: 2015,
            wait_for_throttle: false,
            started: false,
            steps_since_reset: 0,
            late_plans_since_reset: 0,
            sim: None,
            accumulator: 0.0,
            previous_poses: Vec::new(),
            drive: DriveInput::default(),
            steer_rate: 0.0,
            turn: 0.0,
            arcade: ArcadeController::default(),
            optimizer: None,
            planning: false,
            raw_controls: None,
            base,
        }
    }

    fn ready(&mut self) {
        let Some(spawn) = placement(&self.base().get_global_transform()) else {
            godot_error!(
                "BikeSimulation: its transform mirrors or flattens the bike; use a positive scale"
            );
            return;
        };
        let Some(terrain) = self.import_terrain() else {
            return;
        };
        let config = SimulationConfig {
            substeps: self.substeps.clamp(1, 16) as usize,
            ..SimulationConfig::default()
        };
        self.sim = Some(Simulation::new(config, terrain, spawn));
        self.remember_poses();
    }

    fn physics_process(&mut self, delta: f64) {
        let Some(dt) = self.sim.as_ref().map(|s| s.config().control_dt) else {
            return;
        };
        // Fixed control steps whatever the tick rate; at most 4 per tick, so a stall does
        // not snowball into a burst of steps.
        self.accumulator = (self.accumulator + delta).min(4.0 * dt);
        self.started |=
            !self.wait_for_throttle || self.drive.throttle > 0.0 || self.raw_controls.is_some();
        if !self.started {
            self.accumulator = 0.0;
            return;
        }
        while self.accumulator >= dt {
            self.accumulator -= dt;
            self.advance_one();
        }
    }
}

#[godot_api]
impl BikeSimulation {
    /// The ride crashed: a part other than a wheel touched the ground, or it leaned over.
    #[signal]
    fn crashed(cause: GString);
    /// A wheel touched the ground again after the bike was in the air.
    #[signal]
    fn landed();
    /// The physics blew up and the bike was put back at its spawn point.
    #[signal]
    fn recovered(reason: GString);

    /// Throttle and brake, each 0–1 (the rear wheel motor). Bad numbers count as released.
    #[func]
    fn set_drive(&mut self, throttle: f64, brake: f64) {
        if !(throttle.is_finite() && brake.is_finite()) {
            godot_warn!("BikeSimulation.set_drive: non-finite input ({throttle}, {brake}) treated as released");
        }
        let force = self.motor_force.clamp(0.1, 1.0);
        self.drive = DriveInput {
            throttle: throttle * force,
            brake: brake * force,
            max_speed: self.max_speed_kmh / 3.6,
        }
        .sanitized();
        self.raw_controls = None;
    }

    /// The player's turn command in [−1, 1], positive right: it sets the curvature of the
    /// path, and the lean the controller aims for follows from it and the speed (eq. 4.4).
    #[func]
    fn set_turn(&mut self, command: f64) {
        self.turn = finite_input(command, 1.0, "set_turn");
        self.raw_controls = None;
    }

    /// The lean (rad, positive right) the controller aims for now.
    #[func]
    fn get_desired_lean(&self) -> f64 {
        self.sim.as_ref().map_or(0.0, |s| {
            let speed = s.bike().forward_speed(s.world(), s.up());
            TurnIntent::default().lean_for(self.turn, speed, s.config().gravity.length())
        })
    }

    /// Steering rate (rad/s, positive left) while driving without a controller; 0 lets the
    /// bar spring back to centre.
    #[func]
    fn set_steer_rate(&mut self, rate: f64) {
        self.steer_rate = finite_input(rate, 4.0, "set_steer_rate");
        self.raw_controls = None;
    }

    /// Sets all 18 controls directly (13 joint velocities, 5 force tunings); values are
    /// clamped to their bounds. Returns false, changing nothing, for a wrong length.
    #[func]
    fn set_controls(&mut self, values: PackedFloat64Array) -> bool {
        let Ok(raw) = <[f64; CONTROL_DIM]>::try_from(values.as_slice()) else {
            godot_error!(
                "BikeSimulation.set_controls: expected {CONTROL_DIM} values, got {}",
                values.len()
            );
            return false;
        };
        let (controls, changed) = Controls::sanitized(&raw);
        if changed > 0 {
            godot_warn!("BikeSimulation.set_controls: {changed} value(s) were out of range or not numbers and were clamped");
        }
        self.raw_controls = Some(controls);
        true
    }

    /// Puts the bike at rest at `spawn` (a transform facing −z); it becomes the spawn point.
    #[func]
    fn reset_to(&mut self, spawn: Transform3D) {
        let Some(placement) = placement(&spawn) else {
            godot_error!("BikeSimulation.reset_to: the transform mirrors or flattens the bike");
            return;
        };
        if let Some(sim) = &mut self.sim {
            sim.reset_to(placement);
        }
        self.forget_plans();
        self.started = false;
        self.steps_since_reset = 0;
        self.late_plans_since_reset = 0;
        self.accumulator = 0.0;
        self.remember_poses();
    }

    /// Runs `steps` control steps at once, as fast as the machine allows (headless tests
    /// and experiments; stop `_physics_process` first). With `plan_wait_ms` at or above
    /// the planning time every step uses a fresh plan, so results repeat for a seed.
    #[func]
    fn advance(&mut self, steps: i64) {
        if !(0..=100_000).contains(&steps) {
            godot_error!("BikeSimulation.advance: {steps} steps is out of range (0–100000)");
            return;
        }
        self.started = true;
        for _ in 0..steps {
            self.advance_one();
        }
    }

    /// Control steps simulated since the bike was built or last placed.
    #[func]
    fn get_step_count(&self) -> i64 {
        self.steps_since_reset as i64
    }

    /// Control steps since the bike was last placed at which the optimizer drove without a
    /// plan for that step (a late plan, or none): 0 for a ride that repeats exactly.
    #[func]
    fn get_late_plan_count(&self) -> i64 {
        self.late_plans_since_reset as i64
    }

    /// Stands a fallen bike up where it lies.
    #[func]
    fn lift_upright(&mut self) {
        if let Some(sim) = &mut self.sim {
            sim.lift_upright();
        }
        self.forget_plans();
        self.remember_poses();
    }

    /// Reads the terrain again (after a level changed); returns false when it could not.
    #[func]
    fn rebuild_terrain(&mut self) -> bool {
        let Some(terrain) = self.import_terrain() else {
            return false;
        };
        match &mut self.sim {
            Some(sim) => sim.set_terrain(terrain),
            None => return false,
        }
        // The planning thread's replica has the old terrain.
        self.optimizer = None;
        true
    }

    /// Name of the active controller: "arcade", "manual", "optimizer" or "combined".
    #[func]
    fn get_controller_name(&self) -> GString {
        GString::from(
            ["arcade", "manual", "optimizer", "combined"][self.controller.clamp(0, 3) as usize],
        )
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

    /// Resampling steps in the last plan taken over.
    #[func]
    fn get_resample_count(&self) -> i64 {
        self.current_plan().map_or(0, |p| p.resamples as i64)
    }

    /// Hand-over statistics of the planning thread: `last_wait_ms`, `mean_wait_ms`,
    /// `max_wait_ms` (the game thread's waits at control-step boundaries), `boundaries`
    /// and `late` (boundaries with no plan for their step).
    #[func]
    fn get_handover_stats(&self) -> Dictionary<Variant, Variant> {
        let mut d: Dictionary<Variant, Variant> = Dictionary::new();
        let stats = self.optimizer.as_ref().map(|o| o.stats).unwrap_or_default();
        d.set(
            &"last_wait_ms".to_variant(),
            &stats.last_wait_ms.to_variant(),
        );
        d.set(
            &"mean_wait_ms".to_variant(),
            &stats.mean_wait_ms().to_variant(),
        );
        d.set(&"max_wait_ms".to_variant(), &stats.max_wait_ms.to_variant());
        d.set(
            &"boundaries".to_variant(),
            &(stats.boundaries as i64).to_variant(),
        );
        d.set(&"late".to_variant(), &(stats.late as i64).to_variant());
        d
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
        self.sim.is_some() && !self.started && self.wait_for_throttle
    }

    /// True once the simulation runs (the terrain was read and the bike built).
    #[func]
    fn is_running(&self) -> bool {
        self.sim.is_some()
    }

    /// Forward speed in m/s.
    #[func]
    fn get_speed(&self) -> f64 {
        self.sim
            .as_ref()
            .map_or(0.0, |s| s.bike().forward_speed(s.world(), s.up()))
    }

    /// Lean angle in radians, positive to the right.
    #[func]
    fn get_lean(&self) -> f64 {
        self.sim
            .as_ref()
            .map_or(0.0, |s| s.bike().lean(s.world(), s.up()))
    }

    /// Steering angle in radians, positive to the left.
    #[func]
    fn get_steering_angle(&self) -> f64 {
        self.sim
            .as_ref()
            .map_or(0.0, |s| s.bike().steering(s.world()).0)
    }

    #[func]
    fn is_rear_wheel_grounded(&self) -> bool {
        self.sim
            .as_ref()
            .is_some_and(|s| s.bike().wheel_contacts(s.world()).0)
    }

    #[func]
    fn is_front_wheel_grounded(&self) -> bool {
        self.sim
            .as_ref()
            .is_some_and(|s| s.bike().wheel_contacts(s.world()).1)
    }

    /// True after a crash, until the next reset or lift.
    #[func]
    fn is_crashed(&self) -> bool {
        self.sim.as_ref().is_some_and(|s| s.crashed().is_some())
    }

    /// Centre of mass of bike and rider.
    #[func]
    fn get_center_of_mass(&self) -> Vector3 {
        self.sim.as_ref().map_or(Vector3::ZERO, |s| {
            vector3(s.bike().center_of_mass(s.world()))
        })
    }

    /// Number of rigid bodies (9).
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
        let (Some(sim), Some(part)) = (&self.sim, part(index)) else {
            return Transform3D::IDENTITY;
        };
        let body = sim.bike().body(part);
        let now = (
            dvec3_of(sim.world().body_position(body)),
            from_quat(sim.world().body_quaternion(body)),
        );
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

    /// The collision shapes, for drawing the physical model: one Dictionary per shape with
    /// `body` (index), `kind` ("sphere", "box", "capsule"), `radius`, `length` (capsule,
    /// without caps, along local z), `size` (box) and `offset` (Transform3D in the body).
    #[func]
    fn get_shapes(&self) -> Array<Dictionary<Variant, Variant>> {
        let mut shapes = Array::new();
        let Some(sim) = &self.sim else { return shapes };
        for s in sim.bike().shapes() {
            let mut d: Dictionary<Variant, Variant> = Dictionary::new();
            d.set(&"body".to_variant(), &(s.part as i64).to_variant());
            d.set(
                &"offset".to_variant(),
                &Transform3D::new(basis(s.rotation), vector3(s.offset)).to_variant(),
            );
            match s.shape {
                Shape::Sphere { radius } => {
                    d.set(&"kind".to_variant(), &"sphere".to_variant());
                    d.set(&"radius".to_variant(), &radius.to_variant());
                }
                Shape::Cuboid { size } => {
                    d.set(&"kind".to_variant(), &"box".to_variant());
                    d.set(&"size".to_variant(), &vector3(size).to_variant());
                }
                Shape::Capsule { radius, length } => {
                    d.set(&"kind".to_variant(), &"capsule".to_variant());
                    d.set(&"radius".to_variant(), &radius.to_variant());
                    d.set(&"length".to_variant(), &length.to_variant());
                }
            }
            shapes.push(&d);
        }
        shapes
    }
}

impl BikeSimulation {
    fn import_terrain(&mut self) -> Option<Arc<Terrain>> {
        let root_path = self.terrain_root.clone();
        let Some(root) = self.base().get_node_or_null(&root_path) else {
            godot_error!("BikeSimulation: terrain root '{root_path}' not found");
            return None;
        };
        let (pieces, errors) = terrain_import::collect(&root);
        for error in &errors {
            godot_error!("BikeSimulation: terrain shape skipped: {error}");
        }
        match Terrain::new(pieces) {
            Ok(terrain) => Some(Arc::new(terrain)),
            Err(error) => {
                godot_error!("BikeSimulation: broken level geometry: {error}");
                None
            }
        }
    }

    fn advance_one(&mut self) {
        if self.sim.is_none() {
            return;
        }
        self.remember_poses();
        let events = self.step_once();
        self.steps_since_reset += 1;
        self.emit(events);
    }

    fn step_once(&mut self) -> StepEvents {
        let desired_lean = self.get_desired_lean();
        let config = self.optimizer_config();
        let Some(sim) = &mut self.sim else {
            return StepEvents::default();
        };
        let planning = self.raw_controls.is_none() && matches!(self.controller, 2 | 3);
        let controls = match (self.raw_controls, self.controller) {
            (Some(controls), _) => controls,
            (None, 1) => manual_controls(sim.bike(), sim.world(), &self.drive, self.steer_rate),
            (None, 2 | 3) => {
                let optimizer = self
                    .optimizer
                    .get_or_insert_with(|| AnytimeOptimizer::new(sim, PlanWait::EveryPlan));
                optimizer.wait = if self.wait_for_every_plan {
                    PlanWait::EveryPlan
                } else {
                    PlanWait::AtMost(Duration::from_secs_f64(
                        self.plan_wait_ms.clamp(0.0, 1000.0) / 1000.0,
                    ))
                };
                // Plans made while another controller drove are for states long gone.
                if !self.planning {
                    optimizer.reset();
                }
                let late_before = optimizer.stats.late;
                let controls = optimizer.controls(sim, desired_lean, &self.drive, &config);
                self.late_plans_since_reset += optimizer.stats.late - late_before;
                controls
            }
            (None, _) => {
                let dt = sim.config().control_dt;
                self.arcade.controls(
                    sim.bike(),
                    sim.world(),
                    desired_lean,
                    &self.drive,
                    sim.up(),
                    dt,
                )
            }
        };
        self.planning = planning;
        sim.set_controls(controls);
        sim.step()
    }

    fn optimizer_config(&self) -> OptimizerConfig {
        let mode = if self.controller == 2 {
            OptimizerMode::Optimizer
        } else {
            OptimizerMode::Combined
        };
        OptimizerConfig {
            mode,
            particles: self.trajectories.clamp(1, 256) as usize,
            horizon: self.horizon.clamp(0.2, 3.0),
            lean_tolerance: self.lean_tolerance_deg.clamp(1.0, 30.0).to_radians(),
            rollout_substeps: self.rollout_substeps.clamp(1, 8) as usize,
            threads: self.planning_threads.clamp(0, 64) as usize,
            seed: self.planner_seed as u64,
            ..OptimizerConfig::default()
        }
    }

    /// The plan in use, while the optimizer drives.
    fn current_plan(&self) -> Option<&cpbp_core::control::Plan> {
        if !self.planning {
            return None;
        }
        self.optimizer.as_ref().and_then(|o| o.plan())
    }

    fn forget_plans(&mut self) {
        self.arcade.reset();
        if let Some(optimizer) = &mut self.optimizer {
            optimizer.reset();
        }
    }

    fn emit(&mut self, events: StepEvents) {
        if let Some(cause) = events.crashed {
            let text = match cause {
                CrashCause::Touched(part) => format!("{} touched the ground", part.name()),
                CrashCause::Leaned { lean } => format!("leaned over ({:.0}°)", lean.to_degrees()),
            };
            self.signals().crashed().emit(&GString::from(text.as_str()));
        }
        if events.landed {
            self.signals().landed().emit();
        }
        if let Some(reason) = events.recovered_from {
            self.forget_plans();
            godot_warn!("BikeSimulation: the physics blew up ({reason})");
            self.signals()
                .recovered()
                .emit(&GString::from(reason.as_str()));
            self.remember_poses();
        }
    }

    fn remember_poses(&mut self) {
        let Some(sim) = &self.sim else { return };
        self.previous_poses = Part::ALL
            .iter()
            .map(|p| {
                let body = sim.bike().body(*p);
                (
                    dvec3_of(sim.world().body_position(body)),
                    from_quat(sim.world().body_quaternion(body)),
                )
            })
            .collect();
    }
}

/// A player input clamped to ±`bound`; a non-finite one counts as 0, with a warning.
fn finite_input(value: f64, bound: f64, function: &str) -> f64 {
    if value.is_finite() {
        value.clamp(-bound, bound)
    } else {
        godot_warn!("BikeSimulation.{function}: non-finite input {value} treated as 0");
        0.0
    }
}

fn part(index: i64) -> Option<Part> {
    usize::try_from(index)
        .ok()
        .and_then(|i| Part::ALL.get(i).copied())
}

fn dvec3_of(v: [f64; 3]) -> DVec3 {
    DVec3::from_array(v)
}
