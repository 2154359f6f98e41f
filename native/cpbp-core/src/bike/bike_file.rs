//! A bike file (scenes/bike/bikes/*.tres, a Godot `BikeDescription` resource) read
//! without Godot, so the Rust tools ride the bike the game rides: the `[resource]`
//! section's `key = value` lines, numbers by the `fields` table, `suspension` as a
//! switch, `name` as the bike's name; the drawing's and the sound's keys (paint,
//! bodywork, engine/layout) are skipped.

use std::path::Path;

use super::BikeParams;
use crate::resource_file::resource_properties;

/// A bike as its file describes it.
#[derive(Clone, Debug, PartialEq)]
pub struct BikeFile {
    pub name: String,
    /// The file's name without `.tres` ("street_350"): what the bike's own files (its
    /// learned model, `control::learned::model_path`) are named by; empty for a text
    /// read without a file.
    pub key: String,
    pub params: BikeParams,
}

/// The reference bike's file name (scenes/bike/bikes/street_350.tres): the thesis's bike,
/// `BikeParams::default()`, whose files (its learned model) the tools use without
/// `--bike`.
pub const REFERENCE_BIKE: &str = "street_350";

/// The keys a bike file holds for the drawing and the sound alone.
const LOOKS: &[&str] = &[
    "paint",
    "bodywork",
    "engine/layout",
    "resource_name",
    "script",
];

/// Reads the bike file at `path`; the error names the file and the field.
pub fn read_bike_file(path: &Path) -> Result<BikeFile, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|why| format!("the bike {}: {why}", path.display()))?;
    let bike =
        parse_bike_file(&text).map_err(|why| format!("the bike {}: {why}", path.display()))?;
    let key = path
        .file_stem()
        .map(|stem| stem.to_string_lossy().into_owned());
    Ok(BikeFile {
        key: key.unwrap_or_default(),
        ..bike
    })
}

/// Takes `--bike FILE` out of a tool's `arguments` and reads that bike (None without
/// the flag: the tool rides the reference bike).
pub fn take_bike_argument(arguments: &mut Vec<String>) -> Result<Option<BikeFile>, String> {
    let Some(at) = arguments.iter().position(|a| a == "--bike") else {
        return Ok(None);
    };
    if at + 1 >= arguments.len() {
        return Err("--bike needs a bike file (scenes/bike/bikes/*.tres)".into());
    }
    let path = arguments.remove(at + 1);
    arguments.remove(at);
    read_bike_file(Path::new(&path)).map(Some)
}

/// A bike file's text as a bike.
pub fn parse_bike_file(text: &str) -> Result<BikeFile, String> {
    let mut name = String::from("Street 350");
    let mut sprung = true;
    let mut values = Vec::new();
    for (key, value) in resource_properties(text, "BikeDescription")? {
        match key {
            "name" => name = value.trim_matches('"').to_owned(),
            "suspension" => {
                sprung = value
                    .parse()
                    .map_err(|_| format!("suspension must be true or false, not {value}"))?;
            }
            key if LOOKS.contains(&key) => {}
            key => values.push((key.to_owned(), number_of(key, value)?)),
        }
    }
    let params = BikeParams::from_fields(values.iter().map(|(k, v)| (k.as_str(), *v)), sprung)?;
    Ok(BikeFile {
        name,
        key: String::new(),
        params,
    })
}

/// A field's value in a bike file: a number, or `true`/`false` for an on/off field (1/0).
fn number_of(key: &str, value: &str) -> Result<f64, String> {
    if super::field(key).is_some_and(|f| f.is_switch()) {
        return match value {
            "true" => Ok(1.0),
            "false" => Ok(0.0),
            _ => Err(format!("{key} must be true or false, not {value}")),
        };
    }
    value
        .parse::<f64>()
        .map_err(|_| format!("{key} must be a number, not {value}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const REFERENCE: &str = include_str!("../../../../scenes/bike/bikes/street_350.tres");

    #[test]
    fn the_reference_file_is_the_reference_bike() {
        let bike = parse_bike_file(REFERENCE).unwrap();
        assert_eq!(bike.name, "Street 350");
        assert_eq!(bike.params, BikeParams::default());
    }

    #[test]
    fn a_tools_bike_argument_is_taken_out_of_its_arguments() {
        let fixture = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/fixtures/bikes/pit_bike.tres"
        );
        let mut arguments: Vec<String> = ["planning", "--bike", fixture, "5"]
            .map(String::from)
            .into();
        let bike = take_bike_argument(&mut arguments).unwrap().unwrap();
        assert_eq!(bike.params.wheelbase, 1.12);
        assert_eq!(bike.key, "pit_bike");
        assert_eq!(arguments, ["planning", "5"]);
        assert_eq!(take_bike_argument(&mut arguments), Ok(None));
        let mut bare = vec!["--bike".to_string()];
        assert!(take_bike_argument(&mut bare)
            .unwrap_err()
            .contains("needs a bike file"));
    }

    #[test]
    fn a_bad_field_is_named() {
        let broken = REFERENCE.replace("trail = 0.095", "trail = 0.0");
        let why = parse_bike_file(&broken).unwrap_err();
        assert!(why.contains("trail must be within"), "{why}");
        let broken = REFERENCE.replace("wheelbase = 1.39", "wheelbase = long");
        assert!(parse_bike_file(&broken)
            .unwrap_err()
            .contains("wheelbase must be a number"));
        assert!(parse_bike_file("[gd_resource type=\"Mesh\"]").is_err());
        let switch = "tyre_friction_follows_wheel";
        let on = REFERENCE.replace("trail = 0.095", &format!("trail = 0.095\n{switch} = true"));
        assert!(
            parse_bike_file(&on)
                .unwrap()
                .params
                .tyre_friction_follows_wheel
        );
        let broken = REFERENCE.replace("trail = 0.095", &format!("trail = 0.095\n{switch} = 1"));
        let why = parse_bike_file(&broken).unwrap_err();
        assert!(why.contains("must be true or false, not 1"), "{why}");
    }
}
