//! The DXF backend against an independent reader: every fixture's sheets (the worked example
//! in Uzbek, Russian and English) written as DXF R2000 and R12 must load in ezdxf with an
//! audit of no error and no fix (`tools/dxf_audit.py`), hold the entities `entity_counts`
//! says, and as many of each kind as the scene has items (a TEXT a run with letters, a
//! CIRCLE a circle, a HATCH a fill...); every TEXT reads back, its escapes decoded, as the
//! run it sets; layers carry their line type and lineweight; and the bytes are deterministic.
//!
//! ezdxf is a Python package (`python3 -m pip install --quiet ezdxf==1.4.5`, as CI does);
//! without it the reader's checks are skipped with a message.

mod common;

use common::{fixture, root};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::Command;
use tmm_sheets::backend::dxf::{self, DxfVersion};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::path::Seg;
use tmm_sheets::drawing::scene::{Item, Scene};
use tmm_sheets::pipeline;
use tmm_sheets::project::Project;

const VERSIONS: [(DxfVersion, &str, &str); 2] =
    [(DxfVersion::R2000, "r2000", "AC1015"), (DxfVersion::R12, "r12", "AC1009")];

/// Every project under `fixtures/` (sub-folders too), and the worked example in Russian and
/// English besides its own Uzbek.
fn every_fixture() -> Vec<(String, Project)> {
    let mut names = common::fixture_names();
    for dir in ["cams", "gears"] {
        let mut sub: Vec<String> = std::fs::read_dir(root().join("fixtures").join(dir))
            .unwrap()
            .filter_map(|e| Some(e.ok()?.path().file_stem()?.to_string_lossy().into_owned()))
            .map(|n| format!("{dir}/{n}"))
            .collect();
        sub.sort();
        names.extend(sub);
    }
    let mut all: Vec<_> = names.into_iter().map(|n| (n.clone(), fixture(&n))).collect();
    for (language, tag) in [(Language::Ru, "ru"), (Language::En, "en")] {
        let mut p = fixture("worked-example");
        p.info.language = language;
        all.push((format!("worked-example-{tag}"), p));
    }
    all
}

/// Whether ezdxf can be imported.
fn have_ezdxf() -> bool {
    Command::new("python3").args(["-c", "import ezdxf"]).output().is_ok_and(|o| o.status.success())
}

/// The runs a scene prints, as a DXF TEXT holds them: each run with letters, trimmed.
fn runs(scene: &Scene) -> Vec<String> {
    common::runs(scene).map(str::trim).filter(|r| !r.is_empty()).map(String::from).collect()
}

/// The entities a scene must become, by kind, counted from its items (SOLID, whose number
/// depends on the triangulation, as its least: a triangle for each fill and dot).
fn expected(scene: &Scene, version: DxfVersion) -> BTreeMap<&'static str, usize> {
    let r2000 = version == DxfVersion::R2000;
    let mut c: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut add = |k: &'static str, n: usize| {
        if n > 0 {
            *c.entry(k).or_default() += n;
        }
    };
    for g in &scene.groups {
        for item in &g.items {
            match item {
                Item::Path { path, .. } => match (path.closed, path.segs.as_slice()) {
                    (_, []) => {}
                    (false, [Seg::Line(_)]) => add("LINE", 1),
                    (false, [Seg::Arc(a)]) if a.sweep_angle.abs() >= std::f64::consts::TAU - 1e-9 => add("CIRCLE", 1),
                    (false, [Seg::Arc(_)]) => add("ARC", 1),
                    _ => add(if r2000 { "LWPOLYLINE" } else { "POLYLINE" }, 1),
                },
                Item::Circle { filled: false, .. } => add("CIRCLE", 1),
                Item::Circle { filled: true, .. } => add(if r2000 { "HATCH" } else { "SOLID" }, 1),
                Item::Fill { path } => {
                    add(if r2000 { "HATCH" } else { "SOLID" }, if r2000 { 1 } else { path.segs.len().max(2) - 1 })
                }
                Item::Text(_) => {}
            }
        }
    }
    add("TEXT", runs(scene).len());
    c
}

/// What the reader says of one file.
struct Audit {
    json: serde_json::Value,
}

impl Audit {
    fn counts(&self) -> BTreeMap<String, usize> {
        self.json["counts"]
            .as_object()
            .unwrap()
            .iter()
            .map(|(k, v)| (k.clone(), v.as_u64().unwrap() as usize))
            .collect()
    }

    fn texts(&self) -> Vec<String> {
        self.json["texts"].as_array().unwrap().iter().map(|t| t.as_str().unwrap().to_string()).collect()
    }
}

/// Runs the audit script on `files`; panics with its report unless every file is clean.
fn audit(files: &[PathBuf]) -> Vec<Audit> {
    let out =
        Command::new("python3").arg(root().join("tools/dxf_audit.py")).args(files).output().expect("python3 runs");
    let stdout = String::from_utf8(out.stdout).unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let head: String = stdout.chars().take(2000).collect();
    assert!(out.status.success(), "the DXF audit failed:\n{stderr}\n{head}");
    let audits: Vec<Audit> = stdout.lines().map(|l| Audit { json: serde_json::from_str(l).unwrap() }).collect();
    assert_eq!(audits.len(), files.len(), "{stderr}");
    audits
}

struct Written {
    what: String,
    scene: Scene,
    version: DxfVersion,
    tag: &'static str,
    acadver: &'static str,
    path: PathBuf,
}

/// Every fixture's sheets written in both versions into the test's folder.
fn write_all() -> Vec<Written> {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("dxf");
    std::fs::create_dir_all(&dir).unwrap();
    let mut out = Vec::new();
    for (name, p) in every_fixture() {
        for b in pipeline::build(&p, &[]).unwrap_or_else(|e| panic!("{name}: {e:#}")) {
            for (version, tag, acadver) in VERSIONS {
                let bytes = dxf::write(&b.output.scene, version).unwrap();
                assert!(bytes.is_ascii(), "{name}: a DXF of escapes is ASCII");
                let path = dir.join(format!("{}-sheet{}-{tag}.dxf", name.replace('/', "-"), b.output.number));
                std::fs::write(&path, &bytes).unwrap();
                let what = format!("{name} sheet {} {tag}", b.output.number);
                out.push(Written { what, scene: b.output.scene.clone(), version, tag, acadver, path });
            }
        }
    }
    out
}

#[test]
fn every_sheet_passes_the_audit_with_its_entities_texts_and_layers() {
    let written = write_all();
    for w in &written {
        // What the writer says it writes is what the scene has.
        let ours = dxf::entity_counts(&w.scene, w.version);
        let want = expected(&w.scene, w.version);
        for (kind, n) in &want {
            let got = ours.get(kind).copied().unwrap_or(0);
            if *kind == "SOLID" {
                assert!(got >= *n, "{}: {got} SOLID, fewer than the {n} fills and dots", w.what);
            } else {
                assert_eq!(got, *n, "{}: {kind}", w.what);
            }
        }
        assert!(
            ours.keys().all(|k| want.contains_key(k)),
            "{}: {ours:?} has a kind the scene has not: {want:?}",
            w.what
        );
    }
    if !have_ezdxf() {
        eprintln!("skipped: ezdxf not installed (python3 -m pip install --quiet ezdxf==1.4.5)");
        return;
    }
    let files: Vec<PathBuf> = written.iter().map(|w| w.path.clone()).collect();
    let audits = audit(&files);
    eprintln!("{} DXF files audited", files.len());
    let mut russian = false;
    for (w, a) in written.iter().zip(&audits) {
        assert_eq!(a.json["errors"], 0, "{}", w.what);
        assert_eq!(a.json["fixes"], 0, "{}", w.what);
        assert_eq!(a.json["version"], w.acadver, "{}", w.what);
        let ours: BTreeMap<String, usize> =
            dxf::entity_counts(&w.scene, w.version).into_iter().map(|(k, v)| (k.to_string(), v)).collect();
        assert_eq!(a.counts(), ours, "{}: the reader's entities", w.what);
        // Every run reads back as the scene's text, Cyrillic, Greek and ʻ included.
        assert_eq!(a.texts(), runs(&w.scene), "{}: the texts read back", w.what);
        russian |= w.what.contains("-ru") && a.texts().iter().any(|t| t.contains("Механизм"));
        if w.version == DxfVersion::R2000 {
            assert_eq!(a.json["insunits"], 4, "{}: millimetres", w.what);
        }
        let layers = a.json["layers"].as_object().unwrap();
        for (name, l) in layers {
            let (linetype, lineweight) = match name.rsplit('-').next().unwrap() {
                "contour" => ("CONTINUOUS", 70),
                "vector" => ("CONTINUOUS", 50),
                "thin" | "text" | "fill" => ("CONTINUOUS", 25),
                "dashed" => ("DASHED", 25),
                "centre" => ("CENTER", 25),
                _ => {
                    // Layer 0, and Defpoints, which ezdxf adds as it loads.
                    assert!(["0", "Defpoints"].contains(&name.as_str()), "{}: an unexpected layer {name}", w.what);
                    continue;
                }
            };
            assert_eq!(l["linetype"], linetype, "{}: layer {name}", w.what);
            if w.version == DxfVersion::R2000 {
                assert_eq!(l["lineweight"], lineweight, "{}: layer {name}", w.what);
            }
        }
        for g in &w.scene.groups {
            assert!(
                layers.keys().any(|n| n.starts_with(&format!("{}-", g.id))),
                "{}: no layer of group {}",
                w.what,
                g.id
            );
        }
        eprintln!("{} ({}): {} bytes, {:?}", w.what, w.tag, std::fs::metadata(&w.path).unwrap().len(), a.counts());
    }
    assert!(russian, "the Russian worked example's title reads back in Cyrillic");
}

#[test]
fn the_same_scene_gives_the_same_bytes() {
    let p = fixture("worked-example");
    let (a, b) = (pipeline::build(&p, &[]).unwrap(), pipeline::build(&p, &[]).unwrap());
    for (x, y) in a.iter().zip(&b) {
        for (version, tag, _) in VERSIONS {
            let start = std::time::Instant::now();
            let dx = dxf::write(&x.output.scene, version).unwrap();
            let took = start.elapsed();
            let dy = dxf::write(&y.output.scene, version).unwrap();
            assert!(dx == dy, "sheet {}: DXF bytes differ between two runs", x.output.number);
            eprintln!("worked example sheet {} {tag}: {} bytes in {took:?}", x.output.number, dx.len());
        }
    }
}
