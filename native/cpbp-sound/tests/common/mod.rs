//! What the sound tests share: rendering a voice under steady measurements, and the
//! pitch and loudness of what it rendered.
#![allow(dead_code)]

use cpbp_sound::{BikeVoice, Sources};

pub const RATE: f32 = 44_100.0;
pub const TICK: f32 = 1.0 / 60.0;

/// Rides `seconds` with the same measurements every tick and returns the last `keep`
/// seconds of sound.
pub fn render(voice: &mut BikeVoice, sources: Sources, seconds: f32, keep: f32) -> Vec<f32> {
    let per_tick = (RATE * TICK) as usize;
    let ticks = (seconds / TICK) as usize;
    let mut sound = Vec::new();
    let mut block = vec![0.0; per_tick];
    for _ in 0..ticks {
        voice.update(sources, TICK);
        voice.render(&mut block);
        sound.extend_from_slice(&block);
    }
    sound.split_off(sound.len() - (keep * RATE) as usize)
}

pub fn riding(speed: f32, throttle: f32) -> Sources {
    Sources {
        rear_wheel_speed: speed,
        throttle,
        running: true,
        ..Sources::default()
    }
}

/// Fundamental frequency by autocorrelation (10–400 Hz: an inline four near its limiter
/// fires 500 times a second, the game rides it below that): the first lag whose
/// correlation comes within 10 % of the best, so a period's multiples are not taken for
/// it.
pub fn pitch(sound: &[f32]) -> f32 {
    let lags = (RATE / 400.0) as usize..(RATE / 10.0) as usize;
    let n = sound.len() - lags.end;
    let correlation: Vec<f32> = lags
        .clone()
        .map(|lag| (0..n).map(|i| sound[i] * sound[i + lag]).sum::<f32>())
        .collect();
    let best = correlation.iter().cloned().fold(f32::MIN, f32::max);
    // The first local maximum that comes close to the best.
    let first = (1..correlation.len() - 1)
        .find(|&i| {
            correlation[i] >= 0.9 * best
                && correlation[i] >= correlation[i - 1]
                && correlation[i] >= correlation[i + 1]
        })
        .unwrap();
    RATE / (lags.start + first) as f32
}

pub fn rms(sound: &[f32]) -> f32 {
    (sound.iter().map(|s| s * s).sum::<f32>() / sound.len() as f32).sqrt()
}
