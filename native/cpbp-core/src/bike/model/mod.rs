//! Builds the bike and rider into an ODE world and reads back what the game and the
//! controllers need: transforms, speed, lean, steering, contacts, crash.

mod build;

use glam::{DQuat, DVec3};

use crate::bike::controls::{index, Controls, ForceClass};
use crate::bike::params::BikeParams;
use crate::bike::rider_position::RIDER_JOINTS;
use crate::ode::{BodyId, JointId, World};

/// Rigid placement of the bike frame in the world: rotation then translation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub position: DVec3,
    pub rotation: DQuat,
}

impl Placement {
    /// Bike frame at the world origin, facing world +x.
    pub const IDENTITY: Self = Self {
        position: DVec3::ZERO,
        rotation: DQuat::IDENTITY,
    };

    pub fn transform_point(&self, p: DVec3) -> DVec3 {
        self.position + self.rotation * p
    }
}

/// The nine rigid bodies, in body order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    RearWheel,
    FrontWheel,
    Fork,
    Frame,
    LowerLeg,
    UpperLeg,
    Torso,
    UpperArm,
    LowerArm,
}

impl Part {
    pub const ALL: [Part; 9] = [
        Part::RearWheel,
        Part::FrontWheel,
        Part::Fork,
        Part::Frame,
        Part::LowerLeg,
        Part::UpperLeg,
        Part::Torso,
        Part::UpperArm,
        Part::LowerArm,
    ];

    /// Wheels may touch the ground; any other part touching it is a crash.
    pub fn is_wheel(self) -> bool {
        matches!(self, Part::RearWheel | Part::FrontWheel)
    }

    pub fn name(self) -> &'static str {
        match self {
            Part::RearWheel => "rear_wheel",
            Part::FrontWheel => "front_wheel",
            Part::Fork => "fork",
            Part::Frame => "frame",
            Part::LowerLeg => "lower_leg",
            Part::UpperLeg => "upper_leg",
            Part::Torso => "torso",
            Part::UpperArm => "upper_arm",
            Part::LowerArm => "lower_arm",
        }
    }
}

/// A collision shape of a part, in that part's body frame (for drawing the physical model).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        radius: f64,
    },
    Cuboid {
        size: DVec3,
    },
    /// Along the local z axis; `length` excludes the caps.
    Capsule {
        radius: f64,
        length: f64,
    },
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartShape {
    pub part: Part,
    pub shape: Shape,
    pub offset: DVec3,
    pub rotation: DQuat,
}

/// A built bike: the handles of its bodies and joints in one world. Every world built
/// with the same parameters gets the same handles, so one `Bike` describes them all.
#[derive(Clone, Debug)]
pub struct Bike {
    params: BikeParams,
    bodies: [BodyId; 9],
    /// Body poses as built, in the bike frame (for reset).
    rest: [(DVec3, DQuat); 9],
    shapes: Vec<PartShape>,
    steer: JointId,
    rear_axle: JointId,
    waist: JointId,
    knee: JointId,
    shoulder: JointId,
    elbow: JointId,
    wrist: JointId,
    /// The arms' torque limit as a fraction of `MAX_TORQUE` (`PhysicsModel::arm_strength`).
    arm_strength: f64,
}

impl Bike {
    /// The same bike with the rider's arms at `strength` × their full torque.
    pub fn with_arm_strength(mut self, strength: f64) -> Self {
        self.arm_strength = strength;
        self
    }

    pub fn params(&self) -> &BikeParams {
        &self.params
    }

    pub fn body(&self, part: Part) -> BodyId {
        self.bodies[part as usize]
    }

    /// Collision shapes of every part, in body frames.
    pub fn shapes(&self) -> &[PartShape] {
        &self.shapes
    }

    /// Sets every joint motor from a control vector.
    pub fn apply(&self, world: &mut World, controls: &Controls) {
        let c = controls.values();
        world.set_motor(
            self.steer,
            0,
            c[index::STEER],
            controls.max_torque(ForceClass::Steering),
        );
        world.set_motor(
            self.rear_axle,
            0,
            c[index::REAR_WHEEL],
            controls.max_torque(ForceClass::RearWheel),
        );
        let waist = controls.max_torque(ForceClass::Waist);
        let arms = controls.max_torque(ForceClass::Arms) * self.arm_strength;
        for axis in 0..3 {
            world.set_motor(self.waist, axis, c[index::WAIST + axis], waist);
            world.set_motor(self.shoulder, axis, c[index::SHOULDER + axis], arms);
            world.set_motor(self.wrist, axis, c[index::WRIST + axis], arms);
        }
        world.set_motor(
            self.knee,
            0,
            c[index::KNEE],
            controls.max_torque(ForceClass::Knee),
        );
        world.set_motor(self.elbow, 0, c[index::ELBOW], arms);
    }

    /// Puts every body back in its built pose at `placement`, at rest.
    pub fn reset(&self, world: &mut World, placement: &Placement) {
        for (body, (position, rotation)) in self.bodies.iter().zip(&self.rest) {
            world.set_body_position(*body, to_array(placement.transform_point(*position)));
            world.set_body_quaternion(*body, to_quat(placement.rotation * *rotation));
            world.set_body_linear_velocity(*body, [0.0; 3]);
            world.set_body_angular_velocity(*body, [0.0; 3]);
        }
    }

    /// Angles of the rider's joint axes that have motors, in control order after the
    /// rear wheel (waist ×3, knee, shoulder ×3, elbow, wrist ×3); 0 in the riding pose.
    pub fn rider_joint_angles(&self, world: &World) -> [f64; RIDER_JOINTS] {
        let mut angles = [0.0; RIDER_JOINTS];
        for axis in 0..3 {
            angles[axis] = world.joint_angle(self.waist, axis);
            angles[4 + axis] = world.joint_angle(self.shoulder, axis);
            angles[8 + axis] = world.joint_angle(self.wrist, axis);
        }
        angles[3] = world.joint_angle(self.knee, 0);
        angles[7] = world.joint_angle(self.elbow, 0);
        angles
    }

    /// Velocity targets that bring every rider joint back to the riding pose: a velocity
    /// servo (`gain` 1/s) on each joint angle, within the control bounds. The pose prior
    /// of the optimizer and the arcade controller's pose hold both start from this.
    pub fn pose_hold(&self, world: &World, gain: f64, controls: &mut Controls) {
        self.pose_hold_at(world, gain, &[0.0; RIDER_JOINTS], controls);
    }

    /// The same servo towards the riding pose offset by `pose` (rad per rider joint, as
    /// `RiderPosition::pose` gives it).
    pub fn pose_hold_at(
        &self,
        world: &World,
        gain: f64,
        pose: &[f64; RIDER_JOINTS],
        controls: &mut Controls,
    ) {
        for (i, angle) in self.rider_joint_angles(world).into_iter().enumerate() {
            controls.set(index::WAIST + i, -gain * (angle - pose[i]));
        }
    }

    /// Where the rider's centre of mass is relative to where the riding pose has it, in
    /// the frame's axes (x forward, y up, z right; m): the weight shift the player asks
    /// for with `RiderPosition`.
    pub fn rider_offset(&self, world: &World) -> DVec3 {
        let rider = &Part::ALL[Part::LowerLeg as usize..];
        let (mut now, mut rest, mut mass) = (DVec3::ZERO, DVec3::ZERO, 0.0);
        for &part in rider {
            let m = world.body_mass(self.body(part));
            now += from_array(world.body_position(self.body(part))) * m;
            rest += self.rest[part as usize].0 * m;
            mass += m;
        }
        let frame = self.body(Part::Frame);
        let (frame_rest, frame_rest_rotation) = self.rest[Part::Frame as usize];
        let local = self.frame_rotation(world).inverse()
            * (now / mass - from_array(world.body_position(frame)));
        local - frame_rest_rotation.inverse() * (rest / mass - frame_rest)
    }

    /// Steering angle (rad, positive left) and its rate.
    pub fn steering(&self, world: &World) -> (f64, f64) {
        (
            world.joint_angle(self.steer, 0),
            world.hinge_rate(self.steer),
        )
    }

    /// Orientation of the frame (bike frame → world).
    pub fn frame_rotation(&self, world: &World) -> DQuat {
        from_quat(world.body_quaternion(self.body(Part::Frame)))
    }

    /// Mass-weighted centre of all bodies.
    pub fn center_of_mass(&self, world: &World) -> DVec3 {
        self.mass_weighted(world, |b| world.body_position(b))
    }

    /// Mass-weighted velocity of all bodies: only external forces change it.
    pub fn center_of_mass_velocity(&self, world: &World) -> DVec3 {
        self.mass_weighted(world, |b| world.body_linear_velocity(b))
    }

    /// The mass-weighted mean of a per-body vector.
    fn mass_weighted(&self, world: &World, of: impl Fn(BodyId) -> [f64; 3]) -> DVec3 {
        let (sum, mass) = self
            .bodies
            .iter()
            .fold((DVec3::ZERO, 0.0), |(sum, mass), &b| {
                let m = world.body_mass(b);
                (sum + from_array(of(b)) * m, mass + m)
            });
        sum / mass
    }

    /// Forward speed (m/s) along the frame's heading projected on the ground plane
    /// (`up` is the world's up, against gravity).
    pub fn forward_speed(&self, world: &World, up: DVec3) -> f64 {
        let velocity = from_array(world.body_linear_velocity(self.body(Part::Frame)));
        velocity.dot(self.heading(world, up))
    }

    /// Lean angle (rad) of the frame about its heading; positive leans to the right.
    pub fn lean(&self, world: &World, up: DVec3) -> f64 {
        let rotation = self.frame_rotation(world);
        let heading = self.heading(world, up);
        let right = heading.cross(up);
        let bike_up = rotation * DVec3::Y;
        bike_up.dot(right).atan2(bike_up.dot(up))
    }

    /// Lean rate (rad/s, positive when leaning further right): the frame's angular velocity
    /// about its heading. Exact, unlike a difference of two leans a step apart.
    pub fn lean_rate(&self, world: &World, up: DVec3) -> f64 {
        let spin = from_array(world.body_angular_velocity(self.body(Part::Frame)));
        // Tipping up towards right (= heading × up) is a turn about up × right = heading.
        spin.dot(self.heading(world, up))
    }

    /// Ground support point: midway between the two tyres' lowest points (torus tyres:
    /// each contact lies in its wheel's plane, a crown radius above the road).
    pub fn support_point(&self, world: &World, up: DVec3) -> DVec3 {
        let (r, crown) = (self.params.wheel_radius, self.params.tyre_crown);
        let contact = |part: Part| {
            let body = self.body(part);
            let centre = from_array(world.body_position(body));
            let axle = from_quat(world.body_quaternion(body)) * DVec3::Z;
            let down = -(up - axle * up.dot(axle)).normalize_or(up);
            centre + down * (r - crown) - up * crown
        };
        (contact(Part::RearWheel) + contact(Part::FrontWheel)) / 2.0
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

    /// Why the simulation can no longer be trusted, if it cannot: a non-finite number or a
    /// body moving faster than anything on a bike plausibly does.
    pub fn explosion(&self, world: &World) -> Option<String> {
        const MAX_SPEED: f64 = 150.0; // m/s
        const MAX_SPIN: f64 = 400.0; // rad/s; a wheel at 90 km/h spins at 83 rad/s
        for part in Part::ALL {
            let b = self.body(part);
            let state = [
                world.body_position(b),
                world.body_linear_velocity(b),
                world.body_angular_velocity(b),
            ];
            if state.iter().flatten().any(|v| !v.is_finite()) {
                return Some(format!("{} has a non-finite state", part.name()));
            }
            let speed = from_array(state[1]).length();
            let spin = from_array(state[2]).length();
            if speed > MAX_SPEED || spin > MAX_SPIN {
                return Some(format!(
                    "{} moves implausibly fast ({speed:.0} m/s, {spin:.0} rad/s)",
                    part.name()
                ));
            }
        }
        None
    }

    /// Unit heading: the frame's forward axis flattened onto the ground plane.
    pub fn heading(&self, world: &World, up: DVec3) -> DVec3 {
        let forward = self.frame_rotation(world) * DVec3::X;
        (forward - up * forward.dot(up)).normalize_or(forward)
    }
}

fn to_array(v: DVec3) -> [f64; 3] {
    v.to_array()
}

fn from_array(v: [f64; 3]) -> DVec3 {
    DVec3::from_array(v)
}

/// glam stores quaternions as x, y, z, w; ODE as w, x, y, z.
pub fn to_quat(q: DQuat) -> [f64; 4] {
    [q.w, q.x, q.y, q.z]
}

/// An ODE quaternion (w, x, y, z) as glam's.
pub fn from_quat(q: [f64; 4]) -> DQuat {
    DQuat::from_xyzw(q[1], q[2], q[3], q[0])
}
