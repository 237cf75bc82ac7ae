//! The load diagram on inputs the fixtures do not have: a crank-slider whose idle force is a
//! few percent of its working force (found by an audit of 120 random crank-sliders: 10 had
//! the idle line through the S/H values "0", "0.5", "1" and the idle level unmarked).

mod common;

use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::scene::Item;
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
