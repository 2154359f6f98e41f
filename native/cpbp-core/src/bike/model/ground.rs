//! Where a built bike meets the ground: the tyres' contact points, the support point the
//! lean cost measures against, and that point moved back when the player asks for a
//! wheelie.

use glam::DVec3;

use super::{Bike, Part};
use crate::bike::controls::{index, Controls, ForceClass};
use crate::bike::drive::throttle_open;
use crate::bike::manual::POSE_GAIN;
use crate::bike::wheelie_control::PitchRequest;
use crate::ode::World;

/// One of the rider's feet as `Bike::feet` reports it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FootState {
    /// The sole's centre in the frame body's frame (m).
    pub on_frame: DVec3,
    /// Put down (below walking pace, throttle closed).
    pub down: bool,
    /// Stood on the ground in the last step.
    pub on_ground: bool,
}

impl Bike {
    /// Each tyre's lowest point, rear and front (torus tyres: the contact lies in the
    /// wheel's plane, a crown radius above the road). A lifted wheel's is in the air.
    pub fn tyre_contacts(&self, world: &World, up: DVec3) -> (DVec3, DVec3) {
        let (r, crown) = (self.params.wheel_radius, self.params.tyre_crown);
        let contact = |part: Part| {
            let body = self.body(part);
            let centre = world.body_position(body);
            let axle = world.body_quaternion(body) * DVec3::Z;
            let down = -(up - axle * up.dot(axle)).normalize_or(up);
            centre + down * (r - crown) - up * crown
        };
        (contact(Part::RearWheel), contact(Part::FrontWheel))
    }

    /// How fast each tyre slides over the ground (m/s), rear and front: the speed, in the
    /// ground's plane, of the tyre's own material at its lowest point. Rolling, it is near
    /// 0; a locked or spinning wheel, or a tyre sliding sideways, slides. What the game's
    /// tyre marks and smoke answer (a wheel in the air slides too: ask whether it is down).
    pub fn tyre_slip_speeds(&self, world: &World, up: DVec3) -> (f64, f64) {
        let (rear, front) = self.tyre_contacts(world, up);
        (
            self.sliding_speed(world, Part::RearWheel, rear, up),
            self.sliding_speed(world, Part::FrontWheel, front, up),
        )
    }

    /// Where the bike itself scrapes the ground, and how fast (m/s) it slides there: the
    /// deepest terrain contact, in the last step, of each of its bodies that is neither a
    /// wheel nor the rider (the frame, the fork and its legs, the swingarm). What throws
    /// sparks when the bike slides on its side.
    pub fn scrapes(&self, world: &World, up: DVec3) -> Vec<(DVec3, f64)> {
        let mut seen = Vec::new();
        [Part::Frame, Part::Fork, Part::ForkLower, Part::Swingarm]
            .into_iter()
            .filter(|&part| {
                // A bike without suspension rides some parts on one body: once each.
                let body = self.body(part);
                !seen.contains(&body) && {
                    seen.push(body);
                    true
                }
            })
            .filter_map(|part| {
                let at = world.body_ground_point(self.body(part))?;
                Some((at, self.sliding_speed(world, part, at, up)))
            })
            .collect()
    }

    /// The speed (m/s), in the ground's plane, of `part`'s material at `at`.
    fn sliding_speed(&self, world: &World, part: Part, at: DVec3, up: DVec3) -> f64 {
        let body = self.body(part);
        let lever = at - world.body_position(body);
        let moving =
            world.body_linear_velocity(body) + world.body_angular_velocity(body).cross(lever);
        (moving - up * moving.dot(up)).length()
    }

    /// Ground support point: midway between the two tyres' lowest points.
    pub fn support_point(&self, world: &World, up: DVec3) -> DVec3 {
        let (rear, front) = self.tyre_contacts(world, up);
        (rear + front) / 2.0
    }

    /// The support point moved from the midpoint towards the rear tyre by `shift` (0–1)
    /// or towards the front tyre by −`shift`: where the rider's weight belongs in a
    /// wheelie or a stoppie of that height, the balance point at ±1. Exactly
    /// `support_point` at 0.
    pub fn support_point_lifted(&self, world: &World, up: DVec3, shift: f64) -> DVec3 {
        let (rear, front) = self.tyre_contacts(world, up);
        let middle = (rear + front) / 2.0;
        if shift > 0.0 {
            middle + (rear - middle) * shift.min(1.0)
        } else if shift < 0.0 {
            middle + (front - middle) * (-shift).min(1.0)
        } else {
            middle
        }
    }

    /// What of `asked` this bike does now: a wheelie with the rear tyre on the ground,
    /// lower as it topples sideways (`WheelieControl::held_lift`); a turn of the nose
    /// with both wheels in the air; nothing without a wheelie control (the rigid bike
    /// keeps the thesis's plain drive).
    pub fn held_pitch(&self, world: &World, up: DVec3, asked: PitchRequest) -> PitchRequest {
        let Some(control) = &self.params.wheelie_control else {
            return PitchRequest::default();
        };
        if asked == PitchRequest::default() {
            return asked;
        }
        let (rear, front) = self.wheel_contacts(world);
        let lift = if asked.lift > 0.0 && rear {
            control.held_lift(asked.lift, self.lean(world, up))
        } else {
            0.0
        };
        let airborne = !rear && !front;
        let air = if airborne && asked.air.is_finite() {
            asked.air.clamp(-1.0, 1.0)
        } else {
            0.0
        };
        let stoppie = match &self.params.front_brake {
            Some(_) if asked.stoppie > 0.0 && front => {
                control.held_lift(asked.stoppie, self.lean(world, up))
            }
            _ => 0.0,
        };
        PitchRequest { lift, air, stoppie }
    }

    /// How far (m) the centre of mass is ahead of the shifted support point along the
    /// heading (`support_point_lifted`), and how fast that grows (m/s): what the wheelie
    /// and stoppie holds regulate. The support point moves with the axles above it.
    pub fn weight_ahead_of_support(&self, world: &World, up: DVec3, shift: f64) -> (f64, f64) {
        let heading = self.heading(world, up);
        let support = self.support_point_lifted(world, up, shift);
        let ahead = (self.center_of_mass(world) - support).dot(heading);
        let velocity = |part: Part| world.body_linear_velocity(self.body(part));
        let (rear, front) = (velocity(Part::RearWheel), velocity(Part::FrontWheel));
        // Where between the axles the support point sits: 0 at the rear, 1 at the front.
        let along = (1.0 - shift.clamp(-1.0, 1.0)) / 2.0;
        let support_velocity = rear + (front - rear) * along;
        let rate = (self.center_of_mass_velocity(world) - support_velocity).dot(heading);
        (ahead, rate)
    }

    /// Puts the rider's feet down below walking pace and lifts them above it or when the
    /// throttle opens (`Feet`); a rider who fell off has no feet on the bike. Returns
    /// whether they are down.
    pub(super) fn place_feet(&self, world: &mut World, controls: &Controls, up: DVec3) -> bool {
        let (Some(feet), Some(geoms)) = (&self.params.feet, self.feet) else {
            return false;
        };
        if feet.reaching() {
            return self.place_reaching_feet(world, controls, up, feet, geoms);
        }
        let down = self.rider_is_on(world)
            && feet.down_at(self.forward_speed(world, up), throttle_open(controls));
        for foot in geoms {
            world.set_foot_down(foot, down);
        }
        down
    }

    /// `controls` with the bar and the rider's body held still, as a rider standing on a
    /// foot holds them (`Feet::straighten_rate`); the triggers are left as they were.
    pub(super) fn sitting_still(&self, world: &World, controls: &Controls) -> Controls {
        let mut still = *controls;
        let rate = self.params.feet.map_or(0.0, |feet| feet.straighten_rate);
        still.set(index::STEER, -rate * self.steering(world).0);
        self.pose_hold(world, POSE_GAIN, &mut still);
        for class in [
            ForceClass::Steering,
            ForceClass::Waist,
            ForceClass::Knee,
            ForceClass::Arms,
        ] {
            still.set(index::FORCE + class as usize, 1.0);
        }
        still
    }

    /// Whether the rider's left and right feet stood on the ground in the last step.
    pub fn feet_on_ground(&self, world: &World) -> (bool, bool) {
        match &self.feet {
            Some([left, right]) => (
                world.foot_touches_ground(*left),
                world.foot_touches_ground(*right),
            ),
            None => (false, false),
        }
    }

    /// The rider's feet, left then right (none on a bike without them), for drawing.
    pub fn feet(&self, world: &World) -> Vec<FootState> {
        let (Some(feet), Some(geoms)) = (&self.params.feet, &self.feet) else {
            return Vec::new();
        };
        let frame_rest = self.rest[Part::Frame as usize].0;
        feet.positions()
            .iter()
            .zip(geoms)
            .map(|(at, &geom)| FootState {
                on_frame: world.foot_sole(geom).unwrap_or(*at - frame_rest),
                down: world.is_foot_down(geom),
                on_ground: world.foot_touches_ground(geom),
            })
            .collect()
    }

    /// Whether the rear and front wheels touched the ground in the last step.
    pub fn wheel_contacts(&self, world: &World) -> (bool, bool) {
        (
            world.body_touches_static(self.body(Part::RearWheel)),
            world.body_touches_static(self.body(Part::FrontWheel)),
        )
    }

    /// The first part other than a wheel that touched the ground in the last step.
    pub fn part_touching_ground(&self, world: &World) -> Option<Part> {
        Part::ALL
            .into_iter()
            .find(|p| !p.is_wheel() && world.body_touches_static(self.body(*p)))
    }
}
