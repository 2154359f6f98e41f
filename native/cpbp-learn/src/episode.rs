//! One recorded ride: a seed draws the ground (flat, a slope or a bump field) and a script
//! of what the player asks (speeds from walking pace to 40 km/h, turns, the rider's
//! weight, hard stops, shoves); the planner rides it as the expert, and every control
//! step is recorded as (features, the planner's choice). The controls applied may carry
//! noise the labels do not (DART: the expert is shown the states its own mistakes lead
//! to, so the learner learns to recover from them).

use std::sync::Arc;

use cpbp_core::bike::{BikeParams, Controls, DriveInput, Placement, RiderPosition};
use cpbp_core::control::cpbp::COMBINED;
use cpbp_core::control::learned::{
    features, output_entries, value_target, LoadedValue, PolicyNetwork, FEATURE_COUNT,
    OUTPUT_COUNT, VALUE_INPUT_COUNT,
};
use cpbp_core::control::{Goal, PlanningConfig, PlanningSession, TurnIntent};
use cpbp_core::physics::PhysicsModel;
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::{DQuat, DVec3};
use rand::seq::IndexedRandom;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;
use rand_pcg::Pcg64;

pub use crate::family::Family;
use crate::grounds::{bump_field, log_field, platforms};

/// Control steps a second.
const STEPS_PER_SECOND: f64 = 30.0;

/// The independent random sequences an episode's seed starts: its script, its bumps and
/// the noise on its controls (the planner has the seed itself).
#[derive(Clone, Copy)]
pub enum Stream {
    Script = 1,
    Bumps = 2,
    Noise = 3,
    /// Which of a plan's cost-to-go samples are kept.
    Values = 4,
}

/// Planning steps after which the expert records its trajectories for a learned
/// cost-to-go: 0.4, 0.6 and 0.9 s into its 1.2 s horizon (36 steps), so one network
/// stands for the rest after any of the horizons measured.
pub const VALUE_SPLITS: [usize; 3] = [12, 18, 27];
/// Of the up to 3·N states a plan records, how many a control step keeps (drawn at
/// random): two a step are about 200 000 states over a bike's 550 episodes, and keep a
/// shard at about twice its policy rows' size (six a step made it five times).
pub const VALUE_SAMPLES_PER_STEP: usize = 2;

pub fn stream(seed: u64, which: Stream) -> Pcg64 {
    Pcg64::seed_from_u64(seed.wrapping_mul(4).wrapping_add(which as u64))
}

/// How the expert rides, on which bike, and how the episode is shaped.
#[derive(Clone, Debug, PartialEq)]
pub struct ExpertSettings {
    /// The planner's trajectories: large enough to be reliable, not real time.
    pub trajectories: usize,
    /// Length of an episode (s), unless the bike crashes first.
    pub seconds: f64,
    /// Spread of the noise added to the applied controls, as a share of each entry's
    /// range (0: the expert's own controls).
    pub noise: f64,
    /// What kind of episode each seed draws.
    pub family: Family,
    /// The bike every episode rides (`--bike FILE`; the reference bike without it).
    pub bike: BikeParams,
    /// Whether the expert's plans are recorded for a learned cost-to-go too (`--values`).
    pub values: bool,
    /// The planner that drives while the expert labels, planning a short horizon ended by
    /// a learned cost-to-go (`--short-planner`; a DAgger round of the cost-to-go: it is
    /// taught the states its own short plans lead to).
    pub short_planner: Option<ShortPlanner>,
}

/// The game's planner on a shortened horizon: combined C-PBP, `SHORT_PLANNER_N`
/// trajectories, planning `horizon` and costing the rest of the 1.2 s with `value`.
#[derive(Clone, Debug, PartialEq)]
pub struct ShortPlanner {
    pub value: LoadedValue,
    pub horizon: f64,
}

/// The short planner's trajectories: the game's default N.
pub const SHORT_PLANNER_N: usize = 5;

impl Default for ExpertSettings {
    fn default() -> Self {
        Self {
            trajectories: 16,
            seconds: 12.0,
            noise: 0.03,
            family: Family::Mixed,
            bike: BikeParams::default(),
            values: false,
            short_planner: None,
        }
    }
}

/// The ground an episode rides on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Ground {
    Flat,
    /// Tilted about the bike's first heading's lateral axis (rad; positive uphill).
    Slope(f64),
    /// A height map of bumps up to this height (m).
    Bumps(f64),
    /// Flat ground with this many of the test level's log fields one after another ahead.
    Logs(usize),
    /// Flat ground with a row of platforms ahead, the tallest this high (m)
    /// (`grounds::platforms`).
    Platforms(f64),
}

impl Ground {
    pub fn label(&self) -> String {
        match self {
            Self::Flat => "flat".into(),
            Self::Slope(angle) => format!("slope {:+.1}°", angle.to_degrees()),
            Self::Bumps(height) => format!("bumps {:.0} mm", height * 1000.0),
            Self::Logs(fields) => format!("{fields} log fields"),
            Self::Platforms(tallest) => format!("platforms up to {:.0} mm", tallest * 1000.0),
        }
    }
}

/// One stretch of the script: what the player asks from `start` on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub start: usize,
    pub drive: DriveInput,
    /// The turn stick in [−1, 1] (the game's lean for it at the current speed), or a lean
    /// asked directly (rad), as the scripted rides ask.
    pub stick: f64,
    pub lean: Option<f64>,
    pub rider: RiderPosition,
    /// A sideways shove (N·s) at the segment's first step.
    pub push: f64,
}

impl Segment {
    /// Straight on from the start, coasting, the rider sitting neutral: what a segment
    /// asks where nothing else is said.
    pub const STRAIGHT: Self = Self {
        start: 0,
        drive: DriveInput {
            throttle: 0.0,
            brake: 0.0,
            max_speed: 0.0,
        },
        stick: 0.0,
        lean: None,
        rider: RiderPosition::NEUTRAL,
        push: 0.0,
    };
}

/// An episode's ground and script, drawn from its seed.
#[derive(Clone, Debug, PartialEq)]
pub struct Episode {
    pub seed: u64,
    pub ground: Ground,
    pub heading: f64,
    pub steps: usize,
    pub segments: Vec<Segment>,
}

impl Episode {
    /// The episode `seed` draws in `settings`' family (`family.rs` says what each holds).
    pub fn draw(seed: u64, settings: &ExpertSettings) -> Self {
        let steps = (settings.seconds * STEPS_PER_SECOND).round() as usize;
        settings.family.draw(seed, steps)
    }

    /// The simulation at the start: `bike` at rest on the episode's ground.
    pub fn simulation(&self, bike: &BikeParams) -> Simulation {
        let heading = DQuat::from_rotation_y(self.heading);
        let (terrain, rotation) = match self.ground {
            Ground::Flat => (Terrain::flat(), heading),
            Ground::Slope(angle) => {
                let rotation = heading * DQuat::from_rotation_z(angle);
                let plane = TerrainPiece::ground_through_origin("slope", rotation * DVec3::Y);
                (Terrain::new(vec![plane]).expect("a plane"), rotation)
            }
            Ground::Bumps(height) => (bump_field(self.seed, height), heading),
            Ground::Logs(fields) => (log_field(self.seed, heading, fields), heading),
            Ground::Platforms(tallest) => (platforms(self.seed, heading, tallest), heading),
        };
        let lift = match self.ground {
            Ground::Bumps(height) => height + 0.02,
            _ => 0.02,
        };
        let spawn = Placement {
            position: rotation * DVec3::Y * lift,
            rotation,
        };
        let config = SimulationConfig {
            physics: PhysicsModel::Exact,
            bike: bike.clone(),
            ..SimulationConfig::default()
        };
        Simulation::new(config, Arc::new(terrain), spawn)
    }
}

/// What an episode recorded, one row per control step the rider was on the bike.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Records {
    pub features: Vec<[f32; FEATURE_COUNT]>,
    pub labels: Vec<[f32; OUTPUT_COUNT]>,
    /// States the expert's trajectories reached, each as the cost-to-go's inputs (the
    /// features and the seconds of horizon left) and target (`value_target`); empty
    /// unless the settings record them.
    pub value_inputs: Vec<[f32; VALUE_INPUT_COUNT]>,
    pub value_targets: Vec<f32>,
    /// Whether the ride ended in a crash (the rows up to it stay: they are the expert's).
    pub crashed: bool,
    /// Who chose the applied controls: the expert, or the learner (DAgger).
    pub driver: String,
}

/// Rides `episode`, recording every step as labelled by the planner as the expert. The
/// expert drives, or with `learner` the network does and the expert labels the states
/// the network leads to (DAgger: the learner is taught where its own mistakes take it).
pub fn ride(
    episode: &Episode,
    settings: &ExpertSettings,
    learner: Option<&PolicyNetwork>,
) -> Records {
    let mut sim = episode.simulation(&settings.bike);
    let config = PlanningConfig {
        trajectories: settings.trajectories,
        seed: episode.seed,
        threads: 1,
        record_values_after: if settings.values {
            VALUE_SPLITS.to_vec()
        } else {
            Vec::new()
        },
        ..PlanningConfig::default().rolling_out_in(PhysicsModel::Exact)
    };
    let mut short = settings.short_planner.as_ref().map(|short| {
        let config = PlanningConfig {
            trajectories: SHORT_PLANNER_N,
            seed: episode.seed,
            threads: 1,
            terminal_value: true,
            value_horizon: short.horizon,
            value: short.value.clone(),
            ..PlanningConfig::default().rolling_out_in(PhysicsModel::Exact)
        };
        PlanningSession::new(&sim, &COMBINED, config)
    });
    let mut expert = PlanningSession::new(&sim, &COMBINED, config);
    let mut noise = stream(episode.seed, Stream::Noise);
    let mut keep = stream(episode.seed, Stream::Values);
    let (turn, entries) = (TurnIntent::for_bike(&settings.bike), output_entries());
    let driver = match (&settings.short_planner, learner) {
        (Some(short), _) => format!(
            "short planner (combined N = {SHORT_PLANNER_N}, {} s + cost-to-go: {:?})",
            short.horizon, short.value
        ),
        (None, Some(net)) => format!("learner ({})", net.parts().training),
        (None, None) => "expert".to_string(),
    };
    let mut records = Records {
        driver,
        ..Records::default()
    };
    let mut segment = episode.segments[0];
    for step in 0..episode.steps {
        if let Some(next) = episode.segments.iter().find(|s| s.start == step) {
            segment = *next;
            if segment.push != 0.0 {
                let side = sim.bike().frame_rotation(sim.world()) * DVec3::Z;
                sim.push(side * segment.push);
            }
        }
        if !sim.rider_is_on() || sim.crashed().is_some() {
            records.crashed = true;
            break;
        }
        let (bike, world, up) = (sim.bike(), sim.world(), sim.up());
        let speed = bike.forward_speed(world, up);
        let lean = match segment.lean {
            Some(lean) => lean.clamp(-turn.max_lean, turn.max_lean),
            None => turn.lean_for(segment.stick, speed, sim.config().gravity.length()),
        };
        let goal = Goal {
            lean,
            drive: segment.drive,
            rider: segment.rider,
        };
        let seen = features(bike, world, &goal, up);
        let label = expert.controls(&sim, &goal);
        if let Some(plan) = expert.last_plan().filter(|_| settings.values) {
            let dt = sim.config().control_dt;
            let samples = plan.value_samples.sample(&mut keep, VALUE_SAMPLES_PER_STEP);
            for sample in samples {
                let mut inputs = [0.0; VALUE_INPUT_COUNT];
                for (input, &feature) in inputs.iter_mut().zip(&sample.features) {
                    *input = feature as f32;
                }
                inputs[FEATURE_COUNT] = (sample.remaining_steps as f64 * dt) as f32;
                records.value_inputs.push(inputs);
                records.value_targets.push(value_target(sample.cost_to_go));
            }
        }
        // A state the network cannot read (non-finite) is the expert's to drive.
        let driven = match &mut short {
            Some(short) => short.controls(&sim, &goal),
            None => learner
                .and_then(|net| net.controls(bike, world, &goal, up).ok())
                .map_or(label, |c| Controls::sanitized(c.values()).0),
        };
        let mut applied = driven;
        if settings.noise > 0.0 {
            for &i in &entries {
                let range = cpbp_core::bike::UPPER[i] - cpbp_core::bike::LOWER[i];
                let kick: f64 = noise.sample(StandardNormal);
                applied.set(i, driven.get(i) + kick * settings.noise * range);
            }
        }
        if applied != label {
            expert.note_applied(&applied);
        }
        if let Some(short) = short.as_mut().filter(|_| applied != driven) {
            short.note_applied(&applied);
        }
        records.features.push(seen.map(|x| x as f32));
        records.labels.push(entries.map(|i| label.get(i) as f32));
        sim.set_controls(applied);
        sim.set_pitch_request(goal.pitch_request());
        sim.step();
    }
    records
}
