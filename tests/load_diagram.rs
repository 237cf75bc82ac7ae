//! The load diagram on inputs the fixtures do not have: a crank-slider whose idle force is a
//! few percent of its working force (found by an audit of 120 random crank-sliders: 10 had
//! the idle line through the S/H values "0", "0.5", "1" and the idle level unmarked).

mod common;

use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::scene::Item;
use tmm_sheets::num::math::Norm;
use tmm_sheets::pipeline;

/// A crank-slider resisting 16 505 N on its working stroke and 655 N on its idle one (4 %).
const SMALL_IDLE: &str = r#"
project: {title: "R", designation: "TMM CP 01", language: en}
mechanism:
  frame:
    - {name: O, at: [0, 0]}
  crank: {pivot: O, pin: A, length: 0.2788, rpm: 621, sense: cw}
  groups:
    - rrp: {links: [2, 3], joint: A, point: B, length: 0.8896, guide: {through: [0, -0.0710], angle_deg: 30}, branch: forward}
  points:
    - {name: S2, link: 2, from: A, toward: B, ratio: 0.32, mass_centre: true}
    - {name: S3, link: 3, from: B, mass_centre: true}
analysis:
  positions: 12
  assigned_deg: 60
forces:
  links:
    - {link: 2, mass: 6.8, inertia: rod}
    - {link: 3, mass: 4.1}
  loads:
    - resistance: {point: B, working: backward, force: 16505, idle_force: 655}
"#;

/// The texts of the force analysis' drawings (the load diagrams among them).
fn force_texts(scene: &tmm_sheets::drawing::scene::Scene) -> Vec<&str> {
    (scene.groups.iter().filter(|g| g.id.starts_with("forces")))
        .flat_map(|g| &g.items)
        .filter_map(|i| if let Item::Text(t) = i { Some(t.text.as_str()) } else { None })
        .collect()
}

/// The S/H values stand on the side of the axis no curve runs through (below it here, where
/// the idle line runs 1.6 mm above), the sheet's layout measure is clean, and the idle level
/// is written on the P axis, in every language.
#[test]
fn a_small_idle_force_keeps_its_line_off_the_stroke_values_and_is_marked() {
    for lang in Language::ALL {
        let text = SMALL_IDLE.replace("language: en", &format!("language: {}", lang.key()));
        let p = pipeline::load(&text).unwrap_or_else(|e| panic!("{e:#}"));
        let lever = common::build_lever(&p);
        let scene = &lever.composed.scene;
        common::check_layout(&format!("small idle force {lang:?}"), scene);
        let texts = force_texts(scene);
        assert!(texts.contains(&"655"), "{lang:?}: the idle level is not written: {texts:?}");
    }
}

/// A working stroke with corners at 21 % and 20 %, 95 %, 75 % and 100 % of P_max: only each
/// stroke's least and largest levels were written, leaving the corner at 21 229 N (75 %) to
/// be read off between round ticks. Every corner's level is written where it stands 4 mm or
/// more from a larger one: −28305 (P_max), −21229, −5944 and the idle 19475.
#[test]
fn every_corner_of_a_load_diagram_has_its_level_on_the_axis() {
    let text = r#"
project: {title: "R", designation: "TMM CP 00.01.03", language: uz}
mechanism:
  frame:
    - {name: O, at: [0, 0]}
  crank: {pivot: O, pin: A, length: 0.2261, rpm: 711.8, sense: ccw}
  groups:
    - rrp: {links: [2, 3], joint: A, point: B, length: 0.5600, guide: {through: [0, 0.0037], angle_deg: 90}, branch: forward}
  points:
    - {name: S2, link: 2, from: A, toward: B, ratio: 0.454, mass_centre: true}
    - {name: S3, link: 3, from: B, mass_centre: true}
analysis: {positions: 8, assigned_deg: 330}
forces:
  links:
    - {link: 2, mass: 11.75, inertia: rod}
    - {link: 3, mass: 31.20}
  loads:
    - resistance: {point: B, working: backward, force: 28305, idle_force: 19474.6, diagram: [[0, 0.21], [0.2, 0.2], [0.4, 0.95], [0.6, 0.75], [1, 1]]}
"#;
    let p = pipeline::load(text).unwrap_or_else(|e| panic!("{e:#}"));
    let lever = common::build_lever(&p);
    let scene = &lever.composed.scene;
    common::check_layout("corners' levels", scene);
    let texts = force_texts(scene);
    for level in ["−28305", "−21229", "−5944", "19475"] {
        assert!(texts.contains(&level), "{level} is not written: {texts:?}");
    }
}

/// The load diagram's stroke arrows: filled triangles 5 mm long, as (centre, direction).
fn stroke_arrows(scene: &tmm_sheets::drawing::scene::Scene) -> Vec<(kurbo::Point, kurbo::Vec2)> {
    use tmm_sheets::drawing::path::Seg;
    let fills = (scene.groups.iter().filter(|g| g.id.starts_with("forces"))).flat_map(|g| &g.items).filter_map(|i| {
        let Item::Fill { path } = i else { return None };
        let [Seg::Line(b1), Seg::Line(b2)] = path.segs.as_slice() else { return None };
        let base = b1.midpoint(*b2);
        Some((path.start.midpoint(base), path.start - base, (*b1 - *b2).norm()))
    });
    fills
        .filter(|(_, dir, width)| (dir.norm() - 5.0).abs() < 1e-6 && (width - 2.6).abs() < 1e-6)
        .map(|(c, d, _)| (c, d))
        .collect()
}

/// Each stroke of the worked example's load diagram carries an arrow along its line the way
/// the slider travels on it: the working stroke (−4600 N, drawn below the axis) towards
/// S/H = 1, the idle stroke (+1650 N, above it) back towards 0; the stroke's name stands
/// beside its own arrow, not both along the shared axis.
#[test]
fn each_stroke_of_a_load_diagram_shows_which_way_it_runs() {
    for lang in Language::ALL {
        let mut p = pipeline::load(pipeline::DEFAULT_PROJECT).unwrap();
        p.info.language = lang;
        let lever = common::build_lever(&p);
        let scene = &lever.composed.scene;
        let arrows = stroke_arrows(scene);
        assert_eq!(arrows.len(), 2, "{lang:?}: {arrows:?}");
        let forward: Vec<_> = arrows.iter().filter(|a| a.1.x > 0.0).collect();
        let back: Vec<_> = arrows.iter().filter(|a| a.1.x < 0.0).collect();
        assert!(forward.len() == 1 && back.len() == 1, "{lang:?}: {arrows:?}");
        // Paper y grows downwards: the working stroke's −4600 N is the lower line.
        assert!(forward[0].0.y > back[0].0.y + 20.0, "{lang:?}: {arrows:?}");
        let (working, idle) = match lang {
            Language::Uz => ("ishchi yurish", "salt yurish"),
            Language::Ru => ("рабочий ход", "холостой ход"),
            Language::En => ("working stroke", "idle stroke"),
        };
        for ((c, d), name) in [(forward[0], working), (back[0], idle)] {
            assert!(d.y.abs() < 1e-6, "{lang:?}: both strokes are flat here: {d:?}");
            let text = (scene.groups.iter().flat_map(|g| &g.items))
                .find_map(|i| if let Item::Text(t) = i { (t.text == name).then(|| t.bbox()) } else { None })
                .unwrap_or_else(|| panic!("{lang:?}: no «{name}»"));
            let beside = (text.center().y - c.y).abs() < 6.0 && text.x0 - 12.0 < c.x && c.x < text.x1 + 12.0;
            assert!(beside, "{lang:?}: «{name}» at {text:?} is not beside its arrow at {c:?}");
        }
    }
}

/// A stroke whose line runs along the S/H axis is named on the side away from the axis'
/// values: the two-cylinder compressor's «от крышки» and the engine's «II – выпуск» stood
/// on the values' row right after "0,5", read as "0,5 от крышки". No text of the force
/// drawings stands on the row of an S/H value within 4 mm of it, in every language.
#[test]
fn a_stroke_along_the_axis_is_named_away_from_the_stroke_values() {
    for name in ["two-cylinder-compressor", "crank-slider-axial"] {
        for lang in Language::ALL {
            let mut p = common::fixture(name);
            p.info.language = lang;
            let lever = common::build_lever(&p);
            let texts: Vec<_> = (lever.composed.scene.groups.iter().filter(|g| g.id.starts_with("forces")))
                .flat_map(|g| &g.items)
                .filter_map(|i| if let Item::Text(t) = i { Some((t.text.as_str(), t.bbox())) } else { None })
                .collect();
            let halves: Vec<_> = texts.iter().filter(|(t, _)| *t == "0,5" || *t == "0.5").collect();
            assert!(!halves.is_empty(), "{name} {lang:?}: no S/H value 0,5");
            for (half, h) in halves {
                for (t, b) in texts.iter().filter(|(t, _)| t != half) {
                    let same_row = b.y0 < h.y1 && b.y1 > h.y0;
                    let gap = (b.x0 - h.x1).max(h.x0 - b.x1);
                    assert!(!same_row || gap >= 4.0, "{name} {lang:?}: «{t}» {gap:.1} mm beside «{half}»");
                }
            }
        }
    }
}

/// The analysed position's «φ₁ = 60,0°» stands off the S/H values' row: with its mark on
/// the axis, the offset crank-slider's stood under it between «0» and «0,5», read as one
/// more value. No φ₁ of a load diagram stands level with an S/H value's row within the
/// axis, on the fixtures with a load, in every language.
#[test]
fn the_analysed_positions_angle_keeps_off_the_stroke_values_row() {
    for name in ["crank-slider-offset-vertical", "crank-slider-axial", "two-cylinder-compressor", "worked-example"] {
        for lang in Language::ALL {
            let mut p = common::fixture(name);
            p.info.language = lang;
            let lever = common::build_lever(&p);
            for g in lever.composed.scene.groups.iter().filter(|g| g.id.starts_with("forces")) {
                let texts: Vec<_> = g
                    .items
                    .iter()
                    .filter_map(|i| if let Item::Text(t) = i { Some((t, t.bbox())) } else { None })
                    .collect();
                let halves: Vec<_> = texts.iter().filter(|(t, _)| t.text == "0,5" || t.text == "0.5").collect();
                for (_, h) in &halves {
                    for (t, b) in texts.iter().filter(|(t, _)| t.text == "φ" && t.plain().contains('°')) {
                        let same_row = b.y0 < h.y1 && b.y1 > h.y0;
                        assert!(!same_row, "{name} {lang:?}: «{}» on the S/H values' row", t.plain());
                    }
                }
            }
        }
    }
}
