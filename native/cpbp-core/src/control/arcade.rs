//! The arcade controller (thesis §4.3.2): a PD controller on the steering rate that makes
//! the lean follow the desired lean, and in the air a steer towards the neutral angle the
//! bike will need on landing. The rider holds the riding pose.
//!
//! Its state is two numbers, so it runs as well inside a rollout world as on the master
//! (the combined controller warm-starts the planner with its trajectory).

use glam::DVec3;

use super::Goal;
use crate::bike::{index, Bike, Controls, POSE_GAIN};
use crate::ode::World;
use crate::simulation::{up_against, Simulation};

/// Gains of eq. 4.8 and of the steer towards neutral in the air.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcadeGains {
    /// K_p (1/s): the thesis's tuned value, 10.
    pub kp: f64,
    /// K_d: the thesis's tuned value, 0.2.
    pub kd: f64,
    /// Prediction horizon p (s) at and below `prediction_speeds.0`: how far ahead the lean
    /// is extrapolated. The thesis does not give its value. At 10 km/h 0.8 s holds a ±15°
    /// slalom; 0.5 s overshoots it to 22° and 0.4 s falls.
    pub prediction: f64,
    /// p at and above `prediction_speeds.1`. The long horizon damps the lean so much that
    /// it creeps the last degrees towards the asked lean: with 0.8 s throughout, the lean's
    /// RMS error over the second half of each 2 s gate of a ±15° slalom is 5.2° at 20 km/h
    /// and 5.5° at 25; with 0.35 s above 20 km/h 0.4° and 1.0°, still without overshoot
    /// (0.3 s overshoots to 20° at 20 km/h). The steering's grip on the lean grows with
    /// the square of the speed, so faster the loop needs less anticipation.
    pub fast_prediction: f64,
    /// Forward speeds (m/s) between which p goes linearly from `prediction` to
    /// `fast_prediction`: 10 and 20 km/h.
    pub prediction_speeds: (f64, f64),
    /// How fast (1/s) the bar turns towards the neutral angle while airborne.
    pub air_gain: f64,
    /// Braking below this forward speed (m/s) the bar is straightened instead of
    /// balancing: there the steering no longer leans the bike, eq. 4.8's rate only winds
    /// the bar towards full lock, and a bike stopping on a turned bar flops onto it. Riders
    /// straighten the bars to stop. 1.2 m/s is just above the feet's 0.8 m/s, so the bar
    /// is straight when they come down; from 2.5 m/s the bike lost its balance first (3 of
    /// 6 stops on a 10° downhill fell), without it 1 of 10 stops on a 15° uphill fell.
    pub straighten_below: f64,
}

impl Default for ArcadeGains {
    fn default() -> Self {
        Self {
            kp: 10.0,
            kd: 0.2,
            prediction: 0.8,
            fast_prediction: 0.35,
            prediction_speeds: (10.0 / 3.6, 20.0 / 3.6),
            air_gain: 6.0,
            straighten_below: 1.2,
        }
    }
}

impl ArcadeGains {
    /// The gains at forward speed `speed` (m/s) on a bike whose gains hold up to
    /// `tuned_speed` (`BikeParams::arcade_tuned_speed`; 0: at every speed). Eq. 4.8 asks
    /// for a rate of steer, and the lean's response to a rate of steer grows with the
    /// speed: in the linearised bicycle (Åström, Klein & Lennartsson 2005, eq. 2) the bar
    /// turning at δ̇ leans the bike with a torque of m a h v δ̇ / w (a the weight's
    /// distance ahead of the rear contact, h its height, w the wheelbase), so K_p and K_d
    /// shrink as v₀/v to keep the loop's gain as tuned. Kept at every speed with the
    /// rider's bar strength at 100 N·m, the loop rang at 90 km/h (the bar swinging
    /// ±0.5° at 35°/s) and a full brake from there fell in 30 of 30; shrunk as (v₀/v)²,
    /// too weak to catch the brake's first dive (a high-side).
    pub fn at_speed(&self, speed: f64, tuned_speed: f64) -> Self {
        let share = if tuned_speed > 0.0 && speed.abs() > tuned_speed {
            tuned_speed / speed.abs()
        } else {
            return *self;
        };
        Self {
            kp: self.kp * share,
            kd: self.kd * share,
            ..*self
        }
    }

    /// The prediction horizon p (s) at forward speed `speed` (m/s).
    pub fn prediction_at(&self, speed: f64) -> f64 {
        let (slow, fast) = self.prediction_speeds;
        let share = if fast > slow {
            ((speed.abs() - slow) / (fast - slow)).clamp(0.0, 1.0)
        } else {
            f64::from(speed.abs() >= fast)
        };
        self.prediction + (self.fast_prediction - self.prediction) * share
    }
}

/// Steering rate ω of eq. 4.8 in the thesis's terms (positive steers into a positive
/// lean): ω = (α + (α − α_o)/δt · p − α_d) K_p + (e − e_o)/δt K_d, with e the bracket and
/// p the horizon `prediction`. Returns ω and the new error e.
pub fn eq_4_8(
    lean: f64,
    previous_lean: f64,
    desired: f64,
    previous_error: f64,
    dt: f64,
    prediction: f64,
    g: &ArcadeGains,
) -> (f64, f64) {
    let error = lean + (lean - previous_lean) / dt * prediction - desired;
    (error * g.kp + (error - previous_error) / dt * g.kd, error)
}

/// Neutral steering angle σ of eq. 4.12 for wheelbase `w`, lean θ, speed v and caster φ:
/// σ = w cos θ tan θ g / (cos φ v²), the angle at which a bike at that lean and speed turns
/// in balance (positive into the lean). Zero when standing still.
pub fn eq_4_12(wheelbase: f64, lean: f64, speed: f64, caster: f64, gravity: f64) -> f64 {
    if speed.abs() < 0.5 {
        return 0.0;
    }
    wheelbase * lean.cos() * lean.tan() * gravity / (caster.cos() * speed * speed)
}

/// The arcade controller with its memory of the last step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ArcadeController {
    pub gains: ArcadeGains,
    previous: Option<(f64, f64)>,
}

impl ArcadeController {
    pub fn new(gains: ArcadeGains) -> Self {
        Self {
            gains,
            previous: None,
        }
    }

    /// Forgets the last step (after a reset).
    pub fn reset(&mut self) {
        self.previous = None;
    }

    /// Its memory of the last step as numbers (none yet: empty), for a rewind.
    pub fn memory(&self) -> Vec<f64> {
        self.previous.map_or(Vec::new(), |(a, b)| vec![a, b])
    }

    /// Takes back what `memory` gave (anything else: nothing remembered).
    pub fn recall(&mut self, memory: &[f64]) {
        self.previous = match memory {
            [a, b] => Some((*a, *b)),
            _ => None,
        };
    }

    /// Controls for `sim`'s next control step towards `goal`.
    pub fn controls_of(&mut self, sim: &Simulation, goal: &Goal) -> Controls {
        let (bike, world, gravity) = (sim.bike(), sim.world(), sim.config().gravity);
        self.controls(bike, world, goal, gravity, sim.config().control_dt)
    }

    /// Controls for one step of length `dt` towards `goal` under `gravity` (m/s²): the
    /// steering leans the bike, the waist holds the rider's weight where asked (a velocity
    /// servo on the pose: the simple PD of the rider position), the rear wheel drives.
    pub fn controls(
        &mut self,
        bike: &Bike,
        world: &World,
        goal: &Goal,
        gravity: DVec3,
        dt: f64,
    ) -> Controls {
        let desired_lean = goal.lean;
        let up = up_against(gravity);
        let mut controls = Controls::default();
        bike.pose_hold_at(world, POSE_GAIN, &goal.rider.pose(), &mut controls);
        goal.drive.apply(bike.params().wheel_radius, &mut controls);
        let lean = bike.lean(world, up);
        // Eq. 4.8 takes the lean rate as (α − α_o)/δt. A difference of two measured leans
        // a step apart amplifies the rider's jitter by p/δt (24× at p = 0.8 s); the frame's
        // measured lean rate gives the same derivative without it, so α_o is taken as
        // α − rate·δt.
        let previous_lean = lean - bike.lean_rate(world, up) * dt;
        let previous_error = self.previous.map_or(lean - desired_lean, |(_, e)| e);
        let speed = bike.forward_speed(world, up);
        let gains = self.gains.at_speed(speed, bike.params().arcade_tuned_speed);
        let (omega, error) = eq_4_8(
            lean,
            previous_lean,
            desired_lean,
            previous_error,
            dt,
            self.gains.prediction_at(speed),
            &gains,
        );
        self.previous = Some((lean, error));
        let (_, front_grounded) = bike.wheel_contacts(world);
        let stopping = goal.drive.sanitized().brake > 0.0 && speed < self.gains.straighten_below;
        // Our steering angle is positive to the left: steering into a right lean is negative.
        let steer_rate = if stopping {
            -self.gains.air_gain * bike.steering(world).0
        } else if front_grounded {
            -omega
        } else {
            let p = bike.params();
            let neutral = -eq_4_12(p.wheelbase, lean, speed, p.rake, gravity.length());
            self.gains.air_gain * (neutral - bike.steering(world).0)
        };
        controls.set(index::STEER, steer_rate);
        controls
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq_4_8_by_hand() {
        // α = 0.10, α_o = 0.08, δt = 1/30, p = 0.2, α_d = 0: e = 0.10 + 0.6·0.2 = 0.22;
        // e_o = 0.15: ω = 0.22·10 + (0.07·30)·0.2 = 2.2 + 0.42 = 2.62.
        let gains = ArcadeGains::default();
        let (omega, error) = eq_4_8(0.10, 0.08, 0.0, 0.15, 1.0 / 30.0, 0.2, &gains);
        assert!((error - 0.22).abs() < 1e-12);
        assert!((omega - 2.62).abs() < 1e-9, "{omega}");
    }

    #[test]
    fn the_gains_shrink_as_the_speed_grows_past_the_tuned_speed() {
        let g = ArcadeGains::default();
        assert_eq!(g.at_speed(30.0, 0.0), g, "0 keeps the gains at every speed");
        assert_eq!(g.at_speed(5.0, 25.0 / 3.6), g);
        let at_50 = g.at_speed(50.0 / 3.6, 25.0 / 3.6);
        assert!((at_50.kp - g.kp / 2.0).abs() < 1e-12 && (at_50.kd - g.kd / 2.0).abs() < 1e-12);
        assert_eq!(at_50.prediction, g.prediction);
    }

    #[test]
    fn the_horizon_shortens_with_speed() {
        let g = ArcadeGains::default();
        assert_eq!(g.prediction_at(0.0), g.prediction);
        assert_eq!(g.prediction_at(10.0 / 3.6), g.prediction);
        let halfway = g.prediction_at(15.0 / 3.6);
        assert!((halfway - (g.prediction + g.fast_prediction) / 2.0).abs() < 1e-12);
        assert_eq!(g.prediction_at(20.0 / 3.6), g.fast_prediction);
        assert_eq!(g.prediction_at(40.0 / 3.6), g.fast_prediction);
        assert_eq!(
            g.prediction_at(-15.0 / 3.6),
            halfway,
            "rolling back counts its speed"
        );
    }

    #[test]
    fn eq_4_12_by_hand() {
        // w = 1.39, θ = 20°, v = 8 m/s, φ = 25°: σ = 1.39·cos20·tan20·9.81/(cos25·64)
        // = 1.39·0.34202·9.81/(0.90631·64) = 0.08039 rad.
        let sigma = eq_4_12(1.39, 20f64.to_radians(), 8.0, 25f64.to_radians(), 9.81);
        assert!((sigma - 0.080_39).abs() < 1e-4, "{sigma}");
        assert!(
            eq_4_12(1.39, -0.3, 8.0, 0.4, 9.81) < 0.0,
            "into a left lean"
        );
        assert_eq!(eq_4_12(1.39, 0.3, 0.0, 0.4, 9.81), 0.0);
    }
}
