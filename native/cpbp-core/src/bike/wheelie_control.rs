//! Wheelie control: the drive's torque is cut as the front wheel unloads, as a road bike's
//! anti-wheelie does (e.g. Bosch's motorcycle stability control, which also estimates the
//! lift from the chassis's state). With tyres that grip with the load they carry, full
//! throttle at the rear wheel (up to 700 N·m, about 1 g) lifts the front of this bike at
//! any speed: launched towards 25 km/h it loops over. The sensor is the fork itself: with
//! the front wheel loaded the fork sits near its sag, unloaded it tops out, whatever the
//! slope underfoot. Stateless, so a rollout restored from a snapshot cuts as the master.
//!
//! Asked for a wheelie (the rider's weight back with the throttle open, `wheelie_lift`),
//! the same control holds the front up instead, as the wheelie controls of some sports
//! bikes do: it commands the rear wheel's torque to keep the centre of mass over a support
//! point moved back from the wheels' midpoint by the lift (`Bike::support_point_lifted`),
//! the rear tyre itself at full lift, which is the balance point. Drive torque pitches the
//! bike up, the rear brake pitches it down; gravity tips it away from that point at about
//! √(g/h) ≈ 3.6 rad/s, which a PD on where the weight is ahead of the point outruns.

use super::drive::DriveInput;
use super::rider_position::RiderPosition;

/// Where the cut starts and where it is complete, as fork compression (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheelieControl {
    /// At or above this compression the drive gets all the torque asked for.
    pub full_torque_above: f64,
    /// At or below this compression (the fork near full extension) it gets none.
    pub no_torque_below: f64,
    /// Holding a wheelie: drive share per metre the centre of mass is ahead of the
    /// lifted support point (1/m)…
    pub hold_gain: f64,
    /// … and per m/s it moves ahead (s/m).
    pub hold_rate_gain: f64,
    /// The largest share of the rear wheel's torque the hold brakes with when the weight
    /// is behind the point.
    pub hold_brake: f64,
    /// How much faster (m/s at the tyre) than the throttle's speed the hold may drive:
    /// lifting the front takes about 0.9 g for half a second, and a wheelie short of the
    /// balance point keeps accelerating until this runs out and the front comes down.
    pub hold_headroom: f64,
    /// Leaned (rad, either way) up to this, the hold lifts as high as asked…
    pub lift_upright_within: f64,
    /// … and from here it lets the front down, so a wheelie that topples sideways puts
    /// the front wheel back on the road to steer with instead of falling with it.
    pub lift_none_beyond: f64,
    /// A wheelie leaves the rear wheel turning faster than the throttle asks. Beyond this
    /// much (m/s at the tyre) the drive slows it with engine braking (`overrun_share` of
    /// the torque asked) instead of clamping it to the throttle's speed with all of it,
    /// which skids the tyre. Riding without wheelies the drive's motor keeps the wheel
    /// within millimetres per second of that speed, so this never acts.
    pub overrun_margin: f64,
    pub overrun_share: f64,
    /// In the air, the share of the rear wheel's torque the rider's full weight shift
    /// spins it up or brakes it with.
    pub air_share: f64,
}

impl Default for WheelieControl {
    /// The front carries about 100 kg at 39 mm of sag (18 N/mm): the cut starts when it
    /// carries a fifth of that and is complete when it carries a twentieth, so the front
    /// skims the road under full throttle instead of rising.
    fn default() -> Self {
        Self {
            full_torque_above: 0.008,
            no_torque_below: 0.002,
            hold_gain: HOLD_GAIN,
            hold_rate_gain: HOLD_RATE_GAIN,
            hold_brake: 0.5,
            hold_headroom: 30.0 / 3.6,
            lift_upright_within: 8f64.to_radians(),
            lift_none_beyond: 16f64.to_radians(),
            overrun_margin: 1.0,
            overrun_share: 0.1,
            air_share: AIR_SHARE,
        }
    }
}

/// The hold's gains, from the pitch dynamics about the rear tyre (about 220 kg·m²; full
/// torque pitches it at about 7 rad/s², gravity at 10 rad/s² per metre of offset): a
/// closed loop of about 4 rad/s, damped at 0.8.
const HOLD_GAIN: f64 = 3.6;
const HOLD_RATE_GAIN: f64 = 0.9;
/// A fifth of the rear wheel's torque: braked with it from 8 m/s the wheel stops in
/// about a quarter of a second and its spin's reaction turns the nose about 10° down.
const AIR_SHARE: f64 = 0.2;

/// What the rider's weight asks of the bike's pitch through the rear wheel: a wheelie
/// on the ground, a turn of the nose in the air. Both zero with the stick released, so
/// riding without it is riding as before.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PitchRequest {
    /// How high a wheelie (0–1, the balance point at 1): the weight back times the
    /// throttle.
    pub lift: f64,
    /// In the air, the nose up (positive, the weight back) or down (negative, the weight
    /// forward), −1 to 1: the rear wheel spun up or braked, whose reaction pitches the
    /// bike as riders use throttle and rear brake in a jump. The rider's body alone moves
    /// the pitch by about 3° in a 0.7 s jump, and the other way (`tests/rides/air_control.rs`).
    pub air: f64,
    /// How high a stoppie (0–1, the balance point over the front tyre at 1): the weight
    /// forward times the brake.
    pub stoppie: f64,
}

/// The pitch the rider's weight and the throttle ask for (`PitchRequest`).
pub fn pitch_request(rider: &RiderPosition, drive: &DriveInput) -> PitchRequest {
    let (rider, _) = rider.sanitized();
    let drive = drive.sanitized();
    PitchRequest {
        lift: (-rider.forward).max(0.0) * drive.throttle,
        air: -rider.forward,
        stoppie: rider.forward.max(0.0) * drive.brake,
    }
}

impl WheelieControl {
    /// `hold_headroom` as the rear wheel's spin (rad/s) for wheels of `radius` (m).
    pub fn headroom_spin(&self, radius: f64) -> f64 {
        self.hold_headroom / radius
    }

    /// The lift held (0–1) when `asked` with the bike leaned `lean` (rad): all of it
    /// upright, less as the bike topples sideways.
    pub fn held_lift(&self, asked: f64, lean: f64) -> f64 {
        let span = self.lift_none_beyond - self.lift_upright_within;
        let upright = 1.0 - ((lean.abs() - self.lift_upright_within) / span).clamp(0.0, 1.0);
        if asked > 0.0 && upright.is_finite() {
            asked.min(1.0) * upright
        } else {
            0.0
        }
    }

    /// Share of the rear wheel's full torque that holds a wheelie, with the centre of mass
    /// `ahead` (m) of the lifted support point and moving ahead at `rate` (m/s): driving
    /// when positive (up to all of it), braking when negative (up to `hold_brake`).
    pub fn hold_share(&self, ahead: f64, rate: f64) -> f64 {
        let share = self.hold_gain * ahead + self.hold_rate_gain * rate;
        if share.is_finite() {
            share.clamp(-self.hold_brake, 1.0)
        } else {
            0.0
        }
    }

    /// Share (0–1) of the asked drive torque let through at fork compression `front` (m).
    pub fn torque_share(&self, front: f64) -> f64 {
        if !front.is_finite() {
            return 0.0;
        }
        let span = self.full_torque_above - self.no_torque_below;
        ((front - self.no_torque_below) / span).clamp(0.0, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cut_ramps_from_loaded_to_topped_out() {
        let control = WheelieControl::default();
        assert_eq!(control.torque_share(0.039), 1.0);
        assert_eq!(control.torque_share(0.008), 1.0);
        assert!((control.torque_share(0.005) - 0.5).abs() < 1e-12);
        assert_eq!(control.torque_share(0.0), 0.0);
        assert_eq!(control.torque_share(f64::NAN), 0.0);
    }

    #[test]
    fn the_hold_drives_when_the_weight_is_ahead_and_brakes_when_behind() {
        let control = WheelieControl::default();
        assert_eq!(control.hold_share(0.0, 0.0), 0.0);
        assert!(control.hold_share(0.1, 0.0) > 0.0);
        assert_eq!(control.hold_share(0.6, 0.0), 1.0);
        assert_eq!(control.hold_share(-0.6, 0.0), -control.hold_brake);
        assert!(control.hold_share(0.0, -0.2) < 0.0);
        assert_eq!(control.hold_share(f64::NAN, 0.0), 0.0);
    }

    #[test]
    fn a_toppling_wheelie_lets_the_front_down() {
        let control = WheelieControl::default();
        assert_eq!(control.held_lift(0.7, 0.0), 0.7);
        assert_eq!(control.held_lift(0.7, -control.lift_upright_within), 0.7);
        let halfway = (control.lift_upright_within + control.lift_none_beyond) / 2.0;
        assert!((control.held_lift(1.0, halfway) - 0.5).abs() < 1e-12);
        assert_eq!(control.held_lift(1.0, control.lift_none_beyond), 0.0);
        assert_eq!(control.held_lift(1.0, f64::NAN), 0.0);
        assert_eq!(control.held_lift(0.0, 0.0), 0.0);
    }

    #[test]
    fn a_wheelie_takes_the_weight_back_and_the_throttle_open() {
        let drive = |throttle| DriveInput {
            throttle,
            ..DriveInput::default()
        };
        let back = RiderPosition {
            forward: -1.0,
            right: 0.3,
        };
        let lift = |rider: &RiderPosition, throttle| pitch_request(rider, &drive(throttle)).lift;
        assert_eq!(lift(&back, 1.0), 1.0);
        assert_eq!(lift(&back, 0.5), 0.5);
        assert_eq!(lift(&back, 0.0), 0.0);
        assert_eq!(lift(&RiderPosition::NEUTRAL, 1.0), 0.0);
        assert_eq!(pitch_request(&back, &drive(0.0)).air, 1.0);
        assert_eq!(pitch_request(&RiderPosition::NEUTRAL, &drive(1.0)).air, 0.0);
        let forward = RiderPosition {
            forward: 0.8,
            right: 0.0,
        };
        assert_eq!(lift(&forward, 1.0), 0.0);
        assert_eq!(pitch_request(&forward, &drive(1.0)).air, -0.8);
        let broken = RiderPosition {
            forward: f64::NAN,
            right: 0.0,
        };
        assert_eq!(pitch_request(&broken, &drive(1.0)), PitchRequest::default());
    }
}
