//! The front brake. The thesis's bike braked the rear wheel alone (§4.1.1); a road bike
//! stops mostly with the front, whose grip grows with the load braking moves onto it
//! (with ODE patch 04, up to about 1 g here). That much tips the rear up, so, as road
//! bikes' rear-wheel lift-off mitigation does (e.g. Bosch's motorcycle stability control),
//! the brake lets off as the rear suspension tops out. Asked for a stoppie (the rider's
//! weight forward with the brake on) it holds the rear up instead: the brake's torque keeps
//! the centre of mass over a support point moved from the wheels' midpoint towards the
//! front tyre, the balance point at full request, as the wheelie hold does at the rear.
//!
//! Both brakes have ABS, as every new road motorcycle over 125 cc sold in the EU must
//! since 2016 (Regulation (EU) No 168/2013): a braked wheel is not let turn slower than
//! 90 % of its rolling rate until walking pace. Without it a full brake locked the front
//! tyre, then the unloaded rear, and every controller dropped the bike in a stop from
//! 25 km/h (arcade 4 of 6 headings, 5 of 6 from 40 km/h); with it none did (docs/
//! bike-model.md, "Stopping").

/// The front brake's strength and its lift-off mitigation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrontBrake {
    /// Torque (N·m) at full brake: 1 g for bike and rider (225 kg × 9.81 m/s² × 0.30 m ≈
    /// 660 N·m) with some to spare.
    pub max_torque: f64,
    /// Rear suspension compression (m, at the wheel) at or above which the brake acts in
    /// full…
    pub full_above: f64,
    /// … and at or below which it lets off completely (its sag is 39 mm). The rear stays
    /// loaded with a margin: with the brake letting off only at 3 mm the rear hopped in a
    /// full brake, and stopping down a 15° slope it left the road, so the bike stood on
    /// the front tyre and a foot and toppled along that line (3 of 6 stops).
    pub none_below: f64,
    /// Holding a stoppie: brake share per metre the centre of mass is behind the shifted
    /// support point (1/m) and per m/s it falls back (s/m).
    pub hold_gain: f64,
    pub hold_rate_gain: f64,
    /// The share of the rear brake's torque the brake trigger gives it beside the front
    /// brake, as linked brakes split the lever: braking hard, the rear carries little
    /// load, and at full torque it locks and the skidding tyre slews the bike over.
    pub rear_share: f64,
    /// ABS: above `abs_above` (m/s) a braked wheel turns at least (1 − `abs_slip`) of its
    /// rolling rate. 10 % is where a tyre's braking grip peaks (Pacejka, *Tyre and
    /// Vehicle Dynamics*, 2012); ABS lets wheels lock at walking pace, 1.5 m/s here, so
    /// the bike comes to rest and stays held.
    pub abs_slip: f64,
    pub abs_above: f64,
}

impl Default for FrontBrake {
    fn default() -> Self {
        Self {
            max_torque: 700.0,
            full_above: 0.025,
            none_below: 0.012,
            hold_gain: 3.6,
            hold_rate_gain: 0.9,
            rear_share: 0.3,
            abs_slip: 0.1,
            abs_above: 1.5,
        }
    }
}

impl FrontBrake {
    /// The slowest (rad/s) ABS lets a braked wheel of radius `radius` turn at forward
    /// speed `speed` (m/s).
    pub fn abs_floor(&self, speed: f64, radius: f64) -> f64 {
        if speed.is_finite() && speed > self.abs_above {
            (1.0 - self.abs_slip) * speed / radius
        } else {
            0.0
        }
    }

    /// Share (0–1) of the asked braking let through with the rear compressed by `rear` (m).
    pub fn lift_off_share(&self, rear: f64) -> f64 {
        if !rear.is_finite() {
            return 0.0;
        }
        ((rear - self.none_below) / (self.full_above - self.none_below)).clamp(0.0, 1.0)
    }

    /// Share (0–1) of the full torque that holds a stoppie with the centre of mass `ahead`
    /// (m) of the shifted support point, moving ahead at `rate` (m/s): more brake while it
    /// is behind, none once it is past.
    pub fn hold_share(&self, ahead: f64, rate: f64) -> f64 {
        let share = -(self.hold_gain * ahead + self.hold_rate_gain * rate);
        if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_brake_lets_off_as_the_rear_tops_out() {
        let brake = FrontBrake::default();
        assert_eq!(brake.lift_off_share(0.039), 1.0);
        assert_eq!(brake.lift_off_share(0.0), 0.0);
        assert!((brake.lift_off_share(0.0185) - 0.5).abs() < 1e-12);
        assert_eq!(brake.lift_off_share(f64::NAN), 0.0);
    }

    #[test]
    fn abs_keeps_a_braked_wheel_turning_until_walking_pace() {
        let brake = FrontBrake::default();
        // 10 m/s on a 0.3 m wheel rolls at 33.3 rad/s: ABS keeps 30.
        assert!((brake.abs_floor(10.0, 0.3) - 30.0).abs() < 1e-9);
        assert_eq!(brake.abs_floor(1.0, 0.3), 0.0, "held still at walking pace");
        assert_eq!(brake.abs_floor(-3.0, 0.3), 0.0, "rolling back");
        assert_eq!(brake.abs_floor(f64::NAN, 0.3), 0.0);
    }

    #[test]
    fn the_stoppie_hold_brakes_while_the_weight_is_behind() {
        let brake = FrontBrake::default();
        assert_eq!(brake.hold_share(-0.6, 0.0), 1.0);
        assert!(brake.hold_share(-0.1, 0.0) > 0.0);
        assert_eq!(brake.hold_share(0.05, 0.0), 0.0);
        assert_eq!(brake.hold_share(0.0, 0.5), 0.0);
        assert_eq!(brake.hold_share(f64::NAN, 0.0), 0.0);
    }
}
