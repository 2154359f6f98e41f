//! When a ride counts as crashed: any part but a wheel touches the ground, or the bike
//! leans past a limit for a moment (it is down, even if nothing has touched yet).

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

/// Tracks the lean over time; feed it once per step.
#[derive(Clone, Copy, Debug)]
pub struct CrashMonitor {
    /// Largest lean (rad) a ride survives.
    pub lean_limit: f64,
    /// How long (s) the lean may exceed the limit before it counts as a crash.
    pub grace: f64,
    over_limit_for: f64,
}

impl Default for CrashMonitor {
    fn default() -> Self {
        Self {
            lean_limit: 65f64.to_radians(),
            grace: 0.3,
            over_limit_for: 0.0,
        }
    }
}

impl CrashMonitor {
    /// Updates with one step's lean and ground contact; returns the crash, if any.
    pub fn update(&mut self, dt: f64, lean: f64, touching: Option<Part>) -> Option<CrashCause> {
        if let Some(part) = touching {
            return Some(CrashCause::Touched(part));
        }
        if lean.abs() > self.lean_limit {
            self.over_limit_for += dt;
        } else {
            self.over_limit_for = 0.0;
        }
        (self.over_limit_for > self.grace).then_some(CrashCause::Leaned { lean })
    }

    /// Forgets the past (after a reset).
    pub fn reset(&mut self) {
        self.over_limit_for = 0.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_touching_part_is_an_immediate_crash() {
        let mut monitor = CrashMonitor::default();
        assert_eq!(
            monitor.update(0.01, 0.0, Some(Part::Torso)),
            Some(CrashCause::Touched(Part::Torso))
        );
    }

    #[test]
    fn a_deep_lean_is_a_crash_only_after_the_grace_time() {
        let mut monitor = CrashMonitor::default();
        let deep = 1.3;
        assert_eq!(monitor.update(0.2, deep, None), None);
        assert_eq!(monitor.update(0.05, 0.2, None), None); // recovered: the clock restarts
        assert_eq!(monitor.update(0.2, deep, None), None);
        assert!(matches!(
            monitor.update(0.2, deep, None),
            Some(CrashCause::Leaned { .. })
        ));
    }
}
