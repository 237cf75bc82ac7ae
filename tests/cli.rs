//! The `tmm` binary as a user runs it.

use std::process::Command;

fn tmm() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmm"))
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("tmm-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn default_build_writes_every_output() {
    let out = temp_dir("default");
    let st = tmm().args(["-o"]).arg(&out).args(["--png-dpi", "20"]).status().unwrap();
    assert!(st.success());
    for f in ["sheet1.svg", "sheet1.pdf", "sheet1.png", "sheet1-velocities.csv", "sheet1-accelerations.csv", "sheet1-tables.md", "results.json"] {
        let meta = std::fs::metadata(out.join(f)).unwrap_or_else(|_| panic!("{f} missing"));
        assert!(meta.len() > 100, "{f} is empty");
    }
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json["sheet1"]["structure"]["dof"], 1);
    assert_eq!(json["sheet1"]["positions"].as_array().unwrap().len(), 9, "8 positions and the second extreme");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn build_subcommand_with_a_project_file_and_language() {
    let out = temp_dir("file");
    let fixture = concat!(env!("CARGO_MANIFEST_DIR"), "/fixtures/kulisa.yaml");
    let st = tmm().args(["build", fixture, "--sheet", "1", "--lang", "en", "--no-png", "--no-pdf", "-o"]).arg(&out).status().unwrap();
    assert!(st.success());
    let svg = std::fs::read_to_string(out.join("sheet1.svg")).unwrap();
    assert!(svg.contains("Velocity plans"));
    assert!(!out.join("sheet1.png").exists() && !out.join("sheet1.pdf").exists());
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn errors_exit_non_zero_with_a_message() {
    let o = tmm().args(["build", "no-such-file.yaml"]).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read no-such-file.yaml"));
    let o = tmm().args(["--sheet", "2", "-o", "/tmp/tmm-never"]).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("sheet 2 is not available yet"));
    let bad = temp_dir("bad").with_extension("yaml");
    std::fs::write(&bad, "project: {title: x}\nmechanism: {frame: [], crank: {pivot: O}}\n").unwrap();
    let o = tmm().arg("build").arg(&bad).output().unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("line 2") && err.contains("missing field"), "{err}");
    assert!(!err.contains("panicked"));
}

#[test]
fn example_prints_a_project_that_builds() {
    let o = tmm().arg("example").output().unwrap();
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(tmm_sheets::pipeline::load(&text).is_ok());
}
