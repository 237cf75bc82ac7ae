//! The catalogue as a user runs it: `tmm list`, `tmm init`, `tmm build --task/--all`, on a
//! small sample catalogue written for the test (tests/catalogue-sample: four rows of table
//! 7.1, one with a planted misprint and one with a lost cell), and the embedded catalogue's
//! own consistency.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn sample() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/catalogue-sample")
}

fn tmm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmm")).arg("--catalogue").arg(sample()).args(args).output().unwrap()
}

fn temp_dir(name: &str) -> common::Scratch {
    common::Scratch::new(&format!("catalogue-{name}"))
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn init_writes_every_value_with_its_table_and_applies_the_errata() {
    let o = tmm(&["init", "--task", "7", "--variant", "3", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let y = text(&o.stdout);
    // Row 3 as printed: L_O1A = 1,60 (planted misprint, corrected to 0,160), n_1 = 48.
    assert!(y.contains("crank: {pivot: O, pin: A, length: 0.16, rpm: 48, sense: cw}"), "{y}");
    assert!(y.contains(
        "# L_O1A = 0.160 m (crank): table 7.1, variant 3; printed 1.60; corrected: test: the decimal comma slipped"
    ));
    assert!(y.contains("#   L_O1A: 1.60 → 0.160: test: the decimal comma slipped"), "the header lists the errata");
    // kN to N and mm to m through the template's expressions, each computed value named.
    assert!(y.contains("force: 3500}") && y.contains("# P_cmax = 3.5 kN (resistance): table 7.1, variant 3"), "{y}");
    assert!(y.contains("# p_n = 3500 N (resistance in newtons): computed: p_max*1000 = 3500"), "a derived value: {y}");
    assert!(y.contains("stroke: 0.04}"), "{y}");
    // A constant of the task's notes, with its source.
    assert!(y.contains("# m_pl = 2 mm (planetary module): note d)"), "{y}");
    assert!(!y.contains("${"), "every placeholder is filled");
}

#[test]
fn init_comments_in_the_chosen_language_with_decimal_commas() {
    let y = text(&tmm(&["init", "--task", "7", "--variant", "1", "--lang", "ru"]).stdout);
    assert!(y.contains("# L_O1A = 0,120 м (кривошип): табл. 7.1, вариант 1"), "{y}");
    assert!(y.contains("# вычислено: h/1000 = 0,035"), "{y}");
    let y = text(&tmm(&["init", "--task", "7", "--variant", "1"]).stdout);
    assert!(y.contains("# n_1 = 50 ayl/min (krivoship): 7.1-jadval, 1-variant"), "Uzbek by default: {y}");
}

#[test]
fn an_incomplete_variant_is_refused_with_the_lost_value_and_why() {
    let o = tmm(&["init", "--task", "7", "--variant", "5", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(1));
    let e = text(&o.stderr);
    assert!(e.contains("task 7, variant 5 is incomplete in the guide: no value for L_AB, m_2, J_S2"), "{e}");
    assert!(e.ends_with("(test: a lost cell)\n"), "{e}");
}

#[test]
fn a_variant_that_lost_one_sheets_values_gives_the_others() {
    let o = tmm(&["init", "--task", "7", "--variant", "4", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let y = text(&o.stdout);
    assert!(y.contains("# Incomplete in the guide, left out: mechanism (L_AB); analysis; forces"), "{y}");
    assert!(
        y.contains("# mechanism: left out: the guide lost L_AB") && y.contains("\ngears:\n") && y.contains("\ncam:\n")
    );
    assert!(!y.contains("\nmechanism:") && !y.contains("\nforces:"), "{y}");
    let out = temp_dir("part");
    let o = tmm(&["build", "--task", "7", "--variant", "4", "--no-png", "--no-pdf", "-o", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).starts_with("task 7 variant 4: sheet 2, 3 written"), "{}", text(&o.stdout));
}

#[test]
fn an_unknown_task_or_variant_is_a_usage_error_naming_what_exists() {
    let o = tmm(&["init", "--task", "8", "--variant", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("there is no task `8` in the catalogue (tasks: 7)"));
    let o = tmm(&["build", "--task", "7", "--variant", "44"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("task 7 has no variant 44 (its variants are 1–5)"));
}

#[test]
fn init_never_overwrites_a_project_file_without_force() {
    let dir = temp_dir("init");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("my.yaml");
    std::fs::write(&file, "my edits").unwrap();
    let f = file.to_str().unwrap();
    let o = tmm(&["init", "--task", "7", "--variant", "2", "-o", f]);
    assert_eq!(o.status.code(), Some(3));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "my edits");
    let o = tmm(&["init", "--task", "7", "--variant", "2", "-o", f, "--force"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(std::fs::read_to_string(&file).unwrap().contains("rpm: 60"));
}

#[test]
fn list_shows_the_tasks_and_a_tasks_variants_with_the_incomplete_ones() {
    let o = tmm(&["list", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(0));
    let l = text(&o.stdout);
    assert!(l.contains("7    Crank-slider press  crank-slider mechanism  1–5       5           4        none"), "{l}");
    assert!(l.contains("No. 7, 4–5: test: a lost cell"), "{l}");
    let l = text(&tmm(&["list", "--task", "7", "--lang", "ru"]).stdout);
    assert!(l.contains("3        7.1    48           0,160*    0,52     40"), "{l}");
    assert!(
        l.contains("5: неполные: L_AB, m_2, J_S2, m_3, P_cmax, m, z_1"),
        "lost columns, never a derived value: {l}"
    );
    assert!(l.contains("* вариант 3, L_O1A: 1,60 → 0,160"), "{l}");
}

#[test]
fn build_all_writes_every_variant_and_a_summary_and_says_what_was_refused() {
    let out = temp_dir("all");
    let o = tmm(&["build", "--all", "-j", "2", "--no-png", "--no-pdf", "-o", out.to_str().unwrap()]);
    // Rows 1 and 3 ask for planetary ratios a single-row stage cannot give: refused, exit 1.
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 6, "{csv}");
    assert!(rows[0].starts_with("task,variant,status,refusal_kind,reason,explained,warnings,sheet1.balancing.P_m"));
    assert!(rows[2].starts_with("7,2,built,"), "{}", rows[2]);
    assert!(rows[1].starts_with("7,1,refused,design,"), "{}", rows[1]);
    assert!(rows[4].starts_with("7,4,built in part (the guide lost the rest),,"), "{}", rows[4]);
    assert!(rows[5].starts_with("7,5,incomplete in the guide,incomplete,"), "{}", rows[5]);
    // The refused variant still has the sheets its refusal does not concern.
    assert!(out.join("task-07/variant-01/sheet1.svg").is_file() && !out.join("task-07/variant-01/sheet2.svg").exists());
    assert!(out.join("task-07/variant-02/sheet2.svg").is_file());
    assert!(out.join("task-07/variant-04/sheet3.svg").is_file() && !out.join("task-07/variant-04/sheet1.svg").exists());
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("| built | 1 |") && md.contains("| refused | 2 |") && md.contains("| design | 2 |"), "{md}");
}

#[test]
fn build_all_with_sheet_builds_only_that_sheet_of_the_variants_that_have_it() {
    let out = temp_dir("all-sheet3");
    let args = ["build", "--all", "--sheet", "3", "-j", "1", "--no-png", "--no-pdf", "--dxf", "--overlay", "-o"];
    let o = tmm(&[&args[..], &[out.to_str().unwrap()]].concat());
    // Sheet 3 of rows 1 and 3 builds: their planetary stages are not asked for.
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert!(rows[1].starts_with("7,1,built"), "{}", rows[1]);
    assert!(rows[5].starts_with("7,5,incomplete in the guide,"), "{}", rows[5]);
    assert_eq!(o.status.code(), Some(0), "{csv}\n{}", text(&o.stderr));
    // A batch writes what a single build writes: the DXF and the overlay too.
    for f in ["sheet3.svg", "sheet3.dxf", "sheet3-overlay.svg", "sheet3-overlay.pdf", "sheet3-segments.csv"] {
        assert!(out.join("task-07/variant-01").join(f).is_file(), "{f}");
    }
    for v in 1..=4 {
        let dir = out.join(format!("task-07/variant-0{v}"));
        assert!(!dir.join("sheet1.svg").exists() && !dir.join("sheet2.svg").exists(), "variant {v}");
    }
}

#[test]
fn build_task_builds_that_variant_like_a_project_file() {
    let out = temp_dir("task");
    let o = tmm(&["build", "--task", "7", "--variant", "2", "--no-png", "--no-pdf", "-o", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).starts_with("task 7 variant 2: sheet 1, 2, 3 written"));
    let results = std::fs::read_to_string(out.join("results.json")).unwrap();
    assert!(results.contains("\"sheet2.pair.epsilon\""));
}
