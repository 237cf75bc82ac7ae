//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;
use tmm_sheets::pipeline::{self, Project};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every project file in `fixtures/`, sorted by name.
pub fn fixture_names() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("fixtures"))
        .expect("fixtures/ exists")
        .filter_map(|e| {
            let p = e.ok()?.path();
            if p.extension()? != "yaml" { return None; }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    names.sort();
    names
}

pub fn fixture(name: &str) -> Project {
    let text = std::fs::read_to_string(root().join("fixtures").join(format!("{name}.yaml"))).expect("fixture exists");
    pipeline::load(&text).unwrap_or_else(|e| panic!("{name}: {e:#}"))
}

/// Relative closeness with an absolute floor.
pub fn close(a: f64, b: f64, rel: f64, floor: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()) + floor
}
