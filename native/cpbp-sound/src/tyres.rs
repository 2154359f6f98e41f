//! Tyre scrub and skid: band-passed noise whose level follows how fast the tyre slides
//! over the ground at its contact patch (locked under braking, spinning under power, or
//! drifting sideways). Rolling without slip is silent.

use crate::dsp::{approach, Noise, Resonator};

/// Slip below this speed (m/s) is the tyre's ordinary creep: no sound.
pub const SILENT_SLIP: f32 = 0.4;
/// Slip at which the scrub is at its loudest (m/s).
pub const LOUDEST_SLIP: f32 = 4.0;

/// How loud (0–1) a tyre sliding at `slip` m/s sounds.
pub fn scrub_level(slip: f32) -> f32 {
    ((slip.abs() - SILENT_SLIP) / (LOUDEST_SLIP - SILENT_SLIP)).clamp(0.0, 1.0)
}

/// One tyre's voice.
#[derive(Clone, Debug)]
pub struct TyreVoice {
    sample_rate: f32,
    target: f32,
    level: f32,
    carcass: Resonator,
    tread: Resonator,
    noise: Noise,
}

impl TyreVoice {
    /// A tyre whose carcass rings near `pitch` Hz (the two tyres differ a little).
    pub fn new(pitch: f32, seed: u32, sample_rate: f32) -> Self {
        Self {
            sample_rate,
            target: 0.0,
            level: 0.0,
            carcass: Resonator::new(pitch, pitch * 0.25, sample_rate),
            tread: Resonator::new(pitch * 2.7, pitch, sample_rate),
            noise: Noise::new(seed),
        }
    }

    /// The tyre slides at `slip` m/s (0 when it is off the ground).
    pub fn set_slip(&mut self, slip: f32) {
        self.target = scrub_level(slip);
    }

    pub fn sample(&mut self) -> f32 {
        self.level = approach(self.level, self.target, 0.03, self.sample_rate);
        if self.level < 1e-4 {
            return 0.0;
        }
        let grain = self.noise.sample();
        let squeal = self.carcass.process(grain) * 6.0 + self.tread.process(grain) * 3.0;
        squeal * self.level * 0.5
    }
}
