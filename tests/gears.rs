//! Sheet 2 as a user builds it: the worked example's pair and stage against numbers computed
//! here, a gears-only project, `--sheet 2` without the linkage, the sheet's own layout in
//! every language, and every kind of bad gear input refused at its line.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{english_on_russian, fixture_text, root, runs};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline;
use tmm_sheets::project::Project;

/// The gears-only fixtures, `fixtures/gears/*.yaml`.
fn gear_fixtures() -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = std::fs::read_dir(root().join("fixtures/gears"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| (p.file_stem().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    out.sort();
    out
}

fn sheet2(p: &Project) -> pipeline::Built {
    pipeline::build(p, &[2]).unwrap_or_else(|e| panic!("{e:#}")).remove(0)
}

#[test]
fn the_worked_example_pair_and_stage_are_exact_and_valid() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet2(&p);
    let r = &b.output.results;
    // The guide's pair by hand: m = 5 mm, z = 17/19, α = 20°, no shift.
    let (m, a) = (0.005f64, 20f64.to_radians());
    let (r1, r2) = (m * 17.0 / 2.0, m * 19.0 / 2.0);
    let (rb1, rb2) = (r1 * a.cos(), r2 * a.cos());
    let (ra1, ra2) = (r1 + m, r2 + m);
    let aw = r1 + r2;
    let eps = ((ra1 * ra1 - rb1 * rb1).sqrt() + (ra2 * ra2 - rb2 * rb2).sqrt() - aw * a.sin())
        / (std::f64::consts::PI * m * a.cos());
    let got = r["pair"]["contact_ratio"].as_f64().unwrap();
    assert!((got - eps).abs() < 1e-12, "{got} vs {eps}");
    assert_eq!(format!("{eps:.3}"), "1.529", "the guide's 1.53 is this rounded");
    let drawn = r["pair"]["contact_ratio_drawing"].as_f64().unwrap();
    assert!((drawn - eps).abs() / eps < 1e-5, "measured on the drawing: {drawn}");
    assert!((r["pair"]["centre_distance"].as_f64().unwrap() - 0.09).abs() < 1e-15);
    assert!(r["drawing"]["tooth_height_mm"].as_f64().unwrap() > 50.0);
    assert!(r["drawing"]["involute_deviation"].as_f64().unwrap() < 1e-6);

    // The stage: u_pl = (750/70)/(19/17); every condition re-verified here.
    let pl = &r["planetary"];
    let z: Vec<u64> = pl["z"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap()).collect();
    let k = pl["planets"].as_u64().unwrap();
    let required = 750.0 / 70.0 / (19.0 / 17.0);
    assert!((pl["ratio_required"].as_f64().unwrap() - required).abs() < 1e-12);
    let (z1, z2, z3) = (z[0], z[1], z[2]);
    let u = 1.0 + z3 as f64 / z1 as f64;
    assert!((u - required).abs() / required <= 0.03, "u = {u}");
    assert_eq!(z1 + 2 * z2, z3, "coaxial");
    assert!((std::f64::consts::PI / k as f64).sin() > (z2 as f64 + 2.0) / (z1 + z2) as f64, "neighbours");
    assert_eq!((z1 + z3) % k, 0, "assembly");
    assert!(z1 >= 17 && z2 >= 17 && z3 >= 85 && z3 - z2 > 8);
    assert_ne!((z1, z2, z3, k), (17, 68, 153, 5), "the guide's set fails the neighbour condition");
    assert!(pl["conditions"].as_array().unwrap().iter().all(|c| c["ok"] == true));
}

#[test]
fn a_project_with_only_gears_builds_sheet_2_alone() {
    for (name, text) in gear_fixtures() {
        let p = pipeline::load(&text).unwrap_or_else(|e| panic!("{name}: {e:#}"));
        assert!(p.lever.is_none());
        let built = pipeline::build(&p, &[]).unwrap();
        assert_eq!(built.len(), 1, "{name}");
        assert_eq!(built[0].output.number, 2);
        // Its tables are the note's first: numbered from 1, not after a sheet 1 it lacks.
        let first = &built[0].output.tables[0].title;
        assert!(
            first.starts_with("1-jadval – ") || first.starts_with("Таблица 1 – ") || first.starts_with("Table 1 – "),
            "{name}: {first}"
        );
        let e = pipeline::build(&p, &[1]).unwrap_err().to_string();
        assert!(e.contains("needs a `mechanism` section"), "{name}: {e}");
    }
}

/// A mechanism that cannot turn fails sheet 1, and `--sheet 2` still builds: sheet 2 does not
/// analyse the linkage.
#[test]
fn sheet_2_computes_nothing_of_the_linkage() {
    let text = fixture_text("worked-example").replacen("lengths: [0.46, 0.39]", "lengths: [0.1, 0.39]", 1);
    let p = pipeline::load(&text).unwrap();
    match pipeline::build(&p, &[1]).unwrap_err() {
        pipeline::Error::Refused(r) => {
            assert_eq!(r.blocks, [1], "{}", r.refusal);
            assert_eq!(r.refusal.path, "mechanism.groups[0]", "{}", r.refusal);
        }
        other => panic!("{other}"),
    }
    let b = sheet2(&p);
    assert_eq!(b.output.number, 2);
    // n1 still comes from the crank's rpm, a number in the file, not from an analysis.
    assert!(b.output.results["planetary"]["ratio_required"].as_f64().unwrap() > 9.0);
}

#[test]
fn the_layout_of_sheet_2_is_clean_in_every_language() {
    let mut projects = vec![("worked-example".to_string(), pipeline::DEFAULT_PROJECT.to_string())];
    projects.extend(gear_fixtures());
    for (name, text) in projects {
        for lang in Language::ALL {
            let mut p = pipeline::load(&text).unwrap();
            p.info.language = lang;
            if lang == Language::Ru {
                p.info.title = "Редуктор".into();
                p.info.institution = "ТГТУ".into();
                p.info.designation = "ТММ 02.00.00".into();
                p.gears.as_mut().unwrap().assumptions.clear();
            }
            let b = sheet2(&p);
            let l = &b.output.results["layout"];
            let faults = common::layout_faults(l);
            assert!(faults.is_empty(), "{name} {lang:?}: {faults:?}: {}", l["problems"]);
            if lang == Language::Ru {
                for t in runs(&b.output.scene) {
                    assert_eq!(english_on_russian(t), None, "{name}: English on the Russian sheet: {t:?}");
                }
            }
        }
    }
}

fn refusal(text: &str) -> String {
    match pipeline::load(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => format!("{:#}", anyhow::Error::from(e)),
    }
}

/// Bad gear input is refused with the field, the line and the reason, never a panic.
#[test]
fn bad_gear_input_is_refused_at_its_line() {
    let base = |gears: &str| format!("project: {{title: t}}\ngears:\n{gears}\n");
    let cases = [
        ("  pair: {module: 5, z: [4, 19]}", "gears.pair.z[0]", "at least 5"),
        ("  pair: {module: 0, z: [17, 19]}", "line 3", "positive"),
        ("  pair: {module: 5, z: [17, 19], shift: [1.9, 0]}", "gears.pair.shift", "pointed"),
        ("  pair: {module: 5, z: [12, 12], shift: [-1.4, -1.4]}", "gears.pair.shift", "α_w"),
        ("  pair: {module: 5, z: [17, 19], shift: fast}", "gears.pair.shift", "auto"),
        (
            "  pair: {module: 5, z: [17, 19]}\n  planetary: {scheme: wolfrom, module: 5, ratio: 9}",
            "unknown scheme 'wolfrom'",
            "sun-planet-ring",
        ),
        (
            "  pair: {module: 5, z: [17, 19]}\n  planetary: {scheme: sun-planet-ring, module: 5}",
            "gears.motor_rpm",
            "ratio",
        ),
        (
            "  pair: {module: 5, z: [17, 19]}\n  motor_rpm: 1000\n  planetary: {scheme: sun-planet-ring, module: 5}",
            "gears.output_rpm",
            "n1",
        ),
        (
            "  pair: {module: 5, z: [17, 19]}\n  planetary: {scheme: sun-planet-ring, module: 5, ratio: 2.0}",
            "gears.planetary",
            "reaches only",
        ),
        (
            "  pair: {module: 5, z: [17, 19]}\n  planetary: {scheme: sun-planet-ring, module: 5, ratio: 9, planets: 1}",
            "planets",
            "1",
        ),
        ("  pair: {module: 5, z: [17, 19], teeth: 3}", "gears.pair.teeth", "unknown key `teeth`"),
        ("  pair: {module: .nan, z: [17, 19]}", "line 3, column 18: gears.pair.module", "not a finite number"),
    ];
    for (gears, field, reason) in cases {
        let e = refusal(&base(gears));
        assert!(e.contains(field) && e.contains(reason), "{gears}\n→ {e}");
        assert!(e.contains("line"), "{gears}\n→ {e}");
    }
}

#[test]
fn an_undercut_pinion_builds_with_a_warning_and_a_note_on_the_sheet() {
    let (_, text) = gear_fixtures().into_iter().find(|(n, _)| n == "undercut").unwrap();
    let p = pipeline::load(&text).unwrap();
    assert!(
        p.warnings.iter().any(|w| w.field == "gears.pair.shift" && w.message.contains("undercut")),
        "{:?}",
        p.warnings
    );
    let b = sheet2(&p);
    assert_eq!(b.output.results["pair"]["undercut"][0], true);
    assert_eq!(b.output.results["pair"]["undercut_course"][0], true, "z = 10 at x = 0: below (17 − 10)/17");
    assert!(b.output.scene.texts().any(|t| t.text.contains("xₘᵢₙ")), "the sheet says so");
}

/// The wheels' table flows over two drawn tables (the wheels', the pair's): the second is
/// headed as GOST 2.105 heads a table's continued part — "Продолжение таблицы N" with the
/// wheels' table's number N, its title not repeated — in every language.
#[test]
fn the_pair_table_is_headed_as_the_wheels_tables_continuation() {
    for lang in [Language::Uz, Language::Ru, Language::En] {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let b = sheet2(&p);
        let wheels = b.output.tables.iter().find(|t| t.table.id == "wheels").expect("the wheels' table");
        let n: String =
            wheels.title.chars().skip_while(|c| !c.is_ascii_digit()).take_while(char::is_ascii_digit).collect();
        let expected = match lang {
            Language::Uz => format!("{n}-jadvalning davomi"),
            Language::Ru => format!("Продолжение таблицы {n}"),
            Language::En => format!("Table {n} (continued)"),
        };
        let g = b.output.scene.groups.iter().find(|g| g.id == "tables").expect("a tables group");
        assert!(g.texts().any(|t| t.text == expected), "{lang:?}: no heading {expected:?}");
        let old_style = [", davomi)", ", продолжение)", ", continued)"];
        assert!(!g.texts().any(|t| old_style.iter().any(|o| t.text.ends_with(o))), "{lang:?}: the title repeated");
        // The note's Markdown heads the two parts as the sheet does, the title once.
        let files = pipeline::sheet_files(&b, &[]).unwrap();
        let md = files.iter().find(|(name, _)| name == "sheet2-tables.md").expect("the tables' Markdown");
        let md = String::from_utf8(md.1.clone()).unwrap();
        let headings: Vec<&str> = md.lines().filter_map(|l| l.strip_prefix("### ")).collect();
        assert_eq!(headings.iter().filter(|h| **h == wheels.title).count(), 1, "{lang:?}: {headings:?}");
        assert!(headings.contains(&expected.as_str()), "{lang:?}: {headings:?}");
    }
}

/// `shift: auto` picks the course's least shift, (17 − z)/17 rounded up to 0.001: at z = 12
/// 5/17 = 0.2941 → 0.295, below the exact limit 1 − 12·sin²20°/2 = 0.29813. The sheet's
/// note states the course's rule (not "without undercut"), and `results.json` names both
/// verdicts, so the note and the file agree.
#[test]
fn an_automatic_shift_is_noted_by_the_course_rule_and_the_results_name_both_rules() {
    let (_, text) = gear_fixtures().into_iter().find(|(n, _)| n == "shifted-double-planet").unwrap();
    let mut p = pipeline::load(&text).unwrap();
    p.info.language = Language::En;
    let b = sheet2(&p);
    let pair = &b.output.results["pair"];
    assert_eq!(pair["z"][0], 12, "the fixture's pinion");
    assert_eq!(pair["shift"][0], 0.295);
    let course = 5.0 / 17.0;
    let exact = 1.0 - 12.0 * 20f64.to_radians().sin().powi(2) / 2.0;
    assert!((pair["x_min_course"][0].as_f64().unwrap() - course).abs() < 1e-15);
    assert!((pair["x_min"][0].as_f64().unwrap() - exact).abs() < 1e-15);
    assert_eq!(pair["undercut_course"][0], false, "0.295 ≥ 5/17");
    assert_eq!(pair["undercut"][0], true, "0.295 < 0.29813: a hair, drawn, unnoted");
    let note = "Wheel 1 shifted by x = 0.295 ≥ xₘᵢₙ = 0.2941 (the course's least shift)";
    assert!(b.output.scene.texts().any(|t| t.text == note), "no note {note:?}");
    assert!(!b.output.scene.texts().any(|t| t.text.contains("without undercut")));
}

/// The addendum coefficient is printed h, subscript a, then its star at full size (hₐ*,
/// like c*): a star set inside the subscript reads as part of the index.
#[test]
fn the_addendum_coefficients_star_follows_its_subscript() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet2(&p);
    let pair = b.output.tables.iter().find(|t| t.table.id == "pair").expect("the pair's table");
    let rows = tmm_sheets::sheets::scaffold::drawn_rows(pair, p.info.language, true);
    let h = rows.iter().find(|(l, _)| l.main == "h" && l.sub == "a").map(|(l, _)| l);
    assert_eq!(h.map(|l| l.tail.as_str()), Some("*"), "{:?}", rows.iter().map(|r| &r.0).collect::<Vec<_>>());
    assert!(!rows.iter().any(|(l, _)| l.sub.contains('*')), "a star in a subscript");
}

/// Where the right half has the room, sheet 2's tables are lettered 3.5 or 5 mm (titles
/// 5 mm), not the 2.5 mm of a crowded sheet, and every table stays inside its region; the
/// worked example's, under the planetary views, in 5 mm in every language (in Russian, whose
/// conditions' table is the widest, in rows: that table under the others).
#[test]
fn sheet_2_letters_its_tables_in_3_5_mm_or_more_where_they_fit() {
    for (name, text) in
        std::iter::once(("worked-example".to_string(), pipeline::DEFAULT_PROJECT.to_string())).chain(gear_fixtures())
    {
        let b = sheet2(&pipeline::load(&text).unwrap());
        let tables = b.output.scene.groups.iter().find(|g| g.id == "tables").expect("a tables group");
        let sizes: Vec<f64> = tables.texts().map(|t| t.h).collect();
        assert!(!sizes.is_empty() && sizes.iter().all(|&h| h == 3.5 || h == 5.0), "{name}: {sizes:?}");
        assert!(sizes.contains(&5.0), "{name}: the titles at 5 mm");
        assert_eq!(b.output.results["layout"]["outside_region"], 0, "{name}");
    }
    for lang in Language::ALL {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let b = sheet2(&p);
        let tables = b.output.scene.groups.iter().find(|g| g.id == "tables").unwrap();
        assert!(tables.texts().all(|t| t.h == 5.0), "{lang:?}: the tables not all in 5 mm");
    }
}

/// The course's "done when": at most half of the worked example's sheet 2 (20 mm cells
/// inside the frame, the title block's excluded) holds no ink, in every language.
#[test]
fn the_worked_examples_sheet_2_is_at_most_half_empty() {
    for lang in Language::ALL {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let layout = &sheet2(&p).output.results["layout"];
        let empty = layout["empty_share"].as_f64().unwrap();
        assert!(empty <= 0.5, "{lang:?}: {empty} of sheet 2 is empty");
        assert_eq!(layout["texts_crossed"], 0, "{lang:?}");
        assert_eq!(layout["text_overlaps"], 0, "{lang:?}");
    }
}

/// The centre distance is dimensioned from O1 to O2 right of the teeth: a vertical dimension
/// line as long as a_w at the drawing's scale, the guide's pair by hand (a_w = m(z1 + z2)/2 =
/// 5·36/2 = 90 mm at 5:1: 450 mm), its value "a_w = 90,00" beside it, in every language.
#[test]
fn the_centre_distance_is_dimensioned_between_the_wheels_centres() {
    use tmm_sheets::drawing::obstacles::segments;
    for lang in Language::ALL {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let b = sheet2(&p);
        let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
        let value = mesh.texts().find(|t| t.text == "a" && t.sub == "w").expect("a_w's value");
        let expected = " = 90";
        assert_eq!(value.tail, expected, "{lang:?}");
        let vertical: Vec<(kurbo::Point, kurbo::Point)> = mesh
            .items
            .iter()
            .flat_map(segments)
            .filter(|(a, b)| (a.x - b.x).abs() < 1e-9 && ((a.y - b.y).abs() - 450.0).abs() < 1e-6)
            .collect();
        assert_eq!(vertical.len(), 1, "{lang:?}: one 450 mm vertical line (the line of centres is longer)");
        let x = vertical[0].0.x;
        assert!((value.bbox().x1 - x).abs() < 25.0, "{lang:?}: the value far from its line");
    }
}

/// Where wheel 2's centre is off the drawing (KHK's pair at 10:1: a_w = 56.50 mm is 565 mm
/// on paper), a_w is still dimensioned: an extension line from O1 to the right, the dimension
/// line from it up to the drawing's edge with one arrow, its value the whole a_w (KHK's
/// reference gives 56.4999 mm).
#[test]
fn the_centre_distance_is_dimensioned_broken_off_where_o2_is_off_the_drawing() {
    use tmm_sheets::drawing::obstacles::segments;
    let b = sheet2(&pipeline::load(&fixture_text("gears/handbook-khk")).unwrap());
    let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
    assert!(!mesh.texts().any(|t| t.text == "O" && t.sub == "2"), "O2 is off the drawing");
    let value = mesh.texts().find(|t| t.text == "a" && t.sub == "w").expect("a_w's value");
    assert!([" = 56,50", " = 56.50"].contains(&value.tail.as_str()), "{}", value.tail);
    let o1 = mesh.texts().find(|t| t.text == "O" && t.sub == "1").expect("O1's name").bbox();
    let lines: Vec<_> = mesh.items.iter().flat_map(segments).collect();
    let vertical = lines
        .iter()
        .find(|(a, b)| {
            (a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() > 300.0 && (a.x - value.bbox().center().x).abs() < 25.0
        })
        .unwrap_or_else(|| {
            panic!(
                "a long vertical dimension line beside the value {:?}: {:?}",
                value.bbox(),
                lines.iter().filter(|(a, b)| (a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() > 100.0).collect::<Vec<_>>()
            )
        });
    let bottom = vertical.0.y.max(vertical.1.y);
    assert!((bottom - o1.center().y).abs() < 8.0, "the line ends at O1's level: {bottom} vs {:?}", o1);
    let extension = lines.iter().find(|(a, b)| {
        (a.y - bottom).abs() < 1e-9
            && (b.y - bottom).abs() < 1e-9
            && a.x.max(b.x) > vertical.0.x
            && a.x.min(b.x) < o1.x1
    });
    assert!(extension.is_some(), "an extension line from O1 to the dimension line");
}

/// Wheel 1's addendum and dedendum are dimensioned along one of its radii, the guide's pair
/// by hand: h_a = h_a*·m = 5 mm and h_f = (h_a* + c*)·m = 6.25 mm, at 5:1 lines 25 and 31.25 mm
/// long pointing at O1, their values "h_a1 = 5" and "h_f1 = 6,25" (exact, as a hand writes them;
/// wheel 1's, as a shifted pair's wheel 2 has others).
#[test]
fn the_addendum_and_dedendum_are_dimensioned_on_a_radius_of_wheel_1() {
    use tmm_sheets::drawing::obstacles::segments;
    use tmm_sheets::num::math::Norm;
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet2(&p);
    let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
    let o1 = mesh.texts().find(|t| t.text == "O" && t.sub == "1").expect("O1's name").bbox();
    for (sub, tail, length) in [("a1", " = 5", 25.0), ("f1", " = 6,25", 31.25)] {
        assert!(mesh.texts().any(|t| t.text == "h" && t.sub == sub && t.tail == tail), "h_{sub}{tail}");
        let radial = mesh.items.iter().flat_map(segments).find(|(a, b)| {
            let d = *b - *a;
            // Along a line through O1 (its name is a few mm off it): the cross product small.
            let to_o1 = o1.center() - *a;
            (d.norm() - length).abs() < 1e-6 && (d.cross(to_o1) / d.norm()).abs() < 8.0
        });
        assert!(radial.is_some(), "no {length} mm line along a radius for h_{sub}");
    }
}

/// Without a planetary stage the mesh takes the sheet's width up to the tables (the right
/// half held the tables alone, three quarters of it empty), in every language the same
/// region (what is measured on the drawing must not depend on the language).
#[test]
fn a_pair_alone_takes_the_width_the_tables_leave() {
    let text = fixture_text("gears/handbook-khk");
    let regions: Vec<(f64, f64)> = Language::ALL
        .into_iter()
        .map(|lang| {
            let mut p = pipeline::load(&text).unwrap();
            p.info.language = lang;
            let b = sheet2(&p);
            let g = |id: &str| b.output.scene.groups.iter().find(|g| g.id == id).unwrap().region;
            let (mesh, tables) = (g("mesh"), g("tables"));
            assert!(mesh.x1 < tables.x0, "{lang:?}: the mesh {mesh:?} reaches the tables {tables:?}");
            assert!(mesh.width() > 600.0, "{lang:?}: the mesh is {} mm wide", mesh.width());
            let empty = b.output.results["layout"]["empty_share"].as_f64().unwrap();
            assert!(empty < 0.65, "{lang:?}: {empty} of the sheet is empty");
            (mesh.x0, mesh.x1)
        })
        .collect();
    assert!(regions.windows(2).all(|w| w[0] == w[1]), "{regions:?}");
}

/// The stage's ratio from its tooth numbers, written here: 1 + z3/z1 for a single row,
/// 1 + z2·z3/(z1·z2′) for a double planet.
fn stage_ratio(z: &[f64]) -> f64 {
    match z {
        [z1, _, z3] => 1.0 + z3 / z1,
        [z1, z2, z2b, z3] => 1.0 + z2 * z3 / (z1 * z2b),
        _ => panic!("a stage has 3 or 4 wheels: {z:?}"),
    }
}

#[test]
fn the_stage_ratio_is_read_off_the_plan_of_angular_velocities() {
    let double = fixture_text("gears/shifted-double-planet");
    for (name, text) in [("worked example", pipeline::DEFAULT_PROJECT), ("double planet", double.as_str())] {
        let p = pipeline::load(text).unwrap();
        let b = sheet2(&p);
        let pl = &b.output.results["planetary"];
        let z: Vec<f64> = pl["z"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        let u = stage_ratio(&z);
        let g = &pl["graphic"];
        let (s1, sh) = (g["segment_01_mm"].as_f64().unwrap(), g["segment_0h_mm"].as_f64().unwrap());
        // Exact as drawn: the segments are ω1 and ω_H at one scale.
        assert!((s1 / sh - u).abs() / u < 1e-9, "{name}: 0–1 / 0–H = {s1} / {sh}, u = {u}");
        assert!(sh >= 15.0, "{name}: the plan measurable: {s1}, {sh}");
        assert_eq!(b.output.results["layout"]["outside_region"], 0, "{name}: the plan on its region");
        // Read as a student reads it: each segment to 0.1 mm, the error within that reading.
        let read = |x: f64| (x * 10.0).round() / 10.0;
        let got = g["ratio"].as_f64().unwrap();
        assert!((got - read(s1) / read(sh)).abs() < 1e-12, "{name}: {got}");
        let bound = u * (0.05 / read(sh) + 0.05 / read(s1)) * 1.001;
        assert!((got - u).abs() <= bound, "{name}: read {got}, exact {u}, bound {bound}");
        // The sheet prints the reading with its segments.
        let printed = format!("{:.1} / {:.1}", read(s1), read(sh));
        let comma = printed.replace('.', ",");
        assert!(b.svg.contains(&printed) || b.svg.contains(&comma), "{name}: {printed} on the sheet");
    }
}

/// The worked example's plan of angular velocities is large enough to read u_1H off it with
/// a ruler: beside the kinematic scheme its 0–H was 7.3 mm (read to 0.1 mm, ±0.7 % on the
/// ratio); in the strip under the views it is at least 15 mm, and the ratio read off it,
/// each segment to 0.1 mm, is within that reading's precision of 1 + z3/z1 — the guide's
/// scheme (sun 1, planets 2, fixed ring 3, carrier out) with the worked example's teeth.
#[test]
fn the_worked_examples_plan_of_angular_velocities_reads_u_1h_to_a_third_of_a_percent() {
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet2(&p);
    let r = &b.output.results;
    let pl = &r["planetary"];
    assert_eq!(pl["scheme"], "sun-planet-ring");
    // The worked example's stage (the search's choice for u = 750/70 / (19/17)).
    let z: Vec<u64> = pl["z"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap()).collect();
    assert_eq!(z, [17, 64, 145]);
    let u = 1.0 + 145.0 / 17.0;
    let g = &pl["graphic"];
    let (s1, sh) = (g["segment_01_mm"].as_f64().unwrap(), g["segment_0h_mm"].as_f64().unwrap());
    assert!(sh >= 15.0, "0–H is {sh:.2} mm: too short to read u_1H off it");
    assert!(s1 > sh * 9.0, "0–1 is {s1:.2} mm");
    assert_eq!(g["read_to_mm"].as_f64(), Some(0.1));
    // Each segment read to 0.1 mm is off by at most 0.05 mm; their ratio by at most this.
    let read = |x: f64| (x * 10.0).round() / 10.0;
    let bound = u * (0.05 / read(sh) + 0.05 / read(s1));
    assert!(bound / u < 0.0035, "the reading's precision {:.3} %", bound / u * 100.0);
    let got = g["ratio"].as_f64().unwrap();
    assert!((got - u).abs() <= bound * 1.001, "read {got}, analytic {u}, within {bound}");
    let faults = common::layout_faults(&r["layout"]);
    assert!(faults.is_empty(), "sheet 2: {faults:?}");
}

#[test]
fn the_mesh_dimensions_s_e_and_p_on_wheel_1_in_true_size() {
    // The worked example's pair by hand: m = 5 mm, no shift: p = πm, s = e = p/2 (true size,
    // not the 5:1 drawing's), to 0,01 mm with the decimal comma, as every dimension of the
    // drawing that is not exact at fewer decimals (not 7,854 beside p = 15,71).
    let p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
    let b = sheet2(&p);
    let pitch = std::f64::consts::PI * 5.0;
    let half = format!("{:.2}", pitch / 2.0).replace('.', ",");
    let whole = format!("{:.2}", pitch).replace('.', ",");
    // s and e are wheel 1's, p the pair's.
    let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
    for (name, sub, value) in [("s", "", &half), ("e", "", &half), ("p", "", &whole)] {
        let tail = format!(" = {value}");
        assert!(
            mesh.texts().any(|t| t.text == name && t.sub == sub && t.tail == tail),
            "{name}_{sub}{tail} on the mesh"
        );
    }
}

/// The kinematic scheme draws each planet on its axle in a bearing (GOST 2.770: a revolute
/// pair with the carrier, a short line along the axle on each side, not hatched): on the
/// worked example's scheme, both planets shown have one on their axle, and so does each of
/// a double planet's.
#[test]
fn each_planet_turns_on_its_axle_in_a_bearing() {
    use tmm_sheets::drawing::path::Seg;
    use tmm_sheets::drawing::scene::{Item, MAIN};
    for name in ["worked-example", "gears/shifted-double-planet"] {
        let g = planetary_group(name);
        // Horizontal thick lines (the scheme's axis runs across the sheet).
        let flat: Vec<(f64, f64, f64)> = g
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Path { path, pen } if *pen == MAIN => match path.segs.as_slice() {
                    [Seg::Line(e)] if (e.y - path.start.y).abs() < 1e-9 => {
                        Some((path.start.x.min(e.x), path.start.x.max(e.x), e.y))
                    }
                    _ => None,
                },
                _ => None,
            })
            .collect();
        // A bearing: two 5 mm lines 1.6 mm either side of a longer line (the axle) they lie along.
        let bearings = flat
            .iter()
            .filter(|a| (a.1 - a.0 - 5.0).abs() < 1e-6)
            .filter(|a| {
                flat.iter().any(|axle| {
                    axle.1 - axle.0 > 10.0 && (axle.2 - a.2 - 1.6).abs() < 1e-6 && axle.0 < a.0 && axle.1 > a.1
                })
            })
            .filter(|a| flat.iter().any(|c| (c.2 - a.2 - 3.2).abs() < 1e-6 && (c.0 - a.0).abs() < 1e-6))
            .count();
        assert_eq!(bearings, 2, "{name}: one bearing on each of the two planets' axles the scheme shows");
    }
}

/// The front view numbers the ring on its rim between two planets: "3" is set within a few
/// mm of the ring's pitch circle and outside every planet's circle (a double planet's larger
/// gear reaches over the rim: a "3" inside it reads as that gear's number).
#[test]
fn the_ring_is_numbered_on_its_rim_clear_of_the_planets() {
    use tmm_sheets::drawing::scene::{Item, MAIN};
    for name in ["worked-example", "gears/shifted-double-planet"] {
        let g = planetary_group(name);
        let circles: Vec<(kurbo::Point, f64)> = g
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Circle { c, r, pen, filled: false } if *pen == MAIN && *r > 5.0 => Some((*c, *r)),
                _ => None,
            })
            .collect();
        // The ring: the largest thick circle; the planets: the thick circles off its centre.
        let ring = circles.iter().copied().fold((kurbo::Point::ZERO, 0.0), |a, c| if c.1 > a.1 { c } else { a });
        let planets: Vec<_> = circles.iter().filter(|c| (c.0 - ring.0).hypot() > 1.0).collect();
        assert!(planets.len() >= 2, "{name}: the planets drawn: {planets:?}");
        let numbers: Vec<kurbo::Point> = g
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Text(t) if t.text == "3" => Some(t.bbox().center()),
                _ => None,
            })
            .filter(|c| (*c - ring.0).hypot() < ring.1 + 15.0)
            .collect();
        assert_eq!(numbers.len(), 1, "{name}: one \"3\" in the front view: {numbers:?}");
        let at = numbers[0];
        assert!(((at - ring.0).hypot() - ring.1).abs() < 6.0, "{name}: \"3\" at {at:?} beside the rim {ring:?}");
        for (c, r) in planets {
            assert!((at - *c).hypot() > *r + 1.0, "{name}: \"3\" at {at:?} inside the planet at {c:?}, r {r}");
        }
    }
}

/// The planetary views' group of a fixture's sheet 2.
fn planetary_group(name: &str) -> tmm_sheets::drawing::scene::Group {
    let p = pipeline::load(&fixture_text(name)).unwrap();
    let mut b = pipeline::build(&p, &[2]).unwrap().remove(0);
    let at = b.output.scene.groups.iter().position(|g| g.id == "planetary").expect("a planetary group");
    b.output.scene.groups.swap_remove(at)
}

/// The wheels' table writes every radius with one number of decimals, and both thicknesses
/// with one: the KHK pair printed r = 18 over r_b = 16,91, two precisions for one kind of
/// length (GOST 2.105).
#[test]
fn the_wheels_radii_are_written_with_one_number_of_decimals() {
    for (name, text) in gear_fixtures() {
        let built = sheet2(&pipeline::load(&text).unwrap());
        let wheels = &built.output.tables[0];
        let decimals = |keys: &[&str]| -> Vec<usize> {
            let rows = wheels.table.rows.iter().filter(|r| keys.contains(&r.key.as_str()));
            let printed = rows.flat_map(|r| wheels.printed_values(r));
            printed.map(|v| v.split_once([',', '.']).map_or(0, |(_, d)| d.len())).collect()
        };
        for keys in [&["r", "r_b", "r_a", "r_f", "r_w"][..], &["s", "s_a"]] {
            let d = decimals(keys);
            assert!(
                d.len() == 2 * keys.len() && d.iter().all(|&k| k == d[0]),
                "{name}: {keys:?} printed with {d:?} decimals"
            );
        }
    }
}

/// The tables write a gear's lengths as the mesh dimensions them, to 0,01 mm: the KHK
/// pair's p = 3π = 9,42 mm (the table wrote 9,425 beside the drawing's 9,42) and wheel 1's
/// s = 6,02 mm, the same digits in the table and on the drawing.
#[test]
fn the_tables_and_the_mesh_write_a_length_alike() {
    let mut p = pipeline::load(&fixture_text("gears/handbook-khk")).unwrap();
    p.info.language = tmm_sheets::drawing::labels::Language::Ru;
    let b = sheet2(&p);
    let printed = |table: &str, key: &str| {
        let t = b.output.tables.iter().find(|t| t.table.id == table).unwrap();
        t.printed_values(t.table.rows.iter().find(|r| r.key == key).unwrap())
    };
    assert_eq!(printed("pair", "p"), ["9.42"], "p = 3π");
    let s1 = printed("wheels", "s")[0].replace('.', ",");
    let mesh = b.output.scene.groups.iter().find(|g| g.id == "mesh").unwrap();
    let on_mesh = |name: &str, sub: &str| {
        mesh.texts()
            .find(|t| t.text == name && t.sub == sub && t.tail.starts_with(" = "))
            .map(|t| t.tail[3..].to_string())
    };
    assert_eq!(on_mesh("p", "").as_deref(), Some("9,42"));
    assert_eq!(on_mesh("s", ""), Some(s1));
}
