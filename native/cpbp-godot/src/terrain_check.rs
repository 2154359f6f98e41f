//! `TerrainCheck`: what in a level the bike simulation cannot use, for the editor and
//! for level tests, with the same rules the simulation applies when it reads the level.

use cpbp_core::terrain::Terrain;
use godot::prelude::*;

use crate::terrain_import;

/// Checks a level's static collision shapes the way `BikeSimulation` will read them.
#[derive(GodotClass)]
#[class(init, base=RefCounted)]
pub struct TerrainCheck {
    base: Base<RefCounted>,
}

#[godot_api]
impl TerrainCheck {
    /// One message per problem under `root`: shapes the simulation skips (unsupported
    /// kind, mirrored or non-uniform scale, missing shape) and geometry it rejects
    /// (non-finite, degenerate). Empty when the whole level can be used.
    #[func]
    fn problems(root: Gd<Node>) -> PackedStringArray {
        let (pieces, mut problems) = terrain_import::collect(&root);
        if pieces.is_empty() && problems.is_empty() {
            problems.push("no static collision shapes: the bike would fall forever".into());
        }
        if let Err(error) = Terrain::new(pieces) {
            problems.push(error);
        }
        problems.iter().map(|p| GString::from(p.as_str())).collect()
    }

    /// Number of static collision shapes under `root` the simulation will use.
    #[func]
    fn usable_shape_count(root: Gd<Node>) -> i64 {
        terrain_import::collect(&root).0.len() as i64
    }
}
