//! The engine and rear brake as the rear wheel feels them: the most torque the drive
//! turns it with, the power that caps that torque as the wheel spins faster, and the
//! most torque the rear brake holds it with. A bike's own numbers (`engine/…` and
//! `rear_brake/…` fields): a 125 cc two-stroke pulls a light dirt bike with a third of a
//! 600 cc sport bike's power.
//!
//! The reference bike has the thesis's one motor (§4.1.1): 700 N·m both ways and no
//! power limit, so full throttle pulls as hard at 100 km/h as at walking pace.

use super::controls::{ForceClass, MAX_TORQUE};

/// The reference bike's torque at the rear wheel, driving and braking (N·m).
const REFERENCE_TORQUE: f64 = MAX_TORQUE[ForceClass::RearWheel as usize];

/// The drive and brake at the rear wheel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RearWheelDrive {
    /// The most torque (N·m) the drive turns the rear wheel with: the engine's peak
    /// torque through the first gear and final drive, or what the tyre and the
    /// anti-wheelie let through.
    pub max_torque: f64,
    /// The most power (kW) reaching the rear wheel: above the speed where it is reached,
    /// the drive's torque falls as the wheel spins faster. 0: no limit (the reference's).
    pub max_power_kw: f64,
    /// The most torque (N·m) the rear brake holds the wheel with.
    pub brake_torque: f64,
}

impl Default for RearWheelDrive {
    /// The reference bike's: 700 N·m both ways, no power limit.
    fn default() -> Self {
        Self {
            max_torque: REFERENCE_TORQUE,
            max_power_kw: 0.0,
            brake_torque: REFERENCE_TORQUE,
        }
    }
}

impl RearWheelDrive {
    /// The most torque (N·m) the drive turns the wheel with at `wheel_rate` (rad/s,
    /// either way): the full torque, or less where that would need more than the power.
    pub fn drive_torque(&self, wheel_rate: f64) -> f64 {
        if self.max_power_kw <= 0.0 {
            return self.max_torque;
        }
        let power_limited = self.max_power_kw * 1000.0 / wheel_rate.abs();
        self.max_torque.min(power_limited)
    }

    /// The road speed (m/s) on a wheel of `wheel_radius` where the power limit begins to
    /// cut the torque (infinite without one): what the HUD and menus quote as where the
    /// bike stops pulling its hardest.
    pub fn full_torque_until(&self, wheel_radius: f64) -> f64 {
        if self.max_power_kw <= 0.0 {
            return f64::INFINITY;
        }
        self.max_power_kw * 1000.0 / self.max_torque * wheel_radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_a_power_limit_the_torque_is_the_same_at_every_speed() {
        let drive = RearWheelDrive::default();
        assert_eq!(drive.drive_torque(0.0), 700.0);
        assert_eq!(drive.drive_torque(150.0), 700.0);
        assert_eq!(drive.full_torque_until(0.3), f64::INFINITY);
    }

    #[test]
    fn the_power_limit_cuts_the_torque_above_its_speed_either_way_the_wheel_turns() {
        let drive = RearWheelDrive {
            max_torque: 600.0,
            max_power_kw: 30.0,
            brake_torque: 300.0,
        };
        // 30 kW at 600 N·m: full torque up to 50 rad/s, 15 m/s on a 0.3 m wheel.
        assert_eq!(drive.drive_torque(0.0), 600.0);
        assert_eq!(drive.drive_torque(40.0), 600.0);
        assert!((drive.full_torque_until(0.3) - 15.0).abs() < 1e-12);
        assert!((drive.drive_torque(100.0) - 300.0).abs() < 1e-12);
        assert!((drive.drive_torque(-100.0) - 300.0).abs() < 1e-12);
    }
}
