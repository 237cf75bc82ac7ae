//! The layers of ARCHITECTURE.md, enforced: each top-level module may use only the modules
//! listed for it. In particular the pure domains (`lever`, `num`) import nothing from
//! `drawing`, `sheets`, `backend` or the file format, and nothing outside `sheets` names a
//! sheet.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use std::collections::BTreeMap;
use std::path::Path;

/// Module → the crate modules it may use (besides itself).
const ALLOWED: [(&str, &[&str]); 17] = [
    ("num", &[]),
    ("font", &[]),
    ("lever", &["num"]),
    ("gears", &["num"]),
    ("cams", &["num"]),
    ("drawing", &["num", "font"]),
    ("report", &["num", "lever", "gears", "cams"]),
    ("project", &["num", "font", "lever", "gears", "cams", "drawing::labels::Language"]),
    // A check's report to hand back is composed like a sheet.
    ("sheets", &["num", "font", "lever", "gears", "cams", "drawing", "report", "project", "check"]),
    ("backend", &["num", "font", "drawing::scene", "drawing::path"]),
    // The catalogue writes project files' text: it reads no project and draws nothing.
    ("catalogue", &["num", "drawing::labels", "drawing::label_set"]),
    ("check", &["num", "report"]),
    ("pipeline", &["num", "project", "sheets", "backend", "report", "check"]),
    // The web page's calls: the pipeline and the catalogue, without the file system.
    ("session", &["pipeline", "project", "catalogue", "drawing::labels::Language"]),
    // `tmm bench` measures the domains' trade-offs against their exact references.
    ("bench", &["num", "lever", "gears", "cams", "project", "pipeline", "sheets::gears::INVOLUTE_PIECES"]),
    ("cli", &["pipeline", "project", "catalogue", "check", "bench", "num::digits", "drawing::labels::Language"]),
    ("lib", &["*"]),
];

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Every `crate::a::b::…` path in a file, as written.
fn crate_paths(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in text.match_indices("crate::") {
        let rest = &text[i + 7..];
        let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')).unwrap_or(rest.len());
        let path = rest[..end].trim_end_matches(':');
        // `#[macro_export]` puts the drawing kit's `label_set!` and num's `assert_near!` at the
        // crate root.
        out.push(match path {
            "label_set" => "drawing::label_set".to_string(),
            "assert_near" => "num::assert_near".to_string(),
            _ => path.to_string(),
        });
    }
    out
}

#[test]
fn modules_use_only_the_layers_below_them() {
    let src = common::root().join("src");
    let allowed: BTreeMap<&str, &[&str]> = ALLOWED.into_iter().collect();
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut violations = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap();
        let module = rel.iter().next().unwrap().to_string_lossy().trim_end_matches(".rs").to_string();
        if module == "main" {
            continue;
        }
        let ok = allowed
            .get(module.as_str())
            .unwrap_or_else(|| panic!("{}: module '{module}' is not in the layer table", rel.display()));
        let text = std::fs::read_to_string(f).unwrap();
        for path in crate_paths(&text) {
            let target = path.split("::").next().unwrap_or("");
            let fine = target == module
                || ok.contains(&"*")
                || ok.iter().any(|a| path == *a || path.starts_with(&format!("{a}::")) || *a == target);
            if !fine {
                violations.push(format!("{}: uses crate::{path}", rel.display()));
            }
        }
    }
    assert!(violations.is_empty(), "layer violations:\n{}", violations.join("\n"));
}

#[test]
fn only_the_sheets_name_a_sheet_number() {
    for file in ["pipeline.rs", "cli.rs"] {
        let text = std::fs::read_to_string(common::root().join("src").join(file)).unwrap();
        for needle in ["sheet1", "sheet 1", "Sheet1", "lever::", "COURSE[", "sheets::lever"] {
            assert!(!text.contains(needle), "src/{file} names a sheet: {needle}");
        }
    }
}
