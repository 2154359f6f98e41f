//! `BikeSimulation`: the ODE bike and rider in a Godot scene, as glue over the core's
//! `Ride` (exports, signals, terrain import, pose interpolation); its read-only functions
//! are in bike_queries.rs, its step events in bike_events.rs.

use std::sync::Arc;

use cpbp_core::bike::{Controls, DriveInput, Part, CONTROL_DIM};
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::settings::{self, SettingValues};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::Terrain;
use glam::{DQuat, DVec3};
use godot::classes::{INode3D, Node3D};
use godot::prelude::*;
use godot::register::info::PropertyInfo;

use crate::bike_description::{params_of, BikeDescription};
use crate::bike_queries::pose_of;
use crate::controller_choice::ControllerChoice;
use crate::convert::{finite_input, placement};
use crate::node_settings;
use crate::physics_choice::BikePhysics;
use crate::terrain_import;

/// Simulates the bike and its rider with ODE on the level's static collision shapes.
///
/// It builds at its own global transform (facing −z) when it enters the tree, steps one
/// control period (1/30 s) at a time from `_physics_process`, so pausing the tree pauses
/// it, and interpolates body transforms between steps for smooth visuals.
#[derive(GodotClass)]
#[class(init, base=Node3D)]
pub struct BikeSimulation {
    /// Node whose descendants' static collision shapes form the terrain.
    #[export]
    #[init(val = NodePath::from(".."))]
    terrain_root: NodePath,
    /// The bike, as data (bikes/*.tres); none rides the reference bike. Read when the
    /// ride is built (`_ready`); a description that cannot be built is an error and no
    /// ride is built.
    #[export]
    pub(crate) bike: Option<Gd<BikeDescription>>,
    /// The physics model, by name: `classic` (QuickStep, the physics the thesis
    /// reproduction was evaluated on) or `exact` (direct solver, explicit wheel
    /// gyroscopics: the benchmark bicycle within 10 %, cheaper rollouts). Read when the
    /// ride is built (`_ready`); `physics_names()` lists them.
    #[export]
    #[init(val = BikePhysics::exact)]
    pub(crate) physics: BikePhysics,
    /// Who balances and steers, by the controller registry's name (the inspector lists
    /// them all; `controller_names()` those players pick, `controller_label(name)` what
    /// menus call them). An unknown name is refused with an error.
    #[export]
    #[init(val = ControllerChoice(ControllerKind::ARCADE))]
    pub(crate) controller: ControllerChoice,
    /// How much of the ride (s) is kept to rewind into (`rewind`); 0, the default, keeps
    /// nothing (the experiment's worker pays nothing for it). Read when the ride is built.
    #[export]
    pub(crate) rewind_seconds: f64,
    /// The learned network's model file (the `learned` and `guided` controllers); empty:
    /// the bike's own (`res://models/policy-<bike file's name>.safetensors`, which
    /// `make train BIKE=` writes). A bike without one of its own does not offer `learned`
    /// (`get_offered_controller_names`) and guided plans without it.
    #[export(file = "*.safetensors")]
    pub(crate) policy_model: GString,
    /// The ride's and the planners' settings (`cpbp_core::settings`), shown as the node's
    /// properties (node_settings.rs): each is clamped into its range when set.
    #[init(val = node_settings::node_settings())]
    pub(crate) settings: SettingValues,
    pub(crate) ride: Option<Ride>,
    /// The player's intent as set so far (also before the ride is built).
    pub(crate) intent: Intent,
    /// Throttle and brake as last set (none yet: the intent's drive is its default), so a
    /// later change of `max_speed_kmh` or `motor_force` reaches the drive too.
    pub(crate) pedals: Option<(f64, f64)>,
    pub(crate) accumulator: f64,
    pub(crate) previous_poses: Vec<(DVec3, DQuat)>,
    /// Whether the active controller's failure has been reported.
    pub(crate) failure_reported: bool,
    /// Whether the player was told that the learned model was trained on another bike.
    pub(crate) told_other_bike: bool,
    base: Base<Node3D>,
}

#[godot_api]
impl INode3D for BikeSimulation {
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
        let bike = match params_of(self.bike.as_ref()) {
            Ok(bike) => bike,
            Err(why) => return godot_error!("BikeSimulation: {why}"),
        };
        let config = SimulationConfig {
            substeps: self.settings.count(&settings::SUBSTEPS),
            physics: self.physics.into(),
            bike,
            ..SimulationConfig::default()
        };
        let mut ride = Ride::new(
            Simulation::new(config, terrain, spawn),
            self.controller_kind(),
        );
        ride.set_intent(self.intent);
        ride.keep_history(self.rewind_seconds);
        self.ride = Some(ride);
        self.sync_settings();
        self.remember_poses();
    }

    fn on_get_property_list(&mut self) -> Vec<PropertyInfo> {
        node_settings::property_list(&self.settings)
    }

    fn on_get(&self, property: StringName) -> Option<Variant> {
        let value = self.settings.get(&property.to_string())?;
        Some(node_settings::to_variant(value))
    }

    fn on_set(&mut self, property: StringName, value: Variant) -> bool {
        let name = property.to_string();
        if self.settings.get(&name).is_none() {
            return false;
        }
        match node_settings::from_variant(&value).map(|v| self.settings.set(&name, v)) {
            Some(Ok(None)) => {}
            Some(Ok(Some(warning))) => godot_warn!("BikeSimulation: {warning}"),
            Some(Err(why)) => godot_error!("BikeSimulation: {why}"),
            None => godot_error!("BikeSimulation: {name} cannot be set to {value}"),
        }
        true
    }

    fn on_property_get_revert(&self, property: StringName) -> Option<Variant> {
        let setting = cpbp_core::ride::schema::find(&property.to_string())?;
        self.settings.get(setting.name)?;
        Some(node_settings::to_variant(&setting.default.into()))
    }

    fn physics_process(&mut self, delta: f64) {
        self.sync_settings();
        let Some(ride) = &mut self.ride else {
            return;
        };
        let dt = ride.sim().config().control_dt;
        // Fixed control steps whatever the tick rate; at most 4 per tick, so a stall does
        // not snowball into a burst of steps.
        self.accumulator = (self.accumulator + delta).min(4.0 * dt);
        ride.try_start();
        if ride.holds_the_bike() {
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
    pub(crate) fn crashed(cause: GString);
    /// A wheel touched the ground again after the bike was in the air.
    #[signal]
    pub(crate) fn landed();
    /// The physics blew up and the bike was put back at its spawn point.
    #[signal]
    pub(crate) fn recovered(reason: GString);
    /// The controller cannot drive as itself (`reason` says why and who drives instead:
    /// a planning thread died, or the learned model is missing).
    #[signal]
    pub(crate) fn controller_failed(reason: GString);

    /// Throttle and brake, each 0–1 (the rear wheel motor). Bad numbers count as released.
    #[func]
    fn set_drive(&mut self, throttle: f64, brake: f64) {
        if !(throttle.is_finite() && brake.is_finite()) {
            godot_warn!("BikeSimulation.set_drive: non-finite input ({throttle}, {brake}) treated as released");
        }
        self.pedals = Some((throttle, brake));
        if let Some(drive) = self.drive() {
            self.intent.drive = drive;
        }
        self.apply_intent();
    }

    /// The player's turn command in [−1, 1], positive right: it sets the curvature of the
    /// path, and the lean the controller aims for follows from it and the speed (eq. 4.4).
    #[func]
    fn set_turn(&mut self, command: f64) {
        self.intent.turn = finite_input(command, 1.0, "set_turn");
        self.apply_intent();
    }

    /// The lean (rad, positive right) the controller aims for now.
    #[func]
    fn get_desired_lean(&self) -> f64 {
        self.ride.as_ref().map_or(0.0, Ride::desired_lean)
    }

    /// Steering rate (rad/s, positive left) while driving without a controller; 0 lets the
    /// bar spring back to centre.
    #[func]
    fn set_steer_rate(&mut self, rate: f64) {
        self.intent.steer_rate = finite_input(rate, 4.0, "set_steer_rate");
        self.apply_intent();
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
        if let Some(ride) = &mut self.ride {
            ride.set_raw_controls(controls);
        }
        true
    }

    /// Puts the bike at rest at `spawn` (a transform facing −z); it becomes the spawn point.
    #[func]
    fn reset_to(&mut self, spawn: Transform3D) {
        let Some(placement) = placement(&spawn) else {
            godot_error!("BikeSimulation.reset_to: the transform mirrors or flattens the bike");
            return;
        };
        if let Some(ride) = &mut self.ride {
            ride.reset_to(placement);
        }
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
        self.sync_settings();
        if let Some(ride) = &mut self.ride {
            ride.start();
        }
        for _ in 0..steps {
            self.advance_one();
        }
    }

    /// Makes the planner's thread die with `reason`, as a bug in it would: for tests of
    /// the fallback and its report. Nothing happens unless a planner drives.
    #[func]
    fn inject_planner_fault(&mut self, reason: GString) {
        if let Some(ride) = &mut self.ride {
            ride.inject_fault(&reason.to_string());
        }
    }

    /// Stands a fallen bike up where it lies.
    #[func]
    fn lift_upright(&mut self) {
        if let Some(ride) = &mut self.ride {
            ride.lift_upright();
        }
        self.remember_poses();
    }

    /// Reads the terrain again (after a level changed); returns false when it could not.
    #[func]
    fn rebuild_terrain(&mut self) -> bool {
        let Some(terrain) = self.import_terrain() else {
            return false;
        };
        match &mut self.ride {
            Some(ride) => ride.set_terrain(terrain),
            None => return false,
        }
        true
    }
}

impl BikeSimulation {
    fn import_terrain(&mut self) -> Option<Arc<Terrain>> {
        terrain_import::terrain_under(&self.base(), &self.terrain_root.clone())
    }

    fn advance_one(&mut self) {
        if self.ride.is_none() {
            return;
        }
        self.remember_poses();
        let events = self.ride.as_mut().map(Ride::step).unwrap_or_default();
        self.emit(events);
        self.report_failure();
    }

    pub(crate) fn sim(&self) -> Option<&Simulation> {
        self.ride.as_ref().map(Ride::sim)
    }

    pub(crate) fn controller_kind(&self) -> ControllerKind {
        self.controller.0
    }

    /// The drive the pedals ask for with the present top speed and motor share. The
    /// motor share is the engine's: the brake trigger gives the bike's whole brake, as the
    /// scenarios and the rides that measure it (0.9 g on the street bike) pull it.
    pub(crate) fn drive(&self) -> Option<DriveInput> {
        let (throttle, brake) = self.pedals?;
        let force = self.settings.number(&settings::MOTOR_FORCE);
        let drive = DriveInput {
            throttle: throttle * force,
            brake,
            max_speed: self.settings.number(&settings::MAX_SPEED_KMH) / 3.6,
        };
        Some(drive.sanitized())
    }

    pub(crate) fn apply_intent(&mut self) {
        if let Some(ride) = &mut self.ride {
            ride.set_intent(self.intent);
        }
    }

    /// The plan in use, while a planner drives.
    pub(crate) fn current_plan(&self) -> Option<&cpbp_core::control::Plan> {
        self.ride.as_ref().and_then(Ride::plan)
    }

    pub(crate) fn remember_poses(&mut self) {
        let Some(sim) = self.sim() else { return };
        self.previous_poses = Part::ALL.iter().map(|p| pose_of(sim, *p)).collect();
    }
}
