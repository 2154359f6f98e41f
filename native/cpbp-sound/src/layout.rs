//! How an engine is built, as far as its sound goes: how many cylinders fire how often,
//! the speeds it idles, launches and revs to, the box's ratios and where it shifts, and
//! the exhaust's resonance. A bike file names its layout (`BikeDescription.engine`); the
//! physics never sees it.
//!
//! Figures are of the bikes' classes: a 125 cc motocross two-stroke (YZ125: idles about
//! 1 900 rpm, peak power about 11 500 rpm, revs to 12 500), a 373 cc street single
//! (Duke 390: 1 600 idle, 9 500 rpm peak, 11 000 limiter) and a 600 cc supersport inline
//! four (CBR600RR: 1 300 idle, 13 500 rpm peak, a 15 000 limiter). The box shifts itself
//! where a rider on the road would, well below the limiter, so the game's 0–80 km/h is
//! heard through several gears on every bike.

/// One engine's layout. `ALL` lists the built-in ones; a bike file names one by `name`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EngineLayout {
    /// The name a bike file gives (`four_stroke_single`).
    pub name: &'static str,
    /// For people: "four-stroke single".
    pub label: &'static str,
    pub cylinders: u32,
    /// 2 (a firing every turn per cylinder) or 4 (every second turn).
    pub strokes: u32,
    /// Crank speed at idle, held by a slipping clutch at full throttle pulling away, and
    /// at the rev limiter (rpm).
    pub idle_rpm: f32,
    pub launch_rpm: f32,
    pub limiter_rpm: f32,
    /// Road speed per 1000 rpm in each gear (km/h).
    pub gear_kmh_per_krpm: [f32; 6],
    /// The box shifts up above, and down below, these crank speeds (rpm): after an
    /// upshift the crank must still turn above the downshift point, or it would hunt.
    pub shift_up_rpm: f32,
    pub shift_down_rpm: f32,
    /// The exhaust's resonance (Hz) and its bandwidth: a single's short header booms
    /// low, a two-stroke's expansion chamber rings high, a four's collector sings.
    pub pipe_hz: f32,
    pub pipe_bandwidth: f32,
    /// How fast each exhaust pulse dies, in e-folds per firing interval: a single's bark
    /// is over within its cycle, a four's pulses run into one another.
    pub pulse_decay: f32,
    /// How much of the sound is the intake's and the ports' hiss (0–1): a two-stroke's
    /// rasp is mostly that.
    pub rasp: f32,
    /// The voice's gain: each layout's pulses carry a different share of their energy in
    /// what one hears, so each is brought to about the single's loudness riding at
    /// 40 km/h (tests/layouts.rs holds them within 6 dB).
    pub loudness: f32,
}

impl EngineLayout {
    /// A four-stroke single (the street 350 and 390): the game's first engine, every
    /// figure as it was before layouts.
    pub const FOUR_STROKE_SINGLE: Self = Self {
        name: "four_stroke_single",
        label: "four-stroke single",
        cylinders: 1,
        strokes: 4,
        idle_rpm: 1_700.0,
        launch_rpm: 5_500.0,
        limiter_rpm: 11_000.0,
        gear_kmh_per_krpm: [2.6, 3.5, 4.5, 5.5, 6.5, 7.5],
        shift_up_rpm: 8_500.0,
        shift_down_rpm: 4_000.0,
        pipe_hz: 140.0,
        pipe_bandwidth: 90.0,
        pulse_decay: 4.0,
        rasp: 0.15,
        loudness: 1.0,
    };

    /// A two-stroke single (the dirt 125): it fires every turn, revs high and rasps.
    pub const TWO_STROKE_SINGLE: Self = Self {
        name: "two_stroke_single",
        label: "two-stroke single",
        cylinders: 1,
        strokes: 2,
        idle_rpm: 1_900.0,
        launch_rpm: 7_500.0,
        limiter_rpm: 12_500.0,
        gear_kmh_per_krpm: [3.0, 3.9, 4.8, 5.7, 6.6, 7.4],
        shift_up_rpm: 11_000.0,
        shift_down_rpm: 7_000.0,
        pipe_hz: 320.0,
        pipe_bandwidth: 160.0,
        pulse_decay: 3.0,
        rasp: 0.45,
        loudness: 2.6,
    };

    /// An inline four (the sport 600): four firings every two turns, a smooth wail.
    pub const INLINE_FOUR: Self = Self {
        name: "inline_four",
        label: "inline four",
        cylinders: 4,
        strokes: 4,
        idle_rpm: 1_300.0,
        launch_rpm: 6_000.0,
        limiter_rpm: 15_000.0,
        gear_kmh_per_krpm: [7.0, 9.0, 10.8, 12.3, 13.6, 14.8],
        shift_up_rpm: 10_500.0,
        shift_down_rpm: 6_000.0,
        pipe_hz: 210.0,
        pipe_bandwidth: 140.0,
        pulse_decay: 1.5,
        rasp: 0.2,
        loudness: 1.2,
    };

    /// Every built-in layout; the first is a bike file's default.
    pub const ALL: [Self; 3] = [
        Self::FOUR_STROKE_SINGLE,
        Self::TWO_STROKE_SINGLE,
        Self::INLINE_FOUR,
    ];

    /// The layout a bike file names, or None.
    pub fn named(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|layout| layout.name == name)
    }

    /// The names a bike file may give, comma-separated (an inspector's choice list).
    pub fn names() -> String {
        Self::ALL.map(|layout| layout.name).join(",")
    }

    /// Exhaust pulses per second at `rpm`: the pitch one hears.
    pub fn firing_frequency(&self, rpm: f32) -> f32 {
        rpm / 60.0 * self.cylinders as f32 * 2.0 / self.strokes as f32
    }
}

impl Default for EngineLayout {
    fn default() -> Self {
        Self::FOUR_STROKE_SINGLE
    }
}
