//! Terrain of every supported kind, and the master simulation's events and recovery.

use std::sync::Arc;

use cpbp_core::bike::{Controls, DriveInput, Part, Placement};
use cpbp_core::simulation::{Simulation, SimulationConfig};
use cpbp_core::terrain::{Terrain, TerrainPiece, TerrainShape};
use glam::{DQuat, DVec3};

fn piece(shape: TerrainShape, position: DVec3, rotation: DQuat) -> TerrainPiece {
    TerrainPiece {
        source: "test".into(),
        shape,
        placement: Placement { position, rotation },
    }
}

fn at(shape: TerrainShape, position: DVec3) -> TerrainPiece {
    piece(shape, position, DQuat::IDENTITY)
}

/// Settles the bike, holding the rider's pose, and returns both wheel centres' heights.
fn settle(sim: &mut Simulation, seconds: f64) -> [f64; 2] {
    for _ in 0..(seconds * 30.0) as usize {
        let mut controls = Controls::default();
        sim.bike().pose_hold(sim.world(), 5.0, &mut controls);
        sim.set_controls(controls);
        sim.step();
    }
    [Part::RearWheel, Part::FrontWheel].map(|p| sim.world().body_position(sim.bike().body(p))[1])
}

fn spawn_at(height: f64) -> Placement {
    Placement {
        position: DVec3::new(0.0, height, 0.0),
        rotation: DQuat::IDENTITY,
    }
}

/// Every kind of shape, each with a flat top at `top` under the bike's spawn point.
fn every_kind(top: f64) -> Vec<(&'static str, TerrainPiece)> {
    let square = |y: f64| {
        let (a, b, c, d) = (
            DVec3::new(-10.0, y, -10.0),
            DVec3::new(10.0, y, -10.0),
            DVec3::new(10.0, y, 10.0),
            DVec3::new(-10.0, y, 10.0),
        );
        // Counter-clockwise seen from above.
        vec![a, d, c, a, c, b]
    };
    let corners: Vec<DVec3> = [-10.0, 10.0]
        .into_iter()
        .flat_map(|x| {
            [top - 1.0, top]
                .into_iter()
                .flat_map(move |y| [-10.0, 10.0].map(|z| DVec3::new(x, y, z)))
        })
        .collect();
    vec![
        (
            "box",
            at(
                TerrainShape::Cuboid {
                    size: DVec3::new(20.0, 2.0, 20.0),
                },
                DVec3::new(0.0, top - 1.0, 0.0),
            ),
        ),
        (
            "sphere",
            at(
                TerrainShape::Sphere { radius: 60.0 },
                DVec3::new(0.0, top - 60.0, 0.0),
            ),
        ),
        (
            "capsule lying along x",
            piece(
                TerrainShape::Capsule {
                    radius: 8.0,
                    height: 40.0,
                },
                DVec3::new(0.0, top - 8.0, 0.0),
                DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2),
            ),
        ),
        (
            "cylinder",
            at(
                TerrainShape::Cylinder {
                    radius: 12.0,
                    height: 2.0,
                },
                DVec3::new(0.0, top - 1.0, 0.0),
            ),
        ),
        (
            "plane",
            at(
                TerrainShape::Plane {
                    normal: DVec3::Y,
                    distance: top,
                },
                DVec3::ZERO,
            ),
        ),
        (
            "height map",
            at(
                TerrainShape::HeightMap {
                    width: 11,
                    depth: 11,
                    heights: vec![0.0; 121],
                    spacing: [2.0, 2.0],
                },
                DVec3::new(0.0, top, 0.0),
            ),
        ),
        (
            "triangle mesh",
            at(
                TerrainShape::TriMesh {
                    vertices: square(top),
                },
                DVec3::ZERO,
            ),
        ),
        (
            "convex hull",
            at(TerrainShape::Convex { points: corners }, DVec3::ZERO),
        ),
    ]
}

#[test]
fn the_bike_rests_on_its_wheels_on_every_kind_of_shape() {
    let top = 0.7;
    for (kind, piece) in every_kind(top) {
        let terrain = Arc::new(Terrain::new(vec![piece]).unwrap());
        let mut sim = Simulation::new(SimulationConfig::default(), terrain, spawn_at(top + 0.05));
        let heights = settle(&mut sim, 2.0);
        for h in heights {
            assert!(
                (h - (top + 0.30)).abs() < 0.01,
                "{kind}: wheel centre at {h}, expected {}",
                top + 0.30
            );
        }
        assert_eq!(sim.crashed(), None, "{kind}");
    }
}

#[test]
fn a_height_map_follows_its_samples() {
    // A ramp rising along x by 0.1 per sample: the front wheel sits higher than the rear.
    let heights: Vec<f64> = (0..11 * 11).map(|i| (i % 11) as f64 * 0.1).collect();
    let map = TerrainShape::HeightMap {
        width: 11,
        depth: 11,
        heights,
        spacing: [1.0, 1.0],
    };
    let terrain = Arc::new(Terrain::new(vec![at(map, DVec3::ZERO)]).unwrap());
    let mut sim = Simulation::new(SimulationConfig::default(), terrain, spawn_at(0.6));
    let mut controls = Controls::default();
    DriveInput {
        brake: 1.0,
        ..DriveInput::default()
    }
    .apply(0.3, &mut controls);
    sim.set_controls(controls);
    for _ in 0..15 {
        sim.step();
    }
    let [rear, front] =
        [Part::RearWheel, Part::FrontWheel].map(|p| sim.world().body_position(sim.bike().body(p)));
    let rise = front[1] - rear[1];
    assert!(
        (rise - 0.139).abs() < 0.02,
        "front wheel {rise} m above the rear on a 0.1 slope"
    );
}

#[test]
fn broken_geometry_is_refused_naming_its_source() {
    let bad = [
        TerrainShape::Cuboid {
            size: DVec3::new(1.0, -1.0, 1.0),
        },
        TerrainShape::Sphere { radius: f64::NAN },
        TerrainShape::Capsule {
            radius: 1.0,
            height: 1.0,
        },
        TerrainShape::Plane {
            normal: DVec3::ZERO,
            distance: 0.0,
        },
        TerrainShape::HeightMap {
            width: 3,
            depth: 3,
            heights: vec![0.0; 4],
            spacing: [1.0, 1.0],
        },
        TerrainShape::TriMesh {
            vertices: vec![DVec3::ZERO; 4],
        },
        TerrainShape::TriMesh {
            vertices: vec![DVec3::ZERO; 3],
        },
        TerrainShape::Convex {
            points: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::X + DVec3::Y],
        },
    ];
    for shape in bad {
        let piece = TerrainPiece {
            source: "Level/Ramp/CollisionShape3D".into(),
            shape: shape.clone(),
            placement: Placement::IDENTITY,
        };
        let error = Terrain::new(vec![piece])
            .err()
            .unwrap_or_else(|| panic!("{shape:?} accepted"));
        assert!(
            error.starts_with("Level/Ramp/CollisionShape3D: "),
            "{error}"
        );
    }
}

fn flat() -> Arc<Terrain> {
    Arc::new(
        Terrain::new(vec![at(
            TerrainShape::Plane {
                normal: DVec3::Y,
                distance: 0.0,
            },
            DVec3::ZERO,
        )])
        .unwrap(),
    )
}

#[test]
fn swapping_the_terrain_keeps_the_ride() {
    let mut sim = Simulation::new(SimulationConfig::default(), flat(), spawn_at(0.0));
    settle(&mut sim, 0.5);
    let before = sim.world().snapshot();
    sim.set_terrain(flat());
    assert_eq!(sim.world().snapshot().bodies, before.bodies);
    settle(&mut sim, 0.5);
    assert_eq!(sim.crashed(), None);
}

#[test]
fn a_push_moves_the_bike_sideways_and_a_bad_one_is_ignored() {
    let mut sim = Simulation::new(SimulationConfig::default(), flat(), spawn_at(0.0));
    settle(&mut sim, 0.5);
    let before = sim.world().snapshot();
    sim.push(DVec3::new(f64::NAN, 0.0, 0.0));
    sim.push(DVec3::splat(f64::INFINITY));
    assert_eq!(
        sim.world().snapshot(),
        before,
        "a non-finite push changes nothing"
    );
    let frame = sim.bike().body(Part::Frame);
    sim.push(DVec3::new(0.0, 0.0, 50.0));
    let velocity = sim.world().body_linear_velocity(frame);
    let expected = 50.0 / sim.world().body_mass(frame);
    assert!((velocity[2] - before.bodies[frame.0].linear_velocity[2] - expected).abs() < 1e-9);
    sim.step();
    let com = sim.bike().center_of_mass(sim.world());
    assert!(com.z > 0.0, "the bike moved along the push: {com}");
}

#[test]
fn landing_after_a_drop_is_reported_once() {
    let mut sim = Simulation::new(SimulationConfig::default(), flat(), spawn_at(1.5));
    let landings: usize = (0..60).map(|_| usize::from(sim.step().landed)).sum();
    assert_eq!(landings, 1);
}

#[test]
fn a_blown_up_world_is_recovered_at_the_spawn_point() {
    let spawn = spawn_at(0.0);
    let mut sim = Simulation::new(SimulationConfig::default(), flat(), spawn);
    settle(&mut sim, 0.3);
    let torso = sim.bike().body(Part::Torso);
    sim.world_mut()
        .set_body_linear_velocity(torso, DVec3::new(f64::NAN, 0.0, 0.0));
    let events = sim.step();
    let reason = events.recovered_from.expect("the explosion is reported");
    assert!(reason.contains("non-finite"), "{reason}");
    let frame = sim.world().body_position(sim.bike().body(Part::Frame));
    assert!((frame - DVec3::new(-0.05, 0.55, 0.0)).length() < 1e-9);
    assert!(sim.bike().explosion(sim.world()).is_none());
}

#[test]
fn lifting_stands_a_fallen_bike_up_where_it_lies() {
    // Without the rider's feet, which would catch the push (`tests/rides/feet.rs`).
    let config = SimulationConfig {
        bike: cpbp_core::bike::BikeParams {
            feet: None,
            ..Default::default()
        },
        ..SimulationConfig::default()
    };
    let mut sim = Simulation::new(config, flat(), spawn_at(0.0));
    let frame = sim.bike().body(Part::Frame);
    sim.world_mut()
        .set_body_angular_velocity(frame, DVec3::new(3.0, 0.0, 0.0)); // tip it over
    for _ in 0..60 {
        sim.step();
    }
    assert!(
        sim.crashed().is_some(),
        "the push should have knocked it over"
    );
    let lying_at = sim.world().body_position(frame);
    sim.lift_upright();
    assert_eq!(sim.crashed(), None);
    assert!(
        sim.bike().lean(sim.world(), DVec3::Y).abs() < 1e-6,
        "lifted upright"
    );
    // Standing still it is an inverted pendulum that QuickStep's noise starts tipping at
    // once (about 1–2° by 0.3 s, depending on the random sequence): check it soon, with
    // room for that, before it topples again.
    settle(&mut sim, 0.3);
    let standing_at = sim.world().body_position(frame);
    assert!((standing_at.x - lying_at.x).abs() < 0.6 && (standing_at.z - lying_at.z).abs() < 0.6);
    let lean = sim.bike().lean(sim.world(), DVec3::Y);
    assert!(lean.abs() < 0.05, "lean {lean} rad 0.3 s after the lift");
    assert_eq!(sim.bike().wheel_contacts(sim.world()), (true, true));
}

/// Throttle on and the bar swinging, one state per control step.
fn ride_from_spawn(sim: &mut Simulation, steps: usize) -> Vec<cpbp_core::ode::WorldState> {
    (0..steps)
        .map(|i| {
            let mut controls = Controls::default();
            controls.set(cpbp_core::bike::index::REAR_WHEEL, 10.0);
            controls.set(cpbp_core::bike::index::STEER, 0.4 * (i as f64 * 0.2).sin());
            sim.set_controls(controls);
            sim.step();
            sim.world().snapshot()
        })
        .collect()
}

#[test]
fn a_ride_after_a_reset_repeats_whatever_was_ridden_before() {
    // QuickStep draws from a per-thread random sequence; the experiment rides many
    // attempts in one process and each must repeat exactly when rerun on its own.
    let spawn = spawn_at(0.0);
    let mut sim = Simulation::new(SimulationConfig::default(), flat(), spawn);
    sim.reset_to(spawn);
    let fresh = sim.world().snapshot();
    let first = ride_from_spawn(&mut sim, 60);
    ride_from_spawn(&mut sim, 45);
    sim.reset_to(spawn);
    // Planners read the state before the first step: it must be the fresh one, motors too.
    assert_eq!(sim.world().snapshot(), fresh);
    let again = ride_from_spawn(&mut sim, 60);
    let differs = (0..first.len()).find(|&i| first[i] != again[i]);
    assert_eq!(differs, None, "the replay differs from this step on");
}
