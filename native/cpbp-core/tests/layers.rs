//! The core's modules form layers: no module imports one that imports it back, however
//! far round. The settings module is the bottom (the bike, the planners and the ride read
//! their defaults from it, and it reads none of them), so a setting's default is one
//! entry and nothing above it is needed to know it. Read from the source itself, as
//! `use crate::…` and `crate::…` paths outside comments.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Every top-level module of the crate and the modules it names.
fn module_imports() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut graph = BTreeMap::new();
    for entry in fs::read_dir(&src).expect("src/") {
        let path = entry.expect("an entry of src/").path();
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let is_module = path.is_dir() || path.extension().is_some_and(|e| e == "rs");
        if !is_module || path.is_dir() && name == "bin" || name == "lib" {
            continue;
        }
        let mut imports = BTreeSet::new();
        for file in rust_files(&path) {
            let text = fs::read_to_string(&file).expect("a source file");
            for line in text.lines() {
                let code = line.split("//").next().unwrap_or("");
                for (at, _) in code.match_indices("crate::") {
                    let module: String = code[at + 7..]
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    if !module.is_empty() && module != name {
                        imports.insert(module);
                    }
                }
            }
        }
        graph.insert(name, imports);
    }
    graph
}

fn rust_files(path: &Path) -> Vec<PathBuf> {
    if path.is_file() {
        return vec![path.to_path_buf()];
    }
    let mut files = Vec::new();
    for entry in fs::read_dir(path).expect("a module folder") {
        files.extend(rust_files(&entry.expect("an entry").path()));
    }
    files
}

/// A path of imports from `from` back to itself, if there is one.
fn circle_through(graph: &BTreeMap<String, BTreeSet<String>>, from: &str) -> Option<Vec<String>> {
    let mut stack = vec![vec![from.to_string()]];
    let mut seen = BTreeSet::new();
    while let Some(path) = stack.pop() {
        let last = path.last().unwrap();
        for next in graph.get(last).into_iter().flatten() {
            if next == from {
                return Some([path.clone(), vec![next.clone()]].concat());
            }
            if seen.insert(next.clone()) {
                stack.push([path.clone(), vec![next.clone()]].concat());
            }
        }
    }
    None
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = module_imports();
    assert!(graph.contains_key("settings") && graph.contains_key("ride"));
    for module in graph.keys() {
        if let Some(circle) = circle_through(&graph, module) {
            panic!("the core's imports go round: {}", circle.join(" → "));
        }
    }
}

#[test]
fn the_settings_module_imports_nothing_of_the_core() {
    let graph = module_imports();
    assert_eq!(
        graph["settings"],
        BTreeSet::new(),
        "settings is the bottom layer"
    );
}
