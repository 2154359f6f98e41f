//! The master simulation of a ride: terrain, bike and rider stepped one control period at
//! a time in substeps, with crash, landing and explosion handling. Rollout worlds for
//! the planner are built by the same code, so they match the master body for body.

use std::sync::Arc;

use glam::DVec3;

use crate::bike::{
    Bike, BikeParams, Controls, Crash, CrashMonitor, Exploded, Part, PeriodWatch, PitchRequest,
    Placement, GRAVITY,
};
use crate::ode::World;

mod state;
use crate::physics::PhysicsModel;
use crate::terrain::Terrain;
pub use state::SimulationState;

/// How the world is stepped.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationConfig {
    /// Gravity (m/s²); "up" is against it.
    pub gravity: DVec3,
    /// Length of one control step (s); the thesis used 32 ms, we use 1/30 s.
    pub control_dt: f64,
    /// ODE steps per control step: 4 (1/120 s) keeps the rider's joints stiff and the
    /// steering steady; 1 lets the rider sag and the bar drift by degrees.
    pub substeps: usize,
    /// Solver, wheel gyroscopics and the rollouts' stepping (`PhysicsModel`).
    pub physics: PhysicsModel,
    pub bike: BikeParams,
    /// ABS as the bike's brakes have it, or off (false): then a braked wheel is let lock
    /// at any speed (the players' Pro assist). Every world of the ride, the planners'
    /// rollouts too, is built with the same.
    pub abs: bool,
}

impl Default for SimulationConfig {
    fn default() -> Self {
        Self {
            gravity: DVec3::new(0.0, -GRAVITY, 0.0),
            control_dt: 1.0 / 30.0,
            substeps: crate::settings::SUBSTEPS.default_number() as usize,
            physics: PhysicsModel::default(),
            bike: BikeParams::default(),
            abs: true,
        }
    }
}

/// What happened during one control step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StepEvents {
    /// The ride crashed in this step (reported once).
    pub crashed: Option<Crash>,
    /// A wheel touched the ground again after the bike was airborne.
    pub landed: bool,
    /// The physics blew up and was recovered from (with the reason).
    pub recovered_from: Option<String>,
}

/// Time (s) both wheels must be off the ground to count as airborne.
const AIRBORNE_AFTER: f64 = 0.15;

pub struct Simulation {
    config: SimulationConfig,
    terrain: Arc<Terrain>,
    world: World,
    bike: Bike,
    controls: Controls,
    /// The pitch the rider's weight asks for (`Goal::pitch_request`).
    pitch_request: PitchRequest,
    crash: CrashMonitor,
    crashed: Option<Crash>,
    airborne_for: f64,
    /// The ground's blow in the last step beyond the weight's share (N·s along up).
    ground_blow: f64,
    spawn: Placement,
}

impl Simulation {
    /// A ride on `terrain`, the bike at rest at `spawn`.
    pub fn new(config: SimulationConfig, terrain: Arc<Terrain>, spawn: Placement) -> Self {
        let (world, bike) = build_world(&config, &terrain, &spawn);
        Self {
            config,
            terrain,
            world,
            bike,
            controls: Controls::default(),
            pitch_request: PitchRequest::default(),
            crash: CrashMonitor::default(),
            crashed: None,
            airborne_for: 0.0,
            ground_blow: 0.0,
            spawn,
        }
    }

    /// A fresh world with the same terrain and bike, for rollouts: restore a snapshot of
    /// the master into it and it steps exactly as the master would.
    pub fn new_world(&self) -> World {
        build_world(&self.config, &self.terrain, &self.spawn).0
    }

    /// A second simulation on the same terrain and bike (for a planning thread, which
    /// restores the master's snapshots into it).
    pub fn replica(&self) -> Simulation {
        Simulation::new(self.config.clone(), self.terrain.clone(), self.spawn)
    }

    pub fn config(&self) -> &SimulationConfig {
        &self.config
    }

    pub fn world(&self) -> &World {
        &self.world
    }

    /// The master world, for tools and tests that push it around directly.
    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    pub fn bike(&self) -> &Bike {
        &self.bike
    }

    pub fn controls(&self) -> &Controls {
        &self.controls
    }

    /// Unit vector against gravity.
    pub fn up(&self) -> DVec3 {
        up_against(self.config.gravity)
    }

    /// The crash of this ride, if it crashed (cleared by reset and lift).
    pub fn crashed(&self) -> Option<Crash> {
        self.crashed
    }

    /// Controls for the next steps.
    pub fn set_controls(&mut self, controls: Controls) {
        self.controls = controls;
    }

    /// The pitch the rider's weight asks for from the next step on (a wheelie, a turn
    /// in the air: `Goal::pitch_request`); the bike's wheelie control does it, if it has
    /// one.
    pub fn set_pitch_request(&mut self, request: PitchRequest) {
        self.pitch_request = request;
    }

    /// Advances one control step.
    pub fn step(&mut self) -> StepEvents {
        let up = self.up();
        // A rider who fell off neither rides nor asks anything of the bike.
        let (controls, asked) = if self.bike.rider_is_on(&self.world) {
            (self.controls, self.pitch_request)
        } else {
            (Controls::slack(), PitchRequest::default())
        };
        let substeps = self.config.substeps;
        let period = (substeps, self.config.control_dt / substeps as f64);
        self.ground_blow = 0.0;
        let mut watch = MasterWatch {
            bike: &self.bike,
            up,
            airborne_at_start: self.airborne_for > AIRBORNE_AFTER,
            airborne_for: &mut self.airborne_for,
            crash: &mut self.crash,
            crashed: &mut self.crashed,
            events: StepEvents::default(),
            momentum_before: DVec3::ZERO,
        };
        let stepped = self.bike.step_control_period(
            &mut self.world,
            &controls,
            asked,
            up,
            period,
            &mut watch,
        );
        let (mut events, momentum_before) = (watch.events, watch.momentum_before);
        if let Err(Exploded(reason)) = stepped {
            events.recovered_from = Some(self.recover(reason));
            return events;
        }
        // The rider lets go at the end of the step that crashed, so the step itself (and
        // every result measured at a crash) is what it was before riders fell off.
        if events.crashed.is_some() {
            self.bike.release_rider(&mut self.world);
        }
        let momentum_gained = self.bike.momentum(&self.world) - momentum_before;
        self.ground_blow = momentum_gained.dot(up).max(0.0);
        events
    }

    /// How hard the ground pushed the bike up in the last step beyond carrying its weight
    /// (N·s): a landing's or an impact's blow, about zero riding along.
    pub fn ground_blow(&self) -> f64 {
        self.ground_blow
    }

    /// Whether the rider is on the bike: after a crash the rider falls off (the same
    /// bodies, let go, as a ragdoll) until the bike is placed again.
    pub fn rider_is_on(&self) -> bool {
        self.bike.rider_is_on(&self.world)
    }

    /// Puts the bike at rest at `placement` (and makes that the spawn point), the rider
    /// back on it. The ride from there repeats exactly whatever was simulated before.
    pub fn reset_to(&mut self, placement: Placement) {
        self.spawn = placement;
        self.bike.reset(&mut self.world, &placement);
        self.world.reset_motors();
        self.world.reset_random_seed();
        self.world.forget_contacts();
        self.controls = Controls::default();
        self.pitch_request = PitchRequest::default();
        self.crash.reset();
        self.crashed = None;
        self.airborne_for = 0.0;
        self.ground_blow = 0.0;
    }

    /// Shoves the bike with an impulse (N·s, world frame) through the frame's centre of
    /// mass, as a push or a glancing blow would; the joints share it out over the next
    /// step. A non-finite impulse is ignored.
    pub fn push(&mut self, impulse: DVec3) {
        if !impulse.is_finite() {
            return;
        }
        let frame = self.bike.body(Part::Frame);
        let mass = self.world.body_mass(frame);
        let velocity = self.world.body_linear_velocity(frame);
        self.world
            .set_body_linear_velocity(frame, velocity + impulse / mass);
    }

    /// Stands the bike up where it is, facing where it was heading, a little above the
    /// ground it was on, at rest. The spawn point stays as it was.
    pub fn lift_upright(&mut self) {
        let up = self.up();
        let frame = self.bike.body(Part::Frame);
        let here = self.world.body_position(frame);
        let forward = self.bike.frame_rotation(&self.world) * DVec3::X;
        let heading = (forward - up * forward.dot(up)).normalize_or(DVec3::X);
        let ground = here - up * here.dot(up) + up * self.lowest_wheel_height(up);
        let placement = Placement {
            position: ground + up * 0.05,
            rotation: glam::DQuat::from_mat3(&glam::DMat3::from_cols(
                heading,
                up,
                heading.cross(up),
            )),
        };
        let spawn = self.spawn;
        self.reset_to(placement);
        self.spawn = spawn;
    }

    /// Height (along up) of the lowest point of either tyre: for a torus of outer radius r
    /// and crown ρ about axle a, centre c: c·up − ((r − ρ)·√(1 − (a·up)²) + ρ). Exact whether
    /// the wheel stands or lies on its side.
    fn lowest_wheel_height(&self, up: DVec3) -> f64 {
        let (r, crown) = (self.config.bike.wheel_radius, self.config.bike.tyre_crown);
        [Part::RearWheel, Part::FrontWheel]
            .map(|p| {
                let body = self.bike.body(p);
                let centre = self.world.body_position(body);
                let axle = self.world.body_quaternion(body) * DVec3::Z;
                let tilt = (1.0 - axle.dot(up).powi(2)).max(0.0).sqrt();
                centre.dot(up) - ((r - crown) * tilt + crown)
            })
            .into_iter()
            .fold(f64::INFINITY, f64::min)
    }

    /// Turns ABS on or off (`SimulationConfig::abs`), keeping the ride's state: the bike is
    /// built again with its brakes so and the world restored into it. A replica or a
    /// rollout world made after this brakes the same way.
    pub fn set_abs(&mut self, abs: bool) {
        if self.config.abs == abs {
            return;
        }
        self.config.abs = abs;
        let state = self.world.snapshot();
        let (world, bike) = build_world(&self.config, &self.terrain, &self.spawn);
        self.world = world;
        self.bike = bike;
        self.world
            .restore(&state)
            .expect("the same bike is built in every world");
    }

    /// Swaps the terrain (a level changed or was regenerated), keeping the ride's state.
    pub fn set_terrain(&mut self, terrain: Arc<Terrain>) {
        let state = self.world.snapshot();
        let (world, _) = build_world(&self.config, &terrain, &self.spawn);
        self.world = world;
        self.terrain = terrain;
        self.world
            .restore(&state)
            .expect("the same bike is built in every world");
    }

    /// A world that blew up from some state would blow up again from it (the simulation is
    /// deterministic), so recovery puts the bike back at its spawn point.
    fn recover(&mut self, reason: String) -> String {
        let spawn = self.spawn;
        self.reset_to(spawn);
        format!("{reason}; the bike was put back at its spawn point")
    }
}

/// What the master watches during a control period: landings and crashes, and the
/// momentum the ground's blow is measured from.
struct MasterWatch<'a> {
    bike: &'a Bike,
    up: DVec3,
    airborne_at_start: bool,
    airborne_for: &'a mut f64,
    crash: &'a mut CrashMonitor,
    crashed: &'a mut Option<Crash>,
    events: StepEvents,
    momentum_before: DVec3,
}

impl PeriodWatch for MasterWatch<'_> {
    fn started(&mut self, world: &World) {
        self.momentum_before = self.bike.momentum(world);
    }

    fn stepped(&mut self, world: &World, dt: f64) {
        let (rear, front) = self.bike.wheel_contacts(world);
        if rear || front {
            self.events.landed |= self.airborne_at_start;
            self.airborne_at_start = false;
            *self.airborne_for = 0.0;
        } else {
            *self.airborne_for += dt;
        }
        let lean = self.bike.lean(world, self.up);
        let touching = self.bike.part_touching_ground(world);
        let side_slide = self.bike.tyre_side_slide(world, self.up);
        if let Some(crash) = self.crash.update(dt, lean, touching, side_slide) {
            if self.crashed.is_none() {
                *self.crashed = Some(crash);
                self.events.crashed = Some(crash);
            }
        }
    }
}

fn build_world(config: &SimulationConfig, terrain: &Terrain, spawn: &Placement) -> (World, Bike) {
    let mut world = World::new(config.gravity);
    world.set_solver(config.physics.solver());
    // The bike first: its bodies and joints then have the same indices in every world,
    // whatever the terrain, so snapshots move between worlds and levels.
    let mut params = if config.physics.suspended() {
        config.bike.clone()
    } else {
        config.bike.rigid()
    };
    if !config.abs {
        params.without_abs();
    }
    let bike =
        Bike::build(&mut world, &params, spawn).with_arm_strength(config.physics.arm_strength());
    for wheel in [Part::RearWheel, Part::FrontWheel] {
        world.set_gyroscopic(bike.body(wheel), config.physics.wheel_gyroscopic());
    }
    terrain.add_to(&mut world);
    (world, bike)
}

/// Unit vector against `gravity` (straight up when there is none).
pub fn up_against(gravity: DVec3) -> DVec3 {
    (-gravity).normalize_or(DVec3::Y)
}
