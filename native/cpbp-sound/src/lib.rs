//! Counter-Steer's bike sounds, synthesised at run time from what the simulation measures
//! (no recorded samples): the engine of the bike's layout (`engine`, `layout`), the tyres
//! (`tyres`), landings and impacts (`thump`) and the wind (`wind`), mixed by `BikeVoice`. Free of Godot types; `cpbp-godot` feeds the
//! samples to an `AudioStreamGenerator`.

pub mod dsp;
pub mod engine;
pub mod layout;
pub mod thump;
pub mod tyres;
pub mod wind;

use dsp::{approach, DcBlocker};
use engine::{Drivetrain, EngineVoice};
use layout::EngineLayout;
use thump::{thump_strength, ThumpVoice};
use tyres::TyreVoice;
use wind::WindVoice;

/// The mix's overall level: a revving engine sits around −14 dBFS RMS, leaving headroom
/// for a landing on top.
const MIX_LEVEL: f32 = 0.3;

/// What the simulation measured over the last physics tick.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sources {
    /// Speed of the rear tyre's rim (m/s, forward positive): the engine turns with it.
    pub rear_wheel_speed: f32,
    /// Throttle opening (0–1).
    pub throttle: f32,
    /// How fast each tyre slides over the ground at its contact (m/s; 0 in the air).
    pub rear_slip: f32,
    pub front_slip: f32,
    /// Ground impulse of the hardest blow since the last tick, beyond the weight's share
    /// (N·s along up).
    pub impact: f32,
    /// The engine runs (false after a crash: it stalls).
    pub running: bool,
    /// The bike's speed through the air (m/s): the wind.
    pub speed: f32,
}

/// The whole bike's sound: engine, both tyres and thumps, mixed to one channel.
#[derive(Clone, Debug)]
pub struct BikeVoice {
    sample_rate: f32,
    drivetrain: Drivetrain,
    engine: EngineVoice,
    rear_tyre: TyreVoice,
    front_tyre: TyreVoice,
    thump: ThumpVoice,
    wind: WindVoice,
    dc: DcBlocker,
    engine_volume: f32,
    /// The engine's own level (0 when stalled), and the whole voice's (0 when muted).
    engine_level: f32,
    engine_target: f32,
    gain: f32,
    gain_target: f32,
}

impl BikeVoice {
    /// A bike with the default engine (a four-stroke single).
    pub fn new(sample_rate: f32) -> Self {
        Self::with_engine(EngineLayout::default(), sample_rate)
    }

    /// A bike whose engine is built as `layout` says.
    pub fn with_engine(layout: EngineLayout, sample_rate: f32) -> Self {
        let sample_rate = sample_rate.max(8_000.0);
        Self {
            sample_rate,
            drivetrain: Drivetrain::new(layout),
            engine: EngineVoice::new(layout, sample_rate),
            rear_tyre: TyreVoice::new(700.0, 0x0ea7_0001, sample_rate),
            front_tyre: TyreVoice::new(820.0, 0x0ea7_0002, sample_rate),
            thump: ThumpVoice::new(sample_rate),
            wind: WindVoice::new(sample_rate),
            dc: DcBlocker::new(8.0, sample_rate),
            engine_volume: 1.0,
            engine_level: 1.0,
            engine_target: 1.0,
            gain: 1.0,
            gain_target: 1.0,
        }
    }

    /// Takes a physics tick's measurements (`dt` seconds long). Non-finite values count
    /// as 0, so a broken measurement is silence, not noise.
    pub fn update(&mut self, sources: Sources, dt: f32) {
        let finite = |v: f32| if v.is_finite() { v } else { 0.0 };
        let throttle = finite(sources.throttle).clamp(0.0, 1.0);
        let dt = finite(dt).clamp(0.0, 0.25);
        self.drivetrain
            .update(finite(sources.rear_wheel_speed), throttle, dt);
        self.engine.set(self.drivetrain.rpm(), throttle);
        self.engine_target = if sources.running { 1.0 } else { 0.0 };
        self.rear_tyre.set_slip(finite(sources.rear_slip));
        self.front_tyre.set_slip(finite(sources.front_slip));
        self.thump.hit(thump_strength(finite(sources.impact)));
        self.wind.set_speed(finite(sources.speed));
    }

    /// The engine's layout.
    pub fn engine(&self) -> &EngineLayout {
        self.drivetrain.layout()
    }

    /// Engine loudness relative to the tyres and thumps (0–1, the player's setting).
    pub fn set_engine_volume(&mut self, volume: f32) {
        self.engine_volume = if volume.is_finite() {
            volume.clamp(0.0, 1.0)
        } else {
            1.0
        };
    }

    /// Fades everything out within a few milliseconds (the game paused) or back in; once
    /// faded the output is exactly zero.
    pub fn set_muted(&mut self, muted: bool) {
        self.gain_target = if muted { 0.0 } else { 1.0 };
    }

    pub fn rpm(&self) -> f32 {
        self.drivetrain.rpm()
    }

    pub fn gear(&self) -> usize {
        self.drivetrain.gear()
    }

    /// The engine's firing frequency now (Hz): the pitch one hears.
    pub fn firing_frequency(&self) -> f32 {
        self.drivetrain.firing_frequency()
    }

    /// Fills `out` with the next samples (mono, −1 to 1).
    pub fn render(&mut self, out: &mut [f32]) {
        let rate = self.sample_rate;
        for sample in out.iter_mut() {
            self.gain = approach(self.gain, self.gain_target, 0.005, rate);
            self.engine_level = approach(self.engine_level, self.engine_target, 0.15, rate);
            if self.gain < 1e-4 && self.gain_target == 0.0 {
                *sample = 0.0;
                continue;
            }
            let engine = self.engine.sample() * self.engine_level * self.engine_volume;
            let mixed = 0.8 * engine
                + 0.35 * (self.rear_tyre.sample() + self.front_tyre.sample())
                + 0.6 * self.thump.sample()
                + 0.5 * self.wind.sample();
            // A soft clip keeps a loud landing over a revving engine from wrapping.
            *sample = (self.dc.process(mixed) * MIX_LEVEL * self.gain).tanh();
        }
    }
}
