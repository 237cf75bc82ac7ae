//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;
use tmm_sheets::pipeline;
use tmm_sheets::project::{LeverProject, Project};
use tmm_sheets::sheets::lever::{self, LeverBuild};
use tmm_sheets::sheets::{COURSE, Context};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every project file in `fixtures/`, sorted by name.
pub fn fixture_names() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("fixtures"))
        .expect("fixtures/ exists")
        .filter_map(|e| {
            let p = e.ok()?.path();
            if p.extension()? != "yaml" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    names.sort();
    names
}

pub fn fixture_text(name: &str) -> String {
    std::fs::read_to_string(root().join("fixtures").join(format!("{name}.yaml"))).expect("fixture exists")
}

pub fn fixture(name: &str) -> Project {
    pipeline::load(&fixture_text(name)).unwrap_or_else(|e| panic!("{name}: {e:#}"))
}

/// The lever sections of a project file's text.
pub fn lever_of(text: &str) -> LeverProject {
    pipeline::load(text).unwrap_or_else(|e| panic!("{e:#}")).lever.expect("a mechanism section")
}

/// The lever sections of a fixture.
pub fn lever(name: &str) -> LeverProject {
    fixture(name).lever.unwrap_or_else(|| panic!("{name} has a mechanism"))
}

/// Sheet 1 of a project, with everything computed for it.
pub fn build_lever(p: &Project) -> LeverBuild {
    let ctx = Context { info: &p.info, sheet_count: COURSE.len() as u32 };
    lever::build(&ctx, p.lever.as_ref().expect("a mechanism section")).unwrap_or_else(|e| panic!("{e}"))
}

/// Relative closeness with an absolute floor.
pub fn close(a: f64, b: f64, rel: f64, floor: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()) + floor
}
