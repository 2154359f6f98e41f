//! Every bike the game ships (scenes/bike/bikes/*.tres) builds, and arcade and combined
//! ride each the player may choose with no tuning of their own: from a stand on one foot, off to 25 km/h, into a
//! 20° bend and back, and a full brake to a stand again. What differs between the bikes
//! is their data (`BikeParams`); the controllers read it, nothing else.

use std::path::{Path, PathBuf};

use crate::common;

use cpbp_core::bike::{read_bike_file, BikeFile, FIELDS, REFERENCE_BIKE};
use cpbp_core::control::PlanWait;
use cpbp_core::ride::{ControllerKind, Intent, Ride};
use cpbp_core::settings::BIKE;
use cpbp_core::simulation::SimulationConfig;

/// The game's bike files, by file name.
fn shipped_bikes() -> Vec<(PathBuf, BikeFile)> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/bike/bikes");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&folder)
        .expect("the bikes folder")
        .map(|entry| entry.expect("a bike file").path())
        .filter(|path| path.extension().is_some_and(|e| e == "tres"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|path| {
            let bike = read_bike_file(&path).unwrap_or_else(|why| panic!("{why}"));
            (path, bike)
        })
        .collect()
}

#[test]
fn the_game_ships_a_reference_and_three_bikes_to_choose_each_named_once() {
    let bikes = shipped_bikes();
    let mut names: Vec<&str> = bikes.iter().map(|(_, b)| b.name.as_str()).collect();
    names.sort();
    names.dedup();
    assert_eq!(
        names.len(),
        bikes.len(),
        "two bikes share a name: {names:?}"
    );
    assert_eq!(names, ["Dirt 125", "Sport 600", "Street 350", "Street 390"]);
    // The bike setting offers every file but the reference's, and nothing else.
    let mut files: Vec<String> = bikes
        .iter()
        .filter_map(|(path, _)| path.file_stem()?.to_str().map(str::to_owned))
        .filter(|stem| stem != REFERENCE_BIKE)
        .collect();
    let mut offered: Vec<String> = BIKE.choices.iter().map(|c| c.to_string()).collect();
    files.sort();
    offered.sort();
    assert_eq!(offered, files);
}

/// The unseen bike: a test fixture (tests/fixtures/bikes) that no controller was tuned on
/// and no network trained on, never offered in the game.
fn unseen_bike() -> BikeFile {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/bikes/naked_700.tres");
    read_bike_file(&path).unwrap_or_else(|why| panic!("{why}"))
}

fn lean_deg(ride: &Ride) -> f64 {
    common::lean(ride).to_degrees()
}

fn speed_kmh(ride: &Ride) -> f64 {
    let sim = ride.sim();
    sim.bike().forward_speed(sim.world(), sim.up()) * 3.6
}

/// Steps `seconds`, failing with `what` and the bike's name on a crash.
fn ride_for(ride: &mut Ride, seconds: f64, name: &str, what: &str) {
    for _ in 0..(seconds * common::FRAMES_PER_SECOND as f64).round() as usize {
        ride.step();
        if let Some(crash) = ride.sim().crashed() {
            panic!("{name} fell {what}: {}", crash.describe());
        }
    }
}

/// The ride of one bike and controller: stand, ride off, bend, brake, stand.
fn stand_ride_bend_and_stop(bike: &BikeFile, kind: ControllerKind) {
    let name = format!("{} ({kind:?})", bike.name);
    let sim = common::flat_ride_with(SimulationConfig {
        bike: bike.params.clone(),
        ..SimulationConfig::default()
    });
    let mut ride = Ride::new(sim, kind);
    ride.planner.planning.trajectories = 5;
    ride.planner.wait = PlanWait::EveryPlan;

    ride_for(&mut ride, 3.0, &name, "standing");
    let standing = lean_deg(&ride);
    assert!(standing.abs() < 6.0, "{name} stood leaned {standing:.1}°");

    ride.set_intent(Intent::cruise(25.0));
    ride_for(&mut ride, 8.0, &name, "riding off");
    let cruising = speed_kmh(&ride);
    assert!(
        (cruising - 25.0).abs() < 2.0,
        "{name} cruised at {cruising:.1} km/h"
    );

    let bend: f64 = 20.0;
    common::ask_lean(&mut ride, bend.to_radians());
    ride_for(&mut ride, 3.0, &name, "leaning into the bend");
    let mut held = 0.0;
    for _ in 0..common::FRAMES_PER_SECOND {
        ride_for(
            &mut ride,
            1.0 / common::FRAMES_PER_SECOND as f64,
            &name,
            "in the bend",
        );
        held += lean_deg(&ride) / common::FRAMES_PER_SECOND as f64;
    }
    assert!(
        (held - bend).abs() < 3.0,
        "{name} held {held:.1}° for {bend}°"
    );
    common::ask_lean(&mut ride, 0.0);
    ride_for(&mut ride, 3.0, &name, "standing up out of the bend");

    common::full_brake(&mut ride);
    ride_for(&mut ride, 6.0, &name, "braking to a stand");
    let (stopped, stood) = (speed_kmh(&ride), lean_deg(&ride));
    println!("{name}: stood {standing:.1}°, cruised {cruising:.1} km/h, held {held:.1}° in the bend, stopped at {stopped:.2} km/h on a foot at {stood:.1}°");
    assert!(
        stopped.abs() < 0.5,
        "{name} still rolls at {stopped:.2} km/h"
    );
    assert!(
        stood.abs() < 6.0,
        "{name} stands leaned {stood:.1}° after the stop"
    );
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "rides with planners: run in release (tools/test.sh does)"
)]
fn arcade_and_combined_stand_ride_bend_and_stop_every_bike_with_no_tuning_of_their_own() {
    // The thesis's rigid bike has no feet to stand on: it is the research's reference,
    // not a bike to choose. The unseen bike rides too: nothing was tuned on it.
    let choices = shipped_bikes()
        .into_iter()
        .filter(|(path, _)| path.file_stem().is_some_and(|stem| stem != REFERENCE_BIKE));
    for bike in choices.map(|(_, bike)| bike).chain([unseen_bike()]) {
        for kind in [ControllerKind::ARCADE, ControllerKind::COMBINED] {
            stand_ride_bend_and_stop(&bike, kind);
        }
    }
}

#[test]
fn the_bikes_a_player_chooses_share_the_planners_cost_with_no_tuning_of_their_own() {
    // The planners simulate the bike they ride: what differs between the bikes is the
    // bike, not how the planners cost a ride (the reference keeps the thesis's cost).
    // The unseen bike carries the same cost: what carries to it is the planners'.
    let unseen = (
        PathBuf::from("tests/fixtures/bikes/naked_700.tres"),
        unseen_bike(),
    );
    let chosen: Vec<(PathBuf, BikeFile)> = shipped_bikes()
        .into_iter()
        .filter(|(path, _)| path.file_stem().is_some_and(|s| s != REFERENCE_BIKE))
        .chain([unseen])
        .collect();
    let planners_fields = || FIELDS.iter().filter(|f| f.name.starts_with("planners_"));
    assert!(planners_fields().count() >= 6, "the planners' fields");
    let (first_path, first) = &chosen[0];
    for (path, bike) in &chosen[1..] {
        for field in planners_fields() {
            assert_eq!(
                field.value(&bike.params),
                field.value(&first.params),
                "{} in {} and {}",
                field.name,
                path.display(),
                first_path.display()
            );
        }
    }
}
