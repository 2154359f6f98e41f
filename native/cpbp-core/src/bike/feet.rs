//! The rider's feet at a stop (thesis §5.3's dropped second-leg experiment; issue 14):
//! below walking pace the rider puts a foot down on whichever side the bike leans to, and
//! the bike rests on it as on a leg, indefinitely; riding off, the feet come up again.
//!
//! The foot is a sole on a leg held stiff from the frame (the rider's mid-plane leg stays
//! on the pegs, and the planners' control vector is unchanged): a sphere on the frame
//! beside the footpeg, a stride's width out, that touches the road when the bike leans a
//! degree or so, with a leg's give (a spring–damper) and a shoe's grip. Up, it does not
//! collide at all, so riding is exactly what it was; a launch with the throttle open
//! lifts them at once, so every ride that sets off at full throttle (the experiment's,
//! the tests') is exactly what it was too.
//!
//! That foot is a stiff leg at a fixed place, which stands the bike on level ground but
//! not across a slope: on a road falling 8° to one side the uphill foot touched with the
//! weight already downhill, the bike rolled off it onto the downhill foot and stood
//! leaned 9°, and from there, pulling away, no steering recovered (issue 68). A bike with
//! `reach` has legs that reach: the rider puts one foot down, on the side the bike leans
//! to, and its leg stretches or bends until the bike leans `prop_lean` from upright onto
//! it (upright against gravity, not against the road), and it stays down as a prop while
//! the bike pulls away, to `prop_until`. The rule is in `model/legs.rs`.

use glam::DVec3;

use crate::ode::FootSurface;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Feet {
    /// Centre of the right foot's sole in the bike frame as built (x forward, y up, z to
    /// the right; the left foot mirrors it in z).
    pub right_foot: DVec3,
    /// Radius of the sole's sphere (m).
    pub radius: f64,
    pub surface: FootSurface,
    /// Below this forward speed (m/s) the feet are down.
    pub down_below: f64,
    /// With a foot down the rider sits still, whatever the controller asks: the bar
    /// turns back to centre at this rate per radian off it (1/s) and the body goes back
    /// to the riding pose (`POSE_GAIN`), both at full strength. At a standstill neither
    /// balances the bike, the foot does, but both can topple it. A planner left the bar
    /// at full lock, the fork's flop leaned the bike onto the foot (10–14° on a 15° hill)
    /// and the hill start set off steered into the lean and fell (17 of 30 seeds); with
    /// the bar held, its rider's body still levered the bike from one foot over onto the
    /// other, to 19°, where the flop outweighed the bar.
    pub straighten_rate: f64,
    /// How far (m) a leg stretches from where the sole is built to reach the road; 0 is
    /// a stiff leg, the feet as the reference's rider had them (both down, fixed).
    pub reach: f64,
    /// The lean (rad) from upright, against gravity, a reaching leg holds the bike at.
    pub prop_lean: f64,
    /// How fast (m/s) a reaching leg stretches or shortens while its foot is off the
    /// road: reaching for it.
    pub leg_speed: f64,
    /// With its foot on the road, a reaching leg closes the distance to the length that
    /// props the bike at this time constant (s): it pushes the bike up (or lets it down)
    /// ever slower as the bike nears the lean it props, so that the bike's roll is spent
    /// there rather than carrying it over upright onto the other foot.
    pub push_time: f64,
    /// Pulling away, a reaching leg's foot stays down, a prop, below this forward speed
    /// (m/s), with the throttle open.
    pub prop_until: f64,
    /// A reaching leg whose foot has not met the road keeps its length as the bike leans
    /// towards it, rather than drawing back with its estimate of where the road is (the
    /// bike rolled as a rigid body about its tyres' contact line). On a long, soft
    /// suspension that estimate puts the road over a centimetre nearer than it is, and a
    /// leg that follows it keeps its sole just off the road all the way down: the dirt
    /// 125 on a 15° downhill leaned past 10° without its foot ever touching
    /// (docs/bike-model.md). Off, the leg follows the estimate, as the street 390's does.
    pub steady_reach: bool,
    /// A reaching leg hangs plumb from where its sole is built, stretching against
    /// gravity rather than along the frame's own down axis, as a rider's leg hangs from
    /// the hip to the road. Stretched along the frame, a leg's sole swings in under a
    /// leaned bike by its stretch times the sine of the lean: the dirt 125, its sole built
    /// 0.35 m up, came to rest leaned 11° and lay down onto its foot, its centre of mass
    /// passing over the sole at 24° (docs/bike-model.md, "Braking in a turn"). It wants
    /// `steady_reach` too: a plumb leg following its estimate of the road hovered just off
    /// it facing down a 15° slope (the sport 600 and the naked 700 fell in all 30 such
    /// stops). Off, the leg stretches along the frame, as the street 390's does.
    pub plumb_legs: bool,
}

impl Default for Feet {
    /// A foot 0.40 m out beside the footpeg, its sole a 5 cm sphere 4.5 cm above the
    /// road with the bike upright as built: with the suspension's sag it meets the road
    /// at about 1° of lean, and the bike stands within 3° of upright on whichever foot it
    /// leans to (`tests/rides/feet.rs`). The leg is a propping strut, its knee locked: it
    /// gives 1 cm under 800 N (80 kN/m, damped at about critical for the bike's roll on
    /// it). At 20 kN/m the bike sank onto the leg to 10° standing on a 15° hill and a
    /// planner's hill start from there fell. The shoe grips at μ = 0.8 (rubber soles on
    /// asphalt). Down below 0.8 m/s (about 3 km/h), where steering no longer
    /// balances. The bar goes straight in about half a second (6/s: a 95 % return in
    /// 0.5 s). The legs do not reach (`reach` 0); where they do, the bike stands 2.5° from
    /// upright on one, the leg reaches at 1 m/s (a tenth of a second for the 10 cm a
    /// camber asks) and pushes with a time constant of a second (put down at rest leaned
    /// 3.5–8° onto a foot the bike settles within 2° of its prop; at 0.5 s or at a
    /// constant 0.1 m/s it rocked from foot to foot), and the foot props the bike to
    /// 1.4 m/s (5 km/h, a walk), where steering balances again.
    fn default() -> Self {
        Self {
            right_foot: DVec3::new(-0.05, 0.045, 0.40),
            radius: 0.05,
            surface: FootSurface {
                mu: 0.8,
                stiffness: 80_000.0,
                damping: 3_000.0,
            },
            down_below: 0.8,
            straighten_rate: 6.0,
            reach: 0.0,
            prop_lean: 2.5f64.to_radians(),
            leg_speed: 1.0,
            push_time: 1.0,
            prop_until: 1.4,
            steady_reach: false,
            plumb_legs: false,
        }
    }
}

impl Feet {
    /// The left foot's and the right foot's sole centres in the bike frame as built.
    pub fn positions(&self) -> [DVec3; 2] {
        let right = self.right_foot;
        [DVec3::new(right.x, right.y, -right.z), right]
    }

    /// Whether the legs reach (`reach`): one foot down, stretched to the road.
    pub fn reaching(&self) -> bool {
        self.reach > 0.0
    }

    /// Whether the feet are down at forward speed `speed` (m/s), with the throttle open
    /// or closed: a rider pulling away lifts them as the drive takes up.
    pub fn down_at(&self, speed: f64, throttle_open: bool) -> bool {
        speed.abs() < self.down_below && !throttle_open
    }
}
