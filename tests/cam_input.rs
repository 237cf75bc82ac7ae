//! The project file's `cam` section (sheet 3's input): the fixtures load into the cam they
//! describe, every bad value is refused naming its field and line, and implausible input is
//! warned about.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture_text, root};
use tmm_sheets::assert_near;
use tmm_sheets::cams::follower::Follower;
use tmm_sheets::cams::laws::{Law, Standard as S};
use tmm_sheets::cams::radius::Placement;
use tmm_sheets::cams::{Roller, Sense};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::project::{self, CamProject, Project};

fn load(text: &str) -> Project {
    project::load(text).unwrap_or_else(|e| panic!("{e}"))
}

fn cam_fixture(name: &str) -> Project {
    let text = std::fs::read_to_string(root().join("fixtures/cams").join(format!("{name}.yaml"))).unwrap();
    load(&text)
}

/// A cam-only project; the cam section starts on line 6, one key a line.
const BASE: &str = "project:
  title: \"Cam\"
  designation: \"MMN KL 09.00.00\"
  language: en

cam:
  follower: {rocker: {length: 0.105, swing_deg: 25}}
  roller: auto
  phases_deg: {rise: 70, far_dwell: 10, return: 70}
  law: sine
  pressure_angle_deg: 45
  sense: ccw
";

/// BASE with `from` replaced by `to` (the pattern must be there).
fn with(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "the test's pattern {from:?} is not in BASE");
    BASE.replacen(from, to, 1)
}

/// The 1-based line of `text` that contains `pattern`.
fn line_of(text: &str, pattern: &str) -> usize {
    text.lines().position(|l| l.contains(pattern)).unwrap_or_else(|| panic!("{pattern:?} not in the text")) + 1
}

/// Loads `text`, expecting a refusal; returns its message.
fn refusal(text: &str) -> String {
    match project::load(text) {
        Ok(_) => panic!("the input must be refused:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// Replaces `from` by `to` in BASE and checks that the refusal names `field` and the line
/// of `to`, and says `says`.
fn refused(from: &str, to: &str, field: &str, says: &str) -> String {
    let text = with(from, to);
    let e = refusal(&text);
    let line = line_of(&text, to);
    assert!(e.contains(&format!("line {line},")), "{to}: expected line {line}: {e}");
    assert!(e.contains(&format!("{field}:")), "{to}: expected the field {field}: {e}");
    assert!(e.contains(says), "{to}: expected {says:?}: {e}");
    e
}

fn cam(p: &Project) -> &CamProject {
    p.cam.as_ref().expect("a cam section")
}

#[test]
fn the_worked_example_has_the_guides_cam() {
    let p = load(&fixture_text("worked-example"));
    assert!(p.lever.is_some() && p.gears.is_some());
    let c = cam(&p);
    let spec = &c.design.spec;
    assert_eq!(spec.follower, Follower::Rocker { length: 0.105 });
    assert_near!(spec.program.lift, 25f64.to_radians());
    assert_near!(spec.program.rise, 70f64.to_radians());
    assert_near!(spec.program.far_dwell, 10f64.to_radians());
    assert_near!(spec.program.ret, 70f64.to_radians());
    assert_eq!(c.laws, (Law::Standard(S::Sine), Law::Standard(S::Sine)));
    assert_eq!(
        (spec.program.rise_law.clone(), spec.program.return_law.clone()),
        (Law::Standard(S::Sine), Law::Standard(S::Sine))
    );
    assert_eq!(c.laws.0.guide_number(), Some(4));
    assert_near!(spec.allowed.rise, 45f64.to_radians());
    assert_near!(spec.allowed.ret, 45f64.to_radians());
    assert_eq!(spec.placement, Placement::Free);
    assert_eq!(spec.roller, Roller::Auto);
    assert_eq!(spec.sense, Sense::Ccw);
    assert!(c.roller_auto && !c.offset_auto);
    assert!(c.design.roller > 0.0 && c.design.centre.r_min > c.design.roller);
    let uz: Vec<&str> = c.assumptions.iter().map(|a| a.get(Language::Uz)).collect();
    assert_eq!(uz, ["Qonun rasmi yoʻqolgan: 4-qonun (sinusoidal, sikloidal) qabul qilindi."]);
    let ru: Vec<&str> = c.assumptions.iter().map(|a| a.get(Language::Ru)).collect();
    assert_eq!(ru, ["Рисунок закона утерян: принят закон 4 (синусоидальный, циклоидальный)."]);
    assert!(p.warnings.iter().all(|w| !w.field.starts_with("cam")), "{:?}", p.warnings);
}

#[test]
fn the_translating_fixture_has_auto_offset_and_two_laws() {
    let p = cam_fixture("translating-offset-auto");
    assert!(p.lever.is_none() && p.gears.is_none());
    let c = cam(&p);
    let spec = &c.design.spec;
    assert_eq!(spec.follower, Follower::Translating);
    assert_near!(spec.program.lift, 0.04);
    assert_near!(spec.program.rise, 120f64.to_radians());
    assert_near!(spec.program.far_dwell, 30f64.to_radians());
    assert_near!(spec.program.ret, 90f64.to_radians());
    assert_eq!(c.laws, (Law::Standard(S::Cosine), Law::Standard(S::Polynomial345)));
    assert_near!(spec.allowed.rise, 30f64.to_radians());
    assert_near!(spec.allowed.ret, 45f64.to_radians());
    assert_eq!(spec.placement, Placement::Free);
    assert_eq!(spec.roller, Roller::Radius(0.008));
    assert_eq!(spec.sense, Sense::Cw);
    assert!(!c.roller_auto && c.offset_auto);
    assert_near!(c.design.roller, 0.008);
    assert!(c.design.offset().is_some_and(f64::is_finite));
}

#[test]
fn the_knife_rocker_fixture_has_no_roller_and_no_far_dwell() {
    let p = cam_fixture("knife-rocker");
    assert!(p.lever.is_none() && p.gears.is_none());
    let c = cam(&p);
    let spec = &c.design.spec;
    assert_eq!(spec.follower, Follower::Rocker { length: 0.12 });
    assert_near!(spec.program.lift, 20f64.to_radians());
    assert_near!(spec.program.rise, 90f64.to_radians());
    assert_eq!(spec.program.far_dwell, 0.0);
    assert_near!(spec.program.ret, 60f64.to_radians());
    assert_eq!(c.laws, (Law::Standard(S::LinearlyDecreasing), Law::Standard(S::LinearlyDecreasing)));
    assert_eq!(spec.roller, Roller::Knife);
    assert_eq!(c.design.roller, 0.0);
    assert!(!c.roller_auto && !c.offset_auto);
}

#[test]
fn a_project_with_only_a_cam_loads_with_defaults() {
    let text = BASE.replace("  roller: auto\n", "").replace("  sense: ccw\n", "").replace("far_dwell: 10, ", "");
    let p = load(&text);
    assert!(p.lever.is_none() && p.gears.is_none());
    let c = cam(&p);
    assert_eq!(c.design.spec.roller, Roller::Auto);
    assert_eq!(c.design.spec.sense, Sense::Ccw);
    assert_eq!(c.design.spec.program.far_dwell, 0.0);
    assert!(c.roller_auto && c.assumptions.is_empty());
}

#[test]
fn laws_by_number_and_per_phase() {
    for (law, expect) in [
        ("4", (Law::Standard(S::Sine), Law::Standard(S::Sine))),
        ("\"1\"", (Law::Standard(S::UniformAcceleration), Law::Standard(S::UniformAcceleration))),
        ("modified-sine", (Law::Standard(S::ModifiedSine), Law::Standard(S::ModifiedSine))),
        ("{rise: 3, return: trapezoid}", (Law::Standard(S::Cosine), Law::Standard(S::Trapezoid))),
        ("{rise: \"5\", return: 6}", (Law::Standard(S::Triangular), Law::Standard(S::Trapezoid))),
    ] {
        let p = load(&with("law: sine", &format!("law: {law}")));
        assert_eq!(cam(&p).laws, expect, "{law}");
    }
}

#[test]
fn a_translating_offset_is_taken_as_written() {
    let follower = "follower: {translating: {stroke: 0.04, offset: 0.01}}";
    let p = load(&with("follower: {rocker: {length: 0.105, swing_deg: 25}}", follower));
    let c = cam(&p);
    assert_eq!(c.design.spec.placement, Placement::Offset(0.01));
    assert!(!c.offset_auto);
    let p =
        load(&with("follower: {rocker: {length: 0.105, swing_deg: 25}}", "follower: {translating: {stroke: 0.04}}"));
    assert_eq!(cam(&p).design.spec.placement, Placement::Offset(0.0));
}

#[test]
fn phases_are_checked_where_written() {
    let e = refused(
        "phases_deg: {rise: 70, far_dwell: 10, return: 70}",
        "phases_deg: {rise: 200, far_dwell: 10, return: 170}",
        "cam.phases_deg",
        "380",
    );
    assert!(e.contains("360"), "{e}");
    for rise in ["0", "-70"] {
        refused("rise: 70,", &format!("rise: {rise},"), "cam.phases_deg.rise", "positive");
    }
    refused("return: 70}", "return: 0}", "cam.phases_deg.return", "positive");
    refused("far_dwell: 10,", "far_dwell: -10,", "cam.phases_deg.far_dwell", "≥ 0");
}

#[test]
fn phases_on_separate_lines_name_their_own_line() {
    let text = with(
        "phases_deg: {rise: 70, far_dwell: 10, return: 70}",
        "phases_deg:\n    rise: 70\n    far_dwell: 10\n    return: -70",
    );
    let e = refusal(&text);
    assert!(
        e.contains(&format!("line {},", line_of(&text, "return: -70"))) && e.contains("cam.phases_deg.return"),
        "{e}"
    );
}

#[test]
fn the_follower_is_checked_where_written() {
    refused("swing_deg: 25", "swing_deg: 0", "cam.follower.rocker.swing_deg", "between 0° and 180°");
    refused("swing_deg: 25", "swing_deg: 180", "cam.follower.rocker.swing_deg", "between 0° and 180°");
    refused("swing_deg: 25", "swing_deg: -5", "cam.follower.rocker.swing_deg", "between 0° and 180°");
    refused("length: 0.105", "length: 0", "cam.follower.rocker.length", "positive");
    refused("length: 0.105", "length: -0.105", "cam.follower.rocker.length", "positive");
    let rocker = "follower: {rocker: {length: 0.105, swing_deg: 25}}";
    refused(rocker, "follower: {translating: {stroke: 0}}", "cam.follower.translating.stroke", "positive");
    refused(
        rocker,
        "follower: {translating: {stroke: 0.04, offset: left}}",
        "cam.follower.translating.offset",
        "`auto`",
    );
    refused(rocker, "follower: {}", "cam.follower", "exactly one");
    refused(
        rocker,
        "follower: {rocker: {length: 0.105, swing_deg: 25}, translating: {stroke: 0.04}}",
        "cam.follower",
        "exactly one",
    );
    // An unknown kind: the parser names it, its line, and the two accepted.
    let text = with(rocker, "follower: {slider: {stroke: 0.04}}");
    let e = refusal(&text);
    assert!(e.contains("slider") && e.contains("rocker") && e.contains("translating"), "{e}");
    assert!(e.contains(&format!("line {}", line_of(&text, "slider"))), "{e}");
}

#[test]
fn a_swing_no_centre_can_serve_is_an_error_at_the_swing() {
    // Half the swing (50°) is over the allowed angle (45°).
    refused("swing_deg: 25", "swing_deg: 100", "cam.follower.rocker.swing_deg", "twice the allowed pressure angle");
}

#[test]
fn allowed_pressure_angles_are_checked() {
    for bad in ["0", "-10", "90", "120"] {
        refused(
            "pressure_angle_deg: 45",
            &format!("pressure_angle_deg: {bad}"),
            "cam.pressure_angle_deg",
            "between 0° and 90°",
        );
    }
    refused(
        "pressure_angle_deg: 45",
        "pressure_angle_deg: {rise: 30, return: 95}",
        "cam.pressure_angle_deg.return",
        "between 0° and 90°",
    );
    refused("pressure_angle_deg: 45", "pressure_angle_deg: steep", "cam.pressure_angle_deg", "degrees");
    let text = with("pressure_angle_deg: 45", "pressure_angle_deg:\n    rise: 0\n    return: 45");
    let e = refusal(&text);
    assert!(
        e.contains(&format!("line {},", line_of(&text, "rise: 0"))) && e.contains("cam.pressure_angle_deg.rise"),
        "{e}"
    );
}

#[test]
fn an_unknown_law_lists_the_accepted_ones() {
    for bad in ["hyperbolic", "7", "0", "4.5", "\"\""] {
        let e = refused("law: sine", &format!("law: {bad}"), "cam.law", "unknown law");
        assert!(e.contains("cosine (3)") && e.contains("polynomial-345") && e.contains("1–6"), "{e}");
    }
    refused("law: sine", "law: {rise: sine, return: cubic}", "cam.law.return", "unknown law 'cubic'");
    let text = with("law: sine", "law:\n    rise: nine\n    return: sine");
    let e = refusal(&text);
    assert!(e.contains(&format!("line {},", line_of(&text, "rise: nine"))) && e.contains("cam.law.rise"), "{e}");
    let e = refusal(&with("law: sine", "law: [4]"));
    assert!(e.contains("line 10") && e.contains("`{rise: …, return: …}`"), "{e}");
    let e = refusal(&with("law: sine", "law: {rise: sine, fall: sine}"));
    assert!(e.contains("fall") && e.contains("return"), "{e}");
    let e = refusal(&with("law: sine", "law: {rise: sine}"));
    assert!(e.contains("return"), "{e}");
}

#[test]
fn an_unknown_sense_is_refused() {
    refused("sense: ccw", "sense: left", "cam.sense", "`cw`");
}

#[test]
fn the_roller_is_checked_where_written() {
    for bad in ["0", "-0.01"] {
        refused("roller: auto", &format!("roller: {bad}"), "cam.roller", "positive");
    }
    refused("roller: auto", "roller: big", "cam.roller", "`knife`");
    // A roller larger than the profile's curvature (here 8 mm written as 8 m).
    refused("roller: auto", "roller: 8", "cam.roller", "radius of curvature");
    refused("roller: auto", "roller: 0.5", "cam.roller", "undercut");
}

#[test]
fn nan_and_infinity_are_refused_where_written() {
    for (from, field) in [
        ("length: 0.105", "length"),
        ("swing_deg: 25", "swing_deg"),
        ("rise: 70,", "rise"),
        ("far_dwell: 10,", "far_dwell"),
        ("roller: auto", "roller"),
        ("pressure_angle_deg: 45", "pressure_angle_deg"),
        ("law: sine", "law"),
    ] {
        for bad in [".nan", ".inf", "-.inf", "1.0e300"] {
            let to = format!("{field}: {bad}{}", if from.ends_with(',') { "," } else { "" });
            let text = with(from, &to);
            let e = refusal(&text);
            assert!(e.contains(&format!("line {}", line_of(&text, &to))), "{to}: {e}");
            assert!(
                ["expected a finite number", "not a finite number", "too large", "unknown law"]
                    .iter()
                    .any(|m| e.contains(m)),
                "{to}: {e}"
            );
        }
    }
    let e = refusal(&with("pressure_angle_deg: 45", "pressure_angle_deg: {rise: .nan, return: 45}"));
    assert!(
        e.contains("not a finite number") && e.contains("line 11") && e.contains("cam.pressure_angle_deg.rise"),
        "{e}"
    );
}

#[test]
fn assumptions_are_checked_like_the_other_texts() {
    let text = format!("{BASE}  assumptions: [\"ok\", \"bad \\u0007 bell\"]\n");
    let e = refusal(&text);
    assert!(e.contains("cam.assumptions[1]") && e.contains("U+0007") && e.contains("line 13"), "{e}");
    let p = load(&format!("{BASE}  assumptions: [\"Qonun 4-qonun.\"]\n"));
    let texts: Vec<&str> = cam(&p).assumptions.iter().map(|a| a.get(Language::En)).collect();
    assert_eq!(texts, ["Qonun 4-qonun."]);
}

#[test]
fn millimetres_written_as_metres_are_warned_about() {
    let rocker = "follower: {rocker: {length: 0.105, swing_deg: 25}}";
    let text = with(rocker, "follower: {translating: {stroke: 40}}");
    let p = load(&text);
    let w: Vec<_> = p.warnings.iter().filter(|w| w.field == "cam.follower.translating.stroke").collect();
    assert_eq!(w.len(), 1, "{:?}", p.warnings);
    assert_eq!(w[0].line, 7);
    assert!(w[0].message.contains("millimetres") && w[0].message.contains("0.04"), "{}", w[0]);
    let p = load(&with("length: 0.105", "length: 105"));
    assert!(p.warnings.iter().any(|w| w.field == "cam.follower.rocker.length" && w.message.contains("millimetres")));
    let p = load(&with(rocker, "follower: {translating: {stroke: 0.0004}}"));
    assert!(p.warnings.iter().any(|w| w.field == "cam.follower.translating.stroke" && w.message.contains("small")));
}

#[test]
fn implausible_angles_and_rollers_are_warned_about() {
    let p = load(&with("swing_deg: 25", "swing_deg: 70"));
    assert!(p.warnings.iter().any(|w| w.field == "cam.follower.rocker.swing_deg" && w.line == 7), "{:?}", p.warnings);
    for a in ["25", "60"] {
        let p = load(&with("pressure_angle_deg: 45", &format!("pressure_angle_deg: {a}")));
        assert!(
            p.warnings
                .iter()
                .any(|w| w.field == "cam.pressure_angle_deg" && w.line == 11 && w.message.contains("30–50°")),
            "{a}: {:?}",
            p.warnings
        );
    }
    // A roller well below the course's 0.25–0.4·r_min: the design's warning, at the roller, in mm.
    let p = load(&with("roller: auto", "roller: 0.001"));
    let w = p.warnings.iter().find(|w| w.field == "cam.roller").unwrap_or_else(|| panic!("{:?}", p.warnings));
    assert_eq!(w.line, 8);
    assert!(w.message.contains("1.000 mm") && w.message.contains("r_min"), "{w}");
    // The guide's data warns about nothing.
    assert!(load(BASE).warnings.is_empty(), "{:?}", load(BASE).warnings);
}

#[test]
fn unknown_keys_in_the_section_are_refused() {
    let text = format!("{BASE}  speed: 100\n");
    let e = refusal(&text);
    assert!(e.contains("unknown key `speed`") && e.contains("line 13") && e.contains("cam.speed"), "{e}");
}

#[test]
fn nothing_to_draw_mentions_the_cam() {
    let text = BASE.split("\ncam:").next().unwrap();
    let e = refusal(text);
    assert!(e.contains("`cam` section (sheet 3)"), "{e}");
}

#[test]
fn extreme_input_is_refused_or_designed_never_a_panic() {
    let followers = [
        "{rocker: {length: 1.0e-9, swing_deg: 1.0e-6}}",
        "{rocker: {length: 1.0e9, swing_deg: 179.9}}",
        "{rocker: {length: 1.0e9, swing_deg: 25}}",
        "{rocker: {length: 0.1, swing_deg: 89.99}}",
        "{translating: {stroke: 1.0e-9, offset: auto}}",
        "{translating: {stroke: 1.0e9, offset: -1.0e9}}",
        "{translating: {stroke: 0.04, offset: 1.0e9}}",
    ];
    let phases = ["{rise: 1.0e-6, return: 1.0e-6}", "{rise: 359.9999, return: 1.0e-4}", "{rise: 180, return: 180}"];
    let allowed = ["0.001", "89.999", "{rise: 89.999, return: 0.001}"];
    let rollers = ["auto", "knife", "1.0e-9", "1.0e9"];
    for f in followers {
        for ph in phases {
            for a in allowed {
                for r in rollers {
                    let text = with("{rocker: {length: 0.105, swing_deg: 25}}", f)
                        .replace("{rise: 70, far_dwell: 10, return: 70}", ph)
                        .replace("pressure_angle_deg: 45", &format!("pressure_angle_deg: {a}"))
                        .replace("roller: auto", &format!("roller: {r}"));
                    if let Ok(p) = project::load(&text) {
                        let d = &cam(&p).design;
                        assert!(d.centre.r_min.is_finite() && d.roller.is_finite(), "{text}");
                    }
                }
            }
        }
    }
}

#[test]
fn a_cam_too_large_to_design_is_refused_at_what_makes_it_so() {
    // A kilometre rocker, and a 4 cm stroke over a millionth of a degree: the centre's search
    // would need a resolution the doubles do not have there, and no sheet can draw it.
    refused("length: 0.105", "length: 1.0e6", "cam.follower.rocker.length", "too large to draw");
    refused("rise: 70,", "rise: 1.0e-6,", "cam.phases_deg.rise", "too large to draw");
    let translating = with("{rocker: {length: 0.105, swing_deg: 25}}", "{translating: {stroke: 0.04, offset: auto}}");
    let e = refusal(&translating.replace("rise: 70,", "rise: 1.0e-6,"));
    assert!(e.contains("cam.phases_deg.rise") && e.contains("too large"), "{e}");
    // A given offset is bounded the same way (it used to be designed: r_min 4.6e6 m).
    let given = translating.replace("offset: auto", "offset: 0").replace("rise: 70,", "rise: 1.0e-6,");
    let e = refusal(&given);
    assert!(e.contains("cam.phases_deg.rise") && e.contains("too large"), "{e}");
}

/// The title, the institution and each assumption may be written per language; the sheet's
/// language picks, a language not written takes the first one; an unknown language is
/// refused at its line.
#[test]
fn user_texts_may_be_written_per_language() {
    let text = with("  title: \"Cam\"", "  title: {en: \"Cam\", ru: \"Кулачок\"}").replacen(
        "  sense: ccw\n",
        "  sense: ccw\n  assumptions:\n    - {uz: \"Qonun\", ru: \"Закон\"}\n",
        1,
    );
    let mut p = load(&text);
    assert_eq!(p.info.title(), "Cam");
    p.info.language = Language::Ru;
    assert_eq!(p.info.title(), "Кулачок");
    p.info.language = Language::Uz;
    assert_eq!(p.info.title(), "Cam", "Uzbek not written: the first one written");
    assert_eq!(cam(&p).assumptions[0].get(Language::Ru), "Закон");
    assert_eq!(cam(&p).assumptions[0].get(Language::En), "Qonun");
    let bad = with("  title: \"Cam\"", "  title: {de: \"Nocke\"}");
    let e = refusal(&bad);
    assert!(e.contains("line 2") && e.contains("`de`"), "{e}");
}
