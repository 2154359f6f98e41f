//! Conversions between Godot's types (f32, Godot's axes) and the core's (f64, glam).
//!
//! The ODE world uses Godot's world axes directly (y up). Only the bike's own frame
//! differs: the core builds the bike facing +x with +z to its right, while a Godot node
//! faces −z with +x to its right.

use cpbp_core::bike::Placement;
use glam::{DMat3, DQuat, DVec3};
use godot::prelude::*;

pub fn dvec3(v: Vector3) -> DVec3 {
    DVec3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z))
}

pub fn vector3(v: DVec3) -> Vector3 {
    Vector3::new(v.x as f32, v.y as f32, v.z as f32)
}

pub fn basis(q: DQuat) -> Basis {
    let m = DMat3::from_quat(q);
    Basis::from_cols(vector3(m.x_axis), vector3(m.y_axis), vector3(m.z_axis))
}

pub fn transform(position: DVec3, rotation: DQuat) -> Transform3D {
    Transform3D::new(basis(rotation), vector3(position))
}

/// Rotation, per-axis scale and translation of a Godot transform; `None` when it mirrors
/// or squashes an axis to nothing (no rigid shape can follow it).
pub fn decompose(t: &Transform3D) -> Option<(DQuat, DVec3, DVec3)> {
    let cols = [t.basis.col_a(), t.basis.col_b(), t.basis.col_c()].map(dvec3);
    let scale = DVec3::new(cols[0].length(), cols[1].length(), cols[2].length());
    if scale.min_element() < 1e-9 || !scale.is_finite() {
        return None;
    }
    let m = DMat3::from_cols(cols[0] / scale.x, cols[1] / scale.y, cols[2] / scale.z);
    if m.determinant() < 0.0 {
        return None;
    }
    Some((DQuat::from_mat3(&m).normalize(), scale, dvec3(t.origin)))
}

/// Maps the bike frame (x forward, y up, z right) onto a Godot node's axes (−z forward).
fn bike_to_node() -> DQuat {
    DQuat::from_mat3(&DMat3::from_cols(DVec3::NEG_Z, DVec3::Y, DVec3::X))
}

/// Where to build the bike for a Godot spawn transform (scale is ignored).
pub fn placement(t: &Transform3D) -> Option<Placement> {
    let (rotation, _, position) = decompose(t)?;
    Some(Placement {
        position,
        rotation: rotation * bike_to_node(),
    })
}

/// A player input clamped to ±`bound`; a non-finite one counts as 0, with a warning.
pub(crate) fn finite_input(value: f64, bound: f64, function: &str) -> f64 {
    if value.is_finite() {
        value.clamp(-bound, bound)
    } else {
        godot_warn!("BikeSimulation.{function}: non-finite input {value} treated as 0");
        0.0
    }
}
