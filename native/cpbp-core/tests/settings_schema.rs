//! The settings schema as the Python tools read it (tools/cpbp_experiment/settings.json)
//! is the core's.

use std::path::Path;

#[test]
fn the_tools_copy_of_the_settings_schema_is_current() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tools/cpbp_experiment/settings.json");
    let expected = cpbp_core::settings::schema_json();
    if std::env::var_os("UPDATE_REGISTRY").is_some() {
        std::fs::write(&path, &expected).expect("write the tools' settings schema");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(
        committed,
        expected,
        "{} differs from cpbp_core::settings: run `UPDATE_REGISTRY=1 tools/cargo test \
         --release -p cpbp-core --test settings_schema` and commit it",
        path.display()
    );
}
