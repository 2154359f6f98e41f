//! A Godot text resource (.tres) read without Godot, for the data files the game and the
//! tools share (bikes, log fields): the `[resource]` section's `key = value` lines, as
//! Godot writes them, each property on one line.

/// The `[resource]` properties of a .tres text whose resource type is `class`, in file
/// order; the error says which line is not a property, or that it is another type.
pub fn resource_properties<'a>(
    text: &'a str,
    class: &str,
) -> Result<Vec<(&'a str, &'a str)>, String> {
    let header = format!("[gd_resource type=\"{class}\"");
    if !text.trim_start().starts_with(&header) {
        return Err(format!("not a {class} resource"));
    }
    let mut section = "";
    let mut properties = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.starts_with('[') {
            section = line;
            continue;
        }
        if section != "[resource]" || line.is_empty() || line.starts_with(';') {
            continue;
        }
        let Some(property) = line.split_once(" = ") else {
            return Err(format!(
                "line {}: not a key = value line: {line}",
                index + 1
            ));
        };
        properties.push(property);
    }
    Ok(properties)
}

#[cfg(test)]
mod tests {
    use super::resource_properties;

    #[test]
    fn the_resource_sections_lines_in_order() {
        let text = "[gd_resource type=\"Thing\" format=3 uid=\"uid://x\"]\n\n\
                    [ext_resource type=\"Script\" path=\"res://a.gd\" id=\"1\"]\n\n\
                    [resource]\nscript = ExtResource(\"1\")\n; a note\nsize = 3\n";
        assert_eq!(
            resource_properties(text, "Thing").unwrap(),
            [("script", "ExtResource(\"1\")"), ("size", "3")]
        );
        assert!(resource_properties(text, "Other")
            .unwrap_err()
            .contains("not a Other"));
        let broken = "[gd_resource type=\"Thing\"]\n[resource]\nsize: 3\n";
        assert!(resource_properties(broken, "Thing")
            .unwrap_err()
            .contains("line 3"));
    }
}
