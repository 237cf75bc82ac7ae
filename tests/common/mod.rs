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

/// Latin words a Russian sheet must not show: a run of two or more Latin letters with a
/// lowercase one ("mm", "working"), or a unit "N"/"m"/"s"/"kg" after a number or a comma
/// ("0,5 N", "P, N"). Symbols and plan letters ("m", "p=b=s3"), min/max and a derivative's
/// numerator ("ds/dφ") are not words.
pub fn english_on_russian(text: &str) -> Option<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if !chars[i].is_ascii_alphabetic() {
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && chars[i].is_ascii_alphabetic() {
            i += 1;
        }
        let token: String = chars[start..i].iter().collect();
        let before = chars[..start].iter().rev().find(|c| !c.is_whitespace());
        let after_number = before.is_some_and(|c| c.is_ascii_digit() || *c == ',');
        // "min" and "max" are mathematical notation in Russian too (x_min, z_min).
        let math = ["min", "max"].contains(&token.as_str());
        // A derivative's numerator ("ds/dφ") is notation, not a word.
        let derivative = token.starts_with('d') && chars.get(i) == Some(&'/');
        let word = token.len() >= 2 && token.chars().any(|c| c.is_ascii_lowercase()) && !math && !derivative;
        if word || (["N", "m", "s", "kg"].contains(&token.as_str()) && after_number) {
            return Some(token);
        }
    }
    None
}
