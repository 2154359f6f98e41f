//! `BikeShape`: one collision shape of the bike and rider as
//! `BikeSimulation.get_shapes()` reports it, for drawing the physical model.

use cpbp_core::bike::{PartShape, Shape};
use godot::prelude::*;

use crate::convert::{basis, vector3};

/// One collision shape of a body (read-only).
#[derive(GodotClass)]
#[class(no_init, base=RefCounted)]
pub struct BikeShape {
    /// Index of the body it belongs to (`get_body_name(body)`).
    #[var(no_set)]
    body: i64,
    /// "sphere", "box" or "capsule".
    #[var(no_set)]
    kind: GString,
    /// Sphere or capsule radius (m); 0 for a box.
    #[var(no_set)]
    radius: f64,
    /// A capsule's length without its caps, along its local z (m); 0 otherwise.
    #[var(no_set)]
    length: f64,
    /// A box's size (m); zero otherwise.
    #[var(no_set)]
    size: Vector3,
    /// Where it sits in its body.
    #[var(no_set)]
    offset: Transform3D,
}

impl BikeShape {
    pub fn of(shape: &PartShape) -> Gd<Self> {
        let (kind, radius, length, size) = match shape.shape {
            Shape::Sphere { radius } => ("sphere", radius, 0.0, Vector3::ZERO),
            Shape::Cuboid { size } => ("box", 0.0, 0.0, vector3(size)),
            Shape::Capsule { radius, length } => ("capsule", radius, length, Vector3::ZERO),
        };
        Gd::from_object(Self {
            body: shape.part as i64,
            kind: GString::from(kind),
            radius,
            length,
            size,
            offset: Transform3D::new(basis(shape.rotation), vector3(shape.offset)),
        })
    }
}
