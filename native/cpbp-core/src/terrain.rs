//! Level geometry as plain data, turned into static ODE geoms in every world.
//!
//! Shapes follow Godot's conventions, so the binding only copies numbers: capsules and
//! cylinders stand along their local y axis, a capsule's height includes its caps, height
//! maps are centred with samples `spacing` apart, planes are `normal · p = distance`.
//! Trimesh and height data are built once and shared by all worlds.

use std::sync::Arc;

use glam::{DQuat, DVec3};

use crate::bike::Placement;
use crate::ode::{HeightFieldData, TriMeshData, World};

/// One collision shape of a level, in its own frame.
#[derive(Clone, Debug, PartialEq)]
pub enum TerrainShape {
    Cuboid {
        size: DVec3,
    },
    Sphere {
        radius: f64,
    },
    Capsule {
        radius: f64,
        height: f64,
    },
    Cylinder {
        radius: f64,
        height: f64,
    },
    /// World-frame plane; the placement is ignored.
    Plane {
        normal: DVec3,
        distance: f64,
    },
    HeightMap {
        width: usize,
        depth: usize,
        heights: Vec<f64>,
        spacing: [f64; 2],
    },
    /// Triangles as vertex triples, counter-clockwise seen from the solid side's outside.
    TriMesh {
        vertices: Vec<DVec3>,
    },
    /// A convex hull of points.
    Convex {
        points: Vec<DVec3>,
    },
}

/// A shape where the level put it, with the name of what it came from (for errors).
#[derive(Clone, Debug, PartialEq)]
pub struct TerrainPiece {
    pub source: String,
    pub shape: TerrainShape,
    pub placement: Placement,
}

impl TerrainPiece {
    /// Endless flat ground: the plane y = 0.
    pub fn flat_ground() -> Self {
        Self::ground_through_origin("flat ground", DVec3::Y)
    }

    /// An endless plane through the origin with unit `normal`: a slope, for a tilted one.
    pub fn ground_through_origin(source: &str, normal: DVec3) -> Self {
        Self {
            source: source.into(),
            shape: TerrainShape::Plane {
                normal,
                distance: 0.0,
            },
            placement: Placement::IDENTITY,
        }
    }
}

/// A level's shapes, checked and ready to go into any number of worlds.
pub struct Terrain {
    pieces: Vec<ReadyPiece>,
}

enum ReadyShape {
    Simple(TerrainShape),
    Mesh(Arc<TriMeshData>),
    Heights(Arc<HeightFieldData>),
}

struct ReadyPiece {
    shape: ReadyShape,
    placement: Placement,
}

impl Terrain {
    /// Checks every piece and builds shared data. The error names the offending source.
    pub fn new(pieces: Vec<TerrainPiece>) -> Result<Self, String> {
        let pieces = pieces
            .into_iter()
            .map(|piece| {
                let shape = ready(&piece.shape).map_err(|e| format!("{}: {e}", piece.source))?;
                if !(piece.placement.position.is_finite() && piece.placement.rotation.is_finite()) {
                    return Err(format!("{}: non-finite transform", piece.source));
                }
                Ok(ReadyPiece {
                    shape,
                    placement: piece.placement,
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Self { pieces })
    }

    /// Endless flat ground: the plane y = 0 (benchmarks, profiles and tests).
    pub fn flat() -> Self {
        Self::new(vec![TerrainPiece::flat_ground()]).expect("a horizontal plane is valid terrain")
    }

    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }

    /// Adds every piece to a world as static geoms.
    pub fn add_to(&self, world: &mut World) {
        for piece in &self.pieces {
            let geom = match &piece.shape {
                ReadyShape::Simple(TerrainShape::Plane { normal, distance }) => {
                    world.add_plane(*normal, *distance);
                    continue;
                }
                ReadyShape::Simple(TerrainShape::Cuboid { size }) => world.add_box(*size, None),
                ReadyShape::Simple(TerrainShape::Sphere { radius }) => {
                    world.add_sphere(*radius, None)
                }
                ReadyShape::Simple(TerrainShape::Capsule { radius, height }) => {
                    world.add_capsule(*radius, height - 2.0 * radius, None)
                }
                ReadyShape::Simple(TerrainShape::Cylinder { radius, height }) => {
                    world.add_cylinder(*radius, *height, None)
                }
                ReadyShape::Simple(_) => unreachable!("meshes and heights are prepared"),
                ReadyShape::Mesh(data) => world.add_trimesh(data),
                ReadyShape::Heights(data) => world.add_heightfield(data),
            };
            // ODE's capsules and cylinders lie along z; Godot's stand along y.
            let along_y = matches!(
                piece.shape,
                ReadyShape::Simple(TerrainShape::Capsule { .. } | TerrainShape::Cylinder { .. })
            );
            let local = if along_y {
                DQuat::from_rotation_x(-std::f64::consts::FRAC_PI_2)
            } else {
                DQuat::IDENTITY
            };
            world.set_geom_position(geom, piece.placement.position);
            world.set_geom_quaternion(geom, piece.placement.rotation * local);
        }
    }
}

fn ready(shape: &TerrainShape) -> Result<ReadyShape, String> {
    let positive = |what: &str, v: f64| {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(format!("{what} must be a positive number, got {v}"))
        }
    };
    match shape {
        TerrainShape::Cuboid { size } => {
            for v in size.to_array() {
                positive("box size", v)?;
            }
        }
        TerrainShape::Sphere { radius } => positive("sphere radius", *radius)?,
        TerrainShape::Capsule { radius, height } => {
            positive("capsule radius", *radius)?;
            if !(height.is_finite() && *height >= 2.0 * radius) {
                return Err(format!(
                    "capsule height {height} is less than its two caps ({})",
                    2.0 * radius
                ));
            }
        }
        TerrainShape::Cylinder { radius, height } => {
            positive("cylinder radius", *radius)?;
            positive("cylinder height", *height)?;
        }
        TerrainShape::Plane { normal, distance } => {
            if !(normal.is_finite() && normal.length() > 1e-9 && distance.is_finite()) {
                return Err("a plane needs a non-zero finite normal and a finite distance".into());
            }
        }
        TerrainShape::HeightMap {
            width,
            depth,
            heights,
            spacing,
        } => {
            if heights.iter().any(|h| !h.is_finite()) {
                return Err("height map has non-finite heights".into());
            }
            positive("height map spacing", spacing[0])?;
            positive("height map spacing", spacing[1])?;
            return HeightFieldData::new(heights, *width, *depth, *spacing)
                .map(|d| ReadyShape::Heights(Arc::new(d)));
        }
        TerrainShape::TriMesh { vertices } => return mesh(vertices.clone()),
        TerrainShape::Convex { points } => return mesh(convex_hull_triangles(points)?),
    }
    Ok(ReadyShape::Simple(shape.clone()))
}

/// Shares equal vertices and drops degenerate triangles, then builds ODE mesh data.
fn mesh(corners: Vec<DVec3>) -> Result<ReadyShape, String> {
    if !corners.len().is_multiple_of(3) {
        return Err(format!(
            "a triangle list needs a multiple of 3 vertices, got {}",
            corners.len()
        ));
    }
    if corners.iter().any(|v| !v.is_finite()) {
        return Err("mesh has non-finite vertices".into());
    }
    let vertices: Vec<[f64; 3]> = corners.iter().map(|v| v.to_array()).collect();
    let triangles: Vec<[u32; 3]> = (0..corners.len() as u32 / 3)
        .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
        .filter(|t| {
            let [a, b, c] = t.map(|i| corners[i as usize]);
            (b - a).cross(c - a).length_squared() > 1e-18
        })
        .collect();
    if triangles.is_empty() {
        return Err("mesh has no triangle with an area".into());
    }
    TriMeshData::new(vertices, triangles).map(|d| ReadyShape::Mesh(Arc::new(d)))
}

/// The hull's faces as a counter-clockwise triangle list, the same in every run. The hull
/// library finds the faces in an order, and splits a flat face (a ramp's quad) along a
/// diagonal, that vary from run to run (its maps are randomly seeded), and where a wheel
/// meets which triangle decides its contacts: rides on the levels did not repeat. So the
/// triangles are regrouped into the hull's flat faces, each triangulated as a fan from
/// its smallest vertex, in the order of their smallest vertices.
fn convex_hull_triangles(points: &[DVec3]) -> Result<Vec<DVec3>, String> {
    if points.len() < 4 || points.iter().any(|p| !p.is_finite()) {
        return Err(format!(
            "a convex shape needs 4 or more finite points, got {}",
            points.len()
        ));
    }
    let input: Vec<Vec<f64>> = points.iter().map(|p| p.to_array().to_vec()).collect();
    let hull = chull::ConvexHullWrapper::try_new(&input, None)
        .map_err(|e| format!("no convex hull for these points ({e:?}); are they flat?"))?;
    let (vertices, indices) = hull.vertices_indices();
    let centre = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    let mut faces: Vec<(DVec3, Vec<DVec3>)> = Vec::new();
    for face in indices.chunks_exact(3) {
        let corners = [face[0], face[1], face[2]].map(|i| DVec3::from_slice(&vertices[i]));
        let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
        if normal.length_squared() < 1e-24 {
            continue;
        }
        // Outwards, whatever order the hull library gives.
        let normal = normal.normalize() * (corners[0] - centre).dot(normal).signum();
        let offset = normal.dot(corners[0]);
        let same_plane = |(n, v): &&mut (DVec3, Vec<DVec3>)| {
            n.dot(normal) > 1.0 - 1e-9 && (n.dot(v[0]) - offset).abs() < 1e-9
        };
        match faces.iter_mut().find(same_plane) {
            Some((_, face)) => face.extend(corners),
            None => faces.push((normal, corners.to_vec())),
        }
    }
    let mut polygons: Vec<Vec<DVec3>> = faces
        .into_iter()
        .map(|(normal, corners)| counter_clockwise(corners, normal))
        .collect();
    polygons.sort_by(|a, b| lexical(a[0], b[0]).then(lexical(a[1], b[1])));
    Ok(polygons
        .iter()
        .flat_map(|p| (1..p.len() - 1).flat_map(move |i| [p[0], p[i], p[i + 1]]))
        .collect())
}

/// A flat face's distinct corners, counter-clockwise seen along `normal` from outside,
/// starting at the smallest.
fn counter_clockwise(mut corners: Vec<DVec3>, normal: DVec3) -> Vec<DVec3> {
    corners.sort_by(|a, b| lexical(*a, *b));
    corners.dedup();
    let middle = corners.iter().copied().sum::<DVec3>() / corners.len() as f64;
    let start = corners[0] - middle;
    let angle = |p: &DVec3| {
        let d = *p - middle;
        let a = start.cross(d).dot(normal).atan2(start.dot(d));
        if a < 0.0 {
            a + std::f64::consts::TAU
        } else {
            a
        }
    };
    let first = corners[0];
    corners.sort_by(|a, b| {
        if *a == first {
            std::cmp::Ordering::Less
        } else if *b == first {
            std::cmp::Ordering::Greater
        } else {
            angle(a).total_cmp(&angle(b))
        }
    });
    corners
}

/// Points ordered by x, then y, then z.
fn lexical(a: DVec3, b: DVec3) -> std::cmp::Ordering {
    a.x.total_cmp(&b.x)
        .then(a.y.total_cmp(&b.y))
        .then(a.z.total_cmp(&b.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hull_comes_out_the_same_every_time() {
        // A kicker's prism: quads on its slopes, top, bottom and back, which the hull
        // library splits along either diagonal, in a random order, run after run.
        let profile = [(0.0, 0.0), (-3.0, 0.45), (-4.0, 0.45), (-7.0, 0.0)];
        let mut points: Vec<DVec3> = profile
            .iter()
            .flat_map(|&(z, y)| [DVec3::new(-2.5, y, z), DVec3::new(2.5, y, z)])
            .collect();
        let first = convex_hull_triangles(&points).unwrap();
        for turn in 0..12 {
            let n = points.len();
            points.rotate_left(turn % n);
            assert_eq!(
                convex_hull_triangles(&points).unwrap(),
                first,
                "turn {turn}"
            );
        }
        // Every face is there: the triangles' areas add up to the prism's surface.
        let area: f64 = first
            .chunks_exact(3)
            .map(|t| (t[1] - t[0]).cross(t[2] - t[0]).length() / 2.0)
            .sum();
        let slope = (3.0f64.powi(2) + 0.45f64.powi(2)).sqrt();
        let side = 0.45 * (1.0 + 7.0) / 2.0; // a trapezoid: top 1 m, bottom 7 m
        let expected = 5.0 * (2.0 * slope + 1.0 + 7.0) + 2.0 * side;
        assert!((area - expected).abs() < 1e-9, "{area} vs {expected}");
    }
}
