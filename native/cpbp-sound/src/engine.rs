//! The engine, of the layout its bike names (`EngineLayout`), geared to the rear wheel
//! through a six-speed box that shifts itself. Its crank speed follows the rear wheel's
//! speed (or the slipping clutch when the wheel is slower than the throttle asks), and
//! each firing sends an exhaust pulse down a resonant pipe whose strength and brightness
//! follow the throttle.

use crate::dsp::{approach, LowPass, Noise, Resonator};
use crate::layout::EngineLayout;

/// Gear and crank speed from the rear wheel and the throttle, updated at the physics rate.
#[derive(Clone, Debug)]
pub struct Drivetrain {
    layout: EngineLayout,
    gear: usize,
    rpm: f32,
}

impl Default for Drivetrain {
    fn default() -> Self {
        Self::new(EngineLayout::default())
    }
}

impl Drivetrain {
    /// In first gear, idling.
    pub fn new(layout: EngineLayout) -> Self {
        Self {
            layout,
            gear: 0,
            rpm: layout.idle_rpm,
        }
    }

    /// Advances `dt` seconds with the rear wheel's rim moving at `wheel_speed` (m/s,
    /// forward positive) and the throttle open by `throttle` (0–1).
    pub fn update(&mut self, wheel_speed: f32, throttle: f32, dt: f32) {
        let l = &self.layout;
        let ratios = &l.gear_kmh_per_krpm;
        let wheel_rpm = |gear: usize| wheel_speed.abs() * 3.6 / ratios[gear] * 1000.0;
        while self.gear + 1 < ratios.len() && wheel_rpm(self.gear) > l.shift_up_rpm {
            self.gear += 1;
        }
        while self.gear > 0 && wheel_rpm(self.gear) < l.shift_down_rpm {
            self.gear -= 1;
        }
        let clutch = l.idle_rpm + throttle * (l.launch_rpm - l.idle_rpm);
        let target = wheel_rpm(self.gear).max(clutch).min(l.limiter_rpm);
        // The crank spins up quicker than it winds down.
        let lag = if target > self.rpm { 0.05 } else { 0.12 };
        self.rpm += (target - self.rpm) * (1.0 - (-dt / lag).exp());
    }

    pub fn rpm(&self) -> f32 {
        self.rpm
    }

    /// Gear engaged, 1 to 6.
    pub fn gear(&self) -> usize {
        self.gear + 1
    }

    pub fn layout(&self) -> &EngineLayout {
        &self.layout
    }

    /// Exhaust pulses per second now: the pitch one hears.
    pub fn firing_frequency(&self) -> f32 {
        self.layout.firing_frequency(self.rpm)
    }
}

/// The engine's sound, sample by sample.
#[derive(Clone, Debug)]
pub struct EngineVoice {
    layout: EngineLayout,
    sample_rate: f32,
    /// Crank speed and throttle the voice is moving towards, and where it is now.
    target_rpm: f32,
    target_load: f32,
    rpm: f32,
    load: f32,
    /// Position in the firing cycle (0–1) and the current pulse's strength.
    phase: f32,
    pulse: f32,
    brightness: LowPass,
    pipe: Resonator,
    intake: Resonator,
    noise: Noise,
}

impl EngineVoice {
    pub fn new(layout: EngineLayout, sample_rate: f32) -> Self {
        Self {
            layout,
            sample_rate,
            target_rpm: layout.idle_rpm,
            target_load: 0.0,
            rpm: layout.idle_rpm,
            load: 0.0,
            phase: 0.0,
            pulse: 0.0,
            brightness: LowPass::default(),
            pipe: Resonator::new(layout.pipe_hz, layout.pipe_bandwidth, sample_rate),
            intake: Resonator::new(900.0, 300.0, sample_rate),
            noise: Noise::new(0x5eed_e11e),
        }
    }

    /// What the engine does now: crank speed (rpm) and throttle (0–1).
    pub fn set(&mut self, rpm: f32, load: f32) {
        self.target_rpm = rpm.clamp(0.0, self.layout.limiter_rpm);
        self.target_load = load.clamp(0.0, 1.0);
    }

    pub fn sample(&mut self) -> f32 {
        let rate = self.sample_rate;
        // Glide over ~10 ms between physics ticks, so the pitch does not step.
        self.rpm = approach(self.rpm, self.target_rpm, 0.01, rate);
        self.load = approach(self.load, self.target_load, 0.02, rate);
        let frequency = self.layout.firing_frequency(self.rpm);
        self.phase += frequency / rate;
        if self.phase >= 1.0 {
            self.phase -= 1.0;
            // No two combustions are alike: a few per cent of jitter per firing.
            self.pulse = (0.35 + 0.65 * self.load) * (1.0 + 0.08 * self.noise.sample());
        }
        // Each pulse dies away within its own cycle (a single's within a quarter period),
        // so the firing frequency is the loudest partial.
        self.pulse *= (-self.layout.pulse_decay * frequency / rate).exp();
        let cutoff = 250.0 + 2_000.0 * self.load + 0.15 * self.rpm;
        let exhaust = self.brightness.process(self.pulse, cutoff, rate);
        let pipe = self.pipe.process(exhaust) * 2.5;
        let hiss = self.intake.process(self.noise.sample() * self.pulse) * (0.5 + self.load);
        // The single's mix (0.55 exhaust, 0.3 pipe, 0.15 hiss) with the layout's rasp.
        let rasp = self.layout.rasp;
        let voice = (1.0 - rasp) / 0.85 * (0.55 * exhaust + 0.3 * pipe) + rasp * hiss;
        voice * self.layout.loudness
    }
}
