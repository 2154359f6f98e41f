//! Builds the bike and rider into an ODE world and reads back what the game and the
//! controllers need: transforms, speed, lean, steering, contacts, crash.

mod build;
mod contact_patch;
mod control_period;
mod drive;
mod falling_off;
mod ground;
mod legs;
mod rider;

pub use control_period::{Exploded, PeriodWatch};
pub use ground::FootState;

use glam::{DQuat, DVec3};

use crate::bike::controls::{index, Controls, ForceClass, MAX_TORQUE};
use crate::bike::params::BikeParams;
use crate::bike::wheelie_control::PitchRequest;
use crate::ode::{BodyId, GeomId, JointId, World};

/// Number of rigid bodies of bike and rider.
pub const PARTS: usize = 11;

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

/// The rigid bodies, in body order; the rider's come last.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    RearWheel,
    FrontWheel,
    /// The steered fork above the sliders, with the handlebar.
    Fork,
    Frame,
    /// The fork's lower legs, sliding on the fork along the steering axis.
    ForkLower,
    /// Pivots on the frame and carries the rear wheel.
    Swingarm,
    LowerLeg,
    UpperLeg,
    Torso,
    UpperArm,
    LowerArm,
}

impl Part {
    pub const ALL: [Part; PARTS] = [
        Part::RearWheel,
        Part::FrontWheel,
        Part::Fork,
        Part::Frame,
        Part::ForkLower,
        Part::Swingarm,
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
            Part::ForkLower => "fork_lower",
            Part::Swingarm => "swingarm",
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

/// The fork's slider (extension positive, m) and the swingarm's pivot (rad), with how far
/// behind the pivot the rear axle is (m): the swingarm's lever.
#[derive(Clone, Copy, Debug)]
struct SuspensionJoints {
    fork_slider: JointId,
    swingarm_pivot: JointId,
    swingarm_reach: f64,
}

/// A built bike: the handles of its bodies and joints in one world. Every world built
/// with the same parameters gets the same handles, so one `Bike` describes them all.
#[derive(Clone, Debug)]
pub struct Bike {
    params: BikeParams,
    bodies: [BodyId; PARTS],
    /// Body poses as built, in the bike frame (for reset).
    rest: [(DVec3, DQuat); PARTS],
    shapes: Vec<PartShape>,
    steer: JointId,
    rear_axle: JointId,
    front_axle: JointId,
    /// The suspension's joints; none on a rigid bike.
    suspension: Option<SuspensionJoints>,
    /// The rider's feet (left, right), if the bike has them (`BikeParams::feet`).
    feet: Option<[GeomId; 2]>,
    /// The parts with a body of their own, found once at build: the centre of mass, which
    /// every rollout step's cost reads, sums over them.
    own_parts: Vec<Part>,
    /// What holds the rider on: the foot on the peg, the hand on the grip and the wrist's
    /// motor. Switched off when the rider falls off (`release_rider`).
    rider_holds: [JointId; 3],
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

    /// Sets every joint motor from a control vector, no pitch asked for.
    pub fn apply(&self, world: &mut World, controls: &Controls) {
        self.apply_pitching(world, controls, PitchRequest::default(), up_y());
    }

    /// Sets every joint motor from a control vector while the rider's weight asks for a
    /// pitch (`held`, as `held_pitch` gives it; `up` is against gravity): driving with a
    /// wheelie asked for, the wheelie control holds the rider's weight over the lifted
    /// support point instead of keeping the front down; in the air it spins the rear
    /// wheel up or brakes it to turn the nose.
    pub fn apply_pitching(
        &self,
        world: &mut World,
        controls: &Controls,
        held: PitchRequest,
        up: DVec3,
    ) {
        // Standing on a foot the rider sits still, whatever the controller asks
        // (`Feet::straighten_rate`); the planners' rollouts step the same rule.
        let sitting_still;
        let controls = if self.place_feet(world, controls, up) {
            sitting_still = self.sitting_still(world, controls);
            &sitting_still
        } else {
            controls
        };
        let c = controls.values();
        // The controls' steering tuning scales the rider's own strength at the bar
        // (`BikeParams::max_steer_torque`; 60/60 = 1 exactly on the reference bike).
        let rider_share = self.params.max_steer_torque / MAX_TORQUE[ForceClass::Steering as usize];
        world.set_motor(
            self.steer,
            0,
            c[index::STEER],
            controls.max_torque(ForceClass::Steering) * rider_share,
        );
        self.set_rear_motor(world, controls, held, up);
        self.set_front_brake(world, controls, held, up, 0.0);
        self.set_rider_motors(world, controls, held);
    }

    /// Puts every body back in its built pose at `placement`, at rest.
    pub fn reset(&self, world: &mut World, placement: &Placement) {
        for part in self.own_parts() {
            let (body, (position, rotation)) = (self.body(part), self.rest[part as usize]);
            world.set_body_position(body, placement.transform_point(position));
            world.set_body_quaternion(body, placement.rotation * rotation);
            world.set_body_linear_velocity(body, DVec3::ZERO);
            world.set_body_angular_velocity(body, DVec3::ZERO);
        }
    }

    /// How far each end has compressed from full extension (m; the rear measured at the
    /// wheel): front, rear. Sag at rest with the rider aboard; the travel when bottomed.
    /// Zero on a rigid bike.
    pub fn suspension_compression(&self, world: &World) -> (f64, f64) {
        let (Some(s), Some(joints)) = (&self.params.suspension, &self.suspension) else {
            return (0.0, 0.0);
        };
        let reach = joints.swingarm_reach;
        let (_, rear_top) = s.rear_travel_range(reach);
        let rear = (rear_top - world.joint_position(joints.swingarm_pivot)) * reach;
        (self.fork_compression(world), rear)
    }

    /// How far the fork has compressed from full extension (m); zero on a rigid bike. The
    /// anti-wheelie reads it every control step, so it reads the fork alone.
    pub fn fork_compression(&self, world: &World) -> f64 {
        let (Some(s), Some(joints)) = (&self.params.suspension, &self.suspension) else {
            return 0.0;
        };
        let (_, front_top) = s.front_travel_range();
        front_top - world.joint_position(joints.fork_slider)
    }

    /// The parts with a body of their own, in body order (on a rigid bike the fork's
    /// lower legs and the swingarm ride on the fork and the frame).
    pub fn own_parts(&self) -> impl Iterator<Item = Part> + '_ {
        self.own_parts.iter().copied()
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
        world.body_quaternion(self.body(Part::Frame))
    }

    /// Mass-weighted centre of all bodies.
    pub fn center_of_mass(&self, world: &World) -> DVec3 {
        self.mass_weighted(world, |b| world.body_position(b))
    }

    /// Bike and rider's mass (kg): the bodies of the parts that have their own.
    pub fn mass(&self, world: &World) -> f64 {
        self.own_parts()
            .map(|part| world.body_mass(self.body(part)))
            .sum()
    }

    /// Mass-weighted velocity of all bodies: only external forces change it.
    pub fn center_of_mass_velocity(&self, world: &World) -> DVec3 {
        self.mass_weighted(world, |b| world.body_linear_velocity(b))
    }

    /// The mass-weighted mean of a per-body vector.
    fn mass_weighted(&self, world: &World, of: impl Fn(BodyId) -> DVec3) -> DVec3 {
        let (sum, mass) = self.own_parts().map(|part| self.body(part)).fold(
            (DVec3::ZERO, 0.0),
            |(sum, mass), b| {
                let m = world.body_mass(b);
                (sum + of(b) * m, mass + m)
            },
        );
        sum / mass
    }

    /// Forward speed (m/s) along the frame's heading projected on the ground plane
    /// (`up` is the world's up, against gravity).
    pub fn forward_speed(&self, world: &World, up: DVec3) -> f64 {
        let velocity = world.body_linear_velocity(self.body(Part::Frame));
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
        let spin = world.body_angular_velocity(self.body(Part::Frame));
        // Tipping up towards right (= heading × up) is a turn about up × right = heading.
        spin.dot(self.heading(world, up))
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
            if state.iter().any(|v| !v.is_finite()) {
                return Some(format!("{} has a non-finite state", part.name()));
            }
            let speed = state[1].length();
            let spin = state[2].length();
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

fn up_y() -> DVec3 {
    DVec3::Y
}
