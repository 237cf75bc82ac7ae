//! Sheet 3 as a user builds it: the worked example's cam (a rocker) and the cam fixtures in
//! every language, a cam-only project, `--sheet 3` without the other sections, the layout
//! the sheet measures itself, finite outputs, Russian words only on a Russian sheet, and the
//! diagrams' numbers against the law computed here.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{check_layout, english_on_russian, fixture_text, root, runs};
use std::f64::consts::PI;
use tmm_sheets::catalogue::{Catalogue, Variant};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline;
use tmm_sheets::project::Project;

/// The cam fixtures, `fixtures/cams/*.yaml`, and the worked example.
fn cam_projects() -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = std::fs::read_dir(root().join("fixtures/cams"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| (p.file_stem().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    out.sort();
    out.insert(0, ("worked-example".into(), pipeline::DEFAULT_PROJECT.to_string()));
    out
}

/// A project file read with the sheets' language set to `lang`.
fn load_in(text: &str, lang: Language) -> Project {
    let mut p = pipeline::load(text).unwrap();
    p.info.language = lang;
    p
}

/// Sheet 3 of a catalogue variant in `lang` (its project file written in that language).
fn catalogue_sheet3(task: &str, variant: u32, lang: Language) -> pipeline::Built {
    let text = common::catalogue_text(task, variant, lang);
    pipeline::build(&pipeline::load_for(&text, &[3]).unwrap(), &[3]).unwrap_or_else(|e| panic!("{e:#}")).remove(0)
}

fn sheet3(p: &Project) -> pipeline::Built {
    pipeline::build(p, &[3]).unwrap_or_else(|e| panic!("{e:#}")).remove(0)
}

#[test]
fn the_layout_of_sheet_3_is_clean_and_finite_in_every_language() {
    for (name, text) in cam_projects() {
        for lang in Language::ALL {
            let p = load_in(&text, lang);
            // The fixtures write their title, institution and assumptions in every language.
            let b = sheet3(&p);
            check_layout(&format!("{name} {lang:?}"), &b.output.scene);
            let l = &b.output.results["layout"];
            let faults = common::layout_faults(l);
            assert!(faults.is_empty(), "{name} {lang:?}: {faults:?}: {}", l["problems"]);
            assert!(!b.svg.contains("NaN") && !b.svg.contains("inf"), "{name} {lang:?}: non-finite number in the SVG");
            let json = serde_json::to_string(&b.output.results).unwrap();
            assert!(!json.contains("null"), "{name} {lang:?}: a non-finite number became null in results.json");
            if lang == Language::Ru {
                for t in runs(&b.output.scene) {
                    assert_eq!(english_on_russian(t), None, "{name}: English on the Russian sheet: {t:?}");
                }
            }
        }
    }
}

#[test]
fn a_cam_only_project_builds_sheet_3_alone() {
    for (name, text) in cam_projects().into_iter().skip(1) {
        let p = pipeline::load(&text).unwrap_or_else(|e| panic!("{name}: {e:#}"));
        assert!(p.lever.is_none() && p.gears.is_none(), "{name}");
        let built = pipeline::build(&p, &[]).unwrap();
        assert_eq!(built.len(), 1, "{name}");
        assert_eq!(built[0].output.number, 3);
        let e = pipeline::build(&p, &[2]).unwrap_err().to_string();
        assert!(e.contains("needs a `gears` section"), "{name}: {e}");
    }
}

/// A mechanism that cannot turn fails sheet 1, and `--sheet 3` still builds.
#[test]
fn sheet_3_computes_nothing_of_the_linkage() {
    let text = fixture_text("worked-example").replacen("lengths: [0.46, 0.39]", "lengths: [0.1, 0.39]", 1);
    let p = pipeline::load(&text).unwrap();
    assert!(pipeline::build(&p, &[1]).is_err());
    assert_eq!(sheet3(&p).output.number, 3);
}

/// The worked example's results: the guide's rocker, its exact minimum radius admissible, the
/// finished profile's pressure angles within 45°, the scales of the course's rule.
#[test]
fn the_worked_example_cam_is_the_guides_rocker_and_its_results_hold() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let r = sheet3(&p).output.results;
    assert_eq!(r["follower"], "rocker");
    let r_min = r["r_min"].as_f64().unwrap();
    // The guide draws 56.22 mm by placing O near the zone's vertex; the exact minimum for the
    // cycloidal law (assumed) is of that size.
    assert!((0.050..0.060).contains(&r_min), "{r_min}");
    for phase in ["rise", "return"] {
        let a = r["max_pressure_angle_deg"][phase].as_f64().unwrap();
        assert!(a <= 45.0 + 1e-6 && a > 44.9, "{phase}: {a}");
    }
    let roller = r["roller_radius"].as_f64().unwrap();
    let rho = r["pitch_min_radius_of_curvature"].as_f64().unwrap();
    assert!(roller < rho && roller <= 0.4 * r_min && roller > 0.2 * r_min, "{roller} {rho} {r_min}");
    // H1 = 1/μ_φ (rad/mm): s and ds/dφ share one scale.
    let s = &r["scales"];
    let h1 = s["h1"].as_f64().unwrap();
    let mu_phi = s["mu_phi_rad"].as_f64().unwrap();
    assert!((h1 * mu_phi - 1.0).abs() < 1e-12 && s["mu_s"] == s["mu_ds"], "{s}");
    let mu_dds = s["mu_dds"].as_f64().unwrap();
    let h2 = s["h2"].as_f64().unwrap();
    assert!((s["mu_ds"].as_f64().unwrap() / (h2 * mu_phi) - mu_dds).abs() < 1e-12);
    // The centre distance and the rocker's start angle are reported.
    assert!(r["centre_distance"].as_f64().unwrap() > 0.105 && r["rocker_start_deg"].as_f64().unwrap() > 0.0);
}

/// The law sampled in results.json is the cycloidal law computed here, and the chord
/// integration's error is of the size the midpoint rule gives for eight divisions.
#[test]
fn the_sampled_law_and_the_integration_error_are_the_cycloidal_laws() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let r = sheet3(&p).output.results;
    let (h, phase) = (25f64.to_radians(), 70f64.to_radians());
    for row in r["law"].as_array().unwrap() {
        let v: Vec<f64> = row.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        let phi = v[0].to_radians();
        if phi > phase {
            continue;
        }
        let x = phi / phase;
        let s = h * (x - (2.0 * PI * x).sin() / (2.0 * PI));
        let ds = h / phase * (1.0 - (2.0 * PI * x).cos());
        assert!((v[1] - s).abs() < 1e-12 && (v[2] - ds).abs() < 1e-12, "φ = {}: {v:?}", v[0]);
    }
    let e = &r["integration_error"];
    assert_eq!(e["divisions"], 8);
    let es = e["s_percent_of_lift"].as_f64().unwrap();
    assert!(es > 0.01 && es < 5.0, "{es}");
}

/// Where the acceleration jumps (the cosine law at the start of its rise), the law's table
/// gives the phase's own value, computed here: h·π²/(2φ_rise²), in mm.
#[test]
fn the_law_table_gives_the_phases_own_acceleration_at_a_jump() {
    let text = std::fs::read_to_string(root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    let p = pipeline::load(&text).unwrap();
    let b = sheet3(&p);
    let t = b.output.tables.iter().find(|t| t.table.id == "law-rise").unwrap();
    let row = t.table.rows.iter().find(|r| r.key == "d2s_dphi2").unwrap();
    let expected = 40.0 * PI * PI / (2.0 * (120f64.to_radians()).powi(2));
    assert!((row.values[0] - expected).abs() < 1e-9, "{} vs {expected}", row.values[0]);
}

/// Where the acceleration jumps inside a phase (the custom-laws fixture's return of two
/// rectangles, at a quarter of it: position 11), the law's table gives both values, before
/// and after, as the diagram draws the jump — and nowhere else. The law's acceleration
/// (3 then −1) normalised by its lift ∫∫a = 0.375, computed here: d²s/dφ² = −h·a/(0.375·φ²)
/// on the return, in mm.
#[test]
fn the_law_table_gives_both_values_where_the_acceleration_jumps_inside_a_phase() {
    let text = std::fs::read_to_string(root().join("fixtures/cams/custom-laws.yaml")).unwrap();
    let b = sheet3(&load_in(&text, Language::Ru));
    let t = b.output.tables.iter().find(|t| t.table.id == "law-return").unwrap();
    let row = t.table.rows.iter().find(|r| r.key == "d2s_dphi2").unwrap();
    let per_rad2 = 30.0 / (0.375 * 80f64.to_radians().powi(2));
    let (before, after) = (-3.0 * per_rad2, 1.0 * per_rad2);
    assert!((row.values[2] - before).abs() < 1e-9, "{} vs {before}", row.values[2]);
    let jumped = row.jump_at(2).expect("a jump at position 11");
    assert!((jumped - after).abs() < 1e-9, "{jumped} vs {after}");
    let jumps: Vec<usize> = (0..row.values.len()).filter(|&c| row.jump_at(c).is_some()).collect();
    assert_eq!(jumps, vec![2], "the acceleration jumps at position 11 only");
    let printed = t.printed_values(row);
    assert_eq!(printed[2], "-123.1→41.0", "{printed:?}");
    let md = tmm_sheets::report::markdown(t, "sheet3");
    assert!(md.contains("| −123,1→41,0 |"), "{md}");
    // The rise's triangle law is continuous: no cell of its table jumps.
    let rise = b.output.tables.iter().find(|t| t.table.id == "law-rise").unwrap();
    assert!(rise.table.rows.iter().all(|r| r.jumps.iter().all(Option::is_none)));
}

/// The diagrams are big enough to measure: the lift at most 100 mm and at least 25 mm (a
/// peaky law, like the fixture's two rectangles, spends height on its acceleration), the
/// acceleration analog 20–75 mm each side of its axis from the law's exact peak (the guide
/// takes a 70 mm amplitude; the worked example's is drawn within 10 % of it), μ_s and
/// μ_ds/dφ round ({1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 7.5}·10ⁿ), μ_d²s/dφ² of two
/// significant digits and H2 derived from them in 14–40 mm (its rays apart); and with one law on both phases the drawn
/// displacement closes at zero (the return's chord error cancels the rise's).
#[test]
fn the_diagrams_are_measurable_and_close_for_one_law() {
    for (name, text) in cam_projects() {
        let p = pipeline::load(&text).unwrap();
        let r = sheet3(&p).output.results;
        let s = &r["scales"];
        let f = |k: &str| s[k].as_f64().unwrap();
        let prog = &p.cam.as_ref().unwrap().design.spec.program;
        let lift_mm = prog.lift / f("mu_s");
        assert!((25.0..=100.0 + 1e-9).contains(&lift_mm), "{name}: the lift is drawn {lift_mm} mm");
        for k in ["mu_s", "mu_ds"] {
            assert!(is_round(f(k), &[1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.5]), "{name}: {k} = {}", f(k));
        }
        let two_digits: Vec<f64> = (10..100).map(|m| f64::from(m) / 10.0).collect();
        assert!(is_round(f("mu_dds"), &two_digits), "{name}: μ_d²s/dφ² = {}", f("mu_dds"));
        let h2 = f("h2");
        assert!((14.0..=40.0).contains(&h2), "{name}: H2 = {h2}");
        assert!((f("mu_ds") / (f("mu_dds") * f("mu_phi_rad")) / h2 - 1.0).abs() < 1e-12, "{name}: H2 = {h2}");
        let amax = (prog.rise_law.peaks().1 * prog.lift / (prog.rise * prog.rise))
            .max(prog.return_law.peaks().1 * prog.lift / (prog.ret * prog.ret));
        let a_mm = amax / f("mu_dds");
        assert!((20.0..=75.0).contains(&a_mm), "{name}: the acceleration analog is {a_mm} mm high");
        if name.contains("worked") {
            assert!((a_mm - 70.0).abs() <= 7.0, "{name}: the guide's amplitude is 70 mm, drawn {a_mm}");
        }
        let closure = r["integration_error"]["closure_s"].as_f64().unwrap();
        if prog.rise_law == prog.return_law {
            assert!(closure.abs() < 1e-9 * prog.lift, "{name}: the drawn s ends at {closure}");
        } else {
            assert!(closure.is_finite() && closure.abs() <= 0.01 * prog.lift, "{name}: closure {closure}");
        }
    }
}

/// A scale whose mantissa (in [1, 10)) is one of `mantissas` to within round-off.
fn is_round(mu: f64, mantissas: &[f64]) -> bool {
    let mantissa = mu / 10f64.powf(mu.log10().floor());
    mantissas.iter().chain(&[10.0]).any(|m| (mantissa / m - 1.0).abs() < 1e-9)
}

/// A cosine rise (120°) and a 3-4-5 polynomial return (90°) of a 40 mm lift, integrated by
/// the course's chords in eight divisions (midpoint rule for ds/dφ, trapezoid for s, the
/// return going on from the rise's drawn end, all computed here), end 1.8 mm below the axis
/// — a negative lift; the sheet integrates each division in more chords until the drawn
/// displacement is within 1 % of the lift everywhere, and every position's ordinate
/// (`sheet3-segments.csv`) is within that of the closed-form laws written here.
#[test]
fn different_laws_are_integrated_in_chords_enough_to_close_within_a_percent() {
    let h = 40.0;
    let (rise, ret) = (120f64.to_radians(), 90f64.to_radians());
    let rise_s = |x: f64| h / 2.0 * (1.0 - (PI * x).cos());
    let rise_dds = |x: f64| h / 2.0 * PI * PI * (PI * x).cos() / (rise * rise);
    let ret_s = |x: f64| h * (1.0 - (10.0 * x.powi(3) - 15.0 * x.powi(4) + 6.0 * x.powi(5)));
    let ret_dds = |x: f64| -h * (60.0 * x - 180.0 * x * x + 120.0 * x.powi(3)) / (ret * ret);
    // The eight-division drawing, by hand.
    let (mut s, mut v) = (0.0, 0.0);
    for (span, dds) in [(rise, &rise_dds as &dyn Fn(f64) -> f64), (ret, &ret_dds)] {
        let d = span / 8.0;
        for k in 0..8 {
            let v1 = v + dds((k as f64 + 0.5) / 8.0) * d;
            s += (v + v1) / 2.0 * d;
            v = v1;
        }
    }
    assert!(s < -0.01 * h, "eight divisions end at {s} mm");
    let text = std::fs::read_to_string(root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    let out = sheet3(&pipeline::load(&text).unwrap()).output;
    let e = &out.results["integration_error"];
    assert!(e["rise"]["chords"].as_u64().unwrap() > 1, "{e}");
    for n in 0..18 {
        let id = format!("diagram.s.y{n}");
        let drawn = out.segments.iter().find(|g| g.id == id).unwrap_or_else(|| panic!("{id}")).value;
        let exact = if n <= 8 { rise_s(n as f64 / 8.0) } else { ret_s((n - 9) as f64 / 8.0) };
        assert!((drawn - exact).abs() <= 0.01 * h, "position {n}: drawn {drawn} mm, the law {exact} mm");
    }
}

/// Catalogue variants whose nomogram left its region: a long r_min over a short lift put
/// the point the zone's name points at (0.4 r_min under O) below the picture, and its leader
/// out of the region or off the page (task 15, variants 10 and 17); a nomogram drawn small
/// in the diagrams' column had a region narrower than its Uzbek title (task 1, variant 2;
/// task 8, variant 26); the offset's dimension, set a paper depth under O, ran below a small
/// picture (task 12, variant 34 with the rise's allowed angle raised to 45°: the smallest
/// cam's centre is off the axis). Each view keeps inside its region.
#[test]
fn the_nomogram_keeps_its_labels_and_title_inside_its_region_on_catalogue_variants() {
    let catalogue = Catalogue::embedded().unwrap();
    let unequal = Some(("pressure_angle_deg: 30\n", "pressure_angle_deg: {rise: 45, return: 30}\n"));
    for (task, variant, lang, edit) in [
        ("15", 10, Language::En, None),
        ("15", 17, Language::Ru, None),
        ("1", 2, Language::Uz, None),
        ("8", 26, Language::Uz, None),
        ("12", 34, Language::En, unequal),
    ] {
        let name = format!("task {task} variant {variant} {lang:?}");
        let Variant::Project { mut text, .. } = catalogue.task(task).unwrap().project(variant, lang, "").unwrap()
        else {
            panic!("{name}: incomplete in the catalogue");
        };
        if let Some((from, to)) = edit {
            assert!(text.contains(from), "{name}: no {from:?} to edit");
            text = text.replacen(from, to, 1);
        }
        let b = sheet3(&pipeline::load(&text).unwrap_or_else(|e| panic!("{name}: {e:#}")));
        let l = &b.output.results["layout"];
        let faults = common::layout_faults(l);
        assert!(faults.is_empty(), "{name}: {faults:?}: {}", l["problems"]);
        check_layout(&name, &b.output.scene);
    }
}

/// Catalogue variants whose working profile's name hung 56–59 mm off in Russian, its
/// leader across the cam or round it, where the middles of the phases it was named at had
/// no near spot: a small cam in a fan of rocker lines (task 4 variant 40), a rocker cam
/// (task 10 variant 11) and a large cam whose near dwell had room inside it a quarter of
/// the way along (task 11 variant 45). Named further along its line, each stands near.
#[test]
fn the_working_profiles_name_stands_near_the_profile_on_catalogue_variants() {
    let catalogue = Catalogue::embedded().unwrap();
    for (task, variant) in [("4", 40), ("10", 11), ("11", 45)] {
        let name = format!("task {task} variant {variant} Ru");
        let Variant::Project { text, .. } = catalogue.task(task).unwrap().project(variant, Language::Ru, "").unwrap()
        else {
            panic!("{name}: incomplete in the catalogue");
        };
        let b = sheet3(&pipeline::load(&text).unwrap_or_else(|e| panic!("{name}: {e:#}")));
        let l = &b.output.results["layout"];
        let faults = common::layout_faults(l);
        assert!(faults.is_empty(), "{name}: {faults:?}: {}", l["problems"]);
        let longest = l["longest_leader_mm"].as_f64().unwrap_or(0.0);
        assert!(longest <= NEAR_LEADER_MM, "{name}: a leader of {longest} mm");
    }
}

/// The longest leader those sheets may hold, mm: the catalogue's limit for sheet 3.
const NEAR_LEADER_MM: f64 = 50.0;

/// Positions the nomogram draws at one point share one label (the rise's end and the
/// return's start at the far dwell, the turn's end and start at B₀), and each allowed angle is
/// written once, at its mark.
#[test]
fn the_nomogram_merges_coincident_positions_and_marks_each_allowed_angle() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet3(&p);
    let g = b.output.scene.groups.iter().find(|g| g.id == "nomogram").expect("a nomogram group");
    let texts: Vec<&str> = g.texts().map(|t| t.text.as_str()).collect();
    for merged in ["8≡9", "0≡17"] {
        assert!(texts.contains(&merged), "no {merged:?} among {texts:?}");
    }
    for lone in ["8", "9", "0", "17"] {
        assert!(!texts.contains(&lone), "{lone:?} is written apart from its twin: {texts:?}");
    }
    assert_eq!(texts.iter().filter(|t| t.starts_with('α')).count(), 2, "{texts:?}");
}

/// The law's and the profiles' tables come one a phase (rise, return), each with its own
/// number in the note (after sheet 1's five and sheet 2's three in the worked example) and
/// its phase in the title, wherever the columns put them.
#[test]
fn each_phase_table_is_titled_with_its_number_and_phase() {
    for (lang, titles) in [
        (
            Language::Ru,
            [
                "Таблица 9 – Закон движения по положениям: подъём",
                "Таблица 10 – Закон движения по положениям: возврат",
                "Таблица 11 – Полярные координаты профилей: подъём",
                "Таблица 12 – Полярные координаты профилей: возврат",
                "Таблица 13 – Результаты",
            ],
        ),
        (
            Language::En,
            [
                "Table 9 – Follower motion by position: rise",
                "Table 10 – Follower motion by position: return",
                "Table 11 – Polar coordinates of the profiles: rise",
                "Table 12 – Polar coordinates of the profiles: return",
                "Table 13 – Results",
            ],
        ),
    ] {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let built = pipeline::build(&p, &[]).unwrap();
        let b = built.iter().find(|b| b.output.number == 3).unwrap();
        // A title wrapped to its table's width is its lines joined by spaces.
        let all = b.output.scene.texts().map(|t| t.text.clone()).collect::<Vec<_>>().join(" ");
        for title in titles {
            assert!(all.contains(title), "{lang:?}: no title {title:?}");
        }
    }
}

/// The allowed angle's marks on the nomogram are arcs of 10 mm whose sweep is the allowed
/// angle of each phase (computed here from the project file's 30° and 45°), and the zone is
/// hatched: a drawn angle of another size, or no hatching, fails.
#[test]
fn the_nomogram_marks_the_allowed_angles_at_their_size_and_hatches_the_zone() {
    use tmm_sheets::drawing::path::Seg;
    use tmm_sheets::drawing::scene::Item;
    let text = std::fs::read_to_string(root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    let p = pipeline::load(&text).unwrap();
    let b = sheet3(&p);
    let g = b.output.scene.groups.iter().find(|g| g.id == "nomogram").unwrap();
    let mut sweeps: Vec<f64> = g
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Path { path, .. } => Some(path.segs.iter()),
            _ => None,
        })
        .flatten()
        .filter_map(|s| match s {
            Seg::Arc(a) if (a.radii.x - 10.0).abs() < 1e-9 => Some(a.sweep_angle.abs().to_degrees()),
            _ => None,
        })
        .collect();
    sweeps.sort_by(f64::total_cmp);
    assert_eq!(sweeps.len(), 2, "{sweeps:?}");
    assert!((sweeps[0] - 30.0).abs() < 1e-9 && (sweeps[1] - 45.0).abs() < 1e-9, "{sweeps:?}");
    // The hatching: many short strokes of 0.9 × 2.5 mm.
    let strokes = g
        .items
        .iter()
        .filter(|i| match i {
            Item::Path { path, .. } => {
                path.segs.len() == 1
                    && matches!(path.segs[0], Seg::Line(q) if ((q - path.start).hypot() - 2.25).abs() < 1e-6)
            }
            _ => false,
        })
        .count();
    assert!(strokes >= 20, "{strokes} hatch strokes");
}

/// The phase angles are dimensioned under the displacement as the course draws them: each
/// value (from the project file: rise 120°, far dwell 30°, return 90°, working angle 240°)
/// written once, between the position numbers that bound its phase (0–8, 8–9, 9–17, 0–17).
#[test]
fn the_phases_are_dimensioned_between_their_positions() {
    let text = std::fs::read_to_string(root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    for lang in Language::ALL {
        let b = sheet3(&load_in(&text, lang));
        let g = b.output.scene.groups.iter().find(|g| g.id == "diagrams").unwrap();
        let texts: Vec<(&str, f64)> = g.texts().map(|t| (t.text.as_str(), t.bbox().center().x)).collect();
        // The position numbers stand under the displacement's axis first (the nomogram
        // has its own group).
        let x_of = |name: &str| texts.iter().find(|t| t.0 == name).unwrap_or_else(|| panic!("no {name:?}")).1;
        for (value, from, to) in [("120°", "0", "8"), ("30°", "8", "9"), ("90°", "9", "17"), ("240°", "0", "17")] {
            let tails: Vec<f64> =
                g.texts().filter(|t| t.tail.trim() == format!("= {value}")).map(|t| t.bbox().center().x).collect();
            assert_eq!(tails.len(), 1, "{lang:?}: {value} written {} times", tails.len());
            let (a, b) = (x_of(from), x_of(to));
            assert!(a < tails[0] && tails[0] < b, "{lang:?}: {value} at {} outside {a}..{b}", tails[0]);
        }
    }
}

/// Every phase value stands on a line — its dimension line, or a leader's shelf where the
/// phase is too short to hold it (the worked example's far dwell of 10°) — and none hangs
/// under one, where it reads as the value of the line above it.
#[test]
fn the_phase_values_stand_on_their_lines_and_hang_under_none() {
    use kurbo::PathEl;
    use tmm_sheets::drawing::scene::Item;
    let text = std::fs::read_to_string(root().join("fixtures/worked-example.yaml")).unwrap();
    for lang in Language::ALL {
        let b = sheet3(&load_in(&text, lang));
        let g = b.output.scene.groups.iter().find(|g| g.id == "diagrams").unwrap();
        // The horizontal straight lines of the diagrams: (y, x from, x to).
        let mut lines = Vec::new();
        for item in &g.items {
            if let Item::Path { path, .. } = item {
                let mut last = None;
                for el in path.to_bez().elements() {
                    match *el {
                        PathEl::MoveTo(p) => last = Some(p),
                        PathEl::LineTo(q) => {
                            if let Some(p) = last.filter(|p: &kurbo::Point| (p.y - q.y).abs() < 1e-9) {
                                lines.push((p.y, p.x.min(q.x), p.x.max(q.x)));
                            }
                            last = Some(q);
                        }
                        _ => last = None,
                    }
                }
            }
        }
        let values: Vec<_> = g.texts().filter(|t| t.text == "φ" && t.tail.trim().ends_with('°')).collect();
        assert_eq!(values.len(), 4, "{lang:?}: rise, far dwell, return and the working angle");
        for t in values {
            let r = t.bbox();
            let spans = |&&(_, x0, x1): &&(f64, f64, f64)| x0 <= r.x0 + 0.5 && x1 >= r.x1 - 0.5;
            let under = lines.iter().filter(spans).filter(|l| l.0 >= r.y1 - 0.5 && l.0 - r.y1 < 1.5).count();
            let over =
                lines.iter().filter(|l| l.1 < r.x1 && l.2 > r.x0).filter(|l| l.0 <= r.y0 && r.y0 - l.0 < 2.0).count();
            assert!(under >= 1, "{lang:?}: {:?}{:?} stands on no line", t.text, t.tail);
            assert_eq!(over, 0, "{lang:?}: {:?}{:?} hangs under a line", t.text, t.tail);
        }
    }
}

/// The worked example's numbers as the student copies them: the positions' angles of the
/// return (80° to 150° in eighths) with the decimals that write each exactly, 106,25 not
/// 106,2, in the drawn table and in the note's Markdown alike; the allowed pressure angle,
/// given as 45°, written so on the nomogram and in the notes, never "45,00°".
#[test]
fn the_positions_angles_and_the_given_angles_are_written_exactly() {
    let text = std::fs::read_to_string(root().join("fixtures/worked-example.yaml")).unwrap();
    for lang in Language::ALL {
        let b = sheet3(&load_in(&text, lang));
        let comma = |s: &str| if lang == Language::En { s.to_string() } else { s.replace('.', ",") };
        let expected: Vec<String> = (0..=8).map(|k| comma(&format!("{:.2}", 80.0 + 8.75 * k as f64))).collect();
        let t = b.output.tables.iter().find(|t| t.table.id == "law-return").unwrap();
        let md = tmm_sheets::report::markdown(t, "sheet3");
        let phi_row = md.lines().find(|l| l.contains("law-return.phi\"")).unwrap();
        assert!(phi_row.ends_with(&format!("| {} |", expected.join(" | "))), "{lang:?}: {phi_row}");
        let texts: Vec<String> = b.output.scene.groups.iter().flat_map(|g| g.texts().map(|t| t.plain())).collect();
        for e in &expected {
            assert!(texts.iter().any(|t| t == e), "{lang:?}: the drawn table has no {e}");
        }
        assert!(texts.iter().any(|t| t.ends_with(" = 45°")), "{lang:?}: no allowed angle written as 45°");
        let padded = comma("45.00°");
        assert!(texts.iter().all(|t| !t.contains(&padded)), "{lang:?}: {padded} written");
    }
}

/// On the profile every position number stands outside every roller (inside another
/// roller's circle it reads as that roller's number), in every cam fixture.
#[test]
fn the_profiles_position_numbers_stand_outside_the_rollers() {
    use tmm_sheets::drawing::scene::Item;
    for (name, text) in cam_projects() {
        let p = pipeline::load(&text).unwrap();
        let b = sheet3(&p);
        let r = &b.output.results;
        let roller_mm = r["roller_radius"].as_f64().unwrap() / r["profile_mu_l"].as_f64().unwrap();
        if roller_mm == 0.0 {
            continue;
        }
        let g = b.output.scene.groups.iter().find(|g| g.id == "profile").unwrap();
        let rollers: Vec<_> = g
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Circle { c, r, .. } if (r - roller_mm).abs() < 1e-9 => Some(*c),
                _ => None,
            })
            .collect();
        assert!(rollers.len() >= 16, "{name}: {} rollers", rollers.len());
        let numbers = g.texts().filter(|t| t.text.chars().all(|c| c.is_ascii_digit() || c == '≡'));
        for t in numbers {
            let b = t.core_box();
            for &c in &rollers {
                let nearest = kurbo::Point::new(c.x.clamp(b.x0, b.x1), c.y.clamp(b.y0, b.y1));
                assert!((nearest - c).hypot() >= roller_mm - 1e-6, "{name}: {:?} inside the roller at {c:?}", t.text);
            }
        }
    }
}

/// The analogs' y axes carry their values, and the values read the graph's own scale: two of
/// them v₁, v₂ stand (v₁ − v₂)/μ apart on paper (μ_ds/dφ, μ_d²s/dφ² from results.json, in
/// mm per mm for a translating follower, whose values are in mm), in
/// every cam fixture and language (the rays from the poles reach the axis, so a value may
/// stand right of it, or be left out, but never on a ray).
#[test]
fn the_analogs_axes_carry_values_at_their_own_scale() {
    use tmm_sheets::drawing::scene::Item;
    for (name, text) in cam_projects() {
        for lang in Language::ALL {
            let p = load_in(&text, lang);
            let b = sheet3(&p);
            let s = &b.output.results["scales"];
            let g = b.output.scene.groups.iter().find(|g| g.id == "diagrams").unwrap();
            // A translating follower's values are in mm, as its tables give them.
            let rocker = matches!(
                p.cam.as_ref().unwrap().design.spec.follower,
                tmm_sheets::cams::follower::Follower::Rocker { .. }
            );
            for (part, mu) in [("diagram.v", "mu_ds"), ("diagram.a", "mu_dds")] {
                let mu = s[mu].as_f64().unwrap() * if rocker { 1.0 } else { 1000.0 };
                let range = g.parts.iter().find(|p| p.id == part).unwrap().items.clone();
                let values: Vec<(f64, f64)> = g.items[range]
                    .iter()
                    .filter_map(|i| match i {
                        Item::Text(t) => {
                            let v = t.text.replace(',', ".").replace('−', "-").parse::<f64>().ok()?;
                            Some((v, t.bbox().center().y))
                        }
                        _ => None,
                    })
                    .collect();
                assert!(values.len() >= 2, "{name} {lang:?} {part}: values {values:?}");
                let (v0, y0) = values[0];
                for &(v, y) in &values[1..] {
                    let expected = (v0 - v) / mu;
                    assert!(((y - y0) - expected).abs() < 0.05, "{name} {lang:?} {part}: {v} at {y}, {v0} at {y0}");
                }
            }
        }
    }
}

/// Of the column's widths and the tables' letterings, the sheet keeps the arrangement that
/// leaves the least of it empty (the pressure angle's diagram in the room the others leave):
/// at most half of the 20 mm cells are empty on the worked example and on task 1 variant 5.
#[test]
fn sheet_3_keeps_the_arrangement_that_leaves_at_most_half_of_it_empty() {
    let catalogue = Catalogue::embedded().unwrap();
    let Variant::Project { text, .. } = catalogue.task("1").unwrap().project(5, Language::Uz, "").unwrap() else {
        panic!("task 1 variant 5: incomplete in the catalogue");
    };
    for (name, text) in [("worked example", pipeline::DEFAULT_PROJECT), ("task 1 variant 5", &text)] {
        let b = sheet3(&pipeline::load(text).unwrap());
        let empty = b.output.results["layout"]["empty_share"].as_f64().unwrap();
        assert!(empty <= 0.5, "{name}: {empty} of sheet 3 is empty");
    }
}

/// Where the law's tables stand under the diagrams, they stand side by side when the column
/// is wide enough for both (stacked they took twice the height), and the diagrams are planned
/// as tall as leaves them that room: no band of empty 20 mm cells between the notes and the
/// tables.
#[test]
fn the_law_tables_stand_side_by_side_close_under_the_diagrams() {
    let mut seen = 0;
    for (name, text) in cam_projects() {
        let b = sheet3(&pipeline::load(&text).unwrap());
        let group = |id: &str| b.output.scene.groups.iter().find(|g| g.id == id);
        let Some(law) = group("law-tables") else { continue };
        seen += 1;
        let boxes: Vec<_> = law
            .parts
            .iter()
            .map(|p| law.items[p.items.clone()].iter().map(|i| i.bbox()).reduce(|a, b| a.union(b)).unwrap())
            .collect();
        assert_eq!(boxes.len(), 2, "{name}: the rise's and the return's tables");
        let (rise, ret) = (boxes[0], boxes[1]);
        if rise.width() + ret.width() + 3.0 <= law.region.width() {
            assert!((rise.y0 - ret.y0).abs() < 0.01 && ret.x0 > rise.x1, "{name}: side by side: {rise:?} {ret:?}");
        }
        let notes_end = group("diagrams").unwrap().region.y1;
        let gap = rise.y0.min(ret.y0) - notes_end;
        assert!((0.0..20.0).contains(&gap), "{name}: {gap} mm between the notes and the law's tables");
    }
    assert!(seen > 0, "no fixture has the law's tables under its diagrams");
}

/// One quantity, one precision across the rise's and the return's twin tables (GOST
/// 2.105): a cam angle of the return written 97,5 under the rise's 11,25, a pitch radius
/// of 101,8 beside a working radius of 86,78 read as different precisions. In every cam
/// fixture and in every language, each row has its twin's decimals, and the profiles'
/// radii and angles share theirs; and in task 13 variant 22, whose rise of 52,5° in eight
/// steps is exact at no few decimals (6,5625°): its angles printed 6,56 over the return's
/// 59,1 (a teacher's mark).
#[test]
fn twin_tables_write_one_quantity_with_one_number_of_decimals() {
    let decimals = |cell: &str| cell.split_once([',', '.']).map_or(0, |(_, d)| d.len());
    let mut projects = cam_projects();
    projects.push(("task 13 variant 22".to_string(), common::catalogue_text("13", 22, Language::Ru)));
    for (name, text) in projects {
        for lang in Language::ALL {
            let b = sheet3(&load_in(&text, lang));
            // Each row's key ("law-rise.phi" → "law.phi") and its cells' decimals.
            let mut rows: Vec<(String, Vec<usize>)> = Vec::new();
            for t in b.output.tables.iter().filter(|t| t.table.id != "results") {
                let md = tmm_sheets::report::markdown(t, "sheet3");
                for line in md.lines().filter(|l| l.starts_with("| <a id=")) {
                    let id = line.split('"').nth(1).unwrap();
                    let key = id.replace("-rise", "").replace("-return", "");
                    let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).skip(2).collect();
                    // A jump's cell holds two values ("−123,1→41,0"), each at the row's decimals.
                    rows.push((key, cells.iter().flat_map(|c| c.split('→')).map(decimals).collect()));
                }
            }
            let class = |key: &str| {
                let field = key.rsplit('.').next().unwrap();
                if key.contains("profile") && field.starts_with("r_") {
                    "radius".to_string()
                } else if key.contains("profile") && field.starts_with("theta_") {
                    "angle".to_string()
                } else {
                    key.to_string()
                }
            };
            let mut seen: Vec<(String, usize, String)> = Vec::new();
            for (key, cells) in &rows {
                for &d in cells {
                    match seen.iter().find(|s| s.0 == class(key)) {
                        Some(s) => assert_eq!(s.1, d, "{name} {lang:?}: {key} has {d} decimals, {} has {}", s.2, s.1),
                        None => seen.push((class(key), d, key.clone())),
                    }
                }
            }
            assert!(rows.iter().filter(|r| r.0 == "sheet3.law.phi").count() == 2, "{name}: {rows:?}");
        }
    }
}

/// The rise's and the return's tables (the law's, the profiles') are drawn one under the
/// other with the same columns: the label column and each value column as wide as in the
/// other table, on every cam fixture (the return's values are wider than the rise's). Only
/// a column holding a jump's two values ("−123,1→41,0", the custom laws') is wider than its
/// twin's: lined up too, it widened both tables so far that the custom laws' profile
/// dropped from 5:2 to 1:1.
#[test]
fn a_phases_table_and_the_next_phases_line_up_column_for_column() {
    for (name, text) in cam_projects() {
        let b = sheet3(&pipeline::load(&text).unwrap());
        let table = |id: &str| -> (Vec<f64>, Vec<f64>) {
            let g = b.output.scene.groups.iter().find(|g| g.part(id).is_some()).unwrap();
            let items = g.part(id).unwrap_or_else(|| panic!("{name}: no {id}"));
            let mut xs: Vec<f64> = items
                .iter()
                .filter_map(common::path_points)
                .flat_map(|(pts, _)| pts.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>())
                .filter(|(a, b)| (a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() > 1.0)
                .map(|(a, _)| a.x)
                .collect();
            xs.sort_by(f64::total_cmp);
            xs.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
            let jumps = items
                .iter()
                .filter_map(|i| match i {
                    tmm_sheets::drawing::scene::Item::Text(t) if t.plain().contains('→') => Some(t.at.x),
                    _ => None,
                })
                .collect();
            (xs, jumps)
        };
        for (one, next) in [("table.law-rise", "table.law-return"), ("table.profile-rise", "table.profile-return")] {
            let ((a, jumps_a), (b, jumps_b)) = (table(one), table(next));
            assert_eq!(a.len(), b.len(), "{name}: {one} {a:?}, {next} {b:?}");
            for k in 1..a.len() {
                let (wa, wb) = (a[k] - a[k - 1], b[k] - b[k - 1]);
                let (wider, jumps) = if wa > wb { (&a, &jumps_a) } else { (&b, &jumps_b) };
                let jump_here = jumps.iter().any(|&x| x > wider[k - 1] && x < wider[k]);
                assert!((wa - wb).abs() < 1e-6 || jump_here, "{name}: column {k}: {wa} mm in {one}, {wb} mm in {next}");
            }
        }
    }
}

/// The profiles' polar angles θ are counted on from φ, the turn each is nearest: task 11
/// variant 30's working profile starts a hair behind the rise's radius, and its table read
/// θ_р = 360,00 at position 0 beside 16,04 at position 1. Every θ of every catalogue task
/// with a cam, in both tables, is within a half turn of its φ (the two differ by the
/// follower's offset and the roller's normal, never by a whole turn).
#[test]
fn the_profiles_polar_angles_follow_the_cam_angle_without_a_turns_jump() {
    for (task, variant) in [("11", 30), ("2", 35), ("4", 40), ("15", 6)] {
        let built = catalogue_sheet3(task, variant, Language::Ru);
        let answers: Vec<_> = built.output.tables.iter().flat_map(|t| t.answers("sheet3")).collect();
        let value = |id: &str| answers.iter().find(|a| a.id == id).map(|a| a.value);
        let mut checked = 0;
        for phase in ["profile-rise", "profile-return"] {
            for a in answers.iter().filter(|a| a.id.starts_with(&format!("sheet3.{phase}.theta_"))) {
                let column = a.id.rsplit('.').next().unwrap();
                let phi = value(&format!("sheet3.{phase}.phi.{column}")).unwrap();
                // Degrees, as the tables write them.
                assert!(
                    (a.value - phi).abs() < 180.0,
                    "task {task} variant {variant}: {} = {}° at φ = {phi}°",
                    a.id,
                    a.value
                );
                checked += 1;
            }
        }
        assert!(checked >= 18, "task {task} variant {variant}: {checked} angles");
    }
}

/// Sheet 3 keeps a smaller profile only where its sheet is emptier by the margin a halving
/// must earn against the largest profile of the variants tried, not against the best so far:
/// task 4 variant 40 in Russian drew its cam at 1:10, about 35 mm across with rollers over
/// their numbers (0.429 empty), beside a variant drawing it at 1:5 for 0.431, because that
/// one was compared with the 1:10 sheet after the 1:10 sheet had beaten the usual one. In
/// English and Uzbek it was already at 1:5.
#[test]
fn a_smaller_cam_profile_must_earn_its_margin_against_the_largest_one_tried() {
    for lang in [Language::Ru, Language::En, Language::Uz] {
        let built = catalogue_sheet3("4", 40, lang);
        let results = &built.output.results;
        let mu = results["profile_mu_l"].as_f64().unwrap();
        assert!(mu <= 0.005 + 1e-12, "{lang:?}: the profile at μ_l = {mu} m/mm");
        let faults = common::layout_faults(&results["layout"]);
        assert!(faults.is_empty(), "{lang:?}: {faults:?}");
    }
}

/// The pressure angle's diagram numbers every position under its own tick: where two
/// neighbours' numbers do not fit side by side, the odd ones stand a row lower. Task 2
/// variant 35's positions are 4.4 mm apart: in one row the numbers from 11 on slid right,
/// "15" under position 16's tick and "16" past the axis' end.
#[test]
fn the_pressure_diagrams_position_numbers_stand_under_their_own_ticks() {
    let built = catalogue_sheet3("2", 35, Language::Ru);
    let out = &built.output;
    let mu_phi = out.results["pressure_diagram"]["mu_phi_deg"].as_f64().unwrap();
    // Eight divisions of the rise and of the return, the far dwell between (this cam's).
    let phase = |k: &str| out.results["phases_deg"][k].as_f64().unwrap();
    let (rise, dwell, ret) = (phase("rise"), phase("far_dwell"), phase("return"));
    let phis: Vec<f64> = (0..=8)
        .map(|k| rise * f64::from(k) / 8.0)
        .chain((0..=8).map(|k| rise + dwell + ret * f64::from(k) / 8.0))
        .collect();
    let g = out.scene.groups.iter().find(|g| g.id.ends_with("pressure")).expect("the pressure diagram");
    // The plot's origin is 12 mm inside the region (pressure_view::LEFT).
    let x0 = g.region.x0 + 12.0;
    let mut seen = 0;
    for item in &g.items {
        let tmm_sheets::drawing::scene::Item::Text(t) = item else { continue };
        let Ok(k) = t.text.parse::<usize>() else { continue };
        let b = item.bbox();
        // The α axis' values stand left of the plot.
        if k >= phis.len() || b.center().x < x0 - 0.5 || !t.sub.is_empty() {
            continue;
        }
        let tick = x0 + phis[k] / mu_phi;
        assert!(
            (b.center().x - tick).abs() < 1.0,
            "position {k}'s number at x = {:.1} mm, its tick at {tick:.1}",
            b.center().x
        );
        seen += 1;
    }
    assert!(seen >= 17, "{seen} position numbers");
}

/// The law's tables stand under the diagrams where a column nearly as tall as the tallest
/// leaves them room: task 15 v11's tallest column (432 mm, the two-digit μ_d²s/dφ² let s be
/// drawn larger) left them none, and they took the right side's middle with the other
/// tables, the pressure angle's diagram pushed into a corner (0.537 of the sheet empty); a
/// column of 390 mm leaves them room under it (0.492 empty in Russian).
#[test]
fn the_law_tables_keep_their_place_under_a_column_nearly_as_tall() {
    for lang in [Language::Ru, Language::Uz, Language::En] {
        let b = catalogue_sheet3("15", 11, lang);
        let under = b.output.scene.groups.iter().any(|g| g.id == "law-tables");
        assert!(under, "{lang:?}: the law's tables are not under the diagrams");
        let empty = b.output.results["layout"]["empty_share"].as_f64().unwrap();
        assert!(lang != Language::Ru || empty <= 0.5, "{lang:?}: {empty} of sheet 3 is empty");
    }
}

/// A diagram's scale («μ_β = 0,0075 рад/мм») and an axis value in its row read as one
/// phrase when they stand a word's space apart: «μ_β = 0,0075 рад/мм 20» at 4 mm (a
/// teacher's review). On every cam project in every language, a value to the right of a
/// scale text whose row it shares stands at least 6 mm from it.
#[test]
fn a_diagrams_scale_stands_apart_from_the_values_in_its_row() {
    for (name, text) in cam_projects() {
        for lang in Language::ALL {
            let b = sheet3(&load_in(&text, lang));
            let g = b.output.scene.groups.iter().find(|g| g.id == "diagrams").unwrap();
            let is_value = |s: &str| s.replace(',', ".").replace('−', "-").trim().parse::<f64>().is_ok();
            let scales: Vec<kurbo::Rect> = g.texts().filter(|t| t.text.starts_with('μ')).map(|t| t.bbox()).collect();
            assert!(!scales.is_empty(), "{name} {lang:?}: no scale text");
            for v in g.texts().filter(|t| is_value(&t.text)) {
                let r = v.bbox();
                for s in &scales {
                    let same_row = r.y0 < s.y1 && s.y0 < r.y1;
                    let gap = r.x0 - s.x1;
                    assert!(
                        !same_row || !(0.0..6.0).contains(&gap),
                        "{name} {lang:?}: «{}» {gap:.1} mm after a scale text",
                        v.text
                    );
                }
            }
        }
    }
}

/// A given roller outside the course's 0.25–0.4·r_min is said on the sheet, as the build
/// warns of it: translating-offset-auto's 8 mm roller is 0.2428·r_min (r_min = 32.95 mm),
/// and a sheet handed in showed it as the course's. The worked example's roller is the
/// course's: no such note.
#[test]
fn a_roller_outside_the_courses_share_is_noted_on_the_sheet() {
    let text = std::fs::read_to_string(root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    for lang in Language::ALL {
        let share = match lang {
            Language::Uz => "8,000 mm = 0,2428·rₘᵢₙ",
            Language::Ru => "8,000 мм = 0,2428·rₘᵢₙ",
            Language::En => "8.000 mm = 0.2428·rₘᵢₙ",
        };
        let b = sheet3(&load_in(&text, lang));
        let noted = b.output.scene.texts().any(|t| t.text.contains(share));
        assert!(noted, "{lang:?}: no note of the roller's share «{share}»");
        let worked = sheet3(&load_in(pipeline::DEFAULT_PROJECT, lang));
        assert!(!worked.output.scene.texts().any(|t| t.text.contains("·rₘᵢₙ = ")), "{lang:?}: the worked example");
    }
}
