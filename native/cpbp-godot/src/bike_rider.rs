//! `BikeSimulation`'s rider inputs beyond the drive: where the player asks for the rider's
//! weight (the right stick) and where it is, for the controllers and the HUD, and how
//! tight a turn the turn stick asks for.

use cpbp_core::bike::RiderPosition;
use cpbp_core::control::TurnIntent;
use godot::prelude::*;

use crate::bike_simulation::BikeSimulation;

#[godot_api(secondary)]
impl BikeSimulation {
    /// Where the rider's weight goes on the bike: `forward` towards the handlebar (−1 back
    /// over the rear wheel, +1 over the tank) and `right` to the rider's right, each in
    /// [−1, 1]. Every controller holds the waist there; the planners also weigh the rider's
    /// centre of mass against it, the more firmly the further the stick is pushed.
    /// Out-of-range values are clamped; non-finite ones count as released, with a warning.
    #[func]
    fn set_rider_position(&mut self, forward: f64, right: f64) {
        let (position, changed) = RiderPosition { forward, right }.sanitized();
        if changed && !(forward.is_finite() && right.is_finite()) {
            godot_warn!("BikeSimulation.set_rider_position: non-finite input ({forward}, {right}) treated as released");
        }
        self.intent.rider = position;
        self.apply_intent();
    }

    /// Curvature (1/m) of the tightest circle the turn command asks for at full stick:
    /// a turn of ±1 asks for this much, positive to the right (scripted riders turn a
    /// path's curvature into a stick deflection with it).
    #[func]
    fn max_turn_curvature() -> f64 {
        TurnIntent::default().max_curvature
    }

    /// The deepest lean (rad) the turn command asks for on this bike, its `max_lean_deg`
    /// (the reference bike's before the ride is built): a full stick asks for no more at
    /// any speed.
    #[func]
    fn get_max_lean(&self) -> f64 {
        self.sim().map_or_else(
            || TurnIntent::default().max_lean,
            |sim| sim.config().bike.max_lean,
        )
    }

    /// The rider position asked for, as `set_rider_position` took it: x to the right, y
    /// forward (the right stick's axes, forward up).
    #[func]
    fn get_rider_position_asked(&self) -> Vector2 {
        let p = self.intent.rider;
        Vector2::new(p.right as f32, p.forward as f32)
    }

    /// Where the rider's centre of mass is relative to the riding pose's, in the units of
    /// `set_rider_position` (±1 where a full stick asks for it; beyond 1 when the rider is
    /// thrown further), x to the right and y forward. Zero before the ride is built.
    #[func]
    fn get_rider_position(&self) -> Vector2 {
        let Some(sim) = self.sim() else {
            return Vector2::ZERO;
        };
        let p = RiderPosition::from_com_offset(sim.bike().rider_offset(sim.world()));
        Vector2::new(p.right as f32, p.forward as f32)
    }
}
