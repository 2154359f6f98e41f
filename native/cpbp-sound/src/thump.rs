//! Landings and impacts: a low, quickly damped boom with a short burst of crunch on top,
//! as loud as the blow was hard.

use crate::dsp::{LowPass, Noise};
use std::f32::consts::TAU;

/// Ground impulse (N·s in one control step, beyond what carries the bike's weight) that
/// a wheel rolling over small bumps gives: quieter blows make no thump.
pub const SILENT_IMPULSE: f32 = 15.0;
/// Impulse of the hardest landing the sound tells apart (N·s): a metre's drop onto flat
/// ground for the bike and rider.
pub const LOUDEST_IMPULSE: f32 = 450.0;

/// How loud (0–1) a blow of `impulse` N·s beyond the weight's share sounds.
pub fn thump_strength(impulse: f32) -> f32 {
    ((impulse - SILENT_IMPULSE) / (LOUDEST_IMPULSE - SILENT_IMPULSE)).clamp(0.0, 1.0)
}

#[derive(Clone, Debug)]
pub struct ThumpVoice {
    sample_rate: f32,
    boom: f32,
    crunch: f32,
    phase: f32,
    muffle: LowPass,
    noise: Noise,
}

impl ThumpVoice {
    pub fn new(sample_rate: f32) -> Self {
        Self {
            sample_rate,
            boom: 0.0,
            crunch: 0.0,
            phase: 0.0,
            muffle: LowPass::default(),
            noise: Noise::new(0x7417_a11d),
        }
    }

    /// Starts a thump of `strength` (0–1); a harder one than the one ringing takes over.
    pub fn hit(&mut self, strength: f32) {
        let strength = strength.clamp(0.0, 1.0);
        if strength > self.boom {
            self.boom = strength;
            self.crunch = strength;
            self.phase = 0.0;
        }
    }

    pub fn sample(&mut self) -> f32 {
        if self.boom < 1e-4 {
            return 0.0;
        }
        let rate = self.sample_rate;
        self.phase = (self.phase + 55.0 / rate).fract();
        let boom = (TAU * self.phase).sin() * self.boom;
        let crunch = self.muffle.process(self.noise.sample(), 400.0, rate) * self.crunch * 2.0;
        self.boom *= (-1.0 / (0.12 * rate)).exp();
        self.crunch *= (-1.0 / (0.035 * rate)).exp();
        boom + crunch
    }
}
