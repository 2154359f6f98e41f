//! Building the bike and rider into a world: bodies at their rest poses, collision
//! shapes, and the joints that hold them together.

use glam::{DQuat, DVec3};

use super::{to_array, to_quat, Bike, Part, PartShape, Placement, Shape};
use crate::bike::controls::Controls;
use crate::bike::layout::Layout;
use crate::bike::params::BikeParams;
use crate::ode::{BodyId, JointId, Mass, SurfaceParams, World};

impl Bike {
    /// Builds bike and rider into `world` at `placement`, at rest.
    pub fn build(world: &mut World, params: &BikeParams, placement: &Placement) -> Self {
        let l = Layout::new(params);
        world.set_surface(SurfaceParams {
            mu: params.tyre_friction,
            ..SurfaceParams::default()
        });
        let mut builder = Builder {
            world,
            placement: *placement,
            rest: Vec::new(),
            shapes: Vec::new(),
        };
        let (r, crown) = (params.wheel_radius, params.tyre_crown);
        let rear = builder.wheel(
            Part::RearWheel,
            params.rear_wheel_mass,
            r,
            crown,
            0.13,
            l.rear_axle,
        );
        let front = builder.wheel(
            Part::FrontWheel,
            params.front_wheel_mass,
            r,
            crown,
            0.11,
            l.front_axle,
        );
        let fork = builder.fork(params.fork_mass, l.front_axle, l.fork_top, l.grip);
        let frame = builder.frame(params.frame_mass);
        let [m_shank, m_thigh, m_torso, m_upper_arm, m_forearm] = params.rider_masses;
        let lower_leg = builder.segment(Part::LowerLeg, m_shank, 0.055, l.ankle, l.knee);
        let upper_leg = builder.segment(Part::UpperLeg, m_thigh, 0.075, l.knee, l.hip);
        let torso = builder.segment(Part::Torso, m_torso, 0.14, l.hip, l.head_top);
        let upper_arm = builder.segment(Part::UpperArm, m_upper_arm, 0.045, l.shoulder, l.elbow);
        let lower_arm = builder.segment(Part::LowerArm, m_forearm, 0.04, l.elbow, l.grip);

        let b = &mut builder;
        // ODE's hinge angle and rate are body 1's rotation relative to body 2 about the
        // axis. A wheel rolling forward spins about −z, so with the frame (or fork) as
        // body 1 and axis +z, forward rolling is positive; with the fork as body 1 and
        // the axis pointing up, steering left is positive.
        let z = DVec3::Z;
        let rear_axle = b.hinge(frame, rear, l.rear_axle, z);
        b.hinge(fork, front, l.front_axle, z);
        let steer = b.hinge(fork, frame, l.steer_anchor, l.steer_axis);
        b.world
            .set_joint_limits(steer, 0, -params.steer_limit, params.steer_limit);

        b.ball(lower_leg, frame, l.ankle);
        let knee = b.hinge(upper_leg, lower_leg, l.knee, z);
        b.world.set_joint_limits(knee, 0, -1.0, 1.0);
        let waist = b.ball_with_motor(upper_leg, torso, l.hip, [0.7, 0.5, 0.4]);
        let shoulder = b.ball_with_motor(torso, upper_arm, l.shoulder, [1.0, 0.8, 0.6]);
        let elbow = b.hinge(upper_arm, lower_arm, l.elbow, z);
        b.world.set_joint_limits(elbow, 0, -1.0, 1.0);
        let wrist = b.ball_with_motor(lower_arm, fork, l.grip, [0.8, 0.6, 0.6]);

        let rest = builder.rest.try_into().expect("nine bodies");
        let bike = Self {
            params: params.clone(),
            bodies: [
                rear, front, fork, frame, lower_leg, upper_leg, torso, upper_arm, lower_arm,
            ],
            rest,
            shapes: builder.shapes,
            steer,
            rear_axle,
            waist,
            knee,
            shoulder,
            elbow,
            wrist,
            arm_strength: 1.0,
        };
        bike.apply(world, &Controls::default());
        bike
    }
}

struct Builder<'w> {
    world: &'w mut World,
    placement: Placement,
    rest: Vec<(DVec3, DQuat)>,
    shapes: Vec<PartShape>,
}

impl Builder<'_> {
    /// A body at a bike-frame pose.
    fn body(&mut self, mass: Mass, position: DVec3, rotation: DQuat) -> BodyId {
        let world_position = self.placement.transform_point(position);
        let body = self.world.add_body(mass, to_array(world_position));
        self.world
            .set_body_quaternion(body, to_quat(self.placement.rotation * rotation));
        self.rest.push((position, rotation));
        body
    }

    fn wheel(
        &mut self,
        part: Part,
        mass: f64,
        radius: f64,
        crown: f64,
        width: f64,
        axle: DVec3,
    ) -> BodyId {
        // Inertia of a disc about the axle (z); contact through a torus tyre, so a leaning
        // wheel touches the road in its own plane, offset by the crown's roundness only.
        let body = self.body(
            Mass::cylinder(mass, 2, radius, width),
            axle,
            DQuat::IDENTITY,
        );
        self.world.add_tyre(radius, crown, body);
        self.shape(part, Shape::Sphere { radius }, DVec3::ZERO, DQuat::IDENTITY);
        body
    }

    fn frame(&mut self, mass: f64) -> BodyId {
        // Mass as a box over engine, tank and seat; the collision box is the part that
        // scrapes the ground in a fall.
        let centre = DVec3::new(-0.05, 0.55, 0.0);
        let body = self.body(
            Mass::cuboid(mass, [1.05, 0.45, 0.30]),
            centre,
            DQuat::IDENTITY,
        );
        let size = DVec3::new(0.95, 0.28, 0.28);
        let offset = DVec3::new(0.0, 0.06, 0.0);
        let geom = self.world.add_box(to_array(size), Some(body));
        self.world
            .set_geom_offset(geom, to_array(offset), to_quat(DQuat::IDENTITY));
        self.shape(Part::Frame, Shape::Cuboid { size }, offset, DQuat::IDENTITY);
        body
    }

    fn fork(&mut self, mass: f64, axle: DVec3, top: DVec3, grip: DVec3) -> BodyId {
        let radius = 0.035;
        let body = self.segment(Part::Fork, mass, radius, axle, top);
        // The handlebar: a bar across the bike at the grips.
        let (centre, rotation) = segment_pose(axle, top);
        let size = DVec3::new(0.05, 0.05, 0.76);
        let offset = rotation.inverse() * (grip - centre);
        let bar_rotation = rotation.inverse();
        let geom = self.world.add_box(to_array(size), Some(body));
        self.world
            .set_geom_offset(geom, to_array(offset), to_quat(bar_rotation));
        self.shape(Part::Fork, Shape::Cuboid { size }, offset, bar_rotation);
        body
    }

    /// A capsule body from `a` to `b` (joint centres), its caps reaching the joints.
    fn segment(&mut self, part: Part, mass: f64, radius: f64, a: DVec3, b: DVec3) -> BodyId {
        let (centre, rotation) = segment_pose(a, b);
        let length = ((b - a).length() - radius).max(0.01);
        let body = self.body(Mass::capsule(mass, radius, length), centre, rotation);
        self.world.add_capsule(radius, length, Some(body));
        self.shape(
            part,
            Shape::Capsule { radius, length },
            DVec3::ZERO,
            DQuat::IDENTITY,
        );
        body
    }

    fn hinge(&mut self, a: BodyId, b: BodyId, anchor: DVec3, axis: DVec3) -> JointId {
        let anchor = self.placement.transform_point(anchor);
        let axis = self.placement.rotation * axis;
        self.world
            .add_hinge(a, Some(b), to_array(anchor), to_array(axis))
    }

    fn ball(&mut self, a: BodyId, b: BodyId, anchor: DVec3) {
        self.world
            .add_ball(a, Some(b), to_array(self.placement.transform_point(anchor)));
    }

    /// A ball joint driven by an Euler motor: pitch about z (fixed to `a`), twist about
    /// the derived middle axis, roll about x (fixed to `b`), each limited to ±`limits`.
    fn ball_with_motor(
        &mut self,
        a: BodyId,
        b: BodyId,
        anchor: DVec3,
        limits: [f64; 3],
    ) -> JointId {
        self.ball(a, b, anchor);
        let axis0 = self.placement.rotation * DVec3::Z;
        let axis2 = self.placement.rotation * DVec3::X;
        let motor = self
            .world
            .add_euler_motor(a, b, to_array(axis0), to_array(axis2));
        for (axis, limit) in limits.into_iter().enumerate() {
            self.world.set_joint_limits(motor, axis, -limit, limit);
        }
        motor
    }

    fn shape(&mut self, part: Part, shape: Shape, offset: DVec3, rotation: DQuat) {
        self.shapes.push(PartShape {
            part,
            shape,
            offset,
            rotation,
        });
    }
}

/// Centre and orientation (local z along a→b) of a segment between two points.
fn segment_pose(a: DVec3, b: DVec3) -> (DVec3, DQuat) {
    (
        (a + b) / 2.0,
        DQuat::from_rotation_arc(DVec3::Z, (b - a).normalize()),
    )
}
