//! The engine: a single-cylinder four-stroke, as on the dirt bikes of Trials and MX Bikes,
//! geared to the rear wheel through a six-speed box that shifts itself. Its crank speed
//! follows the rear wheel's speed (or the slipping clutch when the wheel is slower than
//! the throttle asks), and each firing sends an exhaust pulse down a resonant pipe whose
//! strength and brightness follow the throttle.

use crate::dsp::{approach, LowPass, Noise, Resonator};

/// Crank speed at idle and at the rev limiter (rpm).
pub const IDLE_RPM: f32 = 1_700.0;
pub const LIMITER_RPM: f32 = 11_000.0;
/// Crank speed a wide-open throttle holds on a slipping clutch, pulling away (rpm).
pub const LAUNCH_RPM: f32 = 5_500.0;
/// Road speed per 1000 rpm in each gear (km/h): short ratios, so the game's 0–60 km/h
/// uses the first four.
pub const GEAR_KMH_PER_KRPM: [f32; 6] = [2.6, 3.5, 4.5, 5.5, 6.5, 7.5];
/// The box shifts up above, and down below, these crank speeds (rpm); the ratios keep an
/// upshift well above the downshift point, so it never hunts.
pub const SHIFT_UP_RPM: f32 = 8_500.0;
pub const SHIFT_DOWN_RPM: f32 = 4_000.0;

/// Firings per crank revolution: one every second turn for a four-stroke single.
const FIRINGS_PER_REV: f32 = 0.5;

/// Gear and crank speed from the rear wheel and the throttle, updated at the physics rate.
#[derive(Clone, Debug)]
pub struct Drivetrain {
    gear: usize,
    rpm: f32,
}

impl Default for Drivetrain {
    fn default() -> Self {
        Self {
            gear: 0,
            rpm: IDLE_RPM,
        }
    }
}

impl Drivetrain {
    /// Advances `dt` seconds with the rear wheel's rim moving at `wheel_speed` (m/s,
    /// forward positive) and the throttle open by `throttle` (0–1).
    pub fn update(&mut self, wheel_speed: f32, throttle: f32, dt: f32) {
        let wheel_rpm = |gear: usize| wheel_speed.abs() * 3.6 / GEAR_KMH_PER_KRPM[gear] * 1000.0;
        while self.gear + 1 < GEAR_KMH_PER_KRPM.len() && wheel_rpm(self.gear) > SHIFT_UP_RPM {
            self.gear += 1;
        }
        while self.gear > 0 && wheel_rpm(self.gear) < SHIFT_DOWN_RPM {
            self.gear -= 1;
        }
        let clutch = IDLE_RPM + throttle * (LAUNCH_RPM - IDLE_RPM);
        let target = wheel_rpm(self.gear).max(clutch).min(LIMITER_RPM);
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

    /// Exhaust pulses per second at `rpm`: the pitch one hears.
    pub fn firing_frequency(rpm: f32) -> f32 {
        rpm / 60.0 * FIRINGS_PER_REV
    }
}

/// The engine's sound, sample by sample.
#[derive(Clone, Debug)]
pub struct EngineVoice {
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
    pub fn new(sample_rate: f32) -> Self {
        Self {
            sample_rate,
            target_rpm: IDLE_RPM,
            target_load: 0.0,
            rpm: IDLE_RPM,
            load: 0.0,
            phase: 0.0,
            pulse: 0.0,
            brightness: LowPass::default(),
            pipe: Resonator::new(140.0, 90.0, sample_rate),
            intake: Resonator::new(900.0, 300.0, sample_rate),
            noise: Noise::new(0x5eed_e11e),
        }
    }

    /// What the engine does now: crank speed (rpm) and throttle (0–1).
    pub fn set(&mut self, rpm: f32, load: f32) {
        self.target_rpm = rpm.clamp(0.0, LIMITER_RPM);
        self.target_load = load.clamp(0.0, 1.0);
    }

    pub fn sample(&mut self) -> f32 {
        let rate = self.sample_rate;
        // Glide over ~10 ms between physics ticks, so the pitch does not step.
        self.rpm = approach(self.rpm, self.target_rpm, 0.01, rate);
        self.load = approach(self.load, self.target_load, 0.02, rate);
        let frequency = Drivetrain::firing_frequency(self.rpm);
        self.phase += frequency / rate;
        if self.phase >= 1.0 {
            self.phase -= 1.0;
            // No two combustions are alike: a few per cent of jitter per firing.
            self.pulse = (0.35 + 0.65 * self.load) * (1.0 + 0.08 * self.noise.sample());
        }
        // Each pulse dies away within its own cycle (a quarter period's time constant),
        // so the firing frequency is the loudest partial.
        self.pulse *= (-4.0 * frequency / rate).exp();
        let cutoff = 250.0 + 2_000.0 * self.load + 0.15 * self.rpm;
        let exhaust = self.brightness.process(self.pulse, cutoff, rate);
        let pipe = self.pipe.process(exhaust) * 2.5;
        let hiss = self.intake.process(self.noise.sample() * self.pulse) * (0.5 + self.load);
        0.55 * exhaust + 0.3 * pipe + 0.15 * hiss
    }
}
