//! Sheet 1 as a user gets it: deterministic bytes, a valid SVG that parses back with
//! every text, nothing outside its region or overlapping, three languages, an A1 PDF,
//! and the committed reference sheets of the worked example.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;
mod svg_raster;

use common::{check_layout, english_on_russian, fixture, fixture_names, root};
use kurbo::Rect;
use std::path::Path;
use tmm_sheets::drawing::frame;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::scene::Item;
use tmm_sheets::pipeline::{self, Built, Format};
use tmm_sheets::project::Project;
use tmm_sheets::report;

fn build(p: &Project) -> Built {
    pipeline::build(p, &[]).unwrap().remove(0)
}

fn pdf(b: &Built) -> Vec<u8> {
    pipeline::render(b, Format::Pdf).unwrap()
}

fn png(b: &Built, dpi: f64) -> Vec<u8> {
    pipeline::render(b, Format::Png { dpi }).unwrap()
}

#[test]
fn the_same_input_gives_byte_identical_svg_and_pdf() {
    let p = fixture("worked-example");
    let (a, b) = (build(&p), build(&p));
    assert_eq!(a.svg, b.svg);
    assert!(pdf(&a) == pdf(&b), "PDF bytes differ between two runs");
}

fn count_usvg(group: &usvg::Group, paths: &mut usize, texts: &mut usize) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => count_usvg(g, paths, texts),
            usvg::Node::Path(_) => *paths += 1,
            usvg::Node::Text(_) => *texts += 1,
            usvg::Node::Image(_) => {}
        }
    }
}

#[test]
fn svg_parses_back_with_every_path_and_text_and_no_nan() {
    for name in fixture_names() {
        let r = build(&fixture(&name));
        assert!(!r.svg.contains("NaN") && !r.svg.contains("inf"), "{name}: non-finite number in the SVG");
        // Curves are curves: ω/ε arcs as `A`, trajectories as `C`, within 0.01 mm of exact.
        assert!(r.svg.contains(" 0 0 1 ") || r.svg.contains(" 0 0 0 "), "{name}: no arc command");
        let fit = r.output.results["trajectory_fit_error_mm"].as_f64().unwrap();
        assert!(fit <= 0.01, "{name}: trajectories {fit} mm from the exact paths");
        let tree = svg_raster::parse(&r.svg);
        let (mut paths, mut texts) = (0, 0);
        count_usvg(tree.root(), &mut paths, &mut texts);
        let items = r.output.scene.groups.iter().flat_map(|g| &g.items);
        let want_texts = items.clone().filter(|i| matches!(i, Item::Text(_))).count();
        let want_paths = items.filter(|i| !matches!(i, Item::Text(_))).count() + 1; // + the white page
        assert_eq!(texts, want_texts, "{name}: usvg dropped text (font not found?)");
        assert_eq!(paths, want_paths, "{name}: path count");
    }
}

fn inside(outer: Rect, r: Rect) -> bool {
    frame::is_inside(outer, r)
}

#[test]
fn nothing_leaves_its_region_or_overlaps_on_any_fixture() {
    for name in fixture_names() {
        check_layout(&name, &build(&fixture(&name)).output.scene);
    }
}

#[test]
fn every_language_renders_with_full_glyph_coverage() {
    let metrics = tmm_sheets::font::metrics();
    for (lang, probe) in
        [(Language::Uz, "Tezliklar rejalari"), (Language::Ru, "Планы скоростей"), (Language::En, "Velocity plans")]
    {
        let mut p = fixture("worked-example");
        p.info.language = lang;
        let r = build(&p);
        assert!(r.svg.contains(probe), "{lang:?}: missing {probe}");
        for t in common::runs(&r.output.scene) {
            assert!(metrics.covers(t), "{lang:?}: no glyph for some character of {t:?}");
        }
        check_layout(&format!("{lang:?}"), &r.output.scene);
    }
}

#[test]
fn pdf_is_one_a1_page_with_embedded_text() {
    let r = build(&fixture("worked-example"));
    let (pdf, png) = (pdf(&r), png(&r, 20.0));
    assert!(pdf.starts_with(b"%PDF-"));
    let text = String::from_utf8_lossy(&pdf);
    let mb = text.find("/MediaBox").expect("a media box");
    let nums: Vec<f64> = text[mb + 9..]
        .trim_start()
        .trim_start_matches('[')
        .split(']')
        .next()
        .unwrap()
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    let mm = |pt: f64| pt * 25.4 / 72.0;
    assert!(
        (mm(nums[2] - nums[0]) - 841.0).abs() < 0.01 && (mm(nums[3] - nums[1]) - 594.0).abs() < 0.01,
        "MediaBox {nums:?}"
    );
    assert!(text.contains("/Count 1"), "exactly one page");
    assert!(text.contains("/FontFile2") || text.contains("/FontFile3"), "the font is embedded");
    assert!(png.starts_with(b"\x89PNG"));
}

fn reference_dir() -> std::path::PathBuf {
    root().join("sheets/worked-example")
}

/// Pixels of two renderings compared channel by channel: how many differ by more than
/// `PIXEL_TOLERANCE` in some channel, and an image marking them (red on a faded actual).
fn pixel_diff(expected: &[u8], actual: &[u8]) -> Result<(usize, Vec<u8>), String> {
    use resvg::tiny_skia::Pixmap;
    let e = Pixmap::decode_png(expected).map_err(|x| format!("expected PNG: {x}"))?;
    let a = Pixmap::decode_png(actual).map_err(|x| format!("actual PNG: {x}"))?;
    if (e.width(), e.height()) != (a.width(), a.height()) {
        return Err(format!("size {}×{} vs {}×{}", e.width(), e.height(), a.width(), a.height()));
    }
    let mut diff = a.clone();
    let mut count = 0;
    for ((pe, pa), pd) in e.data().chunks(4).zip(a.data().chunks(4)).zip(diff.data_mut().chunks_mut(4)) {
        let differs = pe.iter().zip(pa).any(|(x, y)| x.abs_diff(*y) > PIXEL_TOLERANCE);
        let faded = 255 - (255 - pa[1]) / 4;
        pd.copy_from_slice(&if differs { [255, 0, 0, 255] } else { [faded, faded, faded, 255] });
        count += usize::from(differs);
    }
    Ok((count, diff.encode_png().map_err(|x| x.to_string())?))
}

/// A channel may differ this much (of 255) between renderings before a pixel counts.
const PIXEL_TOLERANCE: u8 = 48;
/// Share of the sheet's pixels that may differ: anti-aliasing of a different rasteriser
/// build, not a moved line or a lost text.
const PIXEL_SHARE: f64 = 5e-4;

/// Writes expected, actual and difference images of a failed comparison to tests/failures/.
fn write_failure_images(name: &str, expected: &[u8], actual: &[u8]) -> String {
    let dir = root().join("tests/failures");
    let _ = std::fs::create_dir_all(&dir);
    let _ = std::fs::write(dir.join(format!("{name}-expected.png")), expected);
    let _ = std::fs::write(dir.join(format!("{name}-actual.png")), actual);
    match pixel_diff(expected, actual) {
        Ok((count, image)) => {
            let _ = std::fs::write(dir.join(format!("{name}-diff.png")), image);
            format!("expected, actual and diff images written to {} ({count} pixels differ)", dir.display())
        }
        Err(e) => format!("expected and actual images written to {} ({e})", dir.display()),
    }
}

fn preview(svg: &str, dpi: f64) -> Vec<u8> {
    svg_raster::png(svg, 841.0, 594.0, dpi)
}

fn compare_or_update(file: &str, actual: &str) {
    let path = reference_dir().join(file);
    if std::env::var_os("UPDATE").is_some() {
        std::fs::create_dir_all(reference_dir()).unwrap();
        std::fs::write(&path, actual).unwrap();
        return;
    }
    let expected = std::fs::read_to_string(&path)
        .unwrap_or_else(|_| panic!("missing reference {}: run UPDATE=1 cargo test --test sheets", path.display()));
    if expected != actual {
        let note = if file.ends_with(".svg") {
            write_failure_images(file, &preview(&expected, 30.0), &preview(actual, 30.0))
        } else {
            String::new()
        };
        panic!(
            "{} differs from the reference; if the change is intended run UPDATE=1 cargo test --test sheets. {note}",
            path.display()
        );
    }
}

/// Full-precision numbers move in the last bits when a formula is rearranged, so the JSON
/// is compared value by value to 1e-9 (absolute, plus relative for large values).
fn json_close(a: &serde_json::Value, b: &serde_json::Value, path: &str) -> Result<(), String> {
    use serde_json::Value::*;
    match (a, b) {
        (Number(x), Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            if (x - y).abs() <= 1e-9 * (1.0 + x.abs().max(y.abs())) {
                Ok(())
            } else {
                Err(format!("{path}: {x} vs {y}"))
            }
        }
        (Array(x), Array(y)) if x.len() == y.len() => {
            x.iter().zip(y).enumerate().try_for_each(|(i, (p, q))| json_close(p, q, &format!("{path}[{i}]")))
        }
        (Object(x), Object(y)) if x.len() == y.len() => x.iter().try_for_each(|(k, v)| {
            json_close(v, y.get(k).ok_or(format!("{path}.{k} missing"))?, &format!("{path}.{k}"))
        }),
        _ if a == b => Ok(()),
        _ => Err(format!("{path}: {a} vs {b}")),
    }
}

fn compare_json_or_update(file: &str, actual: &str) {
    let path = reference_dir().join(file);
    if std::env::var_os("UPDATE").is_some() {
        std::fs::write(&path, actual).unwrap();
        return;
    }
    let expected: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let actual: serde_json::Value = serde_json::from_str(actual).unwrap();
    if let Err(e) = json_close(&expected, &actual, "") {
        panic!(
            "{} differs from the reference at {e}; if intended run UPDATE=1 cargo test --test sheets",
            path.display()
        );
    }
}

#[test]
fn worked_example_matches_the_reference_sheets() {
    let p = fixture("worked-example");
    let built = pipeline::build(&p, &[]).unwrap();
    let numbers: Vec<u32> = built.iter().map(|b| b.output.number).collect();
    assert_eq!(numbers, [1, 2, 3], "the worked example has sheets 1, 2 and 3");
    let stems: Vec<&str> = built[0].output.tables.iter().map(|t| t.table.id).collect();
    assert_eq!(
        stems,
        ["velocities", "accelerations", "inertia", "reactions", "balancing"],
        "the worked example has tables 1–5"
    );
    for r in &built {
        let stem = format!("sheet{}", r.output.number);
        compare_or_update(&format!("{stem}.svg"), &r.svg);
        for t in &r.output.tables {
            compare_or_update(&format!("{stem}-{}.csv", t.table.id), &report::csv(t, &stem));
        }
        let (pdf, png) = (pdf(r), png(r, 60.0));
        let (pdf_name, png_name) = (format!("{stem}.pdf"), format!("{stem}.png"));
        if std::env::var_os("UPDATE").is_some() {
            std::fs::write(reference_dir().join(&pdf_name), pdf).unwrap();
            std::fs::write(reference_dir().join(&png_name), &png).unwrap();
        }
        assert!(Path::new(&reference_dir().join(&pdf_name)).exists());
        // The rendering, pixel by pixel: catches what the SVG text cannot (a font the renderer
        // no longer finds, a changed rasteriser).
        let expected = std::fs::read(reference_dir().join(&png_name)).unwrap();
        let (count, _) = pixel_diff(&expected, &png).unwrap_or_else(|e| panic!("{png_name}: {e}"));
        let pixels = 1987.0 * 1403.0;
        if count as f64 > PIXEL_SHARE * pixels {
            let note = write_failure_images(&png_name, &expected, &png);
            panic!("{png_name} differs from the reference in {count} pixels; {note}");
        }
    }
    let json = pipeline::results_json(&p, &built);
    compare_json_or_update("results.json", &json);
}

/// Every word and unit on a Russian sheet is Russian (user text aside, set here in Cyrillic).
#[test]
fn a_russian_sheet_has_no_english_word_or_unit() {
    assert!(english_on_russian(" = 0,015 m/mm").is_some());
    assert_eq!(english_on_russian("P, N"), Some("N".into()));
    assert_eq!(english_on_russian("m"), None);
    assert_eq!(english_on_russian(" = 0,015 м/мм"), None);
    for name in fixture_names() {
        let mut p = fixture(&name);
        p.info.language = Language::Ru;
        p.info.title = "Механизм".into();
        p.info.institution = "ТГТУ".into();
        p.info.designation = "ТММ 01.00.00".into();
        p.lever.as_mut().unwrap().assumptions.clear();
        let r = build(&p);
        for t in common::runs(&r.output.scene) {
            assert_eq!(english_on_russian(t), None, "{name}: English on the Russian sheet: {t:?}");
        }
    }
}

/// Titles of every length up to the name field's capacity are set smaller, then wrapped, and
/// never leave their field; a designation too long for one 7 mm line is made smaller.
#[test]
fn long_title_block_texts_are_fitted_inside_their_cells() {
    let field = frame::name_field_rect();
    for words in [1, 6, 13, 20, 28] {
        let mut p = fixture("worked-example");
        p.info.title = (0..words).map(|i| format!("soʻz{i}")).collect::<Vec<_>>().join(" ").into();
        p.info.designation =
            "MMN KL 01.00.00.000 TX — ".repeat(1 + words / 10).trim_end_matches(" — ").to_string().into();
        let r = build(&p);
        check_layout(&format!("{words} words"), &r.output.scene);
        let tb = r.output.scene.groups.iter().find(|g| g.id == "title-block").unwrap();
        let texts: Vec<_> =
            tb.items.iter().filter_map(|i| if let Item::Text(t) = i { Some(t) } else { None }).collect();
        for t in &texts {
            assert!(inside(tb.region, t.core_box()), "{words} words: {:?} leaves the title block", t.text);
            if t.text.contains("soʻz") {
                assert!(inside(field, t.core_box()), "{words} words: {:?} leaves the name field", t.text);
            }
        }
        let shown: String =
            texts.iter().filter(|t| t.text.contains("soʻz")).map(|t| t.text.as_str()).collect::<Vec<_>>().join(" ");
        assert_eq!(shown, p.info.title(), "every word of the title is shown, in order");
    }
}

#[test]
fn xml_special_characters_in_user_text_are_escaped() {
    let mut p = fixture("worked-example");
    p.info.title = "A & B <C> \"D\" 'E'".into();
    let r = build(&p);
    assert!(r.svg.contains("A &amp; B &lt;C&gt; &quot;D&quot; &apos;E&apos;"));
    let tree = svg_raster::parse(&r.svg);
    let (mut paths, mut texts) = (0, 0);
    count_usvg(tree.root(), &mut paths, &mut texts);
    assert!(texts > 100);
}

/// φ1 over a turn, for the layout sweep (the assigned position moves the thick drawing, the
/// force drawings and their polygons).
const PHI1_SWEEP: [f64; 4] = [10.0, 100.0, 190.0, 280.0];

/// No plan's longer side is shorter than this on any fixture, mm: measurable with a ruler.
const SMALLEST_PLAN_MM: f64 = 25.0;

/// Every fixture in every language at several φ1: no text crossed by a line or overlapping
/// another, nothing outside its region, every plan large enough to measure — and
/// `results.json` reports the same.
#[test]
fn the_layout_holds_for_every_fixture_language_and_phi1() {
    let mut failures = Vec::new();
    for name in fixture_names() {
        for lang in Language::ALL {
            for phi1 in PHI1_SWEEP {
                let mut p = fixture(&name);
                p.info.language = lang;
                p.lever.as_mut().unwrap().settings.assigned_deg = Some(phi1);
                let label = format!("{name} {lang:?} φ1 = {phi1}°");
                match pipeline::build(&p, &[]) {
                    Ok(mut b) => {
                        let out = b.remove(0).output;
                        let reported = &out.results["layout"];
                        let smallest = reported["smallest_plan_mm"].as_f64().unwrap_or(0.0);
                        if tmm_sheets::drawing::layout::FAULTS.iter().any(|k| reported[*k] != 0) {
                            failures.push(format!("{label}: results.json reports {reported}"));
                        }
                        if smallest < SMALLEST_PLAN_MM {
                            failures.push(format!("{label}: the smallest plan is {smallest:.1} mm"));
                        }
                        if let Err(e) = std::panic::catch_unwind(|| check_layout(&label, &out.scene)) {
                            failures.push(e.downcast_ref::<String>().cloned().unwrap_or(label));
                        }
                    }
                    Err(e) => failures.push(format!("{label}: {e:#}")),
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} layouts fail:\n{}", failures.len(), failures.join("\n"));
}

/// A number as an Uzbek or Russian sheet must not print it: with a decimal point ("2.5",
/// "1:2.5") or, in any language, with a hyphen for its minus ("-4600").
fn misprinted_number(text: &str, comma: bool) -> Option<String> {
    let c: Vec<char> = text.chars().collect();
    for i in 0..c.len() {
        let digit = |j: usize| c.get(j).is_some_and(|x| x.is_ascii_digit());
        let point = comma && c[i] == '.' && i > 0 && digit(i - 1) && digit(i + 1);
        let hyphen = c[i] == '-' && digit(i + 1);
        if point || hyphen {
            return Some(c[i.saturating_sub(3)..(i + 4).min(c.len())].iter().collect());
        }
    }
    None
}

/// Numbers in the sheet's style everywhere (scales in the title block included), and the
/// note's tables with a unit on every row that has one (user text cleared, as it is theirs).
#[test]
fn numbers_and_units_are_printed_in_the_sheets_style() {
    assert!(misprinted_number("1:2.5", true).is_some() && misprinted_number("P = -4600", false).is_some());
    assert!(misprinted_number("1:2,5  −4600  II(4,5)  I – kengayish", true).is_none());
    for name in fixture_names() {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            (p.info.title, p.info.designation, p.info.institution) = ("T".into(), "D".into(), "I".into());
            p.lever.as_mut().unwrap().assumptions.clear();
            let r = build(&p);
            for t in r.output.scene.texts() {
                for part in [&t.text, &t.tail] {
                    assert_eq!(misprinted_number(part, lang != Language::En), None, "{name} {lang:?}: {:?}", t.plain());
                }
            }
            // Table 3's rows name their units: "m, кг", "J_S, кг·м²".
            let kg = tmm_sheets::drawing::labels::Common::get(lang).unit_kg();
            assert!(r.output.scene.texts().any(|t| t.tail == format!(", {kg}")), "{name} {lang:?}: no unit in table 3");
        }
    }
}

/// Each load diagram ticks its force axis at a round step over the whole range (to within
/// one step of either extreme), and marks φ1 with its value.
#[test]
fn load_diagrams_tick_the_force_axis_and_mark_phi1() {
    for name in fixture_names() {
        let p = fixture(&name);
        let lever = common::build_lever(&p);
        let Some((fa, _)) = &lever.forces else { continue };
        // The force cells' groups: the forces' region and the room beside the mechanism.
        let items: Vec<&Item> =
            lever.composed.scene.groups.iter().filter(|g| g.id.starts_with("forces")).flat_map(|g| &g.items).collect();
        assert!(!items.is_empty(), "{name}: no forces group");
        let numbers: Vec<f64> = items
            .iter()
            .filter_map(|i| if let Item::Text(t) = i { Some(t.text.replace('−', "-").replace(',', ".")) } else { None })
            .filter_map(|t| t.parse::<f64>().ok())
            .filter(|v| v.fract() == 0.0 && v.abs() >= 1.0)
            .collect();
        for load in &fa.model.loads {
            let values = load.branches.iter().flat_map(|b| b.curve.points.iter().map(move |q| q.1 * b.scale));
            let (lo, hi) = values.fold((f64::MAX, f64::MIN), |(lo, hi), y| (lo.min(y), hi.max(y)));
            // The round steps a reader can count in: 1, 2, 2.5, 4, 5 × 10^k newtons.
            let covered =
                [1.0, 2.0, 2.5, 4.0, 5.0].iter().flat_map(|m| (0..7).map(move |e| m * 10f64.powi(e))).any(|step| {
                    let ticks: Vec<f64> = numbers.iter().copied().filter(|v| (v / step).fract() == 0.0).collect();
                    let (tmin, tmax) = ticks.iter().fold((0.0f64, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
                    ticks.len() >= 2 && tmin <= lo.min(0.0) + step + 1e-9 && tmax >= hi.max(0.0) - step - 1e-9
                });
            assert!(
                covered,
                "{name}: the load diagram of [{lo}, {hi}] N has no round-step ticks over its range: {numbers:?}"
            );
        }
        let phi = tmm_sheets::drawing::fmt::localise(
            &format!("{:.1}", lever.kinematics.assigned.phi.to_degrees()),
            p.info.language,
        );
        let marked = items.iter().any(|i| matches!(i, Item::Text(t) if t.tail.trim() == format!("= {phi}°")));
        assert!(marked || fa.model.loads.is_empty(), "{name}: φ1 = {phi}° is not marked on the load diagram");
    }
}

/// Each plan is drawn at a round scale (1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6 or 7.5 × 10ᵏ), recorded
/// with its drawn size in `results.json`; the size is the plan's extent at that scale — its
/// diagonal at least the crank pin's velocity |v_A|/μ_v, computed here from ω1·l1. Every plan
/// of a kind shares the sheet's μ_v or μ_a, written in the region's header (a plan leaves it
/// only where one μ would draw a plan under 20 mm, which no fixture does).
#[test]
fn plans_share_one_round_scale_a_kind_recorded_with_their_sizes() {
    let round = |mu: f64| {
        let m = mu / 10f64.powf(mu.log10().floor());
        [1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.5, 10.0].iter().any(|r| (m - r).abs() < 1e-9)
    };
    let written = |mu: f64, lang| {
        format!("= {} ", tmm_sheets::drawing::fmt::localise(&tmm_sheets::drawing::scale::format(mu), lang))
    };
    for name in fixture_names() {
        let p = fixture(&name);
        let b = pipeline::build(&p, &[]).unwrap().remove(0).output;
        let m = &p.lever.as_ref().unwrap().mechanism;
        let v_a = (m.omega1 * m.crank().length).abs();
        let scales = &b.results["scales"];
        for kind in ["velocity_plans", "acceleration_plans"] {
            let plans = scales[kind].as_array().expect("plans recorded");
            assert!(!plans.is_empty(), "{name}: no {kind}");
            let common = scales[if kind == "velocity_plans" { "mu_v" } else { "mu_a" }].as_f64().expect("one scale");
            assert!(round(common), "{name}: {kind} at μ = {common}");
            assert!(b.scene.texts().any(|t| t.tail.trim_start().starts_with(&written(common, p.info.language))));
            for plan in plans {
                let mu = plan["mu"].as_f64().unwrap();
                assert!(round(mu), "{name}: {kind} at μ = {mu}");
                let [w, h] = [0, 1].map(|k| plan["size_mm"][k].as_f64().unwrap());
                if kind == "velocity_plans" {
                    // pa lies inside the plan's box: no longer than its diagonal.
                    let diagonal = w.hypot(h);
                    assert!(
                        diagonal >= v_a / mu - 1e-9,
                        "{name}: plan {} is {w} × {h} mm, pa alone is {} mm",
                        plan["position"],
                        v_a / mu
                    );
                }
                assert_eq!(mu, common, "{name}: {kind} {} leaves the sheet's one μ", plan["position"]);
            }
        }
    }
}

/// The largest plan of each kind is at least 80 mm long where its column allows it (the
/// guide's plans are that large): on these fixtures it does — the next coarser scale drew
/// them under 80 mm (recorded sizes at the sheet's μ, measured here at the plan's own μ
/// times the ratio). The V-compressor's 16 plans reach it with table 1 moved down beside
/// the title block (its acceleration plans were 75 mm under it); the jaw crusher's beside
/// its force drawings do not fit at 80 mm, its largest plans are over 70 mm.
#[test]
fn the_largest_plan_of_each_kind_is_80_mm_where_the_column_allows() {
    for (name, least) in [
        ("worked-example", 80.0),
        ("crank-slider-axial", 80.0),
        ("crank-slider-offset-vertical", 80.0),
        ("two-cylinder-compressor", 80.0),
        ("four-bar", 80.0),
        ("kulisa", 80.0),
        ("v-compressor", 80.0),
        ("jaw-crusher", 70.0),
    ] {
        for lang in Language::ALL {
            let mut p = fixture(name);
            p.info.language = lang;
            let b = pipeline::build(&p, &[]).unwrap().remove(0).output;
            for kind in ["velocity_plans", "acceleration_plans"] {
                let largest = b.results["scales"][kind]
                    .as_array()
                    .expect("plans recorded")
                    .iter()
                    .map(|plan| (0..2).map(|k| plan["size_mm"][k].as_f64().unwrap()).fold(0.0, f64::max))
                    .fold(0.0, f64::max);
                assert!(largest >= least, "{name} {lang:?}: the largest of the {kind} is {largest:.1} mm");
            }
        }
    }
}

/// Force symbols on a Russian sheet carry Russian subscripts (P_и, M_и, P_пс, P_г, P_ур), in
/// the drawings and the tables: no subscript of the Latin letters i, m, c or g is left.
#[test]
fn force_subscripts_on_a_russian_sheet_are_russian() {
    for name in fixture_names() {
        let mut p = fixture(&name);
        if p.lever.as_ref().unwrap().forces.is_none() {
            continue;
        }
        p.info.language = Language::Ru;
        let scene = pipeline::build(&p, &[]).unwrap().remove(0).output.scene;
        let latin = |t: &str| {
            let mut c = t.chars();
            matches!(c.next(), Some('i' | 'm' | 'c' | 'g')) && c.all(|d| d.is_ascii_digit())
        };
        let texts: Vec<&str> = scene.texts().map(|t| t.sub.as_str()).collect();
        let found: Vec<&str> = texts.iter().copied().filter(|t| latin(t)).collect();
        assert!(found.is_empty(), "{name}: Latin force subscripts on a Russian sheet: {found:?}");
        assert!(texts.contains(&"ур") && texts.iter().any(|t| t.starts_with('и')), "{name}: no P_ур or P_и");
    }
}

/// Every sheet of every fixture (the gear and cam ones too) speaks the language it is built
/// in, the user's texts included (title, designation, institution, assumptions, law names):
/// no Latin word (English or Uzbek) on a Russian sheet, no Cyrillic letter and no Uzbek ʻ on
/// an English one, the Uzbek course letters MMN on neither; and no sheet prints a plain-text
/// subscript's underscore.
#[test]
fn every_sheet_of_every_fixture_speaks_its_language() {
    let mut names: Vec<String> = fixture_names();
    for dir in ["gears", "cams"] {
        let mut more: Vec<String> = std::fs::read_dir(root().join("fixtures").join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
            .map(|p| format!("{dir}/{}", p.file_stem().unwrap().to_string_lossy()))
            .collect();
        more.sort();
        names.extend(more);
    }
    for name in names {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            for sheet in pipeline::build(&p, &[]).unwrap_or_else(|e| panic!("{name}: {e:#}")) {
                for t in common::runs(&sheet.output.scene) {
                    // A plain-text subscript ("n_dv") prints its underscore.
                    assert!(!t.contains('_'), "{name} sheet {} in {lang:?}: {t:?}", sheet.output.number);
                    let bad = match lang {
                        Language::Uz => None,
                        Language::Ru => english_on_russian(t),
                        Language::En => t
                            .chars()
                            .find(|c| matches!(c, 'А'..='я' | 'Ё' | 'ё' | 'ʻ'))
                            .map(|c| format!("{c:?} in {t:?}")),
                    };
                    assert_eq!(bad, None, "{name} sheet {} in {lang:?}: {t:?}", sheet.output.number);
                    // The Uzbek course letters (MMN: mashina va mexanizmlar nazariyasi) belong
                    // on an Uzbek sheet only, the designation's included.
                    assert!(
                        lang == Language::Uz || !t.contains("MMN"),
                        "{name} sheet {} in {lang:?}: {t:?}",
                        sheet.output.number
                    );
                }
            }
        }
    }
}

/// The title block's role captions (Drawn, Checked, …, Approved) stay inside their 17 mm
/// column in every language, with room before its rule, and share one height: the Uzbek
/// "Tasdiqladi" at 2.5 mm would touch the rule.
#[test]
fn the_title_blocks_role_captions_fit_their_column() {
    let tb = frame::title_block_rect();
    for lang in Language::ALL {
        let mut p = fixture("worked-example");
        p.info.language = lang;
        let r = build(&p);
        let g = r.output.scene.groups.iter().find(|g| g.id == "title-block").unwrap();
        let column: Vec<_> = g.texts().filter(|t| t.at.x < tb.x0 + 2.0 && t.at.y > tb.y0 + 25.0).collect();
        assert_eq!(column.len(), 5, "{lang:?}: {:?}", column.iter().map(|t| &t.text).collect::<Vec<_>>());
        for t in &column {
            assert!(t.bbox().x1 <= tb.x0 + 17.0 - 0.3, "{lang:?}: {:?} reaches {}", t.text, t.bbox().x1 - tb.x0);
            assert!(t.h >= 1.8 && t.h == column[0].h, "{lang:?}: {:?} at {} mm", t.text, t.h);
        }
    }
}

/// A slider's stroke is dimensioned once per line it runs on: the two-cylinder compressor's
/// pistons share one line and one stroke (one H); the V-compressor's two sliders run on two
/// lines, each H named by its slider's point. The strokes' values are the crank's throw
/// doubled, 2·l_OA, computed here for these axial slider-cranks.
#[test]
fn each_stroke_is_dimensioned_once_and_named_by_its_slider_when_there_are_two() {
    for (name, expected) in [("two-cylinder-compressor", vec![""]), ("v-compressor", vec!["B", "C"])] {
        let p = fixture(name);
        let b = pipeline::build(&p, &[]).unwrap().remove(0).output;
        let throw = 2.0 * p.lever.as_ref().unwrap().mechanism.crank().length * 1e3;
        let strokes: Vec<_> = b.scene.texts().filter(|t| t.text == "H" && t.tail.starts_with(" = ")).collect();
        let subs: Vec<&str> = strokes.iter().map(|t| t.sub.as_str()).collect();
        assert_eq!(subs, expected, "{name}");
        for t in strokes {
            let value: f64 = t.tail[3..].split(' ').next().unwrap().replace(',', ".").parse().unwrap();
            assert!((value - throw).abs() < 0.05, "{name}: H{} = {value} mm, 2·l_OA = {throw} mm", t.sub);
        }
    }
}

/// The title block numbers a project's own sheets: the worked example's cam sheet is "3 of
/// 3", a cam alone or a gear pair alone is sheet 1 of 1 (a student handing in one sheet
/// is not missing two).
#[test]
fn the_title_block_numbers_the_projects_own_sheets() {
    let sheet_texts = |p: &mut Project, n: u32| -> Vec<String> {
        p.info.language = Language::Ru;
        let b = pipeline::build(p, &[n]).unwrap().remove(0);
        let tb = b.output.scene.groups.iter().find(|g| g.id == "title-block").expect("a title block");
        tb.texts().map(|t| t.plain()).filter(|t| t.starts_with("Лист")).collect()
    };
    let mut worked = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    for (n, expect) in [(1, "Лист 1"), (2, "Лист 2"), (3, "Лист 3")] {
        let texts = sheet_texts(&mut worked, n);
        assert!(texts.contains(&expect.to_string()) && texts.contains(&"Листов 3".to_string()), "sheet {n}: {texts:?}");
    }
    for (name, n) in [("cams/knife-rocker", 3), ("gears/undercut", 2)] {
        let texts = sheet_texts(&mut fixture(name), n);
        assert!(texts.contains(&"Лист 1".to_string()) && texts.contains(&"Листов 1".to_string()), "{name}: {texts:?}");
    }
}

/// Positions that coincide on paper are drawn once and numbered once, "3′ ≡ 4": the guide's
/// task 5, variant 23 has its second extreme position a degree or so of the crank before
/// position 4 (variant 22 had, until position 0 moved to the crushing stroke's start).
#[test]
fn positions_that_coincide_on_paper_are_numbered_once() {
    use tmm_sheets::catalogue::{Catalogue, Variant};
    let catalogue = Catalogue::embedded().unwrap();
    let Variant::Project { text, .. } = catalogue.task("5").unwrap().project(23, Language::En, "test").unwrap() else {
        panic!("task 5, variant 23 gives a project");
    };
    let p = pipeline::load(&text).unwrap();
    let lever = p.lever.as_ref().unwrap();
    let k = tmm_sheets::lever::analysis::kinematics(&lever.mechanism, &lever.settings).unwrap();
    let (extreme, next) = {
        let i = k.positions.iter().position(|q| q.label == "3′").expect("an extreme position 3′");
        (&k.positions[i], &k.positions[i + 1])
    };
    assert_eq!(next.label, "4");
    let b = pipeline::build(&p, &[1]).unwrap().remove(0);
    // The two positions, from their states and the sheet's μ_l: every point within 0.8 mm
    // on paper (GOST 2.303's least distance between parallel lines; 1.3° of the crank apart).
    let mu_l = b.output.results["scales"]["mu_l"].as_f64().unwrap();
    let apart = extreme.state.points.iter().zip(&next.state.points).map(|(a, b)| (a.p - b.p).hypot() / mu_l);
    let apart = apart.fold(0.0, f64::max);
    assert!(apart < 0.8, "{apart} mm at {mu_l}");
    let mech = b.output.scene.groups.iter().find(|g| g.id == "mechanism").unwrap();
    let numbers: Vec<String> = mech.texts().map(|t| t.plain()).filter(|t| t.contains('′')).collect();
    assert_eq!(numbers, vec!["3′ ≡ 4".to_string()], "the extreme position's numbers");
    assert!(!mech.texts().any(|t| t.plain() == "4"), "position 4 numbered on its own too");
}

/// The centres of mass' trajectories are thin dashed lines (GOST 2.303 keeps dash-dot for
/// axes), cut into strokes of 4 mm on the scene so that every renderer dashes them alike:
/// on every fixture's sheet 1, no curve is dash-dot, and the mechanism's thin curved
/// strokes are each at most 4 mm long.
#[test]
fn trajectories_are_thin_dashed_curves_not_axes() {
    use kurbo::ParamCurveArclen;
    use tmm_sheets::drawing::scene::{LineType, Seg};
    for name in fixture_names() {
        let r = build(&fixture(&name));
        let mut strokes = 0;
        for g in &r.output.scene.groups {
            for item in &g.items {
                let Item::Path { path, pen } = item else { continue };
                let curved = path.segs.iter().any(|s| matches!(s, Seg::Cubic(..)));
                assert!(!(curved && pen.line == LineType::DashDot), "{name}: a dash-dot curve in {}", g.id);
                if g.id == "mechanism" && curved && pen.line == LineType::Solid && pen.width < 0.3 {
                    let length: f64 = path.to_bez().segments().map(|s| s.arclen(1e-6)).sum();
                    assert!(length <= 4.01, "{name}: a thin curve {length:.2} mm long");
                    strokes += 1;
                }
            }
        }
        assert!(strokes >= 20, "{name}: {strokes} trajectory strokes");
    }
}

/// GOST 2.104's box 26: 70 × 14 mm in the frame's top-left corner, the designation in it
/// turned 180°, and no drawing or text of the sheet entering it (each sheet's first
/// heading starts right of it). Every sheet of every fixture and of the worked example in
/// every language.
#[test]
fn box_26_holds_the_designation_turned_and_nothing_else() {
    use tmm_sheets::drawing::frame::{DESIGNATION_BOX, FRAME};
    let mut projects: Vec<(String, Project)> = fixture_names().into_iter().map(|n| (n.clone(), fixture(&n))).collect();
    for lang in Language::ALL {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        projects.push((format!("worked example {lang:?}"), p));
    }
    for (name, p) in projects {
        for b in pipeline::build(&p, &[]).unwrap() {
            let n = b.output.number;
            let groups = &b.output.scene.groups;
            let g = groups.iter().find(|g| g.id == DESIGNATION_BOX).unwrap_or_else(|| panic!("{name} {n}: no box 26"));
            let f = frame::inner();
            assert_eq!(g.region, Rect::new(f.x0, f.y0, f.x0 + 70.0, f.y0 + 14.0), "{name} {n}");
            let texts: Vec<_> = g.texts().collect();
            let written: String = texts.iter().map(|t| t.text.as_str()).collect::<Vec<_>>().join(" ");
            assert_eq!(written, p.info.designation(), "{name} {n}: box 26 says {written:?}");
            for t in &texts {
                assert_eq!(t.rotate, 180.0, "{name} {n}: box 26's text turned {}°", t.rotate);
                let bb = Item::Text((*t).clone()).bbox();
                assert!(frame::is_inside(g.region, bb), "{name} {n}: box 26's text {bb:?} outside it");
            }
            let inside = g.region.inflate(-0.5, -0.5);
            for other in groups.iter().filter(|o| o.id != DESIGNATION_BOX && o.id != FRAME) {
                for item in &other.items {
                    let bb = item.bbox();
                    let meets = bb.x0 < inside.x1 && inside.x0 < bb.x1 && bb.y0 < inside.y1 && inside.y0 < bb.y1;
                    assert!(!meets, "{name} {n}: '{}' enters box 26: {bb:?}", other.id);
                }
            }
        }
    }
}

/// The three title blocks of one project letter their sheets' names at one height (the
/// worked example's sheet 1 name, two lines long, was 2.5 mm beside sheets 2 and 3 at 3.5
/// mm) in every language, and the project's title at one height too.
#[test]
fn a_projects_title_blocks_letter_the_sheet_names_alike() {
    for lang in Language::ALL {
        let mut p = fixture("worked-example");
        p.info.language = lang;
        let built = pipeline::build(&p, &[]).unwrap();
        assert_eq!(built.len(), 3);
        let heights = |pick: &dyn Fn(&str) -> bool| -> Vec<Vec<u64>> {
            built
                .iter()
                .map(|b| {
                    let tb = b.output.scene.groups.iter().find(|g| g.id == "title-block").unwrap();
                    let field = frame::name_field_rect();
                    let mut h: Vec<u64> = tb
                        .texts()
                        .filter(|t| inside(field, t.core_box()) && pick(&t.text))
                        .map(|t| (t.h * 1000.0).round() as u64)
                        .collect();
                    h.dedup();
                    h
                })
                .collect()
        };
        let title = p.info.title().to_string();
        let names = heights(&|t| !title.contains(t));
        assert!(names.iter().all(|h| h == &names[0]), "{lang:?}: the name field's other lines at {names:?}");
        let titles = heights(&|t| title.contains(t));
        assert!(titles.iter().all(|h| h == &titles[0] && h.len() == 1), "{lang:?}: the title at {titles:?}");
    }
}
