use super::*;

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
}

#[test]
fn a_rigid_bike_keeps_no_sprung_parts() {
    let rigid = BikeParams::from_fields([("suspension/sag", 0.2)], false).unwrap();
    assert_eq!(rigid, BikeParams::default().rigid());
    assert_eq!(field("suspension/sag").unwrap().value(&rigid), None);
}
