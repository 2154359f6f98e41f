//! Legs that reach (`Feet::reach`): the rider puts one foot down, on the side the bike
//! leans to, and stretches its leg until the bike leans `Feet::prop_lean` from upright
//! onto it; pulling away the foot props the bike until `Feet::prop_until`. Which foot is
//! down, how far its leg is stretched and which way (`Feet::plumb_legs`) are the world's
//! state (`WorldState::feet_down`, `feet_extension`, `feet_leg_direction`), so the
//! planners' rollouts step the same rule from the same foot.

use glam::{DQuat, DVec3};

use super::{Bike, Part};
use crate::bike::controls::Controls;
use crate::bike::drive::throttle_open;
use crate::bike::Feet;
use crate::ode::{GeomId, World};

/// The feet's order in `Bike::feet`: left, then right.
const LEFT: usize = 0;
const RIGHT: usize = 1;

/// 1 for the right foot, -1 for the left: a lean (positive to the right) times this is
/// the lean towards that foot.
fn rightward(side: usize) -> f64 {
    if side == RIGHT {
        1.0
    } else {
        -1.0
    }
}

/// The way a leg stretches, in the frame's own axes: down (as built, and always unless
/// it hangs plumb, `Feet::plumb_legs`).
pub(super) const LEG_DIRECTION: DVec3 = DVec3::NEG_Y;

/// How far (m) past the road a leg reaching for it stretches: a sole laid exactly on the
/// road makes no contact, and one kept there as the bike fell towards it drew back ahead
/// of the road all the way down (a fall on a camber). A centimetre is a load of 800 N on
/// the street bike's foot.
const INTO_THE_ROAD: f64 = 0.01;

impl Bike {
    /// Puts down the foot a rider puts down (or keeps the one down) and lifts the other,
    /// or lifts both when riding (`Feet::reaching`). Returns whether the rider stands on
    /// it with the throttle closed (then sitting still).
    pub(super) fn place_reaching_feet(
        &self,
        world: &mut World,
        controls: &Controls,
        up: DVec3,
        feet: &Feet,
        geoms: [GeomId; 2],
    ) -> bool {
        let speed = self.forward_speed(world, up).abs();
        let down = geoms.map(|foot| world.is_foot_down(foot));
        let standing = speed < feet.down_below && !throttle_open(controls);
        let propping = down.contains(&true) && speed < feet.prop_until;
        if !self.rider_is_on(world) || !(standing || propping) {
            for foot in geoms {
                world.set_foot_down(foot, false);
                world.set_foot_extension(foot, 0.0);
            }
            return false;
        }
        let side = self.foot_to_stand_on(world, up, feet, down);
        world.set_foot_down(geoms[side], true);
        world.set_foot_down(geoms[1 - side], false);
        world.set_foot_extension(geoms[1 - side], 0.0);
        standing
    }

    /// Moves a reaching leg that is down towards the length that leans the bike
    /// `Feet::prop_lean` onto it: reaching for the road at `Feet::leg_speed` (over `dt`
    /// seconds) no further than the road where the bike leans now, then, its foot on the
    /// road, pushing the bike up (or letting it down) ever slower as it nears that
    /// length (`Feet::push_time`). A leg that reached at once for the propping length
    /// drove its sole into the road when the bike leaned past it, and one that pushed at
    /// full speed left the bike rolling as it passed the propping lean: either threw the
    /// bike over upright onto the other foot and back, for seconds after a full brake.
    /// Nothing on a bike whose legs do not reach.
    pub(super) fn move_legs(&self, world: &mut World, up: DVec3, dt: f64) {
        let (Some(feet), Some(geoms)) = (&self.params.feet, self.feet) else {
            return;
        };
        if !feet.reaching() {
            return;
        }
        for (side, foot) in geoms.into_iter().enumerate() {
            if !world.is_foot_down(foot) {
                continue;
            }
            if feet.plumb_legs {
                let frame = world.body_quaternion(self.body(Part::Frame));
                world.set_foot_leg_direction(foot, frame.inverse() * -up);
            }
            let propping = self.leg_to_lean(world, up, feet, side, feet.prop_lean);
            let now = world.foot_extension(foot);
            let standing = world.foot_touches_ground(foot);
            let wanted = if standing {
                propping
            } else {
                let toward = rightward(side) * self.lean(world, up);
                let touching = self.leg_to_lean(world, up, feet, side, toward);
                let reaching = propping.min(touching + INTO_THE_ROAD);
                if feet.steady_reach {
                    reaching.max(now.min(propping))
                } else {
                    reaching
                }
            }
            .clamp(0.0, feet.reach);
            let mut step = feet.leg_speed * dt;
            if standing {
                step = step.min((wanted - now).abs() * dt / feet.push_time);
            }
            world.set_foot_extension(foot, now + (wanted - now).clamp(-step, step));
        }
    }

    /// Which foot (`LEFT`, `RIGHT`) to stand on: the one on the side the bike leans to
    /// from upright, as a rider steps out on the side the bike falls to; the one down
    /// until the bike leans away from it by more than it props. A foot cannot lean the
    /// bike onto itself (pressing on the road it only lifts its own side), so on a slope
    /// across it is the uphill or the downhill foot as the bike came to rest; either
    /// holds it `Feet::prop_lean` from upright, the uphill leg bent, the downhill one
    /// stretched.
    fn foot_to_stand_on(&self, world: &World, up: DVec3, feet: &Feet, down: [bool; 2]) -> usize {
        let lean = self.lean(world, up);
        if let Some(side) = down.iter().position(|&d| d) {
            let toward = rightward(side) * lean;
            return if toward < -feet.prop_lean {
                1 - side
            } else {
                side
            };
        }
        if lean >= 0.0 {
            RIGHT
        } else {
            LEFT
        }
    }

    /// The leg's stretch (m) that puts `side`'s sole on the road with the bike leaned
    /// `toward` (rad) from upright towards it: the bike rolled, as a rigid body, about the
    /// line through its tyres' contacts from its lean now to that one, on the plane of
    /// the road under its wheels.
    fn leg_to_lean(&self, world: &World, up: DVec3, feet: &Feet, side: usize, toward: f64) -> f64 {
        let sign = rightward(side);
        let roll = toward - sign * self.lean(world, up);
        let (rear, front) = self.tyre_contacts(world, up);
        let heading = self.heading(world, up);
        let along = (front - rear).normalize_or(heading);
        // A turn about the heading leans the bike to the right (heading × up = right).
        let rolled = DQuat::from_axis_angle(along * sign, roll);
        let frame = self.body(Part::Frame);
        let rotation = world.body_quaternion(frame);
        let sole_on_frame = feet.positions()[side] - self.rest[Part::Frame as usize].0;
        let sole = rear + rolled * (world.body_position(frame) + rotation * sole_on_frame - rear);
        let leg = if feet.plumb_legs {
            -up
        } else {
            rolled * (rotation * LEG_DIRECTION)
        };
        let normal = self.ground_normal(world, up);
        let reach_down = leg.dot(normal);
        if reach_down > -1e-3 {
            // The leg lies along the road or points off it: no stretch reaches it.
            return 0.0;
        }
        (feet.radius - (sole - rear).dot(normal)) / reach_down
    }

    /// The road's normal under the wheels (the sum of theirs; `up` with neither down).
    fn ground_normal(&self, world: &World, up: DVec3) -> DVec3 {
        [Part::RearWheel, Part::FrontWheel]
            .into_iter()
            .filter_map(|part| world.body_ground_normal(self.body(part)))
            .sum::<DVec3>()
            .normalize_or(up)
    }
}
