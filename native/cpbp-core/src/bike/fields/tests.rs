use super::*;
use crate::bike::layout::Layout;
use glam::DVec3;

#[test]
fn the_reference_bike_is_within_every_range_and_its_numbers_rebuild_it_bit_for_bit() {
    let reference = BikeParams::default();
    let mut values = Vec::new();
    for field in FIELDS {
        let value = field
            .value(&reference)
            .expect("the reference bike has every part");
        let r = field.range;
        assert!((r.min..=r.max).contains(&value), "{} = {value}", field.name);
        values.push((field.name, value));
    }
    let rebuilt = BikeParams::from_fields(values, true).unwrap();
    assert_eq!(rebuilt, reference);
}

#[test]
fn names_are_unique() {
    for (i, field) in FIELDS.iter().enumerate() {
        assert!(
            FIELDS[..i].iter().all(|f| f.name != field.name),
            "{}",
            field.name
        );
    }
}

#[test]
fn a_bad_number_is_refused_naming_its_field() {
    let why = BikeParams::from_fields([("trail", 0.0)], true).unwrap_err();
    assert!(why.contains("trail must be within 0.01–0.2 m"), "{why}");
    let why = BikeParams::from_fields([("suspension/sag", f64::NAN)], true).unwrap_err();
    assert!(why.contains("suspension/sag"), "{why}");
    let why = BikeParams::from_fields([("trail", 0.2), ("rake_deg", 10.0)], true).unwrap_err();
    assert!(why.contains("the fork would have no offset"), "{why}");
    let why = BikeParams::from_fields([("colour", 1.0)], true).unwrap_err();
    assert!(why.contains("no bike field is called colour"), "{why}");
    let why = BikeParams::from_fields([("tyre_friction_follows_wheel", 0.5)], true).unwrap_err();
    assert!(
        why.contains("tyre_friction_follows_wheel is 1 (on) or 0 (off), not 0.5"),
        "{why}"
    );
}

#[test]
fn an_on_off_field_reads_and_writes_one_or_zero() {
    let name = "tyre_friction_follows_wheel";
    let on = BikeParams::from_fields([(name, 1.0)], true).unwrap();
    assert!(on.tyre_friction_follows_wheel);
    assert_eq!(field(name).unwrap().value(&on), Some(1.0));
    let off = BikeParams::from_fields([(name, 0.0)], true).unwrap();
    assert_eq!(off, BikeParams::default());
}

#[test]
fn a_rigid_bike_keeps_no_sprung_parts() {
    let rigid = BikeParams::from_fields([("suspension/sag", 0.2)], false).unwrap();
    assert_eq!(rigid, BikeParams::default().rigid());
    assert_eq!(field("suspension/sag").unwrap().value(&rigid), None);
}

#[test]
fn an_identity_names_what_differs_from_the_reference() {
    let reference = BikeParams::default();
    // The reference's is the hash of no differences (FNV-1a's offset basis).
    assert_eq!(reference.identity(), "cbf29ce484222325");
    let grippier = BikeParams::from_fields([("tyre_friction", 1.2)], true).unwrap();
    assert_ne!(grippier.identity(), reference.identity());
    assert_ne!(reference.rigid().identity(), reference.identity());
    // A field set to the reference's value is no difference: adding a field to the model
    // at that value changes no bike's identity.
    let same =
        BikeParams::from_fields([("tyre_friction", 1.2), ("max_lean_deg", 30.0)], true).unwrap();
    assert_eq!(same.identity(), grippier.identity());
}

#[test]
fn the_brake_window_may_be_switched_off_but_not_reversed() {
    let off = [
        ("front_brake/full_above", 0.0),
        ("front_brake/none_below", 0.0),
    ];
    let bike = BikeParams::from_fields(off, true).unwrap();
    assert!(!bike.front_brake.unwrap().has_window());
    let why = BikeParams::from_fields([("front_brake/full_above", 0.01)], true).unwrap_err();
    assert!(why.contains("none_below must be below"), "{why}");
}

#[test]
fn a_posture_the_rider_cannot_reach_is_refused_naming_its_fields() {
    // Pegs a metre below the seat: the leg (0.86 m) does not reach them.
    let why = BikeParams::from_fields([("posture/footpeg_y", 0.2), ("posture/hip_y", 1.2)], true)
        .unwrap_err();
    assert!(
        why.contains("posture/footpeg_*") && why.contains("leg"),
        "{why}"
    );
    // Grips high above and far behind the seat's shoulder: the arm cannot bend to them.
    let why = BikeParams::from_fields(
        [
            ("posture/grip_height", 0.7),
            ("posture/hip_y", 1.2),
            ("posture/torso_lean_deg", -10.0),
        ],
        true,
    )
    .unwrap_err();
    assert!(
        why.contains("posture/grip_height") && why.contains("arm"),
        "{why}"
    );
}

#[test]
fn a_taller_posture_builds_a_rider_whose_segments_keep_their_lengths() {
    // A dirt bike's: pegs 5 cm and seat 10 cm higher, the torso more upright, a taller bar.
    let taller = [
        ("posture/footpeg_y", 0.43),
        ("posture/hip_y", 0.95),
        ("posture/torso_lean_deg", 10.0),
        ("posture/grip_height", 1.15),
    ];
    let bike = BikeParams::from_fields(taller, true).unwrap();
    let (layout, reference) = (Layout::new(&bike), Layout::new(&BikeParams::default()));
    assert_eq!(layout.hip.y, 0.95);
    assert!(layout.head_top.y > reference.head_top.y + 0.1);
    let limb = |a: DVec3, b: DVec3| (a - b).length();
    let pairs = |l: &Layout| {
        [
            limb(l.hip, l.knee),
            limb(l.knee, l.ankle),
            limb(l.shoulder, l.elbow),
            limb(l.elbow, l.grip),
        ]
    };
    for (taller, reference) in pairs(&layout).into_iter().zip(pairs(&reference)) {
        assert!(
            (taller - reference).abs() < 1e-9,
            "{taller} against {reference}"
        );
    }
}
