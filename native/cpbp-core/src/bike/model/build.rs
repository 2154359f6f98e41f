//! Building the bike and rider into a world: bodies at their rest poses, collision
//! shapes, and the joints that hold them together.

use glam::{DQuat, DVec3};

use super::{Bike, Part, PartShape, Placement, Shape, SuspensionJoints};
use crate::bike::controls::Controls;
use crate::bike::layout::Layout;
use crate::bike::params::{BikeParams, GRAVITY};
use crate::bike::suspension::{static_wheel_loads, Suspension};
use crate::ode::{BodyId, JointId, Mass, Spring, SurfaceParams, World};

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
            tyre_friction_follows_wheel: params.tyre_friction_follows_wheel,
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
        // Without suspension the lower legs are part of the fork and the swingarm part of
        // the frame (the thesis's bike): the same bodies in the same order as before the
        // suspension existed, so the classic physics rides exactly as it was evaluated.
        let sprung = params.suspension.is_some();
        let (fork, frame, fork_lower, swingarm) = if sprung {
            let fork = builder.fork(params.fork_mass, l.stanchion_bottom, l.fork_top, l.grip);
            let frame = builder.frame(params.frame_mass);
            let (axle, top) = (l.front_axle, l.fork_lower_top);
            let lower = builder.segment(Part::ForkLower, params.fork_lower_mass, 0.03, axle, top);
            let (pivot, axle) = (l.swingarm_pivot, l.rear_axle);
            let swingarm = builder.segment(Part::Swingarm, params.swingarm_mass, 0.03, pivot, axle);
            (fork, frame, lower, swingarm)
        } else {
            let fork_mass = params.fork_mass + params.fork_lower_mass;
            let fork = builder.fork(fork_mass, l.front_axle, l.fork_top, l.grip);
            let frame = builder.frame(params.frame_mass + params.swingarm_mass);
            let lower = builder.alias(fork, Part::Fork);
            let swingarm = builder.alias(frame, Part::Frame);
            (fork, frame, lower, swingarm)
        };
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
        let rear_axle = b.hinge(swingarm, rear, l.rear_axle, z);
        let front_axle = b.hinge(fork_lower, front, l.front_axle, z);
        let steer = b.hinge(fork, frame, l.steer_anchor, l.steer_axis);
        b.world
            .set_joint_limits(steer, 0, -params.steer_limit, params.steer_limit);
        let suspension_joints = params.suspension.as_ref().map(|_| {
            // The fork extends as the steered part rises along the steering axis relative
            // to the lower legs; the swingarm's angle grows as its rear end drops.
            let axis = b.placement.rotation * l.steer_axis;
            SuspensionJoints {
                fork_slider: b.world.add_slider(fork, Some(fork_lower), axis),
                swingarm_pivot: b.hinge(swingarm, frame, l.swingarm_pivot, z),
                swingarm_reach: l.swingarm_pivot.x - l.rear_axle.x,
            }
        });

        let ankle = b.ball(lower_leg, frame, l.ankle);
        let knee = b.hinge(upper_leg, lower_leg, l.knee, z);
        b.world.set_joint_limits(knee, 0, -1.0, 1.0);
        let (_, waist) = b.ball_with_motor(upper_leg, torso, l.hip, [0.7, 0.5, 0.4]);
        let (_, shoulder) = b.ball_with_motor(torso, upper_arm, l.shoulder, [1.0, 0.8, 0.6]);
        let elbow = b.hinge(upper_arm, lower_arm, l.elbow, z);
        b.world.set_joint_limits(elbow, 0, -1.0, 1.0);
        let (grip, wrist) = if params.rider_wrists_follow_bar {
            // The third axis on the fork's steering axis, with no stop: the bar turns
            // in the hand (`Bike::set_rider_motors` damps it there).
            let steer_axis = b.placement.rotation * l.steer_axis;
            b.ball_with_motor_about(lower_arm, fork, l.grip, steer_axis, &[0.8, 0.6])
        } else {
            b.ball_with_motor(lower_arm, fork, l.grip, [0.8, 0.6, 0.6])
        };

        if let (Some(s), Some(joints)) = (&params.suspension, &suspension_joints) {
            let (fork_spring, rear_spring) =
                suspension_springs(params, s, &l, &builder.rest, joints.swingarm_reach);
            builder.world.set_spring(joints.fork_slider, fork_spring);
            builder.world.set_spring(joints.swingarm_pivot, rear_spring);
        }
        // Last of the bike's geoms: up, they change nothing about how the others collide.
        let feet = params.feet.as_ref().map(|feet| {
            let frame_rest = builder.rest[Part::Frame as usize].0;
            feet.positions().map(|at| {
                let foot = builder.world.add_foot(feet.radius, frame, feet.surface);
                let offset = at - frame_rest;
                builder.world.set_geom_offset(foot, offset, DQuat::IDENTITY);
                if feet.reaching() {
                    builder
                        .world
                        .set_foot_leg(foot, offset, super::legs::LEG_DIRECTION);
                }
                foot
            })
        });
        let rest = builder.rest.try_into().expect("one rest pose per part");
        let bodies = [
            rear, front, fork, frame, fork_lower, swingarm, lower_leg, upper_leg, torso, upper_arm,
            lower_arm,
        ];
        let own_parts = Part::ALL
            .into_iter()
            .filter(|&part| !bodies[..part as usize].contains(&bodies[part as usize]))
            .collect();
        let bike = Self {
            params: params.clone(),
            bodies,
            rest,
            shapes: builder.shapes,
            steer,
            rear_axle,
            front_axle,
            suspension: suspension_joints,
            feet,
            own_parts,
            rider_holds: [ankle, grip, wrist],
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
    /// `BikeParams::tyre_friction_follows_wheel`, for the wheels' tyres.
    tyre_friction_follows_wheel: bool,
}

impl Builder<'_> {
    /// A body at a bike-frame pose.
    fn body(&mut self, mass: Mass, position: DVec3, rotation: DQuat) -> BodyId {
        let world_position = self.placement.transform_point(position);
        let body = self.world.add_body(mass, world_position);
        self.world
            .set_body_quaternion(body, self.placement.rotation * rotation);
        self.rest.push((position, rotation));
        body
    }

    /// A part without a body of its own, riding on `body` (the part `of`'s): it shares
    /// that part's rest pose.
    fn alias(&mut self, body: BodyId, of: Part) -> BodyId {
        self.rest.push(self.rest[of as usize]);
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
        let tyre = self.world.add_tyre(radius, crown, body);
        self.world
            .set_tyre_friction_follows_wheel(tyre, self.tyre_friction_follows_wheel);
        self.shape(part, Shape::Sphere { radius }, DVec3::ZERO, DQuat::IDENTITY);
        body
    }

    fn frame(&mut self, mass: f64) -> BodyId {
        // Mass as a box over engine, tank and seat; the collision box is the part that
        // scrapes the ground in a fall.
        let centre = DVec3::new(-0.05, 0.55, 0.0);
        let body = self.body(
            Mass::cuboid(mass, DVec3::new(1.05, 0.45, 0.30)),
            centre,
            DQuat::IDENTITY,
        );
        let size = DVec3::new(0.95, 0.28, 0.28);
        let offset = DVec3::new(0.0, 0.06, 0.0);
        let geom = self.world.add_box(size, Some(body));
        self.world.set_geom_offset(geom, offset, DQuat::IDENTITY);
        self.shape(Part::Frame, Shape::Cuboid { size }, offset, DQuat::IDENTITY);
        body
    }

    fn fork(&mut self, mass: f64, bottom: DVec3, top: DVec3, grip: DVec3) -> BodyId {
        let radius = 0.035;
        let body = self.segment(Part::Fork, mass, radius, bottom, top);
        // The handlebar: a bar across the bike at the grips.
        let (centre, rotation) = segment_pose(bottom, top);
        let size = DVec3::new(0.05, 0.05, 0.76);
        let offset = rotation.inverse() * (grip - centre);
        let bar_rotation = rotation.inverse();
        let geom = self.world.add_box(size, Some(body));
        self.world.set_geom_offset(geom, offset, bar_rotation);
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
        self.world.add_hinge(a, Some(b), anchor, axis)
    }

    fn ball(&mut self, a: BodyId, b: BodyId, anchor: DVec3) -> JointId {
        self.world
            .add_ball(a, Some(b), self.placement.transform_point(anchor))
    }

    /// A ball joint driven by an Euler motor: pitch about z (fixed to `a`), twist about
    /// the derived middle axis, roll about x (fixed to `b`), each limited to ±`limits`.
    /// Returns the ball and the motor.
    fn ball_with_motor(
        &mut self,
        a: BodyId,
        b: BodyId,
        anchor: DVec3,
        limits: [f64; 3],
    ) -> (JointId, JointId) {
        let axis2 = self.placement.rotation * DVec3::X;
        self.ball_with_motor_about(a, b, anchor, axis2, &limits)
    }

    /// A ball joint with an Euler motor whose first axis is the bike's lateral one (on
    /// `a`) and whose third is `axis2` (on `b`), each axis within ±its limit; axes past
    /// the end of `limits` turn freely.
    fn ball_with_motor_about(
        &mut self,
        a: BodyId,
        b: BodyId,
        anchor: DVec3,
        axis2: DVec3,
        limits: &[f64],
    ) -> (JointId, JointId) {
        let ball = self.ball(a, b, anchor);
        let axis0 = self.placement.rotation * DVec3::Z;
        let motor = self.world.add_euler_motor(a, b, axis0, axis2);
        for (axis, &limit) in limits.iter().enumerate() {
            self.world.set_joint_limits(motor, axis, -limit, limit);
        }
        (ball, motor)
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

/// Mass (kg) of each part, in `Part::ALL` order.
fn part_masses(params: &BikeParams) -> Vec<f64> {
    let [shank, thigh, torso, upper_arm, forearm] = params.rider_masses;
    Part::ALL
        .iter()
        .map(|part| match part {
            Part::RearWheel => params.rear_wheel_mass,
            Part::FrontWheel => params.front_wheel_mass,
            Part::Fork => params.fork_mass,
            Part::Frame => params.frame_mass,
            Part::ForkLower => params.fork_lower_mass,
            Part::Swingarm => params.swingarm_mass,
            Part::LowerLeg => shank,
            Part::UpperLeg => thigh,
            Part::Torso => torso,
            Part::UpperArm => upper_arm,
            Part::LowerArm => forearm,
        })
        .collect()
}

/// The fork's and the swingarm's springs: rates, damping and travel from the suspension
/// parameters, each preloaded so that it carries its end's share of bike and rider at the
/// built pose, which is the pose at sag.
fn suspension_springs(
    params: &BikeParams,
    s: &Suspension,
    l: &Layout,
    rest: &[(DVec3, DQuat)],
    reach: f64,
) -> (Spring, Spring) {
    let masses = part_masses(params);
    let total: f64 = masses.iter().sum();
    let com = rest
        .iter()
        .zip(&masses)
        .fold(DVec3::ZERO, |sum, ((p, _), m)| sum + *p * *m)
        / total;
    let (rear_load, front_load) =
        static_wheel_loads(com, l.rear_axle.x, l.front_axle.x, total * GRAVITY);
    // Front: what the tyre carries less the unsprung lower legs and wheel, along the tubes.
    let front_unsprung = params.front_wheel_mass + params.fork_lower_mass;
    let front_force = (front_load - front_unsprung * GRAVITY) * params.rake.cos();
    let front_sprung_mass = front_load / GRAVITY - front_unsprung;
    let fork = Spring {
        stiffness: s.front_rate,
        damping: s.damping(s.front_rate, front_sprung_mass),
        free_position: front_force / s.front_rate,
        travel: s.front_travel_range(),
    };
    // Rear: torques about the pivot of the tyre's load against the weights of the wheel
    // at the axle and of the swingarm at its middle; rates at the wheel become rates
    // about the pivot through the lever squared.
    let rear_torque = (rear_load - params.rear_wheel_mass * GRAVITY) * reach
        - params.swingarm_mass * GRAVITY * reach / 2.0;
    let rear_unsprung = params.rear_wheel_mass + params.swingarm_mass / 2.0;
    let rate = s.rear_rate * reach * reach;
    let swingarm = Spring {
        stiffness: rate,
        damping: s.damping(s.rear_rate, rear_load / GRAVITY - rear_unsprung) * reach * reach,
        free_position: rear_torque / rate,
        travel: s.rear_travel_range(reach),
    };
    (fork, swingarm)
}

/// Centre and orientation (local z along a→b) of a segment between two points.
fn segment_pose(a: DVec3, b: DVec3) -> (DVec3, DQuat) {
    (
        (a + b) / 2.0,
        DQuat::from_rotation_arc(DVec3::Z, (b - a).normalize()),
    )
}
