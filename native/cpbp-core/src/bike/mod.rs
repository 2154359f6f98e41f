//! The motorcycle and its simplified rider (thesis §4.2): eleven rigid bodies (nine on
//! the thesis's rigid bike), hinges at the axles, steering axis, knee and elbow, motorised
//! ball joints at waist, shoulder and wrist, a passive ankle on the footpeg, a sprung fork
//! and swingarm, and a foot each side for standing still.

mod bike_file;
mod controls;
mod crash;
mod drive;
mod engine;
mod feet;
mod fields;
mod front_brake;
mod layout;
mod manual;
mod model;
mod params;
mod posture;
mod rider_position;
mod suspension;
mod wheelie_control;

pub use bike_file::{
    parse_bike_file, read_bike_file, take_bike_argument, BikeFile, REFERENCE_BIKE,
};
pub use controls::{
    index, Controls, ForceClass, CONTROL_DIM, DRIVE_ENTRIES, FORCE_TUNINGS, JOINT_TARGETS, LOWER,
    MAX_TORQUE, UPPER,
};
pub use crash::{Crash, CrashCause, CrashMonitor, Fall};
pub use drive::{DriveInput, DEFAULT_MAX_SPEED_KMH, TOP_SPEED_KMH};
pub use engine::RearWheelDrive;
pub use feet::Feet;
pub use fields::{field, BikeField, FIELDS};
pub use front_brake::{FrontBrake, OverFrontTyre};
pub use layout::Layout;
pub use manual::{manual_controls, POSE_GAIN};
pub use model::{Bike, Exploded, FootState, Part, PartShape, PeriodWatch, Placement, Shape, PARTS};
pub use params::{BikeParams, GRAVITY};
pub use posture::Posture;
pub use rider_position::{
    rider_position_cost, RiderPosition, BACK_POSE, COM_REACH_FORWARD, COM_REACH_RIGHT,
    FORWARD_POSE, RIDER_JOINTS, RIGHT_POSE,
};
pub use suspension::{static_wheel_loads, Suspension};
pub use wheelie_control::{pitch_request, PitchRequest, WheelieControl};
