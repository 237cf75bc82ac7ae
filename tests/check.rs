//! `tmm check` as a teacher runs it: the worked example's exact values pass, a wrong pb
//! fails by name, lengths on a drawing with its scale are checked at that scale, an empty or
//! unreadable file is refused with exit 2, an unknown name lists the close ones.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

use std::process::{Command, Output};

/// A file holding `text`, named `…-NAME` (its extension is what `tmm check` reads), removed
/// when dropped.
fn temp(name: &str, text: &str) -> tempfile::TempPath {
    let file = tempfile::Builder::new().prefix("tmm-check-").suffix(&format!("-{name}")).tempfile().unwrap();
    std::fs::write(file.path(), text).unwrap();
    file.into_temp_path()
}

fn check(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmm")).arg("check").args(args).output().unwrap()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every answer of the worked example, as `tmm build` writes them in results.json.
fn answers() -> Vec<(String, f64, String)> {
    let dir = std::env::temp_dir().join(format!("tmm-check-build-{}", std::process::id()));
    let o = Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(["build", "--no-png", "--no-pdf", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(o.status.success());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("results.json")).unwrap()).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    json["answers"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(id, a)| (id.clone(), a["value"].as_f64().unwrap(), a["unit"].as_str().unwrap().to_string()))
        .collect()
}

#[test]
fn the_worked_examples_exact_values_all_pass() {
    let all = answers();
    assert!(all.len() > 300);
    let mut csv = String::from("id,value,unit\n");
    for (id, v, u) in &all {
        csv.push_str(&format!("{id},{v:.12},{u}\n"));
    }
    let o = check(&[temp("exact.csv", &csv).to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains(&format!("{n} of {n} values pass", n = all.len())));
}

#[test]
fn a_wrong_pb_fails_by_its_name_and_the_right_one_passes_at_the_students_scale() {
    // v_A at any position from the guide's data alone: n₁ = 70 rev/min, l_OA = 0.12 m.
    let v_a = 70.0 * std::f64::consts::PI / 30.0 * 0.12;
    let text = format!(
        "id;position;value;unit;mm;scale\n\
         v_A;0;{};m/s;;\n\
         pb;3;;;52,0;0,02\n\
         pb;4;;;45;0,02\n\
         v_B;3;1041;mm/s;;\n",
        format!("{v_a:.4}").replace('.', ",")
    );
    let o = check(&[temp("pb.csv", &text).to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    let line =
        |n: &str| out.lines().find(|l| l.starts_with(n)).unwrap_or_else(|| panic!("no line {n}:\n{out}")).to_string();
    assert!(line("2 ").contains("sheet1.velocities.v_A.0") && line("2 ").ends_with("pass"), "{out}");
    // 52.0 mm at 0.02 (m/s)/mm against pb = 52.04 mm: within 0.5 mm.
    assert!(line("3 ").contains("sheet1.plan.v.3.pb") && line("3 ").ends_with("pass"), "{out}");
    // 45 mm against pb = 36.95 mm at position 4: 0.9 m/s for 0.739 m/s.
    assert!(line("4 ").contains("sheet1.plan.v.4.pb") && line("4 ").ends_with("FAIL"), "{out}");
    assert!(line("5 ").ends_with("pass"), "mm/s converts: {out}");
    assert!(out.contains("3 of 4 values pass"));
}

#[test]
fn tolerances_given_per_row_and_for_all() {
    // v_B at 3 is 1.0408 m/s: 1.06 is 1.8 % off (passes 2 %), fails a 1 % tolerance.
    let text = "id,value,tolerance\nv_B.3,1.06,\nv_B.3,1.06,1%\nv_B.3,1.06,0.03\n";
    let f = temp("tol.csv", text);
    let o = check(&[f.to_str().unwrap()]);
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("2 of 3 values pass"), "{out}");
    let o = check(&[f.to_str().unwrap(), "--tolerance", "1"]);
    assert!(stdout(&o).contains("1 of 3 values pass"), "{}", stdout(&o));
}

#[test]
fn bad_files_are_refused_with_exit_2_and_the_reason() {
    for (text, says) in [
        ("", "no values to check"),
        ("id,value\n", "no values to check"),
        ("id,unit\nv_B.3,m/s\n", "no column value"),
        ("id,value\nv_B.3,fast\n", "line 2: value: 'fast' is not a number"),
        ("id,value\nv_b.33,1\n", "did you mean"),
        ("id,value,unit\nv_B.3,1,kg\n", "'kg' is not a unit of sheet1.velocities.v_B.3"),
        ("id,value\nv_B,1\n", "could be any of"),
        ("id,mm\nv_B.3,40\n", "give the scale"),
        ("id;position;value\nab;3;0,40\n", "could be any of sheet1.plan.v.3.ab, sheet1.plan.a.3.ab"),
        ("id;value;Ед. изм.;примечание\nv_B.3;1;м/с;x\n", "column 'примечание' is not one this reads"),
        ("# a comment\r\nid,value\r\n\r\nv_B.3,1\r\nv_X.3,1\r\n", "line 5: 'v_X.3'"),
    ] {
        let o = check(&[temp("bad.csv", text).to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{text:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(says), "{text:?}: {}", stderr(&o));
    }
    let o = check(&["/nonexistent/values.csv"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_prime_typed_as_an_apostrophe_a_length_in_mm_and_a_centre_of_mass() {
    let text = "id,position,value,unit\nv_B,4',0,m/s\nan_BA,3,3.5,mm\nps2,3,0.9425,m/s\nv_B.3,1.0408,\n";
    let o = check(&[temp("prime.csv", text).to_str().unwrap()]);
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{out}{}", stderr(&o));
    assert!(out.contains("sheet1.velocities.v_B.4p") && out.contains("sheet1.plan.a.3.an_BA"), "{out}");
    assert!(out.contains("sheet1.plan.v.3.ps2"), "{out}");
}

#[test]
fn the_values_are_never_overwritten_and_the_project_goes_after_the_subcommand() {
    let f = temp("own.csv", "id,value\nv_B.3,1.04\n");
    let o = check(&[f.to_str().unwrap(), "-o", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&f).unwrap(), "id,value\nv_B.3,1.04\n");
    let project = concat!(env!("CARGO_MANIFEST_DIR"), "/fixtures/kulisa.yaml");
    let o = Command::new(env!("CARGO_BIN_EXE_tmm")).args([project, "check"]).arg(&f).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("comes before the subcommand"), "{}", stderr(&o));
}

#[test]
fn the_report_is_written_as_markdown_or_csv() {
    let f = temp("md.csv", "id,value\nsheet3.results.r_min,1\n");
    // The reports in a directory of their own, removed when dropped (beside the input they
    // were left in the system's temporary directory under fixed names).
    let dir = tempfile::tempdir().unwrap();
    let md = dir.path().join("report.md");
    let o = check(&[f.to_str().unwrap(), "-o", md.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    let text = std::fs::read_to_string(&md).unwrap();
    assert!(text.starts_with("| line | id |") && text.contains("FAIL") && text.contains("0 of 1 values pass"));
    let csv = dir.path().join("report.csv");
    check(&[f.to_str().unwrap(), "-o", csv.to_str().unwrap()]);
    assert!(std::fs::read_to_string(&csv).unwrap().starts_with("line,id,name,exact,student"));
}

#[test]
fn the_report_to_hand_back_is_a_pdf_of_a4_pages_in_the_projects_language() {
    let all = answers();
    let mut csv = String::from("id,value,unit\n");
    for (id, v, u) in &all {
        csv.push_str(&format!("{id},{v:.12},{u}\n"));
    }
    csv.push_str("v_B.3,0.5,m/s\n");
    let f = temp("pdf.csv", &csv);
    let dir = tempfile::tempdir().unwrap();
    let pdf = dir.path().join("report.pdf");
    let o = check(&[f.to_str().unwrap(), "-o", pdf.to_str().unwrap(), "--lang", "ru"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let bytes = std::fs::read(&pdf).unwrap();
    assert!(bytes.starts_with(b"%PDF-"));
    // The same report twice is the same file.
    let again = dir.path().join("again.pdf");
    check(&[f.to_str().unwrap(), "-o", again.to_str().unwrap(), "--lang", "ru"]);
    assert_eq!(bytes, std::fs::read(&again).unwrap());
    let Ok(text) = Command::new("pdftotext").args(["-layout"]).arg(&pdf).arg("-").output() else {
        eprintln!("pdftotext is not installed: the report's text is not read back");
        return;
    };
    let text = String::from_utf8_lossy(&text.stdout);
    // 26 rows a page: every value on some page, the summary and the signature on each.
    let pages = (all.len() + 1).div_ceil(26);
    assert!(text.contains(&format!("Лист {pages} из {pages}")), "{pages} pages? {}", &text[..text.len().min(3000)]);
    assert!(text.contains(&format!("Верно {} из {} значений", all.len(), all.len() + 1)));
    assert_eq!(text.matches("Преподаватель").count(), pages);
    assert_eq!(text.matches("НЕВЕРНО").count(), 1, "the wrong v_B.3 alone fails");
    assert!(!text.contains("pass") && !text.contains("FAIL"), "English on the Russian report");
}

#[test]
fn every_row_that_cannot_be_checked_is_named_at_once_and_a_repeated_one_is_warned() {
    let o = check(&[temp("many.csv", "id,value\nv_X.3,1\nv_B.3,1.04\nv_B.3,1,kg\nqq,2\n").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("line 2: 'v_X.3'") && err.contains("line 5: 'qq'"), "{err}");
    let o = check(&[temp("twice.csv", "id,value\nv_B.3,1.04\nv_B.3,1.041\n").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("line 3: sheet1.velocities.v_B.3 is given on line 2 too"), "{}", stderr(&o));
}

#[test]
fn a_gears_radius_in_mm_is_its_value_and_its_drawn_length_comes_with_the_mm_column() {
    // The worked example's wheel 1: r_b1 = 42.5·cos 20° = 39.937 mm, drawn at 5:1.
    let r_b1 = 42.5 * 20f64.to_radians().cos();
    let text = format!("id,value,unit\nr_b1,{:.2},mm\nr_b1,{:.4},cm\n", r_b1, r_b1 / 10.0);
    let o = check(&[temp("radius.csv", &text).to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let text = format!("id,mm\nmesh.drawing.r_b1,{:.1}\n", 5.0 * r_b1);
    let o = check(&[temp("paper.csv", &text).to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    // Read as a paper length, 39.94 mm would be a fifth of the drawn 199.7 mm: it must not be.
    assert!(stdout(&o).contains("199.7"), "{}", stdout(&o));
}

/// Where the law's acceleration jumps at a position (the custom-laws fixture's return at
/// position 11: −3 then +1 of 30 mm/(0.375·φ_ret²), computed here), the table prints both
/// values and either one passes; a value near neither fails.
#[test]
fn at_a_jump_either_value_passes() {
    let project = concat!(env!("CARGO_MANIFEST_DIR"), "/fixtures/cams/custom-laws.yaml");
    let per_rad2 = 30.0 / (0.375 * 80f64.to_radians().powi(2));
    let run = |v: f64| {
        let text = format!("id,value,unit\nsheet3.law-return.d2s_dphi2.11,{v:.2},mm\n");
        check(&[project, temp("jump.csv", &text).to_str().unwrap()])
    };
    for v in [-3.0 * per_rad2, per_rad2] {
        let o = run(v);
        assert_eq!(o.status.code(), Some(0), "{v}: {}{}", stdout(&o), stderr(&o));
    }
    let o = run(-per_rad2);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
}
