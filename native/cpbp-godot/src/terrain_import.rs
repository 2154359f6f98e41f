//! Reads a level's static collision shapes (CollisionShape3D under StaticBody3D) into the
//! core's terrain description, with their global transforms baked in.

use std::sync::Arc;

use cpbp_core::bike::Placement;
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};
use godot::classes::{
    BoxShape3D, CapsuleShape3D, CollisionShape3D, ConcavePolygonShape3D, ConvexPolygonShape3D,
    CylinderShape3D, HeightMapShape3D, Node, Shape3D, SphereShape3D, StaticBody3D,
    WorldBoundaryShape3D,
};
use godot::prelude::*;

use crate::convert::{decompose, dvec3};

/// The terrain of the static shapes under `root_path` (relative to `node`), with every
/// problem reported as an error; None when there is no usable terrain.
pub fn terrain_under(node: &Node3D, root_path: &NodePath) -> Option<Arc<Terrain>> {
    let Some(root) = node.get_node_or_null(root_path) else {
        godot_error!("BikeSimulation: terrain root '{root_path}' not found");
        return None;
    };
    let (pieces, errors) = collect(&root);
    for error in &errors {
        godot_error!("BikeSimulation: terrain shape skipped: {error}");
    }
    match Terrain::new(pieces) {
        Ok(terrain) => Some(Arc::new(terrain)),
        Err(error) => {
            godot_error!("BikeSimulation: broken level geometry: {error}");
            None
        }
    }
}

/// All usable pieces under `root`, and one message per shape that could not be used.
pub fn collect(root: &Gd<Node>) -> (Vec<TerrainPiece>, Vec<String>) {
    let mut pieces = Vec::new();
    let mut errors = Vec::new();
    visit(root, &mut pieces, &mut errors);
    (pieces, errors)
}

fn visit(node: &Gd<Node>, pieces: &mut Vec<TerrainPiece>, errors: &mut Vec<String>) {
    for child in node.get_children().iter_shared() {
        if let Ok(shape_node) = child.clone().try_cast::<CollisionShape3D>() {
            let static_parent = shape_node
                .get_parent()
                .is_some_and(|p| p.try_cast::<StaticBody3D>().is_ok());
            if static_parent && !shape_node.is_disabled() {
                let source = shape_node.get_path().to_string();
                match convert(&shape_node) {
                    Ok(piece) => pieces.push(TerrainPiece { source, ..piece }),
                    Err(e) => errors.push(format!("{source}: {e}")),
                }
            }
        }
        visit(&child, pieces, errors);
    }
}

fn convert(node: &Gd<CollisionShape3D>) -> Result<TerrainPiece, String> {
    let shape = node.get_shape().ok_or("has no shape")?;
    let (rotation, scale, position) = decompose(&node.get_global_transform())
        .ok_or("its transform mirrors or flattens the shape; use positive scales")?;
    let placed = |shape: TerrainShape| TerrainPiece {
        source: String::new(),
        shape,
        placement: Placement { position, rotation },
    };
    // Vertex data is moved into world space with the full transform, scale included.
    let to_world = |v: Vector3| position + rotation * (dvec3(v) * scale);
    let in_world = |shape: TerrainShape| TerrainPiece {
        source: String::new(),
        shape,
        placement: Placement {
            position: DVec3::ZERO,
            rotation: DQuat::IDENTITY,
        },
    };
    let uniform = |what: &str, a: f64, b: f64| {
        if (a - b).abs() <= 1e-4 * a.max(b) {
            Ok(())
        } else {
            Err(format!(
                "a {what} cannot follow a non-uniform scale ({scale})"
            ))
        }
    };
    // By class, not by class name, so a script's subclass of a shape imports as its base.
    let piece = if let Some(cuboid) = as_a::<BoxShape3D>(&shape) {
        placed(TerrainShape::Cuboid {
            size: dvec3(cuboid.get_size()) * scale,
        })
    } else if let Some(sphere) = as_a::<SphereShape3D>(&shape) {
        uniform("sphere", scale.x, scale.y)?;
        uniform("sphere", scale.x, scale.z)?;
        let radius = f64::from(sphere.get_radius()) * scale.x;
        placed(TerrainShape::Sphere { radius })
    } else if let Some(capsule) = as_a::<CapsuleShape3D>(&shape) {
        uniform("capsule", scale.x, scale.z)?;
        let radius = f64::from(capsule.get_radius()) * scale.x;
        let height = (f64::from(capsule.get_height()) * scale.y).max(2.0 * radius);
        placed(TerrainShape::Capsule { radius, height })
    } else if let Some(cylinder) = as_a::<CylinderShape3D>(&shape) {
        uniform("cylinder", scale.x, scale.z)?;
        let radius = f64::from(cylinder.get_radius()) * scale.x;
        placed(TerrainShape::Cylinder {
            radius,
            height: f64::from(cylinder.get_height()) * scale.y,
        })
    } else if let Some(boundary) = as_a::<WorldBoundaryShape3D>(&shape) {
        let plane = boundary.get_plane();
        let local_normal = dvec3(plane.normal);
        let point = to_world(plane.normal * plane.d);
        let normal = (rotation * (local_normal / scale)).normalize_or_zero();
        in_world(TerrainShape::Plane {
            normal,
            distance: normal.dot(point),
        })
    } else if let Some(map) = as_a::<HeightMapShape3D>(&shape) {
        let heights = map
            .get_map_data()
            .as_slice()
            .iter()
            .map(|h| f64::from(*h) * scale.y)
            .collect();
        placed(TerrainShape::HeightMap {
            width: map.get_map_width().max(0) as usize,
            depth: map.get_map_depth().max(0) as usize,
            heights,
            spacing: [scale.x, scale.z],
        })
    } else if let Some(mesh) = as_a::<ConcavePolygonShape3D>(&shape) {
        // Godot's front faces wind clockwise, ODE's counter-clockwise.
        let vertices = mesh
            .get_faces()
            .as_slice()
            .chunks(3)
            .flat_map(|t| match t {
                [a, b, c] => vec![to_world(*a), to_world(*c), to_world(*b)],
                partial => partial.iter().map(|v| to_world(*v)).collect(),
            })
            .collect();
        in_world(TerrainShape::TriMesh { vertices })
    } else if let Some(hull) = as_a::<ConvexPolygonShape3D>(&shape) {
        let points = hull
            .get_points()
            .as_slice()
            .iter()
            .map(|p| to_world(*p))
            .collect();
        in_world(TerrainShape::Convex { points })
    } else {
        let class = shape.get_class();
        return Err(format!("{class} is not supported by the bike simulation"));
    };
    Ok(piece)
}

/// `shape` as a `T`, if it is one.
fn as_a<T: GodotClass + Inherits<Shape3D>>(shape: &Gd<Shape3D>) -> Option<Gd<T>> {
    shape.clone().try_cast::<T>().ok()
}
