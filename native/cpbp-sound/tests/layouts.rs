//! Every bike sounds like its engine: each layout fires as often as its cylinders and
//! strokes say and is heard at that pitch through its first gear, its box shifts without
//! hunting, and the wind grows with the speed.

mod common;

use common::{pitch, render, riding, rms, RATE, TICK};
use cpbp_sound::engine::Drivetrain;
use cpbp_sound::layout::EngineLayout;
use cpbp_sound::wind::wind_level;
use cpbp_sound::BikeVoice;

#[test]
fn each_layout_fires_as_its_cylinders_and_strokes_say() {
    let at_6000 = |layout: EngineLayout| layout.firing_frequency(6_000.0);
    assert_eq!(at_6000(EngineLayout::FOUR_STROKE_SINGLE), 50.0);
    assert_eq!(at_6000(EngineLayout::TWO_STROKE_SINGLE), 100.0);
    assert_eq!(at_6000(EngineLayout::INLINE_FOUR), 200.0);
    assert_eq!(
        EngineLayout::named("inline_four"),
        Some(EngineLayout::INLINE_FOUR)
    );
    assert_eq!(EngineLayout::named("v_twin"), None);
    assert_eq!(
        EngineLayout::names(),
        "four_stroke_single,two_stroke_single,inline_four"
    );
}

#[test]
fn each_layout_is_heard_at_its_firing_frequency_rising_through_first_gear() {
    for layout in EngineLayout::ALL {
        let clutch = layout.idle_rpm + 0.6 * (layout.launch_rpm - layout.idle_rpm);
        let mut heard = Vec::new();
        for share in [0.3_f32, 0.55, 0.8] {
            // A crank speed in first gear above the slipping clutch's, and its road speed.
            let rpm = clutch + share * (layout.shift_up_rpm - clutch);
            let speed = rpm / 1000.0 * layout.gear_kmh_per_krpm[0] / 3.6;
            let mut voice = BikeVoice::with_engine(layout, RATE);
            let sound = render(&mut voice, riding(speed, 0.6), 1.5, 0.5);
            assert_eq!(
                voice.gear(),
                1,
                "{}: first gear at {rpm:.0} rpm",
                layout.name
            );
            let expected = layout.firing_frequency(rpm);
            let measured = pitch(&sound);
            assert!(
                (measured / expected - 1.0).abs() < 0.04,
                "{} at {rpm:.0} rpm: heard {measured:.1} Hz, firing at {expected:.1} Hz",
                layout.name
            );
            heard.push(measured);
        }
        assert!(heard[0] < heard[1] && heard[1] < heard[2], "{heard:?}");
        println!("{}: {heard:.0?} Hz", layout.name);
    }
}

#[test]
fn each_layouts_box_shifts_up_with_speed_and_down_again_without_hunting() {
    for layout in EngineLayout::ALL {
        let mut drivetrain = Drivetrain::new(layout);
        let mut gears = Vec::new();
        for tick in 0..1200 {
            // Up to 90 km/h over 10 s, and back.
            let speed = 90.0 / 3.6 * (1.0 - (tick as f32 / 600.0 - 1.0).abs());
            drivetrain.update(speed, 0.8, TICK);
            gears.push(drivetrain.gear());
            if drivetrain.gear() < layout.gear_kmh_per_krpm.len() {
                assert!(drivetrain.rpm() <= layout.shift_up_rpm + 500.0);
            }
            if drivetrain.gear() > 1 {
                assert!(drivetrain.rpm() >= layout.shift_down_rpm - 500.0);
            }
        }
        let changes = gears.windows(2).filter(|w| w[0] != w[1]).count();
        let top = *gears.iter().max().unwrap();
        assert!(top >= 2, "{}: 90 km/h is past first gear", layout.name);
        assert_eq!(changes, 2 * (top - 1), "{}: {gears:?}", layout.name);
    }
}

#[test]
fn the_wind_is_silent_standing_and_grows_with_the_square_of_the_speed() {
    let wind = |speed: f32| {
        let mut voice = BikeVoice::new(RATE);
        voice.set_engine_volume(0.0);
        let mut sources = riding(speed, 0.0);
        sources.speed = speed;
        rms(&render(&mut voice, sources, 1.5, 0.5))
    };
    assert_eq!(wind(0.0), 0.0);
    let (slow, fast) = (wind(8.0), wind(24.0));
    assert!(slow > 1e-4, "{slow}");
    // Nine times the pressure; the brighter colour at speed adds a little more.
    assert!(fast > 6.0 * slow, "slow {slow:.5}, fast {fast:.5}");
    assert_eq!(wind_level(60.0), 1.0, "no louder past its loudest speed");
}

#[test]
fn every_engine_is_about_as_loud_riding_at_40_kmh() {
    let loudness: Vec<f32> = EngineLayout::ALL
        .into_iter()
        .map(|layout| {
            let mut voice = BikeVoice::with_engine(layout, RATE);
            rms(&render(&mut voice, riding(40.0 / 3.6, 0.8), 2.0, 1.0))
        })
        .collect();
    println!("engines at 40 km/h, RMS: {loudness:.3?}");
    let (quietest, loudest) = (
        loudness.iter().cloned().fold(f32::MAX, f32::min),
        loudness.iter().cloned().fold(0.0, f32::max),
    );
    assert!(loudest < 2.0 * quietest, "within 6 dB: {loudness:?}");
}
