//! The project-file reader under fuzzing: every fixture (and the embedded worked example)
//! mutated by a few edits a hurried student or a broken editor makes — characters deleted,
//! YAML punctuation, hostile numbers and stray bytes inserted, numbers replaced, lines
//! doubled, swapped or re-indented — is read, and either loads (with finite numbers in what it
//! builds) or is refused with a cause and a line inside the file. Never a panic.
//!
//! `FUZZ_CASES` (default 1500 a CI run, a few seconds) sets the number of mutated files;
//! `FUZZ_SEED` (default a fixed 2026; `random` for new ones each run) the files drawn.
//! `FUZZ_CASES=100000 FUZZ_SEED=random cargo test --release --test reader_fuzz` is the long
//! run. A failure prints the mutated file: it becomes a named case in `tests/bad_input.rs`.

mod common;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};
use std::cell::Cell;
use tmm_sheets::pipeline::{self, DEFAULT_PROJECT, Error};

fn cases() -> u32 {
    common::env_cases("FUZZ_CASES", 1500)
}

fn seed() -> RngSeed {
    common::env_seed("FUZZ_SEED")
}

/// The files mutated: the worked example and every fixture.
fn originals() -> Vec<String> {
    let mut out = vec![DEFAULT_PROJECT.to_string()];
    let mut dirs = vec![std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/fixtures"))];
    while let Some(dir) = dirs.pop() {
        let mut entries: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|e| e == "yaml") {
                out.push(std::fs::read_to_string(&p).unwrap());
            }
        }
    }
    out
}

/// What an edit puts in: YAML's punctuation and its traps, numbers no mechanism has, and
/// characters an editor on Windows leaves behind.
const TOKENS: &[&str] = &[
    "-",
    ":",
    ": ",
    "{",
    "}",
    "[",
    "]",
    ",",
    "\"",
    "'",
    "\n",
    "\r\n",
    "\t",
    "  ",
    "#",
    "&a ",
    "*a",
    "!!str ",
    "!!binary ",
    "~",
    "null",
    "? ",
    "|",
    ">",
    "<<: ",
    "%YAML 1.2\n",
    "---\n",
    "...\n",
    "0",
    "-0",
    "1e308",
    "-1e308",
    "1e-320",
    ".nan",
    ".inf",
    "-.inf",
    "NaN",
    "0x1F",
    "0o17",
    "1_000",
    "99999999999999999999",
    "-1",
    "1.5.2",
    "yes",
    "no",
    "on",
    "0,5",
    "1/2",
    "é",
    "Ё",
    "１",
    "\u{0}",
    "\u{FEFF}",
    "\u{200B}",
    "\u{202E}",
    "𝜔",
    "\u{7F}",
];

/// One edit of a text, at a place given as a fraction of its length.
#[derive(Debug, Clone)]
enum Edit {
    Delete {
        at: f64,
        len: usize,
    },
    Insert {
        at: f64,
        token: usize,
    },
    /// The next number from `at` replaced by a token.
    ReplaceNumber {
        at: f64,
        token: usize,
    },
    DoubleLine {
        at: f64,
    },
    SwapLines {
        a: f64,
        b: f64,
    },
    /// A line indented by `by` more spaces (or fewer, when negative).
    Indent {
        at: f64,
        by: i8,
    },
}

fn edit() -> impl Strategy<Value = Edit> {
    let at = 0.0..1.0f64;
    let token = 0..TOKENS.len();
    prop_oneof![
        (at.clone(), 1..12usize).prop_map(|(at, len)| Edit::Delete { at, len }),
        (at.clone(), token.clone()).prop_map(|(at, token)| Edit::Insert { at, token }),
        (at.clone(), token).prop_map(|(at, token)| Edit::ReplaceNumber { at, token }),
        at.clone().prop_map(|at| Edit::DoubleLine { at }),
        (at.clone(), at.clone()).prop_map(|(a, b)| Edit::SwapLines { a, b }),
        (at, -4..5i8).prop_map(|(at, by)| Edit::Indent { at, by }),
    ]
}

/// The char boundary nearest the fraction `at` of `s`.
fn boundary(s: &str, at: f64) -> usize {
    let mut i = ((s.len() as f64 * at) as usize).min(s.len());
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

fn apply(s: &str, e: &Edit) -> String {
    let mut s = s.to_string();
    let line_of = |s: &str, at: f64| {
        let n = s.lines().count().max(1);
        ((n as f64 * at) as usize).min(n - 1)
    };
    match *e {
        Edit::Delete { at, len } => {
            let i = boundary(&s, at);
            let j = s[i..].char_indices().nth(len).map_or(s.len(), |(k, _)| i + k);
            s.replace_range(i..j, "");
        }
        Edit::Insert { at, token } => {
            let i = boundary(&s, at);
            s.insert_str(i, TOKENS[token]);
        }
        Edit::ReplaceNumber { at, token } => {
            let i = boundary(&s, at);
            if let Some(k) = s[i..].find(|c: char| c.is_ascii_digit()) {
                let start = i + k;
                let end = s[start..].find(|c: char| !(c.is_ascii_digit() || c == '.')).map_or(s.len(), |n| start + n);
                s.replace_range(start..end, TOKENS[token]);
            }
        }
        Edit::DoubleLine { at } => {
            let mut lines: Vec<&str> = s.lines().collect();
            if !lines.is_empty() {
                let k = line_of(&s, at);
                lines.insert(k, lines[k]);
            }
            s = lines.join("\n");
        }
        Edit::SwapLines { a, b } => {
            let mut lines: Vec<&str> = s.lines().collect();
            if !lines.is_empty() {
                let (i, j) = (line_of(&s, a), line_of(&s, b));
                lines.swap(i, j);
            }
            s = lines.join("\n");
        }
        Edit::Indent { at, by } => {
            let mut lines: Vec<String> = s.lines().map(str::to_string).collect();
            if !lines.is_empty() {
                let k = line_of(&s, at);
                let l = &mut lines[k];
                if by >= 0 {
                    l.insert_str(0, &" ".repeat(by as usize));
                } else {
                    let n = l.len() - l.trim_start_matches(' ').len();
                    l.replace_range(0..n.min((-by) as usize), "");
                }
            }
            s = lines.join("\n");
        }
    }
    s
}

/// Whether an SVG attribute (a coordinate, a size: not the texts, which may quote the
/// student's own "NaN") holds a number that is not finite.
fn writes_non_finite(svg: &str) -> bool {
    svg.split("=\"").skip(1).filter_map(|rest| rest.split('"').next()).any(|value| {
        value
            .split(|c: char| !(c.is_alphanumeric() || c == '.' || c == '-'))
            .any(|w| matches!(w, "NaN" | "nan" | "inf" | "-inf" | "Infinity" | "-Infinity"))
    })
}

#[test]
fn a_mutated_project_file_loads_or_is_refused_with_a_line_never_a_panic() {
    let originals = originals();
    let config = Config { cases: cases(), rng_seed: seed(), failure_persistence: None, ..Config::default() };
    let mut runner = TestRunner::new(config);
    let strategy = (0..originals.len(), prop::collection::vec(edit(), 1..5), 0..16u8);
    let (loaded, refused, built) = (Cell::new(0u32), Cell::new(0u32), Cell::new(0u32));
    let result = runner.run(&strategy, |(k, edits, build_one_in)| {
        let text = edits.iter().fold(originals[k].clone(), |s, e| apply(&s, e));
        match pipeline::load(&text) {
            Ok(p) => {
                loaded.set(loaded.get() + 1);
                // Building is a hundred times dearer than reading: one loaded file in 16.
                if build_one_in == 0 {
                    built.set(built.get() + 1);
                    if let Ok(sheets) = pipeline::build(&p, &[]) {
                        for b in &sheets {
                            prop_assert!(
                                !writes_non_finite(&b.svg),
                                "sheet {} writes a NaN or inf:\n{text}",
                                b.output.number
                            );
                        }
                    }
                }
            }
            Err(Error::Refused(r)) => {
                refused.set(refused.get() + 1);
                let lines = text.lines().count() as u64 + 1;
                let f = &r.refusal;
                prop_assert!(!f.cause.trim().is_empty(), "a refusal without a cause:\n{text}");
                prop_assert!(f.line >= 1 && f.line <= lines, "line {} of {lines}: {}\n{text}", f.line, f.cause);
            }
            Err(other) => prop_assert!(false, "{other}:\n{text}"),
        }
        Ok(())
    });
    eprintln!("{} loaded ({} of them built), {} refused", loaded.get(), built.get(), refused.get());
    if let Err(e) = result {
        panic!("{e}");
    }
}
