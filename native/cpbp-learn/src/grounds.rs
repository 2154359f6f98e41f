//! The grounds an episode rides on beyond flat ground and slopes: rolling bump fields
//! and the test level's logs (cylinders lying across the way, half sunk).

use cpbp_core::bike::Placement;
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};
use rand::RngExt;

use crate::episode::{stream, Stream};

/// Rolling bumps over a 320 m square (40 km/h for the longest episode stays on it), the same for every world of the episode.
pub fn bump_field(seed: u64, height: f64) -> Terrain {
    let mut rng = stream(seed, Stream::Bumps);
    let waves: Vec<(f64, f64, f64)> = (0..4)
        .map(|_| {
            (
                rng.random_range(0.3..1.2),
                rng.random_range(0.3..1.2),
                rng.random_range(0.0..std::f64::consts::TAU),
            )
        })
        .collect();
    let (size, spacing) = (321, 1.0);
    let heights = (0..size * size)
        .map(|i| {
            let (x, z) = ((i % size) as f64, (i / size) as f64);
            let sum: f64 = waves
                .iter()
                .map(|(a, b, p)| (a * x + b * z + p).sin())
                .sum();
            height * 0.5 * (1.0 + sum / waves.len() as f64)
        })
        .collect();
    let piece = TerrainPiece {
        source: "bump field".into(),
        shape: TerrainShape::HeightMap {
            width: size,
            depth: size,
            heights,
            spacing: [spacing, spacing],
        },
        placement: Placement {
            position: DVec3::ZERO,
            rotation: DQuat::IDENTITY,
        },
    };
    Terrain::new(vec![piece]).expect("a height map is valid terrain")
}

/// Logs like the test level's, for as long as an episode rides: radius 6–16 cm (the
/// level's are 8–16 cm, scenes/levels/test_level/test_level.tscn), 1–3 m long, up to 35°
/// off square, their axes at ground level, scattered in a 14 m lane from 3 m to 90 m ahead
/// of the start along `heading` (the level's 20 lie in its last 22 m before the goal), on
/// flat ground. One description shared with the level is issue 55's.
pub fn log_field(seed: u64, heading: DQuat, count: usize) -> Terrain {
    let mut rng = stream(seed, Stream::Bumps);
    let mut pieces = vec![TerrainPiece::flat_ground()];
    for i in 0..count {
        let radius = rng.random_range(0.06..0.16);
        let length = rng.random_range(1.0..3.0);
        let angle = rng.random_range(-35f64..35.0).to_radians();
        let ahead = rng.random_range(3.0..90.0);
        let aside = rng.random_range(-7.0..7.0);
        // A cylinder stands along y: lay it along z (across the bike, which faces +x),
        // turn it by `angle`, then into the episode's heading.
        let rotation = heading
            * DQuat::from_rotation_y(angle)
            * DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2);
        pieces.push(TerrainPiece {
            source: format!("log {i}"),
            shape: TerrainShape::Cylinder {
                radius,
                height: length,
            },
            placement: Placement {
                position: heading * DVec3::new(ahead, 0.0, aside),
                rotation,
            },
        });
    }
    Terrain::new(pieces).expect("logs on flat ground are valid terrain")
}
