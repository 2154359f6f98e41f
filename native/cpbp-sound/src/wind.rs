//! Wind past the rider's helmet: noise whose loudness follows the air's pressure on the
//! helmet (the square of the speed) and whose colour brightens as the speed rises. Still
//! air is silent.

use crate::dsp::{approach, LowPass, Noise};

/// Speed (m/s) at which the wind is at its loudest: 108 km/h, past what the game's levels
/// are ridden at, so the wind grows all the way through them.
pub const LOUDEST_SPEED: f32 = 30.0;

/// How loud (0–1) the wind is at `speed` m/s.
pub fn wind_level(speed: f32) -> f32 {
    (speed.abs() / LOUDEST_SPEED).min(1.0).powi(2)
}

/// The wind's voice.
#[derive(Clone, Debug)]
pub struct WindVoice {
    sample_rate: f32,
    speed: f32,
    level: f32,
    body: LowPass,
    rumble: LowPass,
    noise: Noise,
}

impl WindVoice {
    pub fn new(sample_rate: f32) -> Self {
        Self {
            sample_rate,
            speed: 0.0,
            level: 0.0,
            body: LowPass::default(),
            rumble: LowPass::default(),
            noise: Noise::new(0x000_a1d5),
        }
    }

    /// The bike moves at `speed` m/s through still air.
    pub fn set_speed(&mut self, speed: f32) {
        self.speed = speed.abs();
    }

    pub fn sample(&mut self) -> f32 {
        let rate = self.sample_rate;
        // Gusts and buffeting come and go over a fifth of a second.
        self.level = approach(self.level, wind_level(self.speed), 0.2, rate);
        if self.level < 1e-4 {
            return 0.0;
        }
        let hiss = self.noise.sample();
        let body = self.body.process(hiss, 300.0 + 40.0 * self.speed, rate);
        // A low roar under the hiss: the helmet's buffeting.
        let rumble = self.rumble.process(hiss, 60.0, rate);
        (2.0 * body + 6.0 * rumble) * self.level
    }
}
