//! A field of logs lying half-sunk across the way: the test level's bumps, the trainer's
//! log episodes and the scenario tool's `logs` ride all lay theirs from one description
//! with one generator. The test level's own field is `scenes/levels/test_level/
//! log_field.tres`, which the level loads and the tools compile in (`TEST_LEVEL`).

use glam::{DQuat, DVec3};

use super::godot_random::GodotRandom;
use crate::bike::Placement;
use crate::terrain::{TerrainPiece, TerrainShape};

/// Where the logs fall and how big they are. Single precision, as Godot's `Vector2`
/// fields hold them, so the level's layout is the one it always had (`GodotRandom`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogField {
    /// The area the logs' centres fall in (m): across the way (x) × along it (z),
    /// centred on the field's origin.
    pub area: [f32; 2],
    /// How many logs.
    pub count: usize,
    /// Radius range (m); sunk to their axes, this is their height.
    pub radius: [f32; 2],
    /// Length range (m).
    pub length: [f32; 2],
    /// The largest angle between a log and the line across the way (degrees).
    pub max_angle_deg: f32,
}

/// One log: laid along the field's x, turned by `angle` about its up, at `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Log {
    pub radius: f32,
    pub length: f32,
    /// Radians, from the degrees drawn (as GDScript's `deg_to_rad`).
    pub angle: f64,
    /// In the field's frame: x across, z along (the way ahead is −z), y = 0.
    pub centre: [f32; 3],
}

impl Default for LogField {
    fn default() -> Self {
        Self {
            area: [14.0, 20.0],
            count: 10,
            radius: [0.06, 0.12],
            length: [1.0, 3.0],
            max_angle_deg: 35.0,
        }
    }
}

impl LogField {
    /// The test level's field, from the level's own file.
    pub fn test_level() -> Self {
        super::field_file::parse_log_field(TEST_LEVEL)
            .expect("the test level's log field file is valid (a test reads it)")
    }

    /// The logs seed `seed` lays, in the order and with the numbers Godot's
    /// `RandomNumberGenerator` gave the level's script.
    pub fn layout(&self, seed: i64) -> Vec<Log> {
        let mut rng = GodotRandom::new(seed);
        let half = [self.area[0] / 2.0, self.area[1] / 2.0];
        (0..self.count)
            .map(|_| {
                let radius = rng.randf_range(self.radius[0], self.radius[1]);
                let length = rng.randf_range(self.length[0], self.length[1]);
                let degrees = rng.randf_range(-self.max_angle_deg, self.max_angle_deg);
                let x = rng.randf_range(-half[0], half[0]);
                let z = rng.randf_range(-half[1], half[1]);
                Log {
                    radius,
                    length,
                    angle: f64::from(degrees).to_radians(),
                    centre: [x, 0.0, z],
                }
            })
            .collect()
    }

    /// The logs of seed `seed` as terrain, the field's origin at `at`: each a cylinder
    /// laid across the way (Godot's cylinder stands along y; a quarter turn about the
    /// way ahead, −z, lays it along x), then turned by its angle.
    pub fn pieces(&self, seed: i64, at: Placement) -> Vec<TerrainPiece> {
        let lay_down = DQuat::from_axis_angle(DVec3::NEG_Z, std::f64::consts::FRAC_PI_2);
        self.layout(seed)
            .into_iter()
            .enumerate()
            .map(|(i, log)| {
                let centre = DVec3::from_array(log.centre.map(f64::from));
                TerrainPiece {
                    source: format!("log {i}"),
                    shape: TerrainShape::Cylinder {
                        radius: log.radius.into(),
                        height: log.length.into(),
                    },
                    placement: Placement {
                        position: at.position + at.rotation * centre,
                        rotation: at.rotation * DQuat::from_rotation_y(log.angle) * lay_down,
                    },
                }
            })
            .collect()
    }

    /// One field per seed of `seeds`, one after another along `heading`'s +x (a bike's
    /// forward) from `from` m ahead of the origin, each turned so its way ahead is the
    /// bike's.
    pub fn ahead(
        &self,
        seeds: impl IntoIterator<Item = i64>,
        heading: DQuat,
        from: f64,
    ) -> Vec<TerrainPiece> {
        let along = f64::from(self.area[1]);
        // A quarter turn about up takes the field's way ahead (−z) to +x.
        let rotation = heading * DQuat::from_rotation_y(-std::f64::consts::FRAC_PI_2);
        let mut pieces = Vec::new();
        for (k, seed) in seeds.into_iter().enumerate() {
            let centre = from + along * (k as f64 + 0.5);
            let at = Placement {
                position: heading * DVec3::new(centre, 0.0, 0.0),
                rotation,
            };
            pieces.extend(self.pieces(seed, at));
        }
        pieces
    }
}

/// The test level's log field file, compiled in so the tools ride the level's logs
/// wherever they run.
pub const TEST_LEVEL: &str = include_str!("../../../../scenes/levels/test_level/log_field.tres");
