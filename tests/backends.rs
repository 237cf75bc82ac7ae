//! The backends against each other: every fixture's sheets rasterised three ways — our PNG
//! backend, poppler's `pdftoppm` of our PDF, resvg of our SVG — must show the same ink in
//! the same places, and a label moved by 2 mm, a lost text or a moved line must not; the
//! PDF is one A1 page with real, extractable text in a subset font; PDF and PNG bytes are
//! deterministic; a non-finite number is refused by every backend.
//!
//! `pdftoppm`, `pdftotext` and `pdffonts` come from poppler-utils (CI installs it); without
//! them the PDF's rasterised and text checks are skipped with a message.
#![allow(clippy::disallowed_methods)]

mod common;
mod svg_raster;

use common::{fixture, root};
use kurbo::{Point, Rect};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use tmm_sheets::backend::{self, BackendError, Format};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::path::{Path, Seg};
use tmm_sheets::drawing::scene::{AXIS, Anchor, DASHED, Group, Item, MAIN, Scene, THIN, Text};
use tmm_sheets::pipeline;
use tmm_sheets::project::Project;

/// Resolution of the comparisons: 0.5 mm a pixel, so a 2.5 mm letter is still five pixels.
const DPI: f64 = 50.0;
/// A pixel has ink when darker than this (of 255): any visible ink. Renderers disagree on
/// how dark a 0.25 mm line is at half a pixel wide (poppler snaps thin lines to whole
/// pixels, tiny-skia and resvg spread their coverage), not on where it is.
const INK: u8 = 224;
/// Ink in one image counts as matched by ink in the other within this many pixels
/// (Chebyshev): anti-aliasing moves an edge by up to a pixel.
const REACH: usize = 1;
/// Ink is counted in square tiles of this many pixels (20 mm at 50 dpi): a moved or lost
/// label is local, so it is looked for tile by tile, not diluted over the sheet.
const TILE: usize = 39;

/// How much unmatched ink two renderings of one scene may have.
#[derive(Debug, Clone, Copy)]
struct Tolerance {
    /// In the worst tile.
    tile: usize,
    /// Over the whole sheet, per million pixels.
    per_million: usize,
}

/// Measured over every fixture: at most 1 unmatched pixel in any tile and 6 on a sheet
/// (rounding of a glyph edge by a different rasteriser). The negative controls below give
/// 9 and more in one tile and 10 and more on the sheet.
const TOLERANCE: Tolerance = Tolerance { tile: 4, per_million: 4 };

/// Where one rendering's ink is.
struct Ink {
    w: usize,
    h: usize,
    ink: Vec<bool>,
}

impl Ink {
    fn from_png(png: &[u8]) -> Ink {
        let p = tiny_skia::Pixmap::decode_png(png).expect("a PNG");
        let ink = p.pixels().iter().map(|c| c.demultiply().green() < INK).collect();
        Ink { w: p.width() as usize, h: p.height() as usize, ink }
    }

    fn at(&self, x: usize, y: usize) -> bool {
        x < self.w && y < self.h && self.ink[y * self.w + x]
    }

    /// Whether there is ink within [`REACH`] of (x, y).
    fn near(&self, x: usize, y: usize) -> bool {
        let ys = y.saturating_sub(REACH)..=y + REACH;
        ys.into_iter().any(|yy| (x.saturating_sub(REACH)..=x + REACH).any(|xx| self.at(xx, yy)))
    }
}

/// Ink of either image with no ink of the other near it: on the whole sheet and in the
/// worst tile.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Unmatched {
    total: usize,
    worst_tile: usize,
    pixels: usize,
}

impl Unmatched {
    fn within(&self, t: Tolerance) -> bool {
        self.worst_tile <= t.tile && self.total * 1_000_000 <= t.per_million * self.pixels
    }
}

/// The images may differ in size by a pixel (poppler rounds the page up); their common
/// part is compared.
fn unmatched(a: &Ink, b: &Ink) -> Unmatched {
    assert!(a.w.abs_diff(b.w) <= 1 && a.h.abs_diff(b.h) <= 1, "sizes {}×{} and {}×{}", a.w, a.h, b.w, b.h);
    let (w, h) = (a.w.min(b.w), a.h.min(b.h));
    let tw = w.div_ceil(TILE);
    let mut tiles = vec![0usize; tw * h.div_ceil(TILE)];
    for y in 0..h {
        for x in 0..w {
            let lost = (a.at(x, y) && !b.near(x, y)) || (b.at(x, y) && !a.near(x, y));
            tiles[(y / TILE) * tw + x / TILE] += usize::from(lost);
        }
    }
    Unmatched { total: tiles.iter().sum(), worst_tile: tiles.iter().copied().max().unwrap_or(0), pixels: w * h }
}

fn png_at(scene: &Scene, dpi: f64) -> Ink {
    Ink::from_png(&backend::write(scene, Format::Png { dpi }).unwrap())
}

/// Our SVG as written, rasterised by resvg. The SVG asks any renderer to set its text as
/// the other backends do (no kerning, every space kept): without that resvg drops the
/// space that starts a tail run after a lone symbol ("Δ = 0 %" → "Δ= 0 %"), and the
/// comparisons below fail.
fn resvg_at(scene: &Scene, dpi: f64) -> Ink {
    let svg = backend::svg::write(scene).unwrap();
    Ink::from_png(&svg_raster::png(&svg, scene.width, scene.height, dpi))
}

/// A scratch directory of its own (tests run in parallel), made afresh.
fn scratch(name: &str) -> common::Scratch {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    common::Scratch::created(&format!("backends-{name}-{n}"))
}

/// Whether a poppler tool is installed; says so when it is not.
fn have(tool: &str) -> bool {
    let ok = Command::new(tool).arg("-v").output().is_ok();
    if !ok {
        eprintln!("SKIPPED: {tool} (poppler-utils) is not installed; the PDF is not checked with it");
    }
    ok
}

/// A poppler tool's standard output for `pdf`, its arguments `before` the file and `after`.
fn poppler(tool: &str, before: &[&str], pdf: &[u8], after: &[&str]) -> Vec<u8> {
    let dir = scratch(tool);
    let file = dir.join("sheet.pdf");
    std::fs::write(&file, pdf).unwrap();
    let out = Command::new(tool).args(before).arg(&file).args(after).output().unwrap_or_else(|e| panic!("{tool}: {e}"));
    assert!(out.status.success(), "{tool}: {}", String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::remove_dir_all(&dir);
    out.stdout
}

fn pdf(scene: &Scene) -> Vec<u8> {
    backend::write(scene, Format::Pdf).unwrap()
}

/// Our PDF rasterised by poppler at [`DPI`] (a single page goes to standard output).
fn pdftoppm(scene: &Scene) -> Ink {
    Ink::from_png(&poppler("pdftoppm", &["-r", &DPI.to_string(), "-png"], &pdf(scene), &[]))
}

/// Every project under `fixtures/` (sub-folders too), and the worked example in Russian.
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
    all.push(("worked-example ru".into(), russian_worked_example()));
    all
}

fn russian_worked_example() -> Project {
    let mut ru = fixture("worked-example");
    ru.info.language = Language::Ru;
    ru
}

fn check_pair(failures: &mut Vec<String>, what: &str, a: &Ink, b: &Ink) {
    let u = unmatched(a, b);
    eprintln!("{what}: {} unmatched ink pixels ({} in the worst tile)", u.total, u.worst_tile);
    if !u.within(TOLERANCE) {
        failures.push(format!("{what}: {u:?} exceeds {TOLERANCE:?}"));
    }
}

#[test]
fn png_pdf_and_svg_show_the_same_drawing_on_every_fixture() {
    let pdf = have("pdftoppm");
    let mut failures = Vec::new();
    for (name, p) in every_fixture() {
        for b in pipeline::build(&p, &[]).unwrap_or_else(|e| panic!("{name}: {e:#}")) {
            let scene = &b.output.scene;
            let what = format!("{name} sheet {}", b.output.number);
            let (ours, svg) = (png_at(scene, DPI), resvg_at(scene, DPI));
            check_pair(&mut failures, &format!("{what}: PNG / SVG"), &ours, &svg);
            if pdf {
                let from_pdf = pdftoppm(scene);
                check_pair(&mut failures, &format!("{what}: PNG / PDF"), &ours, &from_pdf);
                check_pair(&mut failures, &format!("{what}: PDF / SVG"), &from_pdf, &svg);
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Where item `i` of group `g` is, and the item.
type Found = (usize, usize);

fn find(scene: &Scene, score: impl Fn(&Item) -> Option<f64>) -> Found {
    let all = scene
        .groups
        .iter()
        .enumerate()
        .flat_map(|(g, grp)| grp.items.iter().enumerate().map(move |(i, it)| (g, i, it)));
    let best = all.filter_map(|(g, i, it)| Some((g, i, score(it)?))).min_by(|a, b| a.2.total_cmp(&b.2));
    let (g, i, _) = best.expect("an item to change");
    (g, i)
}

fn text_of(item: &Item) -> Option<&Text> {
    if let Item::Text(t) = item { Some(t) } else { None }
}

/// The worked example's sheet 1 three times changed a little: its smallest label with a
/// subscript moved 2 mm to the right, its smallest text dropped, its longest thin straight
/// line moved 2 mm across.
fn controls(scene: &Scene) -> Vec<(String, Scene)> {
    let label = find(scene, |it| text_of(it).filter(|t| !t.sub.is_empty()).map(|t| t.core_box().area()));
    let smallest = find(scene, |it| text_of(it).map(|t| t.core_box().area()));
    let line = find(scene, |it| match it {
        Item::Path { path, pen } if *pen == THIN && path.segs.len() == 1 => {
            Some(-path.bbox().size().to_vec2().length())
        }
        _ => None,
    });
    let (mut moved, mut dropped, mut shifted) = (scene.clone(), scene.clone(), scene.clone());
    let Item::Text(t) = &mut moved.groups[label.0].items[label.1] else { unreachable!() };
    t.at.x += 2.0;
    let moved_name = format!("label {:?} moved 2 mm", t.plain());
    let gone = dropped.groups[smallest.0].items.remove(smallest.1);
    let Item::Path { path, .. } = &mut shifted.groups[line.0].items[line.1] else { unreachable!() };
    let across = if path.bbox().width() > path.bbox().height() {
        kurbo::Vec2::new(0.0, 2.0)
    } else {
        kurbo::Vec2::new(2.0, 0.0)
    };
    path.start += across;
    if let Seg::Line(q) = &mut path.segs[0] {
        *q += across;
    }
    vec![
        (moved_name, moved),
        (format!("text {:?} dropped", text_of(&gone).unwrap().plain()), dropped),
        (format!("thin line of {:.0} mm moved 2 mm", path.bbox().size().to_vec2().length()), shifted),
    ]
}

#[test]
fn a_moved_label_a_lost_text_or_a_moved_line_exceeds_the_tolerance() {
    let b = pipeline::build(&fixture("worked-example"), &[1]).unwrap().remove(0);
    let scene = &b.output.scene;
    let (ours, svg) = (png_at(scene, DPI), resvg_at(scene, DPI));
    let pdf = have("pdftoppm");
    for (what, changed) in controls(scene) {
        let mut pairs = vec![
            ("PNG / original PNG", png_at(&changed, DPI), &ours),
            ("PNG / original SVG", png_at(&changed, DPI), &svg),
        ];
        if pdf {
            pairs.push(("PDF / original PNG", pdftoppm(&changed), &ours));
        }
        for (pair, a, b) in pairs {
            let u = unmatched(&a, b);
            eprintln!("{what}, {pair}: {} unmatched ink pixels ({} in the worst tile)", u.total, u.worst_tile);
            assert!(!u.within(TOLERANCE), "{what}, {pair}: {u:?} passes {TOLERANCE:?}");
        }
    }
}

/// The numbers of a PDF dictionary's array after `key`: "/MediaBox [0 0 2383.937 1683.78]".
fn array_after(pdf: &str, key: &str) -> Vec<f64> {
    let at = pdf.find(key).unwrap_or_else(|| panic!("no {key}")) + key.len();
    let inner = pdf[at..].trim_start().trim_start_matches('[').split(']').next().unwrap();
    inner.split_whitespace().map(|x| x.parse().unwrap()).collect()
}

#[test]
fn the_pdf_is_one_a1_page_of_selectable_text_in_an_embedded_subset_font() {
    let cases = [
        (fixture("worked-example"), ["Tezliklar rejalari", "μv = 0,015 (m/s)/mm", "Tuzilish formulasi"]),
        (russian_worked_example(), ["Планы скоростей", "μv = 0,015 (м/с)/мм", "Структурная формула"]),
    ];
    let tools = have("pdftotext") && have("pdffonts");
    for (p, probes) in cases {
        let b = pipeline::build(&p, &[1]).unwrap().remove(0);
        let bytes = pdf(&b.output.scene);
        let text = String::from_utf8_lossy(&bytes);
        let mm = |pt: f64| pt * 25.4 / 72.0;
        let mb = array_after(&text, "/MediaBox");
        assert_eq!((mb[0], mb[1]), (0.0, 0.0), "MediaBox {mb:?}");
        assert!((mm(mb[2]) - 841.0).abs() < 0.01 && (mm(mb[3]) - 594.0).abs() < 0.01, "A1: MediaBox {mb:?}");
        assert!(text.contains("/Count 1"), "exactly one page");
        assert!(text.contains("/FontFile2"), "the font is embedded");
        let subset = text.split("/BaseFont/").nth(1).expect("a font").split(['/', '>']).next().unwrap();
        assert!(subset.len() > 7 && subset.as_bytes()[6] == b'+', "a subset's name has a tag: {subset}");
        assert!(subset.ends_with("DejaVuSansCondensed"), "{subset}");
        assert!(!text.contains("/CreationDate") && !text.contains("/ModDate"), "no dates");
        if tools {
            let words = String::from_utf8(poppler("pdftotext", &["-enc", "UTF-8"], &bytes, &["-"])).unwrap();
            for probe in probes {
                assert!(words.contains(probe), "pdftotext does not find {probe:?} in:\n{words}");
            }
            let fonts = String::from_utf8(poppler("pdffonts", &[], &bytes, &[])).unwrap();
            let row = fonts.lines().find(|l| l.contains("DejaVuSansCondensed")).expect("the font");
            assert!(row.contains("yes yes yes"), "embedded, subset, with a Unicode map: {row}");
        }
    }
}

#[test]
fn pdf_and_png_bytes_are_the_same_for_the_same_scene() {
    let p = fixture("worked-example");
    for b in pipeline::build(&p, &[]).unwrap() {
        let again = pipeline::build(&p, &[b.output.number]).unwrap().remove(0);
        for format in [Format::Pdf, Format::Png { dpi: 30.0 }] {
            let (x, y) = (pipeline::render(&b, format).unwrap(), pipeline::render(&again, format).unwrap());
            assert!(x == y, "sheet {}: {format:?} bytes differ between two renders", b.output.number);
        }
    }
}

/// A scene of one group, "g", holding `items`.
fn scene_of(items: Vec<Item>) -> Scene {
    let mut g = Group::new("g", Rect::new(0.0, 0.0, 100.0, 60.0));
    g.items = items;
    Scene {
        ink: Default::default(),
        name: "s".into(),
        width: 100.0,
        height: 60.0,
        title: "test".into(),
        groups: vec![Group::new("ok", Rect::ZERO), g],
    }
}

#[test]
fn every_backend_refuses_a_non_finite_number_naming_its_group() {
    let nan = f64::NAN;
    let bad = [
        Item::Path { path: Path::polyline(&[Point::new(1.0, 1.0), Point::new(nan, 2.0)], false), pen: THIN },
        Item::Path { path: Path::arc(Point::new(5.0, 5.0), f64::INFINITY, 0.0, 1.0), pen: THIN },
        Item::Circle { c: Point::new(1.0, 1.0), r: nan, pen: THIN, filled: true },
        Item::Fill { path: Path::polyline(&[Point::new(1.0, 1.0), Point::new(2.0, f64::NEG_INFINITY)], true) },
        Item::Text(Text::new(Point::new(nan, 1.0), "A", 5.0, Anchor::Start)),
        Item::Path {
            path: Path::polyline(&[Point::new(1.0, 1.0), Point::new(2.0, 2.0)], false),
            pen: tmm_sheets::drawing::scene::Pen { width: nan, ..THIN },
        },
    ];
    for item in bad {
        for format in [Format::Svg, Format::Pdf, Format::Png { dpi: 30.0 }] {
            match backend::write(&scene_of(vec![item.clone()]), format) {
                Err(BackendError::NonFinite { group, .. }) => assert_eq!(group, "g", "{format:?}: {item:?}"),
                other => panic!("{format:?} accepts {item:?}: {other:?}"),
            }
        }
    }
}

/// Texts the sheets do not have yet — turned, upright, anchored three ways, with
/// subscripts and tails — with dashed arcs and circles: the PNG and the PDF set them where
/// an SVG renderer does.
fn turned_texts(sign: f64) -> Scene {
    let mut items = Vec::new();
    for (k, (rotate, anchor, sloped)) in [
        (90.0, Anchor::Start, true),
        (30.0, Anchor::Middle, false),
        (-45.0, Anchor::End, true),
        (0.0, Anchor::Middle, true),
    ]
    .into_iter()
    .enumerate()
    {
        let at = Point::new(20.0 + 22.0 * k as f64, 35.0);
        let mut t = Text::new(at, "Hm", 5.0, anchor).with_sub("BA", " = 12 mm");
        (t.rotate, t.sloped) = (sign * rotate, sloped);
        items.push(Item::Text(t));
    }
    items.push(Item::Path { path: Path::arc(Point::new(50.0, 30.0), 25.0, 0.3, -4.0), pen: DASHED });
    items.push(Item::Circle { c: Point::new(80.0, 45.0), r: 9.0, pen: AXIS, filled: false });
    items.push(Item::Circle { c: Point::new(12.0, 50.0), r: 1.0, pen: MAIN, filled: true });
    scene_of(items)
}

/// Our PNG of `scene` at `dpi` matches resvg's of our SVG and poppler's of our PDF within
/// [`TOLERANCE`].
fn assert_backends_agree(scene: &Scene, dpi: f64) {
    let (ours, svg) = (png_at(scene, dpi), resvg_at(scene, dpi));
    let same = unmatched(&ours, &svg);
    assert!(same.within(TOLERANCE), "PNG / SVG: {same:?}");
    if have("pdftoppm") {
        let page = poppler("pdftoppm", &["-r", &dpi.to_string(), "-png"], &pdf(scene), &[]);
        let from_pdf = unmatched(&Ink::from_png(&page), &ours);
        assert!(from_pdf.within(TOLERANCE), "PDF / PNG: {from_pdf:?}");
    }
}

#[test]
fn turned_and_anchored_text_lands_where_the_svg_puts_it() {
    let dpi = 200.0;
    let scene = turned_texts(1.0);
    assert_backends_agree(&scene, dpi);
    let svg = resvg_at(&scene, dpi);
    let turned_back = unmatched(&png_at(&turned_texts(-1.0), dpi), &svg);
    assert!(!turned_back.within(TOLERANCE), "turning the other way must show: {turned_back:?}");
}

/// Box 26 with a designation that wraps nowhere, so it is condensed (and turned 180°): the
/// PNG, the PDF and the SVG set it in the same place. Centred by its anchor, a condensed
/// turned line was put 14 mm left of the box by the PDF's viewer and 22 mm right by librsvg.
#[test]
fn a_condensed_turned_designation_lands_alike_in_every_backend() {
    let g =
        tmm_sheets::drawing::frame::designation_box_group("ТММ-КП-01.00.00-ПЗ-ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789")
            .unwrap();
    let t = g.texts().next().expect("the designation");
    assert!(t.stretch < 1.0 && t.rotate == 180.0, "condensed and turned: {t:?}");
    let scene = Scene {
        ink: Default::default(),
        name: "s".into(),
        width: 100.0,
        height: 30.0,
        title: "test".into(),
        groups: vec![g],
    };
    let dpi = 200.0;
    assert_backends_agree(&scene, dpi);
}

/// Condensed texts anchored at their middle or end, upright and turned: the PNG and the PDF
/// set them where the SVG does. The runs were offset by the condensed advance in the frame
/// the stretch then scales, so a centred condensed line (the title block's designation or
/// project title, when long) stood off its middle in the PDF and PNG by a sixth of its width.
#[test]
fn condensed_texts_anchored_at_their_middle_or_end_land_alike_in_every_backend() {
    let mut items = Vec::new();
    for (k, (anchor, rotate)) in
        [(Anchor::Middle, 0.0), (Anchor::End, 0.0), (Anchor::Middle, 180.0), (Anchor::End, 90.0)]
            .into_iter()
            .enumerate()
    {
        let at = Point::new(50.0, 10.0 + 12.0 * k as f64);
        let mut t = Text::new(at, "ABCDEFGHIJKLMNOPQRSTUVWXYZ", 2.5, anchor).with_stretch(0.7);
        t.rotate = rotate;
        items.push(Item::Text(t));
    }
    let scene = scene_of(items);
    let dpi = 200.0;
    assert_backends_agree(&scene, dpi);
}
