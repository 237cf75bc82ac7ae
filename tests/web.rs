//! The web page in a real browser: `web/test/e2e.mjs` loads `web/dist` in headless Chromium,
//! builds the worked example and a catalogue variant, and compares every file it downloads
//! with this build's `tmm` (byte for byte); an invalid project must show its line. It needs
//! `web/build.sh` run, `npm ci` in `web/test` and Chromium; without them it is skipped,
//! saying so — unless `TMM_WEB_TEST=required` (as `.ci/run` sets), when that is a failure.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

fn newest(dir: &Path) -> SystemTime {
    let mut t = SystemTime::UNIX_EPOCH;
    for e in std::fs::read_dir(dir).unwrap().map(|e| e.unwrap()) {
        let m = if e.path().is_dir() { newest(&e.path()) } else { e.metadata().unwrap().modified().unwrap() };
        t = t.max(m);
    }
    t
}

/// Why the test cannot run here, if it cannot.
fn missing(root: &Path, chromium: &Path) -> Option<String> {
    let wasm = root.join("web/dist/pkg/tmm_web_bg.wasm");
    let Ok(built) = std::fs::metadata(&wasm).and_then(|m| m.modified()) else {
        return Some("web/dist is not built (web/build.sh)".into());
    };
    if !root.join("web/test/node_modules/playwright-core").is_dir() {
        return Some("playwright-core is not installed (npm ci in web/test)".into());
    }
    if !chromium.is_file() {
        return Some(format!("{} is missing (apt-get install chromium)", chromium.display()));
    }
    let sources = [root.join("src"), root.join("web/static"), root.join("web/wasm/src"), root.join("templates")];
    if sources.iter().any(|d| newest(d) > built) {
        return Some("web/dist is older than the sources (run web/build.sh again)".into());
    }
    None
}

#[test]
fn the_web_page_gives_the_command_lines_files_in_chromium() {
    let root = common::root();
    let chromium = PathBuf::from(std::env::var("CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into()));
    let required = std::env::var("TMM_WEB_TEST").is_ok_and(|v| v == "required");
    if let Some(why) = missing(&root, &chromium) {
        assert!(!required, "TMM_WEB_TEST=required, but {why}");
        eprintln!("skipped: the web page's browser test: {why}");
        return;
    }
    let timings = root.join("target/web-timings.json");
    let o = Command::new("node")
        .arg(root.join("web/test/e2e.mjs"))
        .arg("--cli")
        .arg(env!("CARGO_BIN_EXE_tmm"))
        .arg("--timings")
        .arg(&timings)
        .env("CHROMIUM", &chromium)
        .output()
        .expect("node runs");
    let out = String::from_utf8_lossy(&o.stdout);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "the browser test failed:\n{out}\n{err}");
    // Its checks, each named: every variant as `tmm init` writes it, the zip and a single download of the worked example, the
    // catalogue variant, the invalid file.
    assert_eq!(out.lines().filter(|l| l.starts_with("ok - ")).count(), 5, "{out}");
    eprintln!("{out}");
}
