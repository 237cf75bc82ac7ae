//! The `tmm` binary as a user runs it: outputs, messages, exit codes, the output folder.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use std::path::Path;
use std::process::{Command, Output};

fn tmm() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmm"))
}

fn temp_dir(name: &str) -> common::Scratch {
    common::Scratch::new(&format!("cli-{name}"))
}

fn run(args: &[&str], out: &Path) -> Output {
    tmm().args(args).arg("-o").arg(out).output().unwrap()
}

fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

fn fixture(name: &str) -> String {
    format!("{}/fixtures/{name}.yaml", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn default_build_writes_every_output_and_says_so_on_stdout() {
    let out = temp_dir("default");
    let o = run(&["--png-dpi", "20"], &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("sheet 1, 2, 3 written to") && stdout.contains("(30 files)"), "{stdout}");
    let expected = [
        ".tmm-lock",
        ".tmm-outputs",
        "results.json",
        "sheet1-accelerations.csv",
        "sheet1-balancing.csv",
        "sheet1-inertia.csv",
        "sheet1-reactions.csv",
        "sheet1-segments.csv",
        "sheet1-tables.md",
        "sheet1-velocities.csv",
        "sheet1.pdf",
        "sheet1.png",
        "sheet1.svg",
        "sheet2-conditions.csv",
        "sheet2-pair.csv",
        "sheet2-planetary.csv",
        "sheet2-segments.csv",
        "sheet2-tables.md",
        "sheet2-wheels.csv",
        "sheet2.pdf",
        "sheet2.png",
        "sheet2.svg",
        "sheet3-law-return.csv",
        "sheet3-law-rise.csv",
        "sheet3-profile-return.csv",
        "sheet3-profile-rise.csv",
        "sheet3-results.csv",
        "sheet3-segments.csv",
        "sheet3-tables.md",
        "sheet3.pdf",
        "sheet3.png",
        "sheet3.svg",
    ];
    assert_eq!(listing(&out), expected);
    for f in &expected[2..] {
        assert!(std::fs::metadata(out.join(f)).unwrap().len() > 100, "{f} is empty");
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json["sheet1"]["structure"]["dof"], 1);
    assert_eq!(json["sheet1"]["positions"].as_array().unwrap().len(), 9, "8 positions and the second extreme");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn dxf_and_overlay_are_written_when_asked_for() {
    let out = temp_dir("dxf");
    let o = run(&["build", "--sheet", "2", "--no-png", "--no-pdf", "--dxf", "--overlay"], &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let files = listing(&out);
    for f in ["sheet2.dxf", "sheet2-overlay.svg", "sheet2-overlay.pdf"] {
        assert!(files.contains(&f.to_string()), "{f} missing from {files:?}");
    }
    let dxf = std::fs::read_to_string(out.join("sheet2.dxf")).unwrap();
    assert!(dxf.contains("AC1015"), "R2000 by default");
    let o = run(&["build", "--sheet", "2", "--no-png", "--no-pdf", "--dxf-version", "r12"], &out);
    assert_eq!(o.status.code(), Some(0));
    assert!(std::fs::read_to_string(out.join("sheet2.dxf")).unwrap().contains("AC1009"));
    // The overlay is not asked for this time: the manifest removes the last build's.
    assert!(!listing(&out).contains(&"sheet2-overlay.svg".to_string()));
    let o = run(&["build", "--dxf-version", "r14"], &out);
    assert_eq!(o.status.code(), Some(2), "an unknown DXF version is a usage error");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn build_subcommand_with_a_project_file_and_language() {
    let out = temp_dir("file");
    let o = run(&["build", &fixture("kulisa"), "--sheet", "1", "--lang", "en", "--no-png", "--no-pdf"], &out);
    assert!(o.status.success());
    let svg = std::fs::read_to_string(out.join("sheet1.svg")).unwrap();
    assert!(svg.contains("Velocity plans"));
    assert!(!out.join("sheet1.png").exists() && !out.join("sheet1.pdf").exists());
    let _ = std::fs::remove_dir_all(&out);
}

/// A rebuild removes the outputs of the previous build that it does not write (a force
/// analysis' tables, a PNG), and only those: a user's own file in the folder stays.
#[test]
fn a_rebuild_leaves_no_stale_outputs_and_touches_nothing_else() {
    let out = temp_dir("stale");
    assert!(run(&["--png-dpi", "20", "--no-pdf"], &out).status.success());
    assert!(out.join("sheet1-inertia.csv").exists() && out.join("sheet1.png").exists());
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let kinematics_only = out.join("kinematics.yaml");
    let text = std::fs::read_to_string(fixture("worked-example")).unwrap();
    std::fs::write(&kinematics_only, &text[..text.find("\nforces:").unwrap()]).unwrap();
    let o = run(&["build", kinematics_only.to_str().unwrap(), "--no-png", "--no-pdf"], &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        listing(&out),
        [
            ".tmm-lock",
            ".tmm-outputs",
            "kinematics.yaml",
            "notes.txt",
            "results.json",
            "sheet1-accelerations.csv",
            "sheet1-segments.csv",
            "sheet1-tables.md",
            "sheet1-velocities.csv",
            "sheet1.svg"
        ]
    );
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn errors_name_the_cause_with_documented_exit_codes() {
    let out = temp_dir("errors");
    // 1: the project is refused.
    let o = tmm().args(["build", "no-such-file.yaml"]).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read no-such-file.yaml"));
    // A sheet whose section the project lacks.
    let gears_only = format!("{}/fixtures/gears/handbook-khk.yaml", env!("CARGO_MANIFEST_DIR"));
    let o = tmm().args(["build", &gears_only, "--sheet", "3", "-o"]).arg(&out).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("sheet 3 (the cam) needs a `cam` section"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let bad = temp_dir("bad").with_extension("yaml");
    std::fs::write(&bad, "project: {title: x}\nmechanism: {frame: [], crank: {pivot: O}}\n").unwrap();
    let o = tmm().arg("build").arg(&bad).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("line 2") && err.contains("mechanism.crank: the key `pin` is missing"), "{err}");
    assert!(!err.contains("panicked"));
    // 2: a usage error (more in `out_of_range_options_are_usage_errors`).
    assert_eq!(tmm().args(["--no-such-flag"]).output().unwrap().status.code(), Some(2));
    // 3: the outputs cannot be written (the output "folder" is a file).
    let o = tmm().args(["--no-png", "--no-pdf", "-o"]).arg(&bad).output().unwrap();
    assert_eq!(o.status.code(), Some(3), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot create"));
    assert!(!out.exists(), "a refused build writes nothing");
    let _ = std::fs::remove_file(&bad);
}

#[test]
fn warnings_are_printed_and_the_build_continues() {
    let out = temp_dir("warn");
    let text = std::fs::read_to_string(fixture("worked-example")).unwrap().replace("length: 0.12,", "length: 120,");
    let file = temp_dir("warn-file").with_extension("yaml");
    std::fs::write(&file, text).unwrap();
    let o = run(&["build", file.to_str().unwrap(), "--no-png", "--no-pdf"], &out);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("warning:") && err.contains("mechanism.crank.length") && err.contains("millimetres"), "{err}");
    let _ = std::fs::remove_file(&file);
    let _ = std::fs::remove_dir_all(&out);
}

/// `gears.output_rpm` beside a crank that turns at another speed: a warning at
/// `output_rpm`'s line naming both speeds, and the build goes on; the crank's own speed
/// (also given as ω1 in 1/s) is no warning.
#[test]
fn an_output_speed_other_than_the_cranks_is_warned_about() {
    let text = std::fs::read_to_string(fixture("worked-example")).unwrap();
    let line = text.lines().position(|l| l.starts_with("  motor_rpm: 750")).unwrap() + 2;
    let build = |text: &str, name: &str| {
        let (out, file) = (temp_dir(name), temp_dir(&format!("{name}-file")).with_extension("yaml"));
        std::fs::write(&file, text).unwrap();
        let o = run(&["build", file.to_str().unwrap(), "--sheet", "2", "--no-png", "--no-pdf"], &out);
        let _ = (std::fs::remove_file(&file), std::fs::remove_dir_all(&out));
        (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned())
    };
    let (code, err) = build(&text.replace("  motor_rpm: 750", "  motor_rpm: 750\n  output_rpm: 60"), "rpm-differs");
    assert_eq!(code, Some(0), "{err}");
    let expected = format!(
        "warning: in {}: line {line}, column 15: gears.output_rpm: n1 = 60 rev/min, but the crank turns at 70 rev/min (mechanism.crank.rpm): sheets 1 and 2 then use different speeds",
        temp_dir("rpm-differs-file").with_extension("yaml").display()
    );
    assert!(err.contains(&expected), "{err}");
    let same = text
        .replace("  motor_rpm: 750", "  motor_rpm: 750\n  output_rpm: 70")
        .replace("rpm: 70,", "omega: 7.330382858376184,");
    let (code, err) = build(&same, "rpm-same");
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("output_rpm"), "{err}");
}

#[test]
fn example_prints_a_project_that_builds() {
    let o = tmm().arg("example").output().unwrap();
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(tmm_sheets::pipeline::load(&text).is_ok());
}

/// `--sheet` and `--png-dpi` outside what the README allows are usage errors (exit 2), named
/// with the option and the allowed values, and nothing is built or written.
#[test]
fn out_of_range_options_are_usage_errors() {
    let numbers: Vec<u32> = tmm_sheets::sheets::COURSE.iter().map(|k| k.number).collect();
    let (first, last) = (numbers[0], numbers[numbers.len() - 1]);
    let beyond = (last + 1).to_string();
    let sheets = format!("sheets {first} to {last}");
    let out = temp_dir("usage");
    let cases: [(&[&str], &[&str]); 9] = [
        (&["--sheet", "0"], &["--sheet", "there is no sheet 0", &sheets]),
        (&["--sheet", &beyond], &["--sheet", &format!("there is no sheet {beyond}"), &sheets]),
        (&["--sheet", "1,x"], &["--sheet", "not a sheet number", &sheets]),
        (&["--png-dpi", "0"], &["--png-dpi", "from 10 to 600"]),
        (&["--png-dpi", "601"], &["--png-dpi", "from 10 to 600"]),
        (&["--png-dpi", "9.99"], &["--png-dpi", "from 10 to 600"]),
        (&["--png-dpi", "NaN"], &["--png-dpi", "from 10 to 600"]),
        (&["--png-dpi", "inf"], &["--png-dpi", "from 10 to 600"]),
        (&["build", "--png-dpi=-inf"], &["--png-dpi", "from 10 to 600"]),
    ];
    for (args, needles) in cases {
        let o = run(args, &out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        for n in needles {
            assert!(err.contains(n), "{args:?}: {n:?} missing from: {err}");
        }
        assert!(!out.exists(), "{args:?}: a usage error writes nothing");
    }
}

/// The ends of the documented ranges are accepted.
#[test]
fn the_ends_of_the_ranges_are_accepted() {
    let out = temp_dir("ends");
    let o = run(&["--sheet", "2", "--png-dpi", "10", "--no-pdf"], &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.join("sheet2.png").exists());
    let _ = std::fs::remove_dir_all(&out);
}

/// A wrong `cam` section refuses sheet 3 only: the default build is refused (exit 1), naming
/// the field and how to build the others; `--sheet 1,2` builds them with a warning that
/// names the field.
#[test]
fn a_wrong_section_refuses_its_own_sheet_only() {
    let text = std::fs::read_to_string(fixture("worked-example")).unwrap().replacen("law: sine", "law: wobbly", 1);
    let dir = common::Scratch::created("cli-cam-wrong");
    let file = dir.join("project.yaml");
    std::fs::write(&file, &text).unwrap();
    let out = temp_dir("cam-wrong-out");
    let o = tmm().arg("build").arg(&file).args(["--no-png", "--no-pdf", "-o"]).arg(&out).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("cam.law: unknown law 'wobbly'") && err.contains("`--sheet 1,2` builds the others"), "{err}");
    let o = tmm()
        .arg("build")
        .arg(&file)
        .args(["--sheet", "1,2", "--no-png", "--no-pdf", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("warning:") && err.contains("cam.law") && err.contains("sheet 3 cannot be built"), "{err}");
    assert!(out.join("sheet1.svg").exists() && out.join("sheet2.svg").exists() && !out.join("sheet3.svg").exists());
}

/// A project without a designation builds, warned at the `project` section (or at an empty
/// `designation`): the title block's main field would stay blank.
#[test]
fn a_project_without_a_designation_is_warned_about() {
    let text = std::fs::read_to_string(fixture("worked-example")).unwrap();
    let designation = text.lines().find(|l| l.trim_start().starts_with("designation:")).unwrap();
    let section = text.lines().position(|l| l == "project:").unwrap() + 1;
    let at_section = format!("line {section}, column 1");
    for (name, changed, at) in [
        ("no-designation", text.replace(&format!("{designation}\n"), ""), at_section.as_str()),
        ("empty-designation", text.replace(designation, "  designation: \"\""), "column 3"),
    ] {
        let (out, file) = (temp_dir(name), temp_dir(&format!("{name}-file")).with_extension("yaml"));
        std::fs::write(&file, &changed).unwrap();
        let o = run(&["build", file.to_str().unwrap(), "--sheet", "3", "--no-png", "--no-pdf"], &out);
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        let _ = (std::fs::remove_file(&file), std::fs::remove_dir_all(&out));
        assert_eq!(o.status.code(), Some(0), "{err}");
        assert!(err.contains("project.designation: no designation") && err.contains(at), "{name}: {err}");
    }
}
