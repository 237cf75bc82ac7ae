//! The output folder under stress: a write that fails half-way, symlinks planted in the
//! folder, two builds writing into one folder at once, and project files that are too large
//! or not text. Each test fails on the code before writes were atomic, guarded and limited.

mod common;

use std::collections::BTreeMap;
use std::io::{BufRead, BufReader};
use std::os::unix::fs::{PermissionsExt, symlink};
use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};
use std::sync::{Arc, Barrier};
use std::time::Duration;
use tmm_sheets::cli::write::{LOCK, MANIFEST, TEMP_MARK, write_outputs};

fn tmm() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmm"))
}

fn temp_dir(name: &str) -> common::Scratch {
    common::Scratch::created(&format!("folder-{name}"))
}

fn run(args: &[&str], out: &Path) -> Output {
    tmm().args(args).arg("-o").arg(out).output().unwrap()
}

fn assert_ok(o: &Output) {
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Every entry of the folder (symlinks not followed) with its bytes; a symlink as its target.
fn snapshot(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut files = BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let e = e.unwrap();
        let name = e.file_name().to_string_lossy().into_owned();
        let bytes = if e.file_type().unwrap().is_symlink() {
            format!("-> {}", std::fs::read_link(e.path()).unwrap().display()).into_bytes()
        } else {
            std::fs::read(e.path()).unwrap()
        };
        files.insert(name, bytes);
    }
    files
}

fn temps(dir: &Path) -> Vec<String> {
    snapshot(dir).into_keys().filter(|n| n.contains(TEMP_MARK)).collect()
}

fn without_temps(mut s: BTreeMap<String, Vec<u8>>) -> BTreeMap<String, Vec<u8>> {
    s.retain(|n, _| !n.contains(TEMP_MARK));
    s
}

fn manifest(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join(MANIFEST)).unwrap().lines().map(str::to_string).collect()
}

/// The outputs of a folder (no lock, no manifest, no temporary file).
fn outputs(snapshot: &BTreeMap<String, Vec<u8>>) -> Vec<String> {
    snapshot.keys().filter(|n| !n.starts_with('.')).cloned().collect()
}

/// `tmm ARGS -o OUT` with files limited to `limit` bytes (`ulimit -f`, 512-byte blocks in
/// POSIX sh); with `ignore_xfsz` a write past the limit fails with EFBIG instead of the
/// SIGXFSZ that kills the process.
fn run_limited(args: &[&str], out: &Path, limit: u64, ignore_xfsz: bool) -> Output {
    let trap = if ignore_xfsz { "trap '' XFSZ; " } else { "" };
    let script = format!("{trap}ulimit -f {} && exec \"$0\" \"$@\"", limit / 512);
    Command::new("sh").args(["-c", &script, env!("CARGO_BIN_EXE_tmm")]).args(args).arg("-o").arg(out).output().unwrap()
}

/// A build that cannot write all its files, and the limit that makes it so: the previous
/// build (sheets 2 and 3 in Uzbek) is in `out`; the new one (in English) writes sheet 2's
/// files, then fails on the larger `sheet3.svg`.
fn previous_build_and_limit(out: &Path) -> (BTreeMap<String, Vec<u8>>, u64) {
    assert_ok(&run(&["--sheet", "2,3", "--no-png"], out));
    let before = snapshot(out);
    let sheet2 = before.iter().filter(|(n, _)| n.starts_with("sheet2")).map(|(_, b)| b.len() as u64).max().unwrap();
    let svg3 = before["sheet3.svg"].len() as u64;
    assert!(sheet2 * 5 / 4 < svg3, "the test needs sheet3.svg well above sheet 2's files: {sheet2} and {svg3}");
    (before, (sheet2 + svg3) / 2)
}

const FAILING_BUILD: [&str; 5] = ["--sheet", "2,3", "--no-png", "--lang", "en"];

/// A full disk or `ulimit -f` stops the build half-way: before, sheet 2's files were new, the
/// third SVG truncated and `results.json` old; now no file of the folder changes.
#[test]
fn a_failed_write_leaves_the_previous_build_whole_and_no_temporary_file() {
    let base = temp_dir("efbig");
    let out = base.join("out");
    let (before, limit) = previous_build_and_limit(&out);
    let o = run_limited(&FAILING_BUILD, &out, limit, true);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(3), "{err}");
    assert!(err.contains("cannot write") && err.contains("sheet3.svg"), "{err}");
    assert_eq!(snapshot(&out), before, "the previous build's files changed");
    let _ = std::fs::remove_dir_all(&base);
}

/// SIGXFSZ kills the build before it can clean up: the previous build stays whole, and the
/// next build removes the temporary files left behind.
#[test]
fn a_build_killed_while_writing_leaves_the_previous_build_whole() {
    let base = temp_dir("sigxfsz");
    let out = base.join("out");
    let (before, limit) = previous_build_and_limit(&out);
    let o = run_limited(&FAILING_BUILD, &out, limit, false);
    assert_eq!(o.status.signal(), Some(25), "SIGXFSZ expected: {:?}", o.status);
    assert!(!temps(&out).is_empty(), "a killed build cannot remove its temporary files");
    assert_eq!(without_temps(snapshot(&out)), before, "the previous build's files changed");
    assert_ok(&run(&FAILING_BUILD, &out));
    assert_eq!(temps(&out), Vec::<String>::new(), "the next build removes the leftovers");
    assert!(std::fs::read_to_string(out.join("sheet3.svg")).unwrap().contains("Cam mechanism synthesis"));
    let _ = std::fs::remove_dir_all(&base);
}

/// A symlink planted in the folder is replaced by the output, never written through (before,
/// `ln -s ~/important out/sheet1.svg` made a build overwrite `~/important`); a planted
/// manifest is neither written through nor trusted; a stale name that is now a symlink is
/// left alone; an output folder that is itself a symlink is the user's choice and works.
#[test]
fn symlinks_in_the_folder_are_replaced_never_followed() {
    let base = temp_dir("symlink");
    let out = base.join("out");
    std::fs::create_dir(&out).unwrap();
    let (outside, outside_list) = (base.join("outside.txt"), base.join("outside-list.txt"));
    std::fs::write(&outside, "precious").unwrap();
    std::fs::write(&outside_list, "precious\n").unwrap();
    symlink(&outside, out.join("sheet1.svg")).unwrap();
    symlink(&outside_list, out.join(MANIFEST)).unwrap();
    assert_ok(&run(&["--sheet", "1", "--no-png", "--no-pdf"], &out));
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "precious");
    assert_eq!(std::fs::read_to_string(&outside_list).unwrap(), "precious\n");
    for name in ["sheet1.svg", MANIFEST] {
        assert!(std::fs::symlink_metadata(out.join(name)).unwrap().is_file(), "{name} is not a regular file");
    }
    assert!(std::fs::read_to_string(out.join("sheet1.svg")).unwrap().starts_with("<svg"));
    assert_eq!(manifest(&out), outputs(&snapshot(&out)));

    // Sheet 1's outputs are stale for a build of sheet 2; one of them is now a symlink.
    std::fs::remove_file(out.join("sheet1-velocities.csv")).unwrap();
    symlink(&outside, out.join("sheet1-velocities.csv")).unwrap();
    let link = base.join("link-to-out");
    symlink(&out, &link).unwrap();
    assert_ok(&run(&["--sheet", "2", "--no-png", "--no-pdf"], &link));
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "precious");
    let files = outputs(&snapshot(&out));
    assert!(files.contains(&"sheet1-velocities.csv".to_string()), "a symlink is not ours to remove: {files:?}");
    assert!(files.iter().all(|f| f.starts_with("sheet2") || f == "results.json" || f == "sheet1-velocities.csv"));

    // Outputs keep the mode a plain file gets (not the temporary file's 0o600).
    let probe = base.join("probe");
    std::fs::write(&probe, "x").unwrap();
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&out.join("sheet2.svg")), mode(&probe));
    let _ = std::fs::remove_dir_all(&base);
}

/// A symlink planted as the lock file is refused (exit 3): following it would open a file
/// outside the folder, replacing it would race with the builds that lock it.
#[test]
fn a_symlinked_lock_file_is_refused() {
    let base = temp_dir("lock-link");
    let out = base.join("out");
    std::fs::create_dir(&out).unwrap();
    let outside = base.join("outside.txt");
    std::fs::write(&outside, "precious").unwrap();
    symlink(&outside, out.join(LOCK)).unwrap();
    let o = run(&["--sheet", "2", "--no-png", "--no-pdf"], &out);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(3), "{err}");
    assert!(err.contains(LOCK) && err.contains("not a regular file"), "{err}");
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "precious");
    assert_eq!(snapshot(&out).into_keys().collect::<Vec<_>>(), [LOCK]);
    let _ = std::fs::remove_dir_all(&base);
}

/// Files of one writer: `tag` in every file, `names` its set.
fn files_of(tag: &str, names: &[&str]) -> Vec<(String, Vec<u8>)> {
    names.iter().map(|n| (n.to_string(), format!("{tag} {n}\n").repeat(4000).into_bytes())).collect()
}

/// Two writers of different file sets into one folder, many rounds: the folder always ends as
/// exactly one writer's set, whole, with the manifest listing it. Unguarded, the second
/// writer's stale removal deleted files the first had just written.
#[test]
fn concurrent_writes_into_one_folder_leave_exactly_one_writers_files() {
    let dir = temp_dir("threads");
    let sets = [files_of("A", &["a1.txt", "a2.txt", "common.txt"]), files_of("B", &["b1.txt", "common.txt"])];
    let expected: Vec<BTreeMap<String, Vec<u8>>> =
        sets.iter().map(|s| s.iter().cloned().collect::<BTreeMap<_, _>>()).collect();
    let sets = Arc::new(sets);
    for round in 0..100 {
        let barrier = Arc::new(Barrier::new(2));
        let writers: Vec<_> = (0..2)
            .map(|i| {
                let (sets, barrier, dir) = (Arc::clone(&sets), Arc::clone(&barrier), dir.to_path_buf());
                std::thread::spawn(move || {
                    barrier.wait();
                    write_outputs(&dir, &sets[i]).unwrap();
                })
            })
            .collect();
        writers.into_iter().for_each(|w| w.join().unwrap());
        let mut found = snapshot(&dir);
        found.retain(|n, _| !n.starts_with('.'));
        assert!(expected.contains(&found), "round {round}: a mix: {:?}", found.keys());
        assert_eq!(manifest(&dir), found.keys().cloned().collect::<Vec<_>>(), "round {round}");
        assert_eq!(temps(&dir), Vec::<String>::new(), "round {round}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Starts `tmm ARGS -o OUT` for each of `builds` while the test holds the folder's lock, and
/// returns them once each has said on stderr that it waits (each has built its sheets and
/// is about to write). Panics, killing them, if one does not say so within two minutes.
fn start_waiting(builds: &[&[&str]], out: &Path) -> Vec<Child> {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut children = Vec::new();
    for args in builds {
        let mut child = tmm().args(*args).arg("-o").arg(out).stderr(Stdio::piped()).stdout(Stdio::null()).spawn();
        let stderr = child.as_mut().unwrap().stderr.take().unwrap();
        children.push(child.unwrap());
        let tx = tx.clone();
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines() {
                let _ = tx.send(line.unwrap());
            }
        });
    }
    let mut waiting = 0;
    while waiting < builds.len() {
        match rx.recv_timeout(Duration::from_secs(120)) {
            Ok(line) if line.contains("waiting for another build writing to") => {
                assert!(line.contains(&out.display().to_string()), "{line}");
                waiting += 1;
            }
            Ok(_) => {}
            Err(e) => {
                children.iter_mut().for_each(|c| drop(c.kill()));
                panic!("a build did not say it waits: {e}");
            }
        }
    }
    children
}

/// The report's reproduction: `tmm --sheet 3 -o out` and `tmm -o out` at once made sheet 3's
/// files vanish in 10 of 10 rounds. Here both wait on the lock the test holds, so that their
/// writes start together when it is released; the folder ends as exactly one build's output,
/// and nothing is written while they wait.
#[test]
fn two_builds_into_one_folder_at_once_leave_exactly_one_build() {
    let base = temp_dir("processes");
    let builds: [&[&str]; 2] = [&["--sheet", "3", "--no-png", "--no-pdf"], &["--no-png", "--no-pdf"]];
    let references: Vec<BTreeMap<String, Vec<u8>>> = builds
        .iter()
        .enumerate()
        .map(|(i, args)| {
            let dir = base.join(format!("alone-{i}"));
            assert_ok(&run(args, &dir));
            snapshot(&dir)
        })
        .collect();
    let out = base.join("out");
    std::fs::create_dir(&out).unwrap();
    for round in 0..4 {
        let lock = std::fs::OpenOptions::new().write(true).create(true).truncate(false).open(out.join(LOCK)).unwrap();
        lock.lock().unwrap();
        let before = snapshot(&out);
        let children = start_waiting(&builds, &out);
        assert_eq!(snapshot(&out), before, "round {round}: written while waiting");
        drop(lock);
        for mut c in children {
            assert!(c.wait().unwrap().success(), "round {round}");
        }
        let found = snapshot(&out);
        assert!(references.contains(&found), "round {round}: not one build's folder: {:?}", found.keys());
    }
    let _ = std::fs::remove_dir_all(&base);
}

/// A project file over 16 MiB is refused after reading at most 16 MiB + 1 bytes: before,
/// `tmm build /dev/zero` ate 4.2 GB. Devices and pipes report no size, so the read is bounded.
#[test]
fn a_project_file_over_16_mib_is_refused_without_reading_it_all() {
    let base = temp_dir("huge");
    let sparse = base.join("huge.yaml");
    std::fs::File::create(&sparse).unwrap().set_len((16 << 20) + 1).unwrap();
    for file in [Path::new("/dev/zero"), sparse.as_path()] {
        let o = tmm().arg("build").arg(file).arg("-o").arg(base.join("out")).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(err.contains(&file.display().to_string()) && err.contains("16 MiB"), "{err}");
        assert!(!base.join("out").exists());
    }
    let _ = std::fs::remove_dir_all(&base);
}

/// A project file that is not UTF-8 (saved in a legacy code page) is refused, naming the
/// byte, its offset and its line.
#[test]
fn a_project_file_that_is_not_utf8_is_refused_naming_the_byte() {
    let base = temp_dir("latin1");
    let file = base.join("latin1.yaml");
    std::fs::write(&file, b"project:\n  title: \"caf\xe9\"\n").unwrap();
    let o = tmm().arg("build").arg(&file).arg("-o").arg(base.join("out")).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    for needle in ["latin1.yaml", "not UTF-8", "0xE9", "byte offset 22", "line 2"] {
        assert!(err.contains(needle), "{needle:?} missing from: {err}");
    }
    let _ = std::fs::remove_dir_all(&base);
}
