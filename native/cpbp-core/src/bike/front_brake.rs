//! The front brake. The thesis's bike braked the rear wheel alone (§4.1.1); a road bike
//! stops mostly with the front, whose grip grows with the load braking moves onto it
//! (with ODE patch 04, up to about 1 g here). That much tips the rear up, so, as road
//! bikes' rear-wheel lift-off mitigation does (e.g. Bosch's motorcycle stability control),
//! the brake lets off as the rear suspension tops out (the reference bike's rule), or is
//! held below the force that tips the bike over its front tyre (`tipping_share`, from the
//! bike's geometry at each physics step; off on the reference bike). Asked for a stoppie (the rider's
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
    /// full… (0, with `none_below` 0 too: no compression window)
    pub full_above: f64,
    /// … and at or below which it lets off completely (its sag is 39 mm). The rear stays
    /// loaded with a margin: with the brake letting off only at 3 mm the rear hopped in a
    /// full brake, and stopping down a 15° slope it left the road, so the bike stood on
    /// the front tyre and a foot and toppled along that line (3 of 6 stops). The window
    /// cannot see the last of the rear's load: the spring's preload tops the rear out while
    /// its tyre still carries about 190 N, so it holds a full brake near 0.6 g.
    pub none_below: f64,
    /// The tipping limit: the share (0–1) of the braking force that would tip the bike
    /// over its front tyre that the brake may use; 0 turns the limit off. With the rear
    /// unloaded, bike and rider turn about the front contact when the braking force F
    /// times the centre of mass's height h above the road passes the load N times its
    /// distance b behind the contact: F = N·b/h, about 1.08 g on the level here, and on a
    /// slope N = m·g·cos(slope) while gravity pulls along the road (a 15° downhill leaves
    /// about 0.78 g).
    pub tipping_share: f64,
    /// How far ahead (s) the tipping limit reads the centre of mass, moving over the
    /// front tyre at its rate (the pitch rate's term; 0: where it is now). A full brake
    /// dives the fork and folds the rider forward, and a limit that reads where the weight
    /// is lets the rear up before it lets off.
    pub tipping_lookahead: f64,
    /// Seconds from no brake to the full brake (0: at once): a rider squeezes the lever
    /// in a tenth of a second or two rather than striking it. It only slows the rise;
    /// letting off (the rider, the lift-off limit) is at once.
    pub ramp_time: f64,
    /// Cornering ABS: leaned by θ, the brake gives at most 1 − (θ / `cornering_lean`)² of
    /// itself (rad; 0: the same at any lean; the square leaves a straight-line stop's small
    /// leans their whole brake, as the tyre's friction circle does), as modern road bikes' lean-sensitive ABS
    /// does (e.g. Bosch's motorcycle stability control), leaving the tyre grip for the
    /// turn and the steering time to stand the bike up: with the whole brake at any lean a
    /// full brake at 20° and 25 km/h dropped arcade's street bike in 7 of 30 headings.
    pub cornering_lean: f64,
    /// Below this forward speed (m/s; 0: never) the brake eases off towards `ease_to` of
    /// itself at a standstill, as a rider eases the lever in the last metre of a stop:
    /// stopping from a full brake the fork, deep in its travel, springs the bike back on
    /// its pegs and feet, and the rear lifts as the feet come down.
    pub ease_below: f64,
    pub ease_to: f64,
    /// The righting reserve: leaned, the brake leaves the speed the bike needs to stand
    /// itself up. At lean θ with the bar at full lock the tightest turn holds the lean at
    /// v² = g·R·tan θ, its radius R = L·cos θ / (tan δ·cos ε) (wheelbase L, steering lock
    /// δ, rake ε), so v² = g·L·sin θ / (tan δ·cos ε); only the share 1 − that / v² of the
    /// full-lock turn's pull is left to stand the bike up, and the brake gives that share
    /// of itself (`righting_share`). Without it a full brake at 20° and 25 km/h stopped the
    /// sport 600 in 0.7 s still leaned 15–20° with the bar at full lock, and on legs along
    /// the frame it fell (30 of 30 headings; none with it, stopping in 5.7 m rather than
    /// 2.3); on legs that hang plumb it lies onto its foot leaned instead: the square law
    /// of `cornering_lean` leaves 0.8 of the brake there. The bike's drive eases the rear
    /// brake's share by the same (docs/bike-model.md, "Braking in a turn").
    pub righting_reserve: bool,
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
            tipping_share: 0.0,
            tipping_lookahead: 0.0,
            ramp_time: 0.0,
            cornering_lean: 0.0,
            ease_below: 0.0,
            ease_to: 1.0,
            righting_reserve: false,
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

    /// Whether the compression window limits the brake (`full_above` > 0).
    pub fn has_window(&self) -> bool {
        self.full_above > 0.0
    }

    /// Whether the brake is set again before every physics step rather than once a
    /// control period: the tipping limit and the ramp follow the bike within a period, as
    /// an ABS unit's controller (hundreds of hertz) does. Set once a period the limit let
    /// off a period late and the brake burst to 1.4 g and back. The reference bike's
    /// window alone keeps the once-a-period setting it was evaluated with.
    pub fn modulates(&self) -> bool {
        self.tipping_share > 0.0
            || self.ramp_time > 0.0
            || self.ease_below > 0.0
            || self.cornering_lean > 0.0
            || self.righting_reserve
    }

    /// Share (0–1) of the asked braking let through with the rear compressed by `rear` (m);
    /// all of it without a window.
    pub fn lift_off_share(&self, rear: f64) -> f64 {
        if !self.has_window() {
            return 1.0;
        }
        if !rear.is_finite() {
            return 0.0;
        }
        ((rear - self.none_below) / (self.full_above - self.none_below)).clamp(0.0, 1.0)
    }

    /// Share (0–1) of the full torque, on a wheel of radius `radius`, that the tipping
    /// limit allows with the centre of mass `over` the front tyre as `OverFrontTyre`
    /// describes; all of it with the limit off, none with the weight already over the
    /// tyre or a geometry that is not a number.
    pub fn tipping_limit(&self, over: &OverFrontTyre, radius: f64) -> f64 {
        if self.tipping_share <= 0.0 {
            return 1.0;
        }
        let ahead = self.tipping_lookahead;
        let behind = over.behind + over.behind_rate * ahead;
        let height = over.height + over.height_rate * ahead;
        let force = self.tipping_share * over.load * behind / height;
        let share = force * radius / self.max_torque;
        if share.is_finite() && height > 0.0 {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Share (0–1) of itself the brake gives leaned by `lean` (rad, either way) at forward
    /// speed `speed` (m/s): all of it without cornering ABS, and where ABS rests, at
    /// walking pace (`abs_above`), so a bike standing leaned on a foot stays held.
    pub fn cornering_share(&self, lean: f64, speed: f64) -> f64 {
        if self.cornering_lean <= 0.0 || speed.is_nan() || speed.abs() <= self.abs_above {
            return 1.0;
        }
        let share = 1.0 - (lean / self.cornering_lean).powi(2);
        if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Share (0–1) of itself the brake gives leaned by `lean` (rad, either way) at forward
    /// speed `speed` (m/s) under the righting reserve, for a bike whose full-lock turn at
    /// lean θ holds that lean at v² = `full_lock_lean_speed2` · sin θ (g·L / (tan δ·cos ε),
    /// m²/s²): all of it without the reserve and at walking pace (`abs_above`), where ABS
    /// rests and a bike leaned on a foot stays held (eased there too, the bikes rolled on
    /// leaned and the sport 600 fell in all 30 braked turns again); the front's there
    /// waits for the bar to come straight (`walking_bar_share`).
    pub fn righting_share(&self, lean: f64, speed: f64, full_lock_lean_speed2: f64) -> f64 {
        if !self.righting_reserve || speed.is_nan() || speed.abs() <= self.abs_above {
            return 1.0;
        }
        let share = 1.0 - full_lock_lean_speed2 * lean.sin().abs() / (speed * speed);
        if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Share (0–1) of itself the front brake gives at walking pace (`abs_above`) under the
    /// righting reserve with the bar turned `steer` (rad, either way) of its lock `lock`:
    /// 1 − |δ|/lock, all of it straight and none at full lock; 1 above walking pace and
    /// without the reserve. Turned by δ, the brake's pull along the wheel's heading pushes
    /// the contact patch sideways by sin δ of itself, out of the turn and below the
    /// weight, which rolls the bike into the turn: a rider grabbing the front brake at a
    /// walk with the bar turned drops the bike, so riders stop on the rear and squeeze the
    /// front as the bar comes straight. With the front coming back in full at walking
    /// pace, arcade's dirt 125 reached it leaned 6.5° with the bar 31° into the turn and
    /// the brake kicked the lean to 15° within 0.3 s (docs/bike-model.md, "Braking in a
    /// turn"). The rear wheel stays in the frame's plane and keeps its share.
    pub fn walking_bar_share(&self, speed: f64, steer: f64, lock: f64) -> f64 {
        if !self.righting_reserve || speed.is_nan() || speed.abs() > self.abs_above {
            return 1.0;
        }
        let share = 1.0 - (steer / lock).abs();
        if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Share (0–1) of the lever the brake gives at forward speed `speed` (m/s): all of it
    /// from `ease_below` up, `ease_to` of it at a standstill, in proportion between.
    pub fn eased(&self, speed: f64) -> f64 {
        if self.ease_below <= 0.0 {
            return 1.0;
        }
        let share = self.ease_to + (1.0 - self.ease_to) * speed.abs() / self.ease_below;
        if share.is_finite() {
            share.min(1.0)
        } else {
            1.0
        }
    }

    /// The brake's torque (N·m) after `dt` seconds of lever towards `target` from
    /// `current`: rising at most the full torque per `ramp_time`, falling at once.
    pub fn ramped(&self, current: f64, target: f64, dt: f64) -> f64 {
        if self.ramp_time <= 0.0 || target <= current {
            return target;
        }
        let rise = self.max_torque * dt / self.ramp_time;
        if rise.is_finite() {
            target.min(current.max(0.0) + rise.max(0.0))
        } else {
            target
        }
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

/// Where bike and rider's centre of mass is over the front tyre, in the road's frame
/// (along the road and across it, in the plane of the wheels), as the tipping limit reads
/// it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OverFrontTyre {
    /// How far (m) the centre of mass is behind the front tyre's contact along the road…
    pub behind: f64,
    /// … and how high (m) above the road.
    pub height: f64,
    /// How fast (m/s) each grows.
    pub behind_rate: f64,
    pub height_rate: f64,
    /// The road's push on bike and rider (N) across it: the weight times the cosine of
    /// the slope.
    pub load: f64,
}

#[cfg(test)]
mod tests;
