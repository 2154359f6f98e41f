//! The bike's voice sounds as the simulation says: the engine's pitch is its firing
//! frequency and rises with the rear wheel's speed through the gears, the tyres are silent
//! until they slide, a thump is as loud as the blow, and muted is exactly silent.

mod common;

use common::{pitch, render, riding, rms, RATE, TICK};
use cpbp_sound::engine::Drivetrain;
use cpbp_sound::layout::EngineLayout;
use cpbp_sound::{BikeVoice, Sources};

#[test]
fn the_engine_sounds_at_its_firing_frequency_and_rises_with_speed_in_a_gear() {
    let mut heard = Vec::new();
    for speed_kmh in [8.0_f32, 14.0, 20.0] {
        let mut voice = BikeVoice::new(RATE);
        let sound = render(&mut voice, riding(speed_kmh / 3.6, 0.6), 1.5, 0.5);
        assert_eq!(voice.gear(), 1, "{speed_kmh} km/h is first gear");
        let expected = voice.firing_frequency();
        let measured = pitch(&sound);
        assert!(
            (measured / expected - 1.0).abs() < 0.04,
            "{speed_kmh} km/h: heard {measured:.1} Hz, firing at {expected:.1} Hz"
        );
        heard.push(measured);
    }
    assert!(heard[0] < heard[1] && heard[1] < heard[2], "{heard:?}");
}

#[test]
fn the_box_shifts_up_with_speed_and_down_again_without_hunting() {
    let single = EngineLayout::FOUR_STROKE_SINGLE;
    let mut drivetrain = Drivetrain::default();
    let mut gears = Vec::new();
    for tick in 0..1200 {
        // Up to 60 km/h over 10 s, and back.
        let speed = 60.0 / 3.6 * (1.0 - (tick as f32 / 600.0 - 1.0).abs());
        drivetrain.update(speed, 0.8, TICK);
        gears.push(drivetrain.gear());
        assert!(
            drivetrain.rpm() <= single.shift_up_rpm + 500.0,
            "{} rpm",
            drivetrain.rpm()
        );
        if drivetrain.gear() > 1 {
            assert!(
                drivetrain.rpm() >= single.shift_down_rpm - 500.0,
                "{}",
                drivetrain.rpm()
            );
        }
    }
    let changes = gears.windows(2).filter(|w| w[0] != w[1]).count();
    let top = *gears.iter().max().unwrap();
    assert!(top >= 4, "60 km/h is fourth gear or above, got {top}");
    assert_eq!(
        changes,
        2 * (top - 1),
        "each gear once up and once down: {changes}"
    );
}

#[test]
fn standing_still_it_idles_and_the_throttle_revs_it_on_the_clutch() {
    for layout in EngineLayout::ALL {
        let mut voice = BikeVoice::with_engine(layout, RATE);
        render(&mut voice, riding(0.0, 0.0), 1.0, 0.1);
        assert!(
            (voice.rpm() - layout.idle_rpm).abs() < 50.0,
            "{}",
            voice.rpm()
        );
        render(&mut voice, riding(0.0, 1.0), 1.0, 0.1);
        assert!(
            (voice.rpm() - layout.launch_rpm).abs() < 100.0,
            "{}",
            voice.rpm()
        );
    }
}

#[test]
fn an_open_throttle_is_louder_than_a_closed_one() {
    let closed = rms(&render(
        &mut BikeVoice::new(RATE),
        riding(4.0, 0.0),
        1.0,
        0.5,
    ));
    let open = rms(&render(
        &mut BikeVoice::new(RATE),
        riding(4.0, 1.0),
        1.0,
        0.5,
    ));
    assert!(open > 1.5 * closed, "open {open:.4}, closed {closed:.4}");
}

#[test]
fn muted_is_exactly_silent_and_unmuting_brings_the_sound_back() {
    let mut voice = BikeVoice::new(RATE);
    render(&mut voice, riding(5.0, 0.8), 0.5, 0.1);
    voice.set_muted(true);
    let fading = render(&mut voice, riding(5.0, 0.8), 0.1, 0.1);
    assert!(fading[..50].iter().any(|s| *s != 0.0), "it fades, no click");
    assert!(fading[fading.len() / 2..].iter().all(|s| *s == 0.0));
    voice.set_muted(false);
    let back = render(&mut voice, riding(5.0, 0.8), 0.3, 0.2);
    assert!(rms(&back) > 0.02, "{}", rms(&back));
}

/// A voice whose engine is turned down, so only tyres and thumps sound.
fn without_engine() -> BikeVoice {
    let mut voice = BikeVoice::new(RATE);
    voice.set_engine_volume(0.0);
    voice
}

#[test]
fn tyres_are_silent_while_rolling_and_scrub_when_they_slide() {
    let rolling = render(&mut without_engine(), riding(8.0, 0.5), 0.5, 0.3);
    assert!(rolling.iter().all(|s| *s == 0.0), "{}", rms(&rolling));
    let mut skidding = riding(8.0, 0.0);
    skidding.rear_slip = 3.0;
    let mild = rms(&render(&mut without_engine(), skidding, 0.5, 0.3));
    skidding.rear_slip = 6.0;
    skidding.front_slip = 2.0;
    let hard = rms(&render(&mut without_engine(), skidding, 0.5, 0.3));
    assert!(
        mild > 0.01 && hard > 1.2 * mild,
        "mild {mild:.4}, hard {hard:.4}"
    );
}

#[test]
fn a_thump_is_as_loud_as_the_blow_and_small_bumps_make_none() {
    let thump = |impact: f32| {
        let mut voice = without_engine();
        let mut sources = riding(5.0, 0.0);
        sources.impact = impact;
        voice.update(sources, TICK);
        let mut sound = vec![0.0; (0.2 * RATE) as usize];
        voice.render(&mut sound);
        rms(&sound)
    };
    assert_eq!(thump(10.0), 0.0);
    let (light, hard) = (thump(80.0), thump(400.0));
    assert!(
        light > 0.005 && hard > 2.5 * light,
        "light {light:.4}, hard {hard:.4}"
    );
}

#[test]
fn a_stalled_engine_falls_silent_and_nonsense_input_stays_quiet() {
    let mut voice = BikeVoice::new(RATE);
    let mut stalled = riding(5.0, 1.0);
    stalled.running = false;
    let sound = render(&mut voice, stalled, 1.5, 0.2);
    assert!(rms(&sound) < 1e-3, "{}", rms(&sound));
    let broken = Sources {
        rear_wheel_speed: f32::NAN,
        throttle: f32::INFINITY,
        rear_slip: f32::NAN,
        front_slip: -f32::INFINITY,
        impact: f32::NAN,
        running: true,
        speed: f32::NAN,
    };
    let sound = render(&mut BikeVoice::new(RATE), broken, 0.5, 0.3);
    assert!(sound.iter().all(|s| s.is_finite() && s.abs() <= 1.0));
}
