//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;
use tmm_sheets::drawing::scene::Scene;
use tmm_sheets::drawing::{frame, layout};
use tmm_sheets::pipeline;
use tmm_sheets::project::{LeverProject, Project};
use tmm_sheets::sheets::lever::{self, LeverBuild};
use tmm_sheets::sheets::{COURSE, Context};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every project file in `fixtures/`, sorted by name.
pub fn fixture_names() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("fixtures"))
        .expect("fixtures/ exists")
        .filter_map(|e| {
            let p = e.ok()?.path();
            if p.extension()? != "yaml" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    names.sort();
    names
}

pub fn fixture_text(name: &str) -> String {
    std::fs::read_to_string(root().join("fixtures").join(format!("{name}.yaml"))).expect("fixture exists")
}

pub fn fixture(name: &str) -> Project {
    pipeline::load(&fixture_text(name)).unwrap_or_else(|e| panic!("{name}: {e:#}"))
}

/// The lever sections of a project file's text.
pub fn lever_of(text: &str) -> LeverProject {
    pipeline::load(text).unwrap_or_else(|e| panic!("{e:#}")).lever.expect("a mechanism section")
}

/// The lever sections of a fixture.
pub fn lever(name: &str) -> LeverProject {
    fixture(name).lever.unwrap_or_else(|| panic!("{name} has a mechanism"))
}

/// Sheet 1 of a project, with everything computed for it.
pub fn build_lever(p: &Project) -> LeverBuild {
    let ctx =
        Context { info: &p.info, sheet_no: 1, sheet_count: COURSE.len() as u32, first_table: 1, sheet_names: &[] };
    lever::build(&ctx, p.lever.as_ref().expect("a mechanism section")).unwrap_or_else(|e| panic!("{e}"))
}

/// Latin words a Russian sheet must not show: a run of two or more Latin letters with a
/// lowercase one ("mm", "working"), or a unit "N"/"m"/"s"/"kg" after a number or a comma
/// ("0,5 N", "P, N"). Symbols and plan letters ("m", "p=b=s3"), min/max and a derivative's
/// numerator ("ds/dφ") are not words.
pub fn english_on_russian(text: &str) -> Option<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if !chars[i].is_ascii_alphabetic() {
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && chars[i].is_ascii_alphabetic() {
            i += 1;
        }
        let token: String = chars[start..i].iter().collect();
        let before = chars[..start].iter().rev().find(|c| !c.is_whitespace());
        let after_number = before.is_some_and(|c| c.is_ascii_digit() || *c == ',');
        // "min" and "max" are mathematical notation in Russian too (x_min, z_min).
        let math = ["min", "max"].contains(&token.as_str());
        // A derivative's numerator ("ds/dφ") is notation, not a word.
        let derivative = token.starts_with('d') && chars.get(i) == Some(&'/');
        let word = token.len() >= 2 && token.chars().any(|c| c.is_ascii_lowercase()) && !math && !derivative;
        if word || (["N", "m", "s", "kg"].contains(&token.as_str()) && after_number) {
            return Some(token);
        }
    }
    None
}

/// Every group stays in its region, regions stay inside the frame and apart, and no two
/// texts overlap anywhere on the sheet.
pub fn check_layout(name: &str, scene: &Scene) {
    let inner = frame::inner();
    let tb = frame::title_block_rect();
    for g in &scene.groups {
        for item in &g.items {
            // A border stroke centred on the region's edge counts as inside.
            let half_main = 0.36;
            assert!(
                frame::is_inside(g.region.inflate(half_main, half_main), item.bbox()),
                "{name}: an item of '{}' leaves its region: {:?} not in {:?}: {item:?}",
                g.id,
                item.bbox(),
                g.region
            );
        }
        if g.id != "frame" {
            assert!(frame::is_inside(inner, g.region), "{name}: region '{}' leaves the frame", g.id);
        }
    }
    // Box 26 is a notch in the corner region's room, kept clear of its items (not of its
    // region) as `sheets::box_26_holds_the_designation_turned_and_nothing_else` checks.
    let regions: Vec<_> = scene.groups.iter().filter(|g| g.id != "frame" && g.id != frame::DESIGNATION_BOX).collect();
    for (i, a) in regions.iter().enumerate() {
        for b in &regions[i + 1..] {
            assert!(a.region.intersect(b.region).area() <= 1e-9, "{name}: regions '{}' and '{}' overlap", a.id, b.id);
        }
        if a.id != "title-block" {
            assert!(a.region.intersect(tb).area() <= 1e-9, "{name}: '{}' covers the title block", a.id);
        }
    }
    for t in scene.texts() {
        // SVG collapses leading and trailing white space: a gap made of spaces vanishes.
        assert!(t.text.trim() == t.text && !t.text.is_empty(), "{name}: text {:?} has outer white space", t.text);
    }
    // Independently of the sheet's measurement: no two texts' letters overlap (a turned
    // text's letters boxed piece by piece: one box round a value set along a slanted radius
    // takes in the corner beside it).
    let texts: Vec<_> = scene.texts().map(|t| (t, t.core_box(), t.core_boxes().collect::<Vec<_>>())).collect();
    for (i, (a, a_box, a_pieces)) in texts.iter().enumerate() {
        for (b, b_box, b_pieces) in &texts[i + 1..] {
            if a_box.intersect(*b_box).area() <= 1e-6 {
                continue;
            }
            let overlap =
                a_pieces.iter().flat_map(|p| b_pieces.iter().map(move |q| p.intersect(*q).area())).fold(0.0, f64::max);
            assert!(overlap <= 1e-6, "{name}: texts {:?} and {:?} overlap", a.text, b.text);
        }
    }
    // The sheet's own measurement, held at zero: no text crossed by a line, no two texts
    // overlapping, nothing outside its region.
    let l = layout::measure(scene);
    assert!(l.is_clean(), "{name}: {:?} of {:?}: {:#?}", l.faults(), layout::FAULTS, l.problems);
}

/// Every run of every text of a scene (a symbol, its subscript and its tail each on its own),
/// for checks of what a sheet prints.
pub fn runs(scene: &Scene) -> impl Iterator<Item = &str> {
    scene
        .texts()
        .flat_map(|t| {
            let further = t.then.iter().flat_map(|(sub, tail)| [sub.as_str(), tail.as_str()]);
            [t.text.as_str(), t.sub.as_str(), t.tail.as_str()].into_iter().chain(further)
        })
        .filter(|r| !r.is_empty())
}

/// A count of random cases from the environment variable `var`, else `default`.
pub fn env_cases(var: &str, default: u32) -> u32 {
    std::env::var(var).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// The random cases' seed from the environment variable `var`: a fixed 2026 by default, so
/// that a run is repeatable; a number for other cases, `random` for new ones each run.
pub fn env_seed(var: &str) -> proptest::test_runner::RngSeed {
    use proptest::test_runner::RngSeed;
    match std::env::var(var).ok().as_deref() {
        Some("random") => RngSeed::Random,
        Some(v) => RngSeed::Fixed(v.parse().unwrap_or_else(|_| panic!("{var}: a whole number or 'random'"))),
        None => RngSeed::Fixed(2026),
    }
}

/// A stroked path's line ends (its move-to and line-to points) and its pen; `None` for any
/// other item.
pub fn path_points(
    item: &tmm_sheets::drawing::scene::Item,
) -> Option<(Vec<kurbo::Point>, tmm_sheets::drawing::scene::Pen)> {
    let tmm_sheets::drawing::scene::Item::Path { path, pen } = item else { return None };
    let pts = path
        .to_bez()
        .elements()
        .iter()
        .filter_map(|e| match e {
            kurbo::PathEl::MoveTo(p) | kurbo::PathEl::LineTo(p) => Some(*p),
            _ => None,
        })
        .collect();
    Some((pts, *pen))
}

/// The layout measure's faults in a sheet's `results.layout`: each non-zero count of texts
/// crossed, texts overlapping and items outside their region, named.
pub fn layout_faults(layout: &serde_json::Value) -> Vec<String> {
    tmm_sheets::drawing::layout::FAULTS
        .iter()
        .filter(|k| layout[**k] != 0)
        .map(|k| format!("{k} {}", layout[*k]))
        .collect()
}

/// A fresh folder for a test's outputs (`tmm-NAME-PID` under the temporary directory; not
/// yet created, as `tmm` creates its output folder itself), removed when dropped so that a
/// suite run leaves nothing behind.
pub struct Scratch(PathBuf);

impl Scratch {
    pub fn new(name: &str) -> Scratch {
        let d = std::env::temp_dir().join(format!("tmm-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        Scratch(d)
    }

    /// A fresh folder, made.
    pub fn created(name: &str) -> Scratch {
        let d = Scratch::new(name);
        std::fs::create_dir_all(&d.0).unwrap();
        d
    }
}

impl std::ops::Deref for Scratch {
    type Target = std::path::Path;
    fn deref(&self) -> &std::path::Path {
        &self.0
    }
}

impl AsRef<std::path::Path> for Scratch {
    fn as_ref(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

/// A six-bar of the stress sweep's kind under `header`: a crank-rocker (frame O–C of `frame`,
/// crank O–A of `crank`, coupler and rocker `l2`, `l3`, m) whose rocker's joint B drives a
/// slider D by a rod `rod` on a horizontal guide `offset` above O, the slider's branch
/// `branch` ("forward" or "backward"); each link's centre of mass at its middle.
pub fn six_bar(
    header: &str,
    frame: f64,
    crank: f64,
    (l2, l3): (f64, f64),
    offset: f64,
    rod: f64,
    branch: &str,
) -> String {
    format!(
        "{header}mechanism:\n  frame:\n    - {{name: O, at: [0, 0]}}\n    - {{name: C, at: [{frame:.6}, 0]}}\n  crank: {{pivot: O, pin: A, length: {crank:.6}, rpm: 90, sense: cw}}\n  groups:\n    - rrr: {{links: [2, 3], joints: [A, C], point: B, lengths: [{l2:.6}, {l3:.6}], branch: left}}\n    - rrp: {{links: [4, 5], joint: B, point: D, length: {rod:.6}, guide: {{through: [0, {offset:.6}], angle_deg: 0}}, branch: {branch}}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: S3, link: 3, from: C, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: S4, link: 4, from: B, toward: D, ratio: 0.5, mass_centre: true}}\n    - {{name: S5, link: 5, from: D, mass_centre: true}}\n"
    )
}

/// The guide's `task`, `variant` in `lang`: its sheet 1 built (read for sheet 1 alone: some
/// variants' planetary stage is refused by design).
#[allow(dead_code)]
pub fn catalogue_sheet1(
    task: &str,
    variant: u32,
    lang: tmm_sheets::drawing::labels::Language,
) -> tmm_sheets::sheets::SheetOutput {
    let text = catalogue_text(task, variant, lang);
    tmm_sheets::pipeline::build(&tmm_sheets::pipeline::load_for(&text, &[1]).unwrap(), &[1]).unwrap().remove(0).output
}

/// The project file the guide's catalogue writes for `task`'s `variant` in `lang`.
pub fn catalogue_text(task: &str, variant: u32, lang: tmm_sheets::drawing::labels::Language) -> String {
    use tmm_sheets::catalogue::{Catalogue, Variant};
    let catalogue = Catalogue::embedded().unwrap();
    let Variant::Project { text, .. } = catalogue.task(task).unwrap().project(variant, lang, "test").unwrap() else {
        panic!("task {task}, variant {variant} gives a project");
    };
    text
}

/// The double-arrowed lines of a group (its dimension lines): straight lines each of whose
/// ends is an arrowhead's tip.
pub fn dimension_lines(g: &tmm_sheets::drawing::scene::Group) -> Vec<(kurbo::Point, kurbo::Point)> {
    use kurbo::Point;
    use tmm_sheets::drawing::path::Seg;
    use tmm_sheets::drawing::scene::Item;
    use tmm_sheets::num::math::Norm;
    let tips: Vec<Point> =
        g.items.iter().filter_map(|i| if let Item::Fill { path } = i { Some(path.start) } else { None }).collect();
    let tip = |p: Point| tips.iter().any(|t| (*t - p).norm() < 1e-6);
    g.items
        .iter()
        .filter_map(|i| match i {
            Item::Path { path, .. } if matches!(path.segs[..], [Seg::Line(_)]) => Some((path.start, path.end())),
            _ => None,
        })
        .filter(|&(a, b)| tip(a) && tip(b))
        .collect()
}

/// The language a catalogue sweep's report is in: `SWEEP_LANG` (uz, ru, en), Russian by
/// default.
pub fn sweep_lang() -> tmm_sheets::drawing::labels::Language {
    use tmm_sheets::drawing::labels::Language;
    match std::env::var("SWEEP_LANG").as_deref() {
        Ok("uz") => Language::Uz,
        Ok("en") => Language::En,
        _ => Language::Ru,
    }
}

/// Every catalogue variant's sheet 1 built in `lang`, each with its task's id and its
/// variant's number; those refused left out.
pub fn catalogue_sheets1(
    lang: tmm_sheets::drawing::labels::Language,
) -> impl Iterator<Item = (String, u32, tmm_sheets::sheets::SheetOutput)> {
    use tmm_sheets::catalogue::{Catalogue, Variant};
    let catalogue = Catalogue::embedded().unwrap();
    let variants: Vec<(String, u32, String)> = catalogue
        .tasks
        .iter()
        .flat_map(|task| {
            task.variants().filter_map(move |v| match task.project(v, lang, "test") {
                Ok(Variant::Project { text, .. }) => Some((task.id(), v, text)),
                _ => None,
            })
        })
        .collect();
    variants.into_iter().filter_map(|(task, v, text)| {
        let p = pipeline::load_for(&text, &[1]).ok()?;
        Some((task, v, pipeline::build(&p, &[1]).ok()?.remove(0).output))
    })
}
