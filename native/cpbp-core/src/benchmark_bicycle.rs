//! The benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007), "Linearized
//! dynamics equations for the balance and steer of a bicycle", built from the same ODE
//! bodies, hinges, torus tyres (with zero crown: knife-edge wheels) and contact surface as
//! the game's bike. Coasting it after a small roll kick and comparing the motion with the
//! paper's linear model says whether our physics rides like a bicycle the field agrees on
//! (`tools/bicycle_benchmark`, docs/physics.md).

use glam::{DMat3, DVec3};

use crate::bike::BikeParams;
use crate::ode::{BodyId, Gyroscopic, JointId, Mass, Solver, SurfaceParams, World};

/// The paper's Table 1, in its own frame: x forward, y to the right, z down, origin at the
/// rear wheel's contact; lengths in m, masses in kg, inertias in kg·m² about each body's
/// centre of mass. The rider is lumped into the rear frame.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchmarkParameters {
    /// Wheelbase.
    pub w: f64,
    /// Trail.
    pub c: f64,
    /// Steer axis tilt from vertical (rad).
    pub lam: f64,
    pub g: f64,
    /// Rear wheel radius, mass, in-plane and spin inertia.
    pub r_r: f64,
    pub m_r: f64,
    pub i_rxx: f64,
    pub i_ryy: f64,
    /// Rear frame and rider: centre of mass (x, z), mass, inertia (xx, yy, zz, xz).
    pub x_b: f64,
    pub z_b: f64,
    pub m_b: f64,
    pub i_b: [f64; 4],
    /// Front frame (fork and handlebar): centre of mass (x, z), mass, inertia.
    pub x_h: f64,
    pub z_h: f64,
    pub m_h: f64,
    pub i_h: [f64; 4],
    /// Front wheel radius, mass, in-plane and spin inertia.
    pub r_f: f64,
    pub m_f: f64,
    pub i_fxx: f64,
    pub i_fyy: f64,
}

impl Default for BenchmarkParameters {
    fn default() -> Self {
        Self {
            w: 1.02,
            c: 0.08,
            lam: std::f64::consts::PI / 10.0,
            g: 9.81,
            r_r: 0.3,
            m_r: 2.0,
            i_rxx: 0.0603,
            i_ryy: 0.12,
            x_b: 0.3,
            z_b: -0.9,
            m_b: 85.0,
            i_b: [9.2, 11.0, 2.8, 2.4],
            x_h: 0.9,
            z_h: -0.7,
            m_h: 4.0,
            i_h: [0.05892, 0.06, 0.00708, -0.00756],
            r_f: 0.35,
            m_f: 3.0,
            i_fxx: 0.1405,
            i_fyy: 0.28,
        }
    }
}

impl BenchmarkParameters {
    /// The parameters under the names the `bicycleparameters` package uses
    /// (`Meijaard2007ParameterSet`), so the Python oracle reads them from here.
    pub fn named(&self) -> Vec<(&'static str, f64)> {
        let [bxx, byy, bzz, bxz] = self.i_b;
        let [hxx, hyy, hzz, hxz] = self.i_h;
        vec![
            ("w", self.w),
            ("c", self.c),
            ("lam", self.lam),
            ("g", self.g),
            ("rR", self.r_r),
            ("mR", self.m_r),
            ("IRxx", self.i_rxx),
            ("IRyy", self.i_ryy),
            ("xB", self.x_b),
            ("zB", self.z_b),
            ("mB", self.m_b),
            ("IBxx", bxx),
            ("IByy", byy),
            ("IBzz", bzz),
            ("IBxz", bxz),
            ("xH", self.x_h),
            ("zH", self.z_h),
            ("mH", self.m_h),
            ("IHxx", hxx),
            ("IHyy", hyy),
            ("IHzz", hzz),
            ("IHxz", hxz),
            ("rF", self.r_f),
            ("mF", self.m_f),
            ("IFxx", self.i_fxx),
            ("IFyy", self.i_fyy),
        ]
    }
}

/// How to step the coast: the game rides 1/120 s steps, QuickStep with implicit
/// gyroscopics in the classic physics model, direct with explicit wheels in the exact one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoastConfig {
    /// Forward speed at the start (m/s).
    pub speed: f64,
    /// Roll rate of the kick at the start (rad/s, to the right).
    pub roll_rate: f64,
    /// Longest time to coast (s).
    pub duration: f64,
    /// ODE step (s).
    pub dt: f64,
    pub solver: Solver,
    /// How the wheels' gyroscopic torque is computed (`PhysicsModel::wheel_gyroscopic`).
    pub gyroscopic: Gyroscopic,
    /// The tyres' contact surface; the game's bike uses its tyre friction with ODE's
    /// default softness.
    pub surface: SurfaceParams,
    /// Stop once the roll exceeds this (rad): the linear model holds near upright only.
    pub max_roll: f64,
}

impl Default for CoastConfig {
    fn default() -> Self {
        Self {
            speed: 5.0,
            roll_rate: 0.05,
            duration: 8.0,
            dt: 1.0 / 120.0,
            solver: Solver::QuickStep,
            gyroscopic: Gyroscopic::Implicit,
            surface: SurfaceParams {
                mu: BikeParams::default().tyre_friction,
                ..SurfaceParams::default()
            },
            max_roll: 0.2,
        }
    }
}

/// What a coast recorded after every step, in the paper's sign convention (roll to the
/// right and steer to the right positive).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Coast {
    pub time: Vec<f64>,
    pub roll: Vec<f64>,
    pub steer: Vec<f64>,
    /// Forward speed of the rear frame (m/s): contacts may bleed some off.
    pub speed: Vec<f64>,
}

/// The bicycle built into a world on flat ground.
struct Bicycle {
    world: World,
    rear_frame: BodyId,
    steer: JointId,
    /// Each wheel's body and radius.
    wheels: [(BodyId, f64); 2],
}

/// From the paper's frame (x forward, y right, z down) to the game's (x forward, y up,
/// z right), a proper rotation.
fn to_game(v: DVec3) -> DVec3 {
    DVec3::new(v.x, -v.z, v.y)
}

/// An inertia tensor (xx, yy, zz, xz) of the paper's frame, in the game's frame.
fn inertia_to_game([xx, yy, zz, xz]: [f64; 4]) -> [[f64; 3]; 3] {
    let paper = DMat3::from_cols(
        DVec3::new(xx, 0.0, xz),
        DVec3::new(0.0, yy, 0.0),
        DVec3::new(xz, 0.0, zz),
    );
    let rotation = DMat3::from_cols(to_game(DVec3::X), to_game(DVec3::Y), to_game(DVec3::Z));
    let game = rotation * paper * rotation.transpose();
    [game.row(0).into(), game.row(1).into(), game.row(2).into()]
}

/// A wheel's inertia: in-plane `diametral` about x and y, `spin` about the axle (z).
fn wheel_inertia(diametral: f64, spin: f64) -> [[f64; 3]; 3] {
    [
        [diametral, 0.0, 0.0],
        [0.0, diametral, 0.0],
        [0.0, 0.0, spin],
    ]
}

fn mass(total: f64, inertia: [[f64; 3]; 3]) -> Mass {
    Mass::with_inertia(total, inertia).expect("the benchmark's inertias are physical")
}

impl Bicycle {
    fn build(p: &BenchmarkParameters, config: &CoastConfig) -> Self {
        let mut world = World::new(DVec3::new(0.0, -p.g, 0.0));
        world.set_solver(config.solver);
        world.set_surface(config.surface);
        world.add_plane(DVec3::Y, 0.0);
        let at = |x: f64, z: f64| to_game(DVec3::new(x, 0.0, z));
        let rear_axle = at(0.0, -p.r_r);
        let front_axle = at(p.w, -p.r_f);
        let rear_wheel = world.add_body(mass(p.m_r, wheel_inertia(p.i_rxx, p.i_ryy)), rear_axle);
        world.add_tyre(p.r_r, 0.0, rear_wheel);
        let rear_frame = world.add_body(mass(p.m_b, inertia_to_game(p.i_b)), at(p.x_b, p.z_b));
        let front_frame = world.add_body(mass(p.m_h, inertia_to_game(p.i_h)), at(p.x_h, p.z_h));
        let front_wheel = world.add_body(mass(p.m_f, wheel_inertia(p.i_fxx, p.i_fyy)), front_axle);
        world.add_tyre(p.r_f, 0.0, front_wheel);
        for wheel in [rear_wheel, front_wheel] {
            world.set_gyroscopic(wheel, config.gyroscopic);
        }

        let axle = DVec3::Z;
        world.add_hinge(rear_frame, Some(rear_wheel), rear_axle, axle);
        world.add_hinge(front_frame, Some(front_wheel), front_axle, axle);
        // The steer axis meets the ground one trail ahead of the front contact and tilts
        // back by λ; with the front frame as body 1 and the axis up, steering left is
        // positive, as on the game's bike.
        let steer_axis = to_game(DVec3::new(-p.lam.sin(), 0.0, -p.lam.cos()));
        let steer = world.add_hinge(
            front_frame,
            Some(rear_frame),
            at(p.w + p.c, 0.0),
            steer_axis,
        );
        Self {
            world,
            rear_frame,
            steer,
            wheels: [(rear_wheel, p.r_r), (front_wheel, p.r_f)],
        }
    }

    /// Every body moves forward at `speed` and rolls about the ground line at `roll_rate`
    /// (a rigid motion, so no joint or contact is violated); the wheels roll.
    fn launch(&mut self, speed: f64, roll_rate: f64) {
        // About the forward axis the top moves to the right (+z in the game).
        let roll = DVec3::X * roll_rate;
        for index in 0..self.world.body_count() {
            let body = BodyId(index);
            let position = self.world.body_position(body);
            let velocity = DVec3::X * speed + roll.cross(position);
            self.world.set_body_linear_velocity(body, velocity);
            // Rolling forward spins a wheel about −z.
            let spin = self
                .wheels
                .iter()
                .find(|(wheel, _)| *wheel == body)
                .map_or(0.0, |(_, radius)| -speed / radius);
            let angular = roll + DVec3::Z * spin;
            self.world.set_body_angular_velocity(body, angular);
        }
    }

    /// Roll of the rear frame to the right (rad).
    fn roll(&self) -> f64 {
        let right = self.world.body_quaternion(self.rear_frame) * DVec3::Z;
        (-right.y).clamp(-1.0, 1.0).asin()
    }
}

/// Coasts the benchmark bicycle from upright after a roll kick, with no steer torque,
/// until `config.duration` or until it leans past `config.max_roll`.
pub fn coast(parameters: &BenchmarkParameters, config: &CoastConfig) -> Coast {
    let mut bicycle = Bicycle::build(parameters, config);
    bicycle.launch(config.speed, config.roll_rate);
    let mut coast = Coast::default();
    let steps = (config.duration / config.dt).round() as usize;
    for step in 1..=steps {
        bicycle.world.step(config.dt);
        let roll = bicycle.roll();
        if !roll.is_finite() || roll.abs() > config.max_roll {
            break;
        }
        coast.time.push(step as f64 * config.dt);
        coast.roll.push(roll);
        // The game's steer angle is positive to the left; the paper's to the right.
        coast
            .steer
            .push(-bicycle.world.joint_angle(bicycle.steer, 0));
        coast
            .speed
            .push(bicycle.world.body_linear_velocity(bicycle.rear_frame)[0]);
    }
    coast
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bicycle_stands_on_its_wheels_and_coasts_straight_in_its_stable_band() {
        let parameters = BenchmarkParameters::default();
        let config = CoastConfig {
            speed: 5.0,
            duration: 3.0,
            dt: 1.0 / 1000.0,
            ..CoastConfig::default()
        };
        let coast = coast(&parameters, &config);
        assert_eq!(coast.time.len(), 3000, "it never leaned past 0.2 rad");
        let last = coast.roll.len() - 1;
        assert!(coast.roll[last].abs() < 0.01, "roll {}", coast.roll[last]);
        assert!(
            (coast.speed[last] - 5.0).abs() < 0.05,
            "speed {}",
            coast.speed[last]
        );
    }

    #[test]
    fn a_slow_bicycle_falls_over() {
        let config = CoastConfig {
            speed: 2.0,
            ..CoastConfig::default()
        };
        let coast = coast(&BenchmarkParameters::default(), &config);
        assert!(
            *coast.time.last().unwrap() < 3.0,
            "it leaned past 0.2 rad soon"
        );
    }

    #[test]
    fn the_inertias_turn_into_the_games_frame() {
        // x stays forward; the paper's y (right) is the game's z and its z (down) is −y.
        let i = inertia_to_game([9.2, 11.0, 2.8, 2.4]);
        assert_eq!(i, [[9.2, -2.4, 0.0], [-2.4, 2.8, 0.0], [0.0, 0.0, 11.0]]);
    }
}
