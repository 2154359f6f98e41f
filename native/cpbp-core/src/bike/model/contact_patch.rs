//! How the tyres move over the ground and how hard the ground pushes back, as the game's
//! sound hears them: the rear rim's speed (the engine turns with it), each tyre's slide at
//! its contact patch, and the bike's momentum (whose change in a step is the ground's
//! blow).

use glam::DVec3;

use super::{Bike, Part};
use crate::ode::World;

impl Bike {
    /// Speed of the rear tyre's rim (m/s, forward positive): the wheel's spin about its
    /// axle times its radius, whether or not it grips.
    pub fn rear_rim_speed(&self, world: &World) -> f64 {
        world.hinge_rate(self.rear_axle) * self.params.wheel_radius
    }

    /// The velocity of each tyre's material at its contact point (rear, front), as part of
    /// the spinning wheel; `None` for a tyre off the ground.
    fn contact_velocities(&self, world: &World, up: DVec3) -> [Option<DVec3>; 2] {
        let (rear_contact, front_contact) = self.tyre_contacts(world, up);
        [
            (Part::RearWheel, rear_contact),
            (Part::FrontWheel, front_contact),
        ]
        .map(|(part, contact)| {
            let body = self.body(part);
            world.body_touches_static(body).then(|| {
                let centre = world.body_position(body);
                world.body_linear_velocity(body)
                    + world.body_angular_velocity(body).cross(contact - centre)
            })
        })
    }

    /// How fast each tyre (rear, front) slides over the ground at its contact point
    /// (m/s): the contact's velocity as part of the spinning wheel, across `up`. Zero for
    /// a tyre off the ground and for one rolling without slip.
    pub fn tyre_slip(&self, world: &World, up: DVec3) -> (f64, f64) {
        let [rear, front] = self
            .contact_velocities(world, up)
            .map(|v| v.map_or(0.0, |v| (v - up * v.dot(up)).length()));
        (rear, front)
    }

    /// How fast the tyres on the ground slide sideways (m/s, positive towards the bike's
    /// right): of the two contact points' velocities across the bike's heading, the
    /// larger. Near zero while they grip; what the crash monitor reads a low-side from.
    pub fn tyre_side_slide(&self, world: &World, up: DVec3) -> f64 {
        let right = self.heading(world, up).cross(up);
        let [rear, front] = self
            .contact_velocities(world, up)
            .map(|v| v.map_or(0.0, |v| v.dot(right)));
        if rear.abs() >= front.abs() {
            rear
        } else {
            front
        }
    }

    /// Linear momentum of bike and rider (N·s). Over a step, gravity and the ground are
    /// the only outside forces, so its change along up is the ground's blow beyond what
    /// carries the weight: about zero riding along, a spike on landing.
    pub fn momentum(&self, world: &World) -> DVec3 {
        self.center_of_mass_velocity(world) * self.mass(world)
    }
}
