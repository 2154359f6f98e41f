//! `logs`: the test level's ride in the scenario tool. Straight at 15 km/h (the thesis's
//! test speed) over the test level's own log field (scenes/levels/test_level/
//! log_field.tres, laid by the core as the level lays it) from 3 m ahead; seed i meets
//! the logs of the experiment's attempt i (bump seed 1000 + i). Metric: the RMS lean
//! while the bike is over the field (°); a fall is a fall.

use cpbp_core::bike::Placement;
use cpbp_core::grounds::LogField;
use cpbp_core::terrain::{Terrain, TerrainPiece};
use glam::DVec3;

use super::{fall_cause, heading_of, mean_planning_ms, ride_on, Outcome, Rider, STEPS_PER_SECOND};

pub const SCENARIO: &str = "logs";

/// Where the field begins, ahead of the start (m).
const FROM: f64 = 3.0;
/// The experiment's first bump seed (`tools/experiment --seed`'s default).
const FIRST_BUMP_SEED: i64 = 1000;
const KMH: f64 = 15.0;

pub fn ride(rider: Rider) -> Outcome {
    let field = LogField::test_level();
    let heading = heading_of(rider.seed);
    let mut pieces = vec![TerrainPiece::flat_ground()];
    pieces.extend(field.ahead([FIRST_BUMP_SEED + rider.seed as i64], heading, FROM));
    let terrain = Terrain::new(pieces).expect("logs on flat ground are valid terrain");
    let spawn = Placement {
        position: DVec3::new(0.0, 0.02, 0.0),
        rotation: heading,
    };
    let mut ride = ride_on(rider, KMH, terrain, spawn);
    let forward = heading * DVec3::X;
    let over = FROM..FROM + f64::from(field.area[1]);
    let (mut planning, mut leans) = (Vec::new(), Vec::new());
    // Twice the time the field takes at the asked speed, from the standing start.
    let steps = (2.0 * over.end / (KMH / 3.6) * STEPS_PER_SECOND).round() as usize;
    for _ in 0..steps {
        ride.step();
        planning.extend(ride.plan().map(|p| p.planning_ms));
        let sim = ride.sim();
        let ahead = sim.bike().center_of_mass(sim.world()).dot(forward);
        if over.contains(&ahead) {
            leans.push(sim.bike().lean(sim.world(), sim.up()));
        }
        if sim.crashed().is_some() {
            break;
        }
    }
    let rms = (leans.iter().map(|l| l * l).sum::<f64>() / leans.len().max(1) as f64).sqrt();
    Outcome {
        fell: ride.sim().crashed().is_some(),
        fall_cause: fall_cause(&ride),
        metric: rms.to_degrees(),
        planning_ms: mean_planning_ms(&planning),
        measures: Vec::new(),
    }
}
