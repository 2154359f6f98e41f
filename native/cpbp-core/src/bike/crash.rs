//! When a ride counts as crashed: any part but a wheel touches the ground, or the bike
//! leans past a limit for a moment (it is down, even if nothing has touched yet); and
//! whether the tyres slid out first (a low-side) or slid and threw the bike over the
//! other way (a high-side).

use super::model::Part;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CrashCause {
    /// A part other than a wheel touched the ground.
    Touched(Part),
    /// The lean stayed beyond the limit for the allowed time.
    Leaned { lean: f64 },
}

impl CrashCause {
    /// What happened, for the player: "the rider's head hit the ground", "leaned over
    /// (68°)".
    pub fn describe(&self) -> String {
        match self {
            CrashCause::Touched(part) => {
                let what = match part {
                    Part::Torso => "the rider's head or body",
                    Part::UpperLeg | Part::LowerLeg => "the rider's leg",
                    Part::UpperArm | Part::LowerArm => "the rider's arm",
                    Part::Fork | Part::ForkLower => "the fork",
                    Part::Swingarm => "the swingarm",
                    _ => "the bike",
                };
                format!("{what} hit the ground")
            }
            CrashCause::Leaned { lean } => {
                format!("leaned over ({:.0}°)", lean.abs().to_degrees())
            }
        }
    }
}

/// How the tyres let go before a crash, when they did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fall {
    /// The tyres slid out from under a leaning bike and it fell to the side it leaned to:
    /// the lean asked for more grip than the tyres had.
    LowSide,
    /// The tyres slid out, then the bike went down on the other side: thrown over as
    /// they gripped again.
    HighSide,
}

/// A crash: what touched or how far the bike leaned, and how the tyres let go first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crash {
    pub cause: CrashCause,
    pub fall: Option<Fall>,
}

impl Crash {
    /// What happened, for the player: "low-side, the tyres slid out: the bike hit the
    /// ground".
    pub fn describe(&self) -> String {
        let cause = self.cause.describe();
        match self.fall {
            Some(Fall::LowSide) => format!("low-side, the tyres slid out: {cause}"),
            Some(Fall::HighSide) => format!("high-side, thrown over: {cause}"),
            None => cause,
        }
    }
}

/// Sideways speed (m/s) of a tyre over the ground above which it has let go. ODE's
/// Coulomb friction lets a gripping tyre creep sideways by no more than centimetres per
/// second (no slip angle), so anything near walking pace is a tyre sliding.
const SLID_OUT_ABOVE: f64 = 1.0;
/// Least lean (rad) for a sideways slide to count as the tyres sliding out from under the
/// bike: upright, a slide is a skid, not a fall.
const SLID_OUT_LEAN: f64 = 0.17;
/// How long (s) a slide out is remembered: a fall that follows it within this long is
/// the slide's.
const SLIDE_MEMORY: f64 = 1.0;

/// Tracks the lean and the tyres' slides over time; feed it once per step.
#[derive(Clone, Copy, Debug)]
pub struct CrashMonitor {
    /// Largest lean (rad) a ride survives.
    pub lean_limit: f64,
    /// How long (s) the lean may exceed the limit before it counts as a crash.
    pub grace: f64,
    over_limit_for: f64,
    /// The last slide out: the side the bike leaned to (+1 right, −1 left) and how long
    /// ago (s) it was.
    slid_out: Option<(f64, f64)>,
}

impl Default for CrashMonitor {
    fn default() -> Self {
        Self {
            lean_limit: 65f64.to_radians(),
            grace: 0.3,
            over_limit_for: 0.0,
            slid_out: None,
        }
    }
}

impl CrashMonitor {
    /// Updates with one step's lean (rad, positive right), ground contact and the tyres'
    /// sideways slide (m/s, positive to the bike's right: `Bike::tyre_side_slide`);
    /// returns the crash, if any.
    pub fn update(
        &mut self,
        dt: f64,
        lean: f64,
        touching: Option<Part>,
        side_slide: f64,
    ) -> Option<Crash> {
        self.watch_slides(dt, lean, side_slide);
        let cause = if let Some(part) = touching {
            CrashCause::Touched(part)
        } else {
            if lean.abs() > self.lean_limit {
                self.over_limit_for += dt;
            } else {
                self.over_limit_for = 0.0;
            }
            if self.over_limit_for <= self.grace {
                return None;
            }
            CrashCause::Leaned { lean }
        };
        let fall = self.slid_out.map(|(side, _)| {
            if side * lean >= 0.0 {
                Fall::LowSide
            } else {
                Fall::HighSide
            }
        });
        Some(Crash { cause, fall })
    }

    /// Remembers the tyres sliding out from under a leaning bike: sliding sideways away
    /// from the side it leans to.
    fn watch_slides(&mut self, dt: f64, lean: f64, side_slide: f64) {
        let sliding_out = lean.abs() > SLID_OUT_LEAN
            && side_slide.abs() > SLID_OUT_ABOVE
            && side_slide * lean < 0.0;
        self.slid_out = if sliding_out {
            Some((lean.signum(), 0.0))
        } else {
            self.slid_out
                .map(|(side, ago)| (side, ago + dt))
                .filter(|&(_, ago)| ago <= SLIDE_MEMORY)
        };
    }

    /// Forgets the past (after a reset).
    pub fn reset(&mut self) {
        self.over_limit_for = 0.0;
        self.slid_out = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_touching_part_is_an_immediate_crash() {
        let mut monitor = CrashMonitor::default();
        let crash = monitor.update(0.01, 0.0, Some(Part::Torso), 0.0).unwrap();
        assert_eq!(crash.cause, CrashCause::Touched(Part::Torso));
        assert_eq!(crash.fall, None, "nothing slid");
    }

    #[test]
    fn a_deep_lean_is_a_crash_only_after_the_grace_time() {
        let mut monitor = CrashMonitor::default();
        let deep = 1.3;
        assert_eq!(monitor.update(0.2, deep, None, 0.0), None);
        assert_eq!(monitor.update(0.05, 0.2, None, 0.0), None); // recovered: the clock restarts
        assert_eq!(monitor.update(0.2, deep, None, 0.0), None);
        assert!(matches!(
            monitor.update(0.2, deep, None, 0.0),
            Some(Crash {
                cause: CrashCause::Leaned { .. },
                ..
            })
        ));
    }

    #[test]
    fn tyres_sliding_out_then_a_fall_the_same_way_is_a_low_side() {
        let mut monitor = CrashMonitor::default();
        let (lean, dt) = (0.6, 1.0 / 120.0); // leaned right
                                             // The tyres slide to the left, out from under the bike, for a tenth of a second.
        for _ in 0..12 {
            assert_eq!(monitor.update(dt, lean, None, -2.0), None);
        }
        let crash = monitor.update(dt, 1.0, Some(Part::Frame), 0.0).unwrap();
        assert_eq!(crash.fall, Some(Fall::LowSide));
        assert_eq!(
            crash.describe(),
            "low-side, the tyres slid out: the bike hit the ground"
        );
    }

    #[test]
    fn a_fall_to_the_other_side_after_the_slide_is_a_high_side() {
        let mut monitor = CrashMonitor::default();
        let dt = 1.0 / 120.0;
        monitor.update(dt, 0.6, None, -2.0);
        let crash = monitor.update(0.3, -0.9, Some(Part::Torso), 0.0).unwrap();
        assert_eq!(crash.fall, Some(Fall::HighSide));
    }

    #[test]
    fn a_slide_is_forgotten_after_a_second_and_a_skid_upright_or_inwards_is_none() {
        let mut monitor = CrashMonitor::default();
        monitor.update(0.01, 0.6, None, -2.0);
        monitor.update(1.1, 0.3, None, 0.0);
        let crash = monitor.update(0.01, 0.6, Some(Part::Frame), 0.0).unwrap();
        assert_eq!(crash.fall, None, "the slide was over a second before");
        let mut monitor = CrashMonitor::default();
        monitor.update(0.01, 0.05, None, -2.0); // upright: a skid
        monitor.update(0.01, 0.6, None, 2.0); // towards the lean: not out from under it
        let crash = monitor.update(0.01, 0.6, Some(Part::Frame), 0.0).unwrap();
        assert_eq!(crash.fall, None);
    }
}
