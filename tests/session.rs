//! The web page's library calls (`session`) give exactly `tmm build`'s files: the same
//! names, order and bytes, for the worked example and a catalogue variant; a refusal comes
//! back with its line and column; the catalogue index names every task and variant.

mod common;

use std::path::Path;
use std::process::Command;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline::DxfVersion;
use tmm_sheets::session::{self, Request};

/// The files `tmm build ARGS -o DIR` writes, by name.
fn cli_files(args: &[&str], dir: &Path) -> Vec<(String, Vec<u8>)> {
    let o = Command::new(env!("CARGO_BIN_EXE_tmm")).arg("build").args(args).arg("-o").arg(dir).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .map(|e| (e.file_name().into_string().unwrap(), std::fs::read(e.path()).unwrap()))
        // The manifest and the lock are the folder's, not the build's.
        .filter(|(n, _)| !n.starts_with('.'))
        .collect();
    files.sort();
    files
}

fn assert_same(cli: &[(String, Vec<u8>)], mut ours: Vec<(String, Vec<u8>)>) {
    ours.sort();
    let names = |f: &[(String, Vec<u8>)]| f.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(cli), names(&ours));
    for ((name, a), (_, b)) in cli.iter().zip(&ours) {
        assert!(a == b, "{name} differs from the command line's");
    }
}

#[test]
fn the_worked_example_gives_the_command_lines_files() {
    let dir = tempfile::tempdir().unwrap();
    let cli = cli_files(&["--no-png", "--dxf", "--overlay"], dir.path());
    let request = Request { pdf: true, dxf: Some(DxfVersion::R2000), overlay: true, ..Request::default() };
    let (files, notes) = session::build(tmm_sheets::pipeline::DEFAULT_PROJECT, &request).unwrap();
    assert!(notes.is_empty(), "{notes:?}");
    // The order is the command line's own: per sheet, then results.json, then the overlays.
    let order: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    let results = order.iter().position(|n| *n == "results.json").unwrap();
    assert!(order[..results].iter().all(|n| n.starts_with("sheet") && !n.contains("overlay")), "{order:?}");
    assert!(order[results + 1..].iter().all(|n| n.contains("-overlay.")), "{order:?}");
    assert_eq!(order.len(), cli.len());
    assert_same(&cli, files);
}

#[test]
fn a_catalogue_variant_in_russian_gives_the_command_lines_files() {
    let dir = tempfile::tempdir().unwrap();
    let cli = cli_files(
        &["--task", "7", "--variant", "2", "--lang", "ru", "--no-png", "--no-pdf", "--sheet", "1"],
        dir.path(),
    );
    let text = session::variant("7", 2, Language::Ru).unwrap();
    let request = Request { sheets: vec![1], lang: Some(Language::Ru), ..Request::default() };
    let mut s = session::Session::open(&text, &request).unwrap();
    assert_eq!(s.sheets(), &[1]);
    let mut files = s.build_sheet(1).unwrap();
    files.extend(s.finish().unwrap());
    assert_same(&cli, files);
}

#[test]
fn a_refusal_comes_back_with_its_line_column_and_field() {
    let text = tmm_sheets::pipeline::DEFAULT_PROJECT.replacen("z: [", "z: [-", 1);
    let line = 1 + text[..text.find("z: [-").unwrap()].matches('\n').count() as u64;
    let e = session::build(&text, &Request::default()).unwrap_err();
    assert_eq!((e.line, e.field.as_str(), e.kind), (line, "gears.pair.z[0]", "value"), "{e:?}");
    assert!(e.message.starts_with(&format!("line {line}, column ")), "{}", e.message);
    // It refuses sheet 2 alone: the others (sheets 1 and 3) can be built.
    assert_eq!((e.blocks.as_slice(), e.buildable.as_slice()), (&[2][..], &[1, 3][..]));
    // Asked for the others, the refusal is a warning at the same place.
    let request = Request { sheets: vec![1, 3], ..Request::default() };
    let s = session::Session::open(&text, &request).unwrap();
    assert!(s.notes().iter().any(|n| n.line == line && n.field == "gears.pair.z[0]"), "{:?}", s.notes());
}

#[test]
fn the_catalogue_index_names_every_task_and_variant() {
    for lang in Language::ALL {
        let tasks = session::catalogue(lang).unwrap();
        assert_eq!(tasks.iter().filter(|t| !t.practice).count(), 15);
        for t in &tasks {
            assert!(!t.name.is_empty() && !t.variants.is_empty(), "{t:?}");
            for v in &t.variants {
                // Every variant with a project file gives one; the others say why not.
                let given = session::variant(&t.id, v.number, lang);
                assert_eq!(given.is_ok(), v.status != "incomplete", "task {} variant {}: {given:?}", t.id, v.number);
                assert!(v.status == "complete" || !v.note.is_empty(), "{v:?}");
            }
        }
    }
}
