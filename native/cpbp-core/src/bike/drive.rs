//! Throttle and brake, as the thesis has them (§4.1.1): they set the rear wheel motor's
//! target angular velocity and force directly.

use super::controls::{index, Controls, ForceClass};
use crate::settings::MAX_SPEED_KMH;

/// The fastest full throttle may be set to drive towards (km/h), the bound every drive
/// input is held to: the speed setting's top.
pub const TOP_SPEED_KMH: f64 = MAX_SPEED_KMH.limit().max;
/// What full throttle drives towards unless the player sets otherwise (km/h): the speed
/// setting's default.
pub const DEFAULT_MAX_SPEED_KMH: f64 = MAX_SPEED_KMH.default_number();

/// What the player's triggers ask of the rear wheel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriveInput {
    /// 0–1.
    pub throttle: f64,
    /// 0–1.
    pub brake: f64,
    /// Speed (m/s) full throttle drives towards.
    pub max_speed: f64,
}

impl Default for DriveInput {
    fn default() -> Self {
        Self {
            throttle: 0.0,
            brake: 0.0,
            max_speed: DEFAULT_MAX_SPEED_KMH / 3.6,
        }
    }
}

impl DriveInput {
    /// The input with every number made valid (NaN counts as released).
    pub fn sanitized(self) -> Self {
        let unit = |v: f64| {
            if v.is_finite() {
                v.clamp(0.0, 1.0)
            } else {
                0.0
            }
        };
        Self {
            throttle: unit(self.throttle),
            brake: unit(self.brake),
            max_speed: if self.max_speed.is_finite() {
                self.max_speed.clamp(0.0, TOP_SPEED_KMH / 3.6)
            } else {
                0.0
            },
        }
    }

    /// Sets the rear wheel entries of `controls`: the throttle drives towards `max_speed`
    /// with force in proportion, the brake holds the wheel still with force in proportion,
    /// and with neither the wheel rolls freely.
    pub fn apply(&self, wheel_radius: f64, controls: &mut Controls) {
        let input = self.sanitized();
        let force = index::FORCE + ForceClass::RearWheel as usize;
        if input.brake > 0.0 && input.brake >= input.throttle {
            controls.set(index::REAR_WHEEL, 0.0);
            controls.set(force, input.brake);
        } else {
            controls.set(index::REAR_WHEEL, input.max_speed / wheel_radius);
            controls.set(force, input.throttle);
        }
    }
}

/// Whether `controls` drive the rear wheel (a speed target ahead, as the throttle and a
/// coasting bike set it: `DriveInput::apply`).
pub fn drives(controls: &Controls) -> bool {
    controls.get(index::REAR_WHEEL) > 0.0
}

/// Whether `controls` drive with the throttle open (some force towards the target).
pub fn throttle_open(controls: &Controls) -> bool {
    drives(controls) && controls.get(index::FORCE + ForceClass::RearWheel as usize) > 0.0
}

/// How hard (0–1) `controls` brake: the force holding the rear wheel still, 0 otherwise.
pub fn brake_level(controls: &Controls) -> f64 {
    if controls.get(index::REAR_WHEEL) == 0.0 {
        controls.get(index::FORCE + ForceClass::RearWheel as usize)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn throttle_brake_and_coasting_set_the_rear_motor() {
        let mut controls = Controls::default();
        let drive = DriveInput {
            throttle: 0.5,
            brake: 0.0,
            max_speed: 6.0,
        };
        drive.apply(0.3, &mut controls);
        assert_eq!(controls.get(index::REAR_WHEEL), 20.0);
        assert_eq!(controls.get(index::FORCE + 1), 0.5);
        DriveInput {
            brake: 0.8,
            ..drive
        }
        .apply(0.3, &mut controls);
        assert_eq!(
            (
                controls.get(index::REAR_WHEEL),
                controls.get(index::FORCE + 1)
            ),
            (0.0, 0.8)
        );
        DriveInput {
            throttle: 0.0,
            ..drive
        }
        .apply(0.3, &mut controls);
        assert_eq!(controls.get(index::FORCE + 1), 0.0);
    }

    #[test]
    fn the_triggers_read_back_from_the_controls() {
        let mut controls = Controls::default();
        let drive = |throttle, brake| DriveInput {
            throttle,
            brake,
            max_speed: 6.0,
        };
        drive(0.4, 0.0).apply(0.3, &mut controls);
        assert!(drives(&controls) && throttle_open(&controls));
        assert_eq!(brake_level(&controls), 0.0);
        drive(0.0, 0.0).apply(0.3, &mut controls);
        assert!(drives(&controls) && !throttle_open(&controls));
        drive(0.2, 0.7).apply(0.3, &mut controls);
        assert!(!drives(&controls) && !throttle_open(&controls));
        assert_eq!(brake_level(&controls), 0.7);
    }

    #[test]
    fn bad_numbers_release_the_triggers() {
        let input = DriveInput {
            throttle: f64::NAN,
            brake: 7.0,
            max_speed: f64::INFINITY,
        }
        .sanitized();
        assert_eq!(
            (input.throttle, input.brake, input.max_speed),
            (0.0, 1.0, 0.0)
        );
    }
}
