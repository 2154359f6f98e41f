//! The tools' copies of the built-in controller registry and the settings schema (for the
//! Python experiment tooling) are what the native core makes of them. A process of its
//! own: no test here registers a controller or extends the schema.

use std::path::Path;

use cpbp_core::ride::{schema, ControllerKind};

/// The registry as the Python tools read it (tools/cpbp_experiment/controllers.json).
fn registry_json() -> String {
    let entries: Vec<String> = ControllerKind::BUILT_IN
        .iter()
        .map(|k| {
            format!(
                "    {{\"name\": \"{}\", \"label\": \"{}\", \"offered\": {}, \"plans\": {}}}",
                k.name(),
                k.label(),
                k.offered(),
                k.plans()
            )
        })
        .collect();
    format!(
        "{{\n  \"controllers\": [\n{}\n  ]\n}}\n",
        entries.join(",\n")
    )
}

/// Holds the tools' copy `file` (in tools/cpbp_experiment/) equal to `expected`, what
/// `source` makes of it; with UPDATE_REGISTRY set, writes it first.
fn assert_tools_copy_is_current(file: &str, expected: &str, source: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tools/cpbp_experiment")
        .join(file);
    if std::env::var_os("UPDATE_REGISTRY").is_some() {
        std::fs::write(&path, expected).expect("write the tools' copy");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(
        committed,
        expected,
        "{} differs from {source}: run `UPDATE_REGISTRY=1 tools/cargo test --release -p \
         cpbp-core --test tools_copies` and commit it",
        path.display()
    );
}

#[test]
fn the_tools_copy_of_the_registry_is_current() {
    assert_tools_copy_is_current(
        "controllers.json",
        &registry_json(),
        "ControllerKind::BUILT_IN",
    );
}

/// The settings schema as the Python tools read it (tools/cpbp_experiment/settings.json).
#[test]
fn the_tools_copy_of_the_settings_schema_is_current() {
    let schema = schema::schema_json();
    assert_tools_copy_is_current("settings.json", &schema, "cpbp_core::ride::schema");
}
