//! Labels near their points where the thin lines of many positions crowd them (issue 22's
//! review: the crank's pivot "O" 20–35 mm below its pivot on most fixtures, a cam's "8≡9"
//! on a 45 mm leader): they stand on those lines, interrupted for them.

mod common;

use common::{fixture, fixture_names};
use kurbo::Point;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::scene::Item;
use tmm_sheets::num::math::{Norm, lines_cross as cross};
use tmm_sheets::pipeline;

/// No label of the position plan hangs off its point on a long leader (the review found the
/// crank's pivot "O" 20–35 mm below its pivot, ω1 25 mm from its arrow, on most fixtures):
/// where the nearest free spots are all far, a label stands beside its point on the other
/// positions' thin lines, interrupted for it. Every leader (and the legend's sample line) of
/// the mechanism's drawing is at most 18 mm on every fixture in every language (up to 36
/// before).
#[test]
fn the_position_plans_labels_stand_near_their_points() {
    for name in fixture_names() {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            assert_leaders_within(&p, (1, "mechanism"), 18.0, &format!("{name} {lang:?}"));
        }
    }
}

/// The cam's profile names its follower's positions and pivots near their points, on the
/// positions' thin lines interrupted for them where they crowd (knife-rocker's "8≡9" hung on
/// a 45.6 mm leader parallel to the rocker's lines, the worked example's A₁₃ on 36 mm): every
/// leader of the profile's drawing is at most 30 mm (a profile's name, set where the
/// profile runs clear, is the longest) on every cam fixture and the worked example, in every
/// language.
#[test]
fn the_cam_profiles_labels_stand_near_their_points() {
    for f in cam_projects() {
        for lang in Language::ALL {
            let mut p = pipeline::load(&std::fs::read_to_string(&f).unwrap()).unwrap();
            p.info.language = lang;
            assert_leaders_within(&p, (3, "profile"), 30.0, &format!("{f:?} {lang:?}"));
        }
    }
}

/// Every leader (every line of the writing) of the drawing `group` of sheet `sheet` of `p`
/// is at most `most` mm long.
fn assert_leaders_within(p: &tmm_sheets::project::Project, (sheet, group): (u32, &str), most: f64, what: &str) {
    let out = pipeline::build(p, &[sheet]).unwrap().remove(0).output;
    let g = out.scene.groups.iter().find(|g| g.id == group).expect("the drawing");
    for &k in &g.writing {
        let Item::Path { path, .. } = &g.items[k] else { continue };
        let long = (path.end() - path.start).norm();
        assert!(long <= most, "{what}: a {long:.1} mm leader from {:?}", path.start);
    }
}

/// The nomogram's r_min stands along its radius and the zone's name in two lines inside the
/// zone: a level r_min hung 22–35 mm off on a leader between the limiting lines
/// (custom-laws, translating-offset-auto), the zone's name in one line 36 mm off. Every
/// leader of the nomogram is at most 20 mm on every cam fixture and the worked example, in
/// every language.
#[test]
fn the_nomograms_labels_stand_near_what_they_name() {
    for f in cam_projects() {
        for lang in Language::ALL {
            let mut p = pipeline::load(&std::fs::read_to_string(&f).unwrap()).unwrap();
            p.info.language = lang;
            assert_leaders_within(&p, (3, "nomogram"), 20.0, &format!("{f:?} {lang:?}"));
        }
    }
}

/// The cam fixtures and the worked example's project file.
fn cam_projects() -> Vec<std::path::PathBuf> {
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(common::root().join("fixtures/cams"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    files.sort();
    files.push(common::root().join("fixtures/worked-example.yaml"));
    files
}

/// An axial crank-slider's positions k and 12 − k put its slider on one point (the crank's
/// angles mirror about the guide's axis), and a teacher read the two numbers side by side on
/// leaders into that point («9 3», «5 7») as two positions: each pair shares one label,
/// «k ≡ 12 − k», in every language, and 12 − k stands alone only at the crank's pin.
#[test]
fn an_axial_crank_sliders_mirrored_positions_share_a_slider_number() {
    for lang in Language::ALL {
        let mut p = fixture("crank-slider-axial");
        p.info.language = lang;
        let out = pipeline::build(&p, &[1]).unwrap().remove(0).output;
        let g = out.scene.groups.iter().find(|g| g.id == "mechanism").expect("the drawing");
        let texts: Vec<&str> = g.texts().map(|t| t.text.as_str()).collect();
        for k in 1..=5 {
            let shared = format!("{k} ≡ {}", 12 - k);
            assert!(texts.contains(&shared.as_str()), "{lang:?}: no «{shared}» in {texts:?}");
            let alone = texts.iter().filter(|t| **t == (12 - k).to_string()).count();
            assert_eq!(alone, 1, "{lang:?}: {} alone on the guide", 12 - k);
        }
    }
}

/// How often each position number 0–11 is written in the mechanism's drawing of sheet 1 of
/// fixture `name` in `lang` (each part of a shared «a ≡ b» counted).
fn position_numbers_written(name: &str, lang: Language) -> Vec<usize> {
    let mut p = fixture(name);
    p.info.language = lang;
    let out = pipeline::build(&p, &[1]).unwrap().remove(0).output;
    let g = out.scene.groups.iter().find(|g| g.id == "mechanism").expect("the drawing");
    let parts: Vec<String> =
        g.texts().flat_map(|t| t.text.split(" ≡ ").map(str::to_string).collect::<Vec<_>>()).collect();
    (0..12).map(|k| parts.iter().filter(|s| **s == k.to_string()).count()).collect()
}

/// A teacher marked the V-compressor's two sliders unnumbered: their 50 mm strokes were
/// short of 5 mm for each of 12 numbers, though mirrored positions stand on one point and
/// share a label, which leaves each room. Every position is now numbered at the crank and
/// on both sliders, in every language.
#[test]
fn a_v_compressors_sliders_are_numbered() {
    for lang in Language::ALL {
        assert_eq!(position_numbers_written("v-compressor", lang), vec![3; 12], "{lang:?}");
    }
}

/// The two-cylinder compressor's pistons travel one axis (cylinders one behind the other):
/// numbering both put two numbers at every point (B's 3 ≡ 9 beside E's 9 ≡ 3) and named
/// neither. The first piston's positions are numbered, the second's not: each number is
/// written at the crank and once on the axis, in every language.
#[test]
fn two_pistons_on_one_axis_are_numbered_once() {
    for lang in Language::ALL {
        assert_eq!(position_numbers_written("two-cylinder-compressor", lang), vec![2; 12], "{lang:?}");
    }
}

/// A six-bar's slider (task 12 variant 45) whose stroke is short of 5 mm for each of its 13
/// positions, under its rod's positions fanned across the guide: numbered, its «11» hung on
/// a 46 mm leader across the crank's circle and «1» on 46 mm across S₄. A short stroke's
/// numbers are kept only where each stands clean within 20 mm of its point: this one is
/// drawn unnumbered, and no leader of the mechanism's drawing is over 20 mm.
#[test]
fn a_short_strokes_numbers_far_off_are_left_out() {
    let out = common::catalogue_sheet1("12", 45, Language::En);
    let g = out.scene.groups.iter().find(|g| g.id == "mechanism").expect("the drawing");
    for &k in &g.leaders {
        let Item::Path { path, .. } = &g.items[k] else { continue };
        let long = (path.end() - path.start).norm();
        assert!(long <= 20.0, "a {long:.1} mm leader from {:?}", path.start);
    }
}

/// Two leaders crossing read as each other's (a slider's «3 ≡ 9» over «4 ≡ 8»'s leader): a
/// label whose leader would cross one drawn before takes a spot little further off whose
/// leader crosses none (`place::crossings::off_leaders`). On these catalogue sheets 1 in
/// Russian two leaders crossed (task 1 variant 43 twice); now none does. Over the
/// catalogue's 416 sheets 1 in Russian, crossing leaders went from 373 to 323.
#[test]
fn a_labels_leader_keeps_off_the_leaders_drawn_before() {
    for (task, variant) in [("1", 43), ("10", 1), ("11", 21)] {
        let out = common::catalogue_sheet1(task, variant, Language::Ru);
        for g in &out.scene.groups {
            if let Some((l, m)) = crossing_pairs(&leaders(g)).next() {
                panic!("task {task} v{variant} {}: leaders from {:?} and {:?} cross", g.id, l.0, m.0);
            }
        }
    }
}

/// A slider's number a word's space before a point's letter on its line reads as one
/// designation with it: the worked example's «0» stood 3 mm before «D» («0D», the guide's
/// D₀). No position number of a fixture's mechanism drawing stands level within two of its
/// heights of a taller text, in any language.
#[test]
fn a_position_number_keeps_off_a_points_letter_on_its_line() {
    let number = |t: &str| !t.is_empty() && t.chars().all(|c| c.is_ascii_digit() || " ≡′".contains(c));
    for name in fixture_names() {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            let Ok(mut built) = pipeline::build(&p, &[1]) else { continue };
            let out = built.remove(0).output;
            let Some(g) = out.scene.groups.iter().find(|g| g.id == "mechanism") else { continue };
            let texts: Vec<_> = g.texts().filter(|t| t.rotate == 0.0).collect();
            for n in texts.iter().filter(|t| number(&t.text)) {
                for l in texts.iter().filter(|t| t.h > 1.5 * n.h) {
                    let (a, b) = (n.core_box(), l.core_box());
                    let gap = (b.x0 - a.x1).max(a.x0 - b.x1);
                    let level = (n.at.y - l.at.y).abs() < 0.4 * n.h;
                    assert!(!(level && gap < 2.0 * n.h), "{name} {lang:?}: «{}» {gap:.1} mm from «{}»", n.text, l.text);
                }
            }
        }
    }
}

/// The leaders of a group, each from its label to its point.
fn leaders(g: &tmm_sheets::drawing::scene::Group) -> Vec<(Point, Point)> {
    g.leaders
        .iter()
        .filter_map(|&k| match &g.items[k] {
            Item::Path { path, .. } => Some((path.start, path.end())),
            _ => None,
        })
        .collect()
}

/// Every fixture built in every language (`sheets` as `pipeline::build` takes them), named
/// "fixture Lang"; those refused left out.
fn every_fixture_built(sheets: &[u32]) -> Vec<(String, Vec<pipeline::Built>)> {
    let mut out = Vec::new();
    for name in fixture_names() {
        for lang in Language::ALL {
            let mut p = fixture(&name);
            p.info.language = lang;
            if let Ok(built) = pipeline::build(&p, sheets) {
                out.push((format!("{name} {lang:?}"), built));
            }
        }
    }
    out
}

/// The pairs of `leaders` that cross, but two fanning out of one point (their starts within
/// [`ONE_POINT`]: each starts its gap off the point along its own direction, so they cross
/// right there, where neither reads as the other's).
fn crossing_pairs(leaders: &[(Point, Point)]) -> impl Iterator<Item = ((Point, Point), (Point, Point))> + '_ {
    let apart = |l: (Point, Point), m: (Point, Point)| (l.0 - m.0).norm() > ONE_POINT;
    leaders.iter().enumerate().flat_map(move |(i, &l)| {
        leaders[i + 1..].iter().filter(move |&&m| cross(l, m) && apart(l, m)).map(move |&m| (l, m))
    })
}

/// Two leaders starting this close start at one point, mm: a leader starts 0.8 mm off its
/// point (`place::LEADER_GAP`), so two of one point start at most 1.6 mm apart.
const ONE_POINT: f64 = 1.6;

/// A slider's numbers hung across its stroke's dimension line read as values of it and hide
/// it (the offset crank-slider's «4» and «8», the V-compressor's «5 ≡ 7», task 8 variant 7):
/// on the numbers' side the dimension line stands beyond them, a number crowded across the
/// guide finds room between its hatching and the line, and a leader keeps off the line as
/// it keeps off other leaders. No leader of a fixture's mechanism drawing, in any language,
/// or of that catalogue sheet crosses a dimension line. Over the catalogue's sheets 1 in
/// Russian, leaders across a dimension line went from 471 to 49
/// (`leader_crossings_over_the_catalogue`).
#[test]
fn no_leader_crosses_a_strokes_dimension_line() {
    let mut drawings: Vec<_> =
        every_fixture_built(&[1]).into_iter().map(|(what, mut b)| (what, b.remove(0).output)).collect();
    drawings.push(("task 8 v7".to_string(), common::catalogue_sheet1("8", 7, Language::Ru)));
    let mut dimensioned = 0;
    let mut crossing = Vec::new();
    for (what, out) in &drawings {
        let Some(g) = out.scene.groups.iter().find(|g| g.id == "mechanism") else { continue };
        let lines = common::dimension_lines(g);
        dimensioned += usize::from(!lines.is_empty());
        for l in leaders(g) {
            for &d in lines.iter().filter(|&&d| cross(l, d)) {
                crossing.push(format!("{what}: the leader {l:.1?} crosses the dimension line {d:.1?}"));
            }
        }
    }
    assert!(crossing.is_empty(), "{}", crossing.join("\n"));
    // Every slider's stroke is dimensioned: the test sees the lines it is about.
    assert!(dimensioned >= 10, "{dimensioned} drawings with a dimension line");
}

/// The catalogue's sheets 1 measured (`cargo test --release --test position_plan_labels --
/// --ignored --nocapture`, in the language `SWEEP_LANG` names, Russian by default): leaders
/// crossing a dimension line, leaders crossing each other, leaders over 20 mm in the
/// mechanism's drawing. A report to compare changes by, not a bound.
#[test]
#[ignore]
fn leader_crossings_over_the_catalogue() {
    let lang = common::sweep_lang();
    let (mut across_dimensions, mut across_leaders, mut long) = (0, 0, 0);
    for (task, v, out) in common::catalogue_sheets1(lang) {
        let before = (across_dimensions, across_leaders, long);
        for g in &out.scene.groups {
            let (leaders, lines) = (leaders(g), common::dimension_lines(g));
            across_leaders += crossing_pairs(&leaders).count();
            for &l in &leaders {
                across_dimensions += lines.iter().filter(|&&d| cross(l, d)).count();
                long += usize::from(g.id == "mechanism" && (l.1 - l.0).norm() > 20.0);
            }
        }
        if std::env::var_os("SWEEP_EACH").is_some() {
            let counts = (across_dimensions - before.0, across_leaders - before.1, long - before.2);
            eprintln!("task {task} v{v}: {counts:?}");
        }
    }
    eprintln!(
        "{lang:?}: {across_dimensions} leaders across a dimension line, {across_leaders} pairs of leaders crossing, {long} mechanism leaders over 20 mm"
    );
}

/// Two leaders crossing read as each other's labels: a four-bar's ε₃ hung across ω₃'s
/// leader, each beside the other's arc. Where two labels' leaders cross, the labels swap
/// spots if both then stand clear (`place::untangle`). No two leaders of one drawing cross
/// on any fixture's three sheets, in any language (three pairs before, one per language;
/// over the catalogue's Russian sheets 1, 304 → 262) but the pairs [`CROSSING_ALLOWED`]
/// names.
#[test]
fn no_two_leaders_cross_on_any_fixture() {
    let mut crossing = Vec::new();
    for (what, built) in every_fixture_built(&[]) {
        for g in built.iter().flat_map(|b| &b.output.scene.groups) {
            let pairs: Vec<String> =
                crossing_pairs(&leaders(g)).map(|(l, m)| format!("{what} {}: {l:.1?} × {m:.1?}", g.id)).collect();
            let allowed =
                CROSSING_ALLOWED.iter().find(|(f, id, _)| what.starts_with(f) && g.id == *id).map_or(0, |a| a.2);
            if pairs.len() > allowed {
                crossing.extend(pairs);
            }
        }
    }
    assert!(crossing.is_empty(), "{}", crossing.join("\n"));
}

/// How many pairs of leaders may cross in a fixture's drawing, where no spot near the points
/// is free of both: the vertical slider's twelve positions within 130 mm of its guide, «4»
/// and «8» boxed in by «3», «5», «9» and the rod (since short leaders meet their labels at a
/// corner, not level into their side: catalogue-wide the pairs crossing went 267 → 265); the
/// two-cylinder compressor's «5 ≡ 7» and «6» under the second block (since the first
/// stroke's line moved out to have H over it).
const CROSSING_ALLOWED: [(&str, &str, usize); 2] =
    [("crank-slider-offset-vertical", "mechanism", 1), ("two-cylinder-compressor", "mechanism", 1)];
