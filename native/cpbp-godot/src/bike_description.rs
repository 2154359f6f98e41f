//! `BikeDescription`: a bike as data, a resource file a level designer or a modder
//! edits in the inspector (bikes/*.tres). `BikeSimulation.bike` takes one; a second bike
//! is a second file. Its defaults are the core's reference bike (`BikeParams::default()`).
//! Its looks (paint, bodywork) are the drawing's alone: the core never sees them.

use cpbp_core::bike::BikeParams;
use godot::classes::{IResource, Resource};
use godot::prelude::*;

/// The reference bike's paint.
const STREET_ORANGE: Color = Color::from_rgb(0.92, 0.35, 0.08);

/// Dimensions, masses and equipment of a bike and its rider.
#[derive(GodotClass)]
#[class(base=Resource)]
pub struct BikeDescription {
    /// The bike's name, for people: messages about the bike name it by this.
    #[export]
    name: GString,
    /// Distance between the wheels' ground contact points (m).
    #[export(range = (0.9, 2.0, 0.01, suffix = "m"))]
    wheelbase: f64,
    /// Wheel radius, tyre included (m).
    #[export(range = (0.15, 0.5, 0.005, suffix = "m"))]
    wheel_radius: f64,
    /// Radius of the tyre's round cross-section (m): where a leaning wheel touches.
    #[export(range = (0.02, 0.12, 0.005, suffix = "m"))]
    tyre_crown: f64,
    /// Angle of the steering axis from vertical.
    #[export(range = (10.0, 40.0, 0.5, suffix = "°"))]
    rake_deg: f64,
    /// Ground distance from the front contact back to the steering axis (m).
    #[export(range = (0.0, 0.2, 0.005, suffix = "m"))]
    trail: f64,
    /// Frame with engine and tank (kg).
    #[export(range = (20.0, 300.0, 1.0, suffix = "kg"))]
    frame_mass: f64,
    /// Rear wheel with tyre and disc (kg).
    #[export(range = (2.0, 40.0, 0.5, suffix = "kg"))]
    rear_wheel_mass: f64,
    /// Front wheel with tyre and disc (kg).
    #[export(range = (2.0, 40.0, 0.5, suffix = "kg"))]
    front_wheel_mass: f64,
    /// Largest steering angle either way.
    #[export(range = (10.0, 60.0, 1.0, suffix = "°"))]
    steer_limit_deg: f64,
    /// Coulomb friction of the tyres on the ground.
    #[export(range = (0.3, 1.5, 0.05))]
    tyre_friction: f64,
    /// Springs and dampers at the fork and the swingarm (off: the thesis's rigid bike,
    /// which then has no anti-wheelie, feet or front brake either).
    #[export]
    suspension: bool,
    /// The colour of the tank and the bodywork.
    #[export]
    paint: Color,
    /// The bodywork drawn on the frame (a `BikeBodywork` resource, fitted to this bike's
    /// size); none draws the standard naked bodywork.
    #[export]
    bodywork: Option<Gd<Resource>>,
    base: Base<Resource>,
}

#[godot_api]
impl IResource for BikeDescription {
    fn init(base: Base<Resource>) -> Self {
        let reference = BikeParams::default();
        Self {
            name: GString::from("Street 350"),
            wheelbase: reference.wheelbase,
            wheel_radius: reference.wheel_radius,
            tyre_crown: reference.tyre_crown,
            rake_deg: reference.rake.to_degrees(),
            trail: reference.trail,
            frame_mass: reference.frame_mass,
            rear_wheel_mass: reference.rear_wheel_mass,
            front_wheel_mass: reference.front_wheel_mass,
            steer_limit_deg: reference.steer_limit.to_degrees(),
            tyre_friction: reference.tyre_friction,
            suspension: reference.suspension.is_some(),
            paint: STREET_ORANGE,
            bodywork: None,
            base,
        }
    }
}

impl BikeDescription {
    /// The bike as the core builds it, or why it cannot be built (a value that is not a
    /// number, or a geometry with no steering axis between the wheels).
    pub fn params(&self) -> Result<BikeParams, String> {
        let numbers = [
            ("wheelbase", self.wheelbase),
            ("wheel_radius", self.wheel_radius),
            ("tyre_crown", self.tyre_crown),
            ("rake_deg", self.rake_deg),
            ("trail", self.trail),
            ("frame_mass", self.frame_mass),
            ("rear_wheel_mass", self.rear_wheel_mass),
            ("front_wheel_mass", self.front_wheel_mass),
            ("steer_limit_deg", self.steer_limit_deg),
            ("tyre_friction", self.tyre_friction),
        ];
        if let Some((name, value)) = numbers.iter().find(|(_, v)| !v.is_finite() || *v <= 0.0) {
            return Err(format!("{name} must be a positive number, not {value}"));
        }
        if self.tyre_crown >= self.wheel_radius {
            return Err("tyre_crown must be smaller than wheel_radius".into());
        }
        let reference = BikeParams::default();
        let bike = BikeParams {
            wheelbase: self.wheelbase,
            wheel_radius: self.wheel_radius,
            tyre_crown: self.tyre_crown,
            rake: self.rake_deg.to_radians(),
            trail: self.trail,
            frame_mass: self.frame_mass,
            rear_wheel_mass: self.rear_wheel_mass,
            front_wheel_mass: self.front_wheel_mass,
            steer_limit: self.steer_limit_deg.to_radians(),
            tyre_friction: self.tyre_friction,
            ..reference
        };
        Ok(if self.suspension { bike } else { bike.rigid() })
    }
}

/// The bike `description` describes (the reference bike for none), or why it cannot be
/// built, naming its file.
pub fn params_of(description: Option<&Gd<BikeDescription>>) -> Result<BikeParams, String> {
    match description {
        Some(description) => description
            .bind()
            .params()
            .map_err(|why| format!("the bike {}: {why}", description.get_path())),
        None => Ok(BikeParams::default()),
    }
}
