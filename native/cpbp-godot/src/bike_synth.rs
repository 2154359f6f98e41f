//! `BikeSynth`: the bike's engine, tyres, thumps and wind (`cpbp_sound::BikeVoice`)
//! listening to a `BikeSimulation` and rendering samples for an `AudioStreamGenerator`.

use cpbp_sound::layout::EngineLayout;
use cpbp_sound::{BikeVoice, Sources};
use godot::classes::AudioServer;
use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

/// Synthesises the sound of the bike it listens to. Call `listen` every physics tick and
/// `mix` with the frames the generator has room for; both are cheap (no allocation per
/// sample, a few µs per tick).
#[derive(GodotClass)]
#[class(base=RefCounted)]
pub struct BikeSynth {
    voice: BikeVoice,
    sample_rate: f32,
    engine_volume: f32,
    /// The step whose ground blow was last heard: a blow sounds once, however many ticks
    /// read it.
    heard_step: i64,
    samples: Vec<f32>,
    base: Base<RefCounted>,
}

#[godot_api]
impl IRefCounted for BikeSynth {
    fn init(base: Base<RefCounted>) -> Self {
        Self::at(AudioServer::singleton().get_mix_rate(), base)
    }
}

#[godot_api]
impl BikeSynth {
    /// A synthesiser at `sample_rate` Hz (the generator's `mix_rate`).
    #[func]
    fn at_rate(sample_rate: f32) -> Gd<Self> {
        Gd::from_init_fn(|base| Self::at(sample_rate, base))
    }

    /// Sounds the engine `bike`'s file names (its `engine`; a four-stroke single for the
    /// reference bike, or, with a warning, for a file naming none of the layouts).
    #[func]
    fn hear_engine_of(&mut self, bike: Gd<BikeSimulation>) {
        let layout = match bike.bind().bike.as_ref() {
            Some(description) => description.bind().engine().unwrap_or_else(|why| {
                godot_warn!("BikeSynth: {why}; it sounds as a four-stroke single");
                EngineLayout::default()
            }),
            None => EngineLayout::default(),
        };
        if *self.voice.engine() != layout {
            self.voice = BikeVoice::with_engine(layout, self.sample_rate);
            self.voice.set_engine_volume(self.engine_volume);
        }
    }

    /// The engine's layout: `name` and `label` ("two-stroke single"), `cylinders`,
    /// `strokes`, `idle_rpm`, `limiter_rpm`.
    #[func]
    fn get_engine(&self) -> VarDictionary {
        let layout = self.voice.engine();
        vdict! {
            "name" => layout.name,
            "label" => layout.label,
            "cylinders" => layout.cylinders,
            "strokes" => layout.strokes,
            "idle_rpm" => layout.idle_rpm,
            "limiter_rpm" => layout.limiter_rpm,
        }
    }

    /// Reads what `bike` did over the last `delta` seconds: the rear rim's speed and the
    /// throttle (engine), each tyre's slide, the ground's blow, whether it crashed (the
    /// engine stalls) and its speed (the wind).
    #[func]
    fn listen(&mut self, bike: Gd<BikeSimulation>, delta: f64) {
        let bike = bike.bind();
        let Some(sim) = bike.sim() else { return };
        let up = sim.up();
        let (rear_slip, front_slip) = sim.bike().tyre_slip(sim.world(), up);
        let step = bike.ride.as_ref().map_or(0, |r| r.steps() as i64);
        let impact = if step != self.heard_step {
            sim.ground_blow()
        } else {
            0.0
        };
        self.heard_step = step;
        let sources = Sources {
            rear_wheel_speed: sim.bike().rear_rim_speed(sim.world()) as f32,
            throttle: bike.intent.drive.sanitized().throttle as f32,
            rear_slip: rear_slip as f32,
            front_slip: front_slip as f32,
            impact: impact as f32,
            running: sim.crashed().is_none(),
            speed: sim.bike().center_of_mass_velocity(sim.world()).length() as f32,
        };
        self.voice.update(sources, delta as f32);
    }

    /// The next `frames` samples, the same on both channels.
    #[func]
    fn mix(&mut self, frames: i64) -> PackedVector2Array {
        let frames = usize::try_from(frames).unwrap_or(0).min(1 << 16);
        self.samples.resize(frames, 0.0);
        self.voice.render(&mut self.samples);
        self.samples.iter().map(|s| Vector2::new(*s, *s)).collect()
    }

    /// Engine loudness against tyres and thumps (0–1).
    #[func]
    fn set_engine_volume(&mut self, volume: f32) {
        self.engine_volume = volume;
        self.voice.set_engine_volume(volume);
    }

    /// Fades out to exact silence (the game paused) or back in.
    #[func]
    fn set_muted(&mut self, muted: bool) {
        self.voice.set_muted(muted);
    }

    /// Crank speed (rpm), for a rev counter and tests.
    #[func]
    fn get_rpm(&self) -> f32 {
        self.voice.rpm()
    }

    /// Gear engaged (1–6).
    #[func]
    fn get_gear(&self) -> i64 {
        self.voice.gear() as i64
    }

    /// The engine's firing frequency now (Hz): the pitch one hears.
    #[func]
    fn get_firing_frequency(&self) -> f32 {
        self.voice.firing_frequency()
    }
}

impl BikeSynth {
    fn at(sample_rate: f32, base: Base<RefCounted>) -> Self {
        Self {
            voice: BikeVoice::new(sample_rate),
            sample_rate,
            engine_volume: 1.0,
            heard_step: -1,
            samples: Vec::new(),
            base,
        }
    }
}
