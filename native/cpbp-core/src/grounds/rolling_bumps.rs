//! Rolling ground: the sum of a few plane waves of random direction, frequency and phase,
//! from 0 to `height` high. The trainer's bump episodes ride it as a height field and
//! `make bench` as a triangle mesh (the levels' own shape); one generator for both.

use glam::{DQuat, DVec3};
use rand::RngExt;

use crate::bike::Placement;
use crate::terrain::{TerrainPiece, TerrainShape};

/// A rolling field's waves and height.
#[derive(Clone, Debug, PartialEq)]
pub struct RollingBumps {
    /// Each wave's x and z frequencies (rad/m) and phase (rad).
    waves: Vec<(f64, f64, f64)>,
    /// Highest crest above the lowest trough (m).
    height: f64,
}

impl RollingBumps {
    /// Four waves drawn from `rng`, 0.3–1.2 rad/m each way.
    pub fn draw(rng: &mut impl RngExt, height: f64) -> Self {
        let waves = (0..4)
            .map(|_| {
                (
                    rng.random_range(0.3..1.2),
                    rng.random_range(0.3..1.2),
                    rng.random_range(0.0..std::f64::consts::TAU),
                )
            })
            .collect();
        Self { waves, height }
    }

    /// The ground's height at (x, z) in the field's frame.
    pub fn height_at(&self, x: f64, z: f64) -> f64 {
        let sum: f64 = self
            .waves
            .iter()
            .map(|(a, b, p)| (a * x + b * z + p).sin())
            .sum();
        self.height * 0.5 * (1.0 + sum / self.waves.len() as f64)
    }

    /// A height field of `cells` × `cells` squares of `spacing` m from (0, 0) to +x, +z.
    pub fn height_map(&self, cells: usize, spacing: f64) -> TerrainPiece {
        let size = cells + 1;
        let heights = (0..size * size)
            .map(|i| {
                let (x, z) = ((i % size) as f64, (i / size) as f64);
                self.height_at(x * spacing, z * spacing)
            })
            .collect();
        piece(TerrainShape::HeightMap {
            width: size,
            depth: size,
            heights,
            spacing: [spacing, spacing],
        })
    }

    /// The same ground as a triangle mesh of `cells` × `cells` squares of `spacing` m,
    /// centred on the origin.
    pub fn tri_mesh(&self, cells: usize, spacing: f64) -> TerrainPiece {
        let half = cells as f64 * spacing / 2.0;
        let corner = |i: usize, j: usize| {
            let (x, z) = (i as f64 * spacing - half, j as f64 * spacing - half);
            DVec3::new(x, self.height_at(x, z), z)
        };
        let mut vertices = Vec::with_capacity(cells * cells * 6);
        for i in 0..cells {
            for j in 0..cells {
                let (a, b) = (corner(i, j), corner(i + 1, j));
                let (c, d) = (corner(i + 1, j + 1), corner(i, j + 1));
                vertices.extend([a, d, c, a, c, b]);
            }
        }
        piece(TerrainShape::TriMesh { vertices })
    }
}

fn piece(shape: TerrainShape) -> TerrainPiece {
    TerrainPiece {
        source: "rolling bumps".into(),
        shape,
        placement: Placement {
            position: DVec3::ZERO,
            rotation: DQuat::IDENTITY,
        },
    }
}
