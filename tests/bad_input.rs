//! The corpus of hostile project files (`tests/bad-input/`): each is a small valid project
//! (`base.yaml`) with one thing wrong, and its second line says how it must be refused —
//! the kind, the field's path and the line. Every refusal names the line, the column and the
//! field path (a refusal of the whole document names the document) and says why in the
//! course's words: no Rust type, no serde or YAML-library term.

mod common;

use common::root;
use std::path::PathBuf;
use tmm_sheets::pipeline;
use tmm_sheets::project::{Kind, Refusal};

fn corpus() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("tests/bad-input"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml") && p.file_stem().is_some_and(|s| s != "base"))
        .collect();
    files.sort();
    files
}

/// Loads and builds every sheet; the refusal, if any.
fn refusal_of(text: &str) -> Option<Refusal> {
    match pipeline::load(text).and_then(|p| pipeline::build(&p, &[]).map(|_| ())) {
        Ok(()) => None,
        Err(pipeline::Error::Refused(r)) => Some(r.refusal),
        Err(other) => panic!("not a refusal: {other}"),
    }
}

/// Words that belong to the program's insides, not to the course.
const INTERNALS: [&str; 14] = [
    "u32",
    "f64",
    "usize",
    "struct ",
    "enum ",
    "variant",
    "Spanned",
    "serde",
    "Options",
    "from_str",
    "ScalarBytes",
    "untagged",
    "DuplicateKeyPolicy",
    "invalid type",
];

/// The header's "Refused: <kind> at <path>, line <n>".
fn expected(text: &str, name: &str) -> (String, String, u64) {
    let header = text.lines().nth(1).unwrap_or_default();
    let rest = header.strip_prefix("# Refused: ").unwrap_or_else(|| panic!("{name}: no header"));
    let (kind, rest) = rest.split_once(" at ").unwrap_or_else(|| panic!("{name}: header {header:?}"));
    let (path, line) = rest.rsplit_once(", line ").unwrap_or_else(|| panic!("{name}: header {header:?}"));
    let path = if path == "(file)" { "" } else { path };
    (kind.to_string(), path.to_string(), line.parse().unwrap_or_else(|_| panic!("{name}: header {header:?}")))
}

#[test]
fn the_base_of_the_corpus_builds() {
    let text = std::fs::read_to_string(root().join("tests/bad-input/base.yaml")).unwrap();
    assert_eq!(refusal_of(&text), None);
}

#[test]
fn every_bad_input_is_refused_with_its_kind_field_line_and_reason() {
    let files = corpus();
    assert!(files.len() >= 100, "the corpus has {} files", files.len());
    let mut failures = Vec::new();
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let text = std::fs::read_to_string(f).unwrap();
        let Some(r) = refusal_of(&text) else {
            failures.push(format!("{name}: built, must be refused"));
            continue;
        };
        let actual =
            format!("{} at {}, line {}", r.kind.key(), if r.path.is_empty() { "(file)" } else { &r.path }, r.line);
        let (kind, path, line) = expected(&text, &name);
        if (kind.as_str(), path.as_str(), line) != (r.kind.key(), r.path.as_str(), r.line) {
            failures.push(format!("{name}: refused as {actual} — {}", r.cause));
        }
        let whole_file = matches!(r.kind, Kind::Syntax | Kind::Section);
        assert!(r.line >= 1 && r.column >= 1, "{name}: {r}");
        assert!(!r.path.is_empty() || whole_file, "{name}: no field named: {r}");
        assert!(!r.cause.trim().is_empty(), "{name}: no reason");
        if let Some(word) = INTERNALS.iter().find(|w| r.cause.contains(*w)) {
            failures.push(format!("{name}: the reason says {word:?}: {}", r.cause));
        }
    }
    assert!(failures.is_empty(), "{} of {}:\n{}", failures.len(), files.len(), failures.join("\n"));
}

/// A refusal of one section refuses its sheet only: the other sheets build from the same
/// file, with the refusal as a warning naming the field (`--sheet 1` of a project whose
/// `cam` section is wrong still builds sheet 1).
#[test]
fn a_refused_section_blocks_its_own_sheet_only() {
    let mut checked = 0;
    for f in corpus() {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let text = std::fs::read_to_string(&f).unwrap();
        let (refusal, blocks, buildable) =
            match pipeline::load(&text).and_then(|p| pipeline::build(&p, &[]).map(|_| ())) {
                Err(pipeline::Error::Refused(r)) => (r.refusal, r.blocks, r.buildable),
                other => panic!("{name}: {other:?}"),
            };
        if refusal.section.is_none() {
            assert_eq!(blocks, [1, 2, 3], "{name}: a refusal of the whole file blocks every sheet");
            continue;
        }
        assert_eq!(blocks.len(), 1, "{name}: {blocks:?}");
        let others: Vec<u32> = buildable.into_iter().filter(|n| !blocks.contains(n)).collect();
        let p = match pipeline::load_for(&text, &others) {
            Ok(p) => p,
            // Sheet 2 takes n1 from the crank: a crank whose speed cannot be read blocks it too.
            Err(e) if e.to_string().contains("the `mechanism` section is refused") => continue,
            Err(e) => panic!("{name}: the other sheets: {e}"),
        };
        // A refusal found when the file is read warns; one found building the sheet (a
        // mechanism that cannot turn) is not met when that sheet is not built.
        let found_reading = pipeline::load(&text).is_err();
        assert!(
            !found_reading || p.warnings.iter().any(|w| w.field == refusal.path && w.line == refusal.line),
            "{name}: no warning names {}: {:?}",
            refusal.path,
            p.warnings
        );
        // Building is the slow part: every eighth file builds its other sheets, the rest
        // check that they are selected.
        if checked % 8 == 0 {
            let built = pipeline::build(&p, &others).unwrap_or_else(|e| panic!("{name}: {e}"));
            let numbers: Vec<u32> = built.iter().map(|b| b.output.number).collect();
            assert_eq!(numbers, others, "{name}");
        } else {
            let selected = tmm_sheets::sheets::select(&p, &others).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(selected.iter().map(|s| s.kind().number).collect::<Vec<_>>(), others, "{name}");
        }
        checked += 1;
    }
    assert!(checked >= 60, "only {checked} section refusals in the corpus");
}
