//! The few signal-processing pieces the voices are made of: a noise source, a one-pole
//! low-pass filter and a two-pole resonator.

use std::f32::consts::{PI, TAU};

/// White noise in [−1, 1] from a 32-bit xorshift: cheap, and the same every run for a
/// seed, so rendered audio repeats exactly.
#[derive(Clone, Debug)]
pub struct Noise(u32);

impl Noise {
    pub fn new(seed: u32) -> Self {
        Self(seed.max(1))
    }

    pub fn sample(&mut self) -> f32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x as f32 / u32::MAX as f32 * 2.0 - 1.0
    }
}

/// One-pole low-pass filter (6 dB per octave above its cutoff).
#[derive(Clone, Debug, Default)]
pub struct LowPass {
    state: f32,
}

impl LowPass {
    pub fn process(&mut self, input: f32, cutoff_hz: f32, sample_rate: f32) -> f32 {
        let coefficient = 1.0 - (-TAU * cutoff_hz / sample_rate).exp();
        self.state += coefficient * (input - self.state);
        self.state
    }
}

/// Two-pole resonator: rings at `frequency` with bandwidth `bandwidth` (Hz) when excited,
/// as an exhaust pipe or a tyre carcass does. Unity gain at the centre.
#[derive(Clone, Debug)]
pub struct Resonator {
    a1: f32,
    a2: f32,
    gain: f32,
    y1: f32,
    y2: f32,
}

impl Resonator {
    pub fn new(frequency: f32, bandwidth: f32, sample_rate: f32) -> Self {
        let radius = (-PI * bandwidth / sample_rate).exp();
        Self {
            a1: -2.0 * radius * (TAU * frequency / sample_rate).cos(),
            a2: radius * radius,
            gain: 1.0 - radius,
            y1: 0.0,
            y2: 0.0,
        }
    }

    pub fn process(&mut self, input: f32) -> f32 {
        let y = self.gain * input - self.a1 * self.y1 - self.a2 * self.y2;
        self.y2 = self.y1;
        self.y1 = y;
        y
    }
}

/// Moves `current` towards `target` with time constant `seconds` over one sample.
pub fn approach(current: f32, target: f32, seconds: f32, sample_rate: f32) -> f32 {
    current + (target - current) * (1.0 - (-1.0 / (seconds * sample_rate)).exp())
}

/// Removes the constant part of a signal (a first-order high-pass at `cutoff_hz`): the
/// exhaust pulses are all positive, and a mean left in the output would click when the
/// sound stops.
#[derive(Clone, Debug)]
pub struct DcBlocker {
    pole: f32,
    last_input: f32,
    last_output: f32,
}

impl DcBlocker {
    pub fn new(cutoff_hz: f32, sample_rate: f32) -> Self {
        Self {
            pole: 1.0 - TAU * cutoff_hz / sample_rate,
            last_input: 0.0,
            last_output: 0.0,
        }
    }

    pub fn process(&mut self, input: f32) -> f32 {
        let output = input - self.last_input + self.pole * self.last_output;
        self.last_input = input;
        self.last_output = output;
        output
    }
}
