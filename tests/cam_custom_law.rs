//! Laws a project file defines by their acceleration analog's corners: the corners of the
//! guide's piecewise-linear laws reproduce the closed forms; an asymmetric law checked
//! against values integrated by hand here; every bad corner list refused with its reason;
//! the project file's `cam.laws` table, its errors at their lines, and the sheet's text.
#![allow(clippy::disallowed_methods)]

mod common;

use common::root;
use tmm_sheets::assert_near;
use tmm_sheets::cams::follower::Follower;
use tmm_sheets::cams::laws::{Custom, Law, LawError, Program, Standard};
use tmm_sheets::cams::radius::{Allowed, Placement};
use tmm_sheets::cams::{CamSpec, Roller, Sense, design};
use tmm_sheets::num::Near;
use tmm_sheets::project::{self, Project};

fn custom(corners: &[(f64, f64)]) -> Custom {
    Custom::new("test", None, corners).unwrap_or_else(|e| panic!("{corners:?}: {e}"))
}

/// The guide's laws whose s″ is straight between corners, written as corners here (any
/// scale: the law is normalised to s(1) = 1).
fn piecewise_linear_standards() -> [(Standard, Vec<(f64, f64)>); 4] {
    [
        (Standard::UniformAcceleration, vec![(0.0, 1.0), (0.5, 1.0), (0.5, -1.0), (1.0, -1.0)]),
        (Standard::LinearlyDecreasing, vec![(0.0, 1.0), (1.0, -1.0)]),
        (Standard::Triangular, vec![(0.0, 0.0), (0.25, 1.0), (0.75, -1.0), (1.0, 0.0)]),
        (Standard::Trapezoid, vec![(0.0, 0.0), (0.125, 1.0), (0.375, 1.0), (0.625, -1.0), (0.875, -1.0), (1.0, 0.0)]),
    ]
}

#[test]
fn corners_of_the_guides_straight_laws_reproduce_their_closed_forms() {
    for (law, corners) in piecewise_linear_standards() {
        let c = custom(&corners);
        for k in 0..=400 {
            let x = k as f64 / 400.0;
            let (a, b) = (law.eval(x), c.eval(x));
            assert!((a.s - b.s).abs() < 1e-13, "{law:?} s at {x}: {} vs {}", a.s, b.s);
            assert!((a.ds - b.ds).abs() < 1e-12, "{law:?} s′ at {x}: {} vs {}", a.ds, b.ds);
            // At a jump the two sides differ; compare s″ just off the corners.
            let y = x + 1e-9;
            if y < 1.0 {
                let (a, b) = (law.eval(y), c.eval(y));
                assert!((a.dds - b.dds).abs() < 1e-6, "{law:?} s″ at {y}: {} vs {}", a.dds, b.dds);
            }
        }
        let (p, q) = (law.peaks(), c.peaks());
        assert!((p.0 - q.0).abs() < 1e-12 && (p.1 - q.1).abs() < 1e-12, "{law:?}: {p:?} vs {q:?}");
    }
}

/// s″ = 2 on [0, ¼], −⅔ on [¼, 1]: areas ½ and ½ balance. By hand: s′(¼) = ½, s(¼) = 1/16;
/// then s′ = ½ − ⅔t, s = 1/16 + t/2 − t²/3 with t = x − ¼, so s(1) = 1/16 + 3/8 − 3/16 = ¼.
/// Normalised (×4): s(¼) = ¼, s′ peak 2, s″ peak 8, s(½) = 4·(1/16 + 1/8 − 1/48) = 2/3.
#[test]
fn an_asymmetric_law_integrates_as_by_hand() {
    let c = custom(&[(0.0, 2.0), (0.25, 2.0), (0.25, -2.0 / 3.0), (1.0, -2.0 / 3.0)]);
    let tol = Near::abs(1e-14);
    assert_near!(c.eval(0.25).s, 0.25, tol);
    assert_near!(c.eval(0.5).s, 2.0 / 3.0, tol);
    assert_near!(c.eval(0.25).ds, 2.0, tol);
    assert_near!(c.eval(0.1).dds, 8.0, tol);
    assert_near!(c.eval(0.6).dds, -8.0 / 3.0, tol);
    assert_eq!(c.peaks(), (2.0, 8.0));
    let (a, b) = (c.eval(1.0), c.eval(0.0));
    assert_eq!((a.s, a.ds, b.s, b.ds), (1.0, 0.0, 0.0, 0.0));
    // The normalised corners, as the sheet lists them.
    let corners: Vec<_> = c.corners().collect();
    assert_eq!(corners.len(), 4);
    assert_near!(corners[0].1, 8.0, tol);
    assert_near!(corners[3].1, -8.0 / 3.0, tol);
}

#[test]
fn every_bad_corner_list_is_refused_with_its_reason() {
    use LawError as E;
    type Case<'a> = (&'a [(f64, f64)], fn(&LawError) -> bool);
    let bad: [Case; 9] = [
        (&[(0.0, 1.0)], |e| matches!(e, E::TooFewCorners(1))),
        (&[(0.1, 1.0), (1.0, -1.0)], |e| matches!(e, E::Ends { .. })),
        (&[(0.0, 1.0), (0.9, -1.0)], |e| matches!(e, E::Ends { .. })),
        (&[(0.0, 1.0), (0.6, 0.0), (0.4, 0.0), (1.0, -1.0)], |e| matches!(e, E::Decreasing { index: 2, .. })),
        (&[(0.0, 1.0), (0.5, 1.0), (0.5, 0.0), (0.5, -1.0), (1.0, -1.0)], |e| {
            matches!(e, E::TripleCorner { index: 3, .. })
        }),
        (&[(0.0, 1.0), (1.0, 1.0)], |e| matches!(e, E::VelocityDoesNotClose { .. })),
        (&[(0.0, -1.0), (1.0, 1.0)], |e| matches!(e, E::NoRise(_))),
        // Up, down, up again: s′ reaches −0.1 at x = 0.9 although s(1) = 0.15 > 0.
        (&[(0.0, 1.0), (0.4, 1.0), (0.4, -1.0), (0.9, -1.0), (0.9, 1.0), (1.0, 1.0)], |e| {
            matches!(e, E::MovesBack { .. })
        }),
        (&[(0.0, 1.0), (0.5, f64::NAN), (1.0, -1.0)], |e| matches!(e, E::NotFinite { index: 1, .. })),
    ];
    for (corners, expect) in bad {
        match Custom::new("bad", None, corners) {
            Ok(_) => panic!("{corners:?} must be refused"),
            Err(e) => assert!(expect(&e), "{corners:?}: {e:?}"),
        }
    }
}

#[test]
fn a_custom_triangle_designs_the_same_cam_as_the_built_in_one() {
    let [_, _, (law, corners), _] = piecewise_linear_standards();
    let design = |l: Law| {
        let program =
            Program::new(70f64.to_radians(), 10f64.to_radians(), 70f64.to_radians(), (l.clone(), l), 0.04).unwrap();
        let a = 30f64.to_radians();
        design(&CamSpec {
            follower: Follower::Translating,
            program,
            allowed: Allowed { rise: a, ret: a },
            placement: Placement::Free,
            roller: Roller::Knife,
            sense: Sense::Cw,
        })
        .unwrap()
    };
    let (a, b) = (design(law.into()), design(custom(&corners).into()));
    assert!(
        (a.centre.r_min - b.centre.r_min).abs() < 1e-9 * a.centre.r_min,
        "{} vs {}",
        a.centre.r_min,
        b.centre.r_min
    );
}

fn load(text: &str) -> Project {
    project::load(text).unwrap_or_else(|e| panic!("{e}"))
}

const BASE: &str = "project:
  title: \"Cam\"
  designation: \"MMN KL 09.00.00\"
  language: en

cam:
  follower: {translating: {stroke: 0.03}}
  phases_deg: {rise: 90, far_dwell: 10, return: 90}
  law: {rise: 1, return: skewed}
  laws:
    1:
      acceleration: [[0, 2], [0.5, 2], [0.5, -2], [1, -2]]
    skewed:
      name: {en: \"skewed\", ru: \"скошенный\"}
      acceleration: [[0, 2], [0.25, 2], [0.25, -0.6666666666666666], [1, -0.6666666666666666]]
  pressure_angle_deg: 40
";

#[test]
fn the_project_table_redefines_a_numbered_law_and_adds_a_named_one() {
    let p = load(BASE);
    let c = p.cam.as_ref().unwrap();
    let (rise, ret) = &c.laws;
    assert_eq!(rise.key(), "uniform-acceleration");
    assert_eq!(rise.guide_number(), Some(1));
    assert!(matches!(rise, Law::Custom(_)));
    assert_eq!(ret.key(), "skewed");
    assert_eq!(ret.guide_number(), None);
    assert!((ret.peaks().1 - 8.0).abs() < 1e-12);
    let name = &c.law_names.iter().find(|(k, _)| k == "skewed").unwrap().1;
    assert_eq!(name.get(tmm_sheets::drawing::labels::Language::Ru), "скошенный");
    // Uzbek is not written: the first written one stands in.
    assert_eq!(name.get(tmm_sheets::drawing::labels::Language::Uz), "skewed");
}

/// Replaces `from` by `to` in BASE, expects a refusal naming `field` at the line of `at`.
fn refused(from: &str, to: &str, at: &str, field: &str, says: &str) {
    assert!(BASE.contains(from), "{from:?}");
    let text = BASE.replacen(from, to, 1);
    let e = match project::load(&text) {
        Ok(_) => panic!("must be refused:\n{text}"),
        Err(e) => e.to_string(),
    };
    let line = text.lines().position(|l| l.contains(at)).unwrap() + 1;
    assert!(e.contains(&format!("line {line},")), "{to}: expected line {line}: {e}");
    assert!(e.contains(&format!("{field}:")), "{to}: expected {field}: {e}");
    assert!(e.contains(says), "{to}: expected {says:?}: {e}");
}

#[test]
fn bad_law_tables_are_refused_at_their_lines() {
    let acc = "[[0, 2], [0.5, 2], [0.5, -2], [1, -2]]";
    refused(acc, "[[0, 2], [0.5, 2], [1, -2]]", "[[0, 2], [0.5, 2], [1, -2]]", "cam.laws.1.acceleration", "areas");
    let dec = "[[0, 2], [0.5, 2], [0.4, -2], [1, -2]]";
    refused(acc, dec, dec, "cam.laws.1.acceleration[2]", "must not decrease");
    refused("    skewed:\n", "    7:\n", "    7:", "cam.laws.7", "1–6");
    refused("    skewed:\n", "    two words:\n", "    two words:", "cam.laws.two words", "a word");
    refused(
        "    1:\n",
        "    uniform-acceleration:\n      acceleration: [[0, 1], [1, -1]]\n    1:\n",
        "    1:",
        "cam.laws.1",
        "defined twice",
    );
    refused("return: skewed}", "return: lopsided}", "return: lopsided}", "cam.law.return", "skewed;");
}

#[test]
fn the_custom_law_fixture_names_its_laws_on_the_sheet_in_every_language() {
    let text = std::fs::read_to_string(root().join("fixtures/cams/custom-laws.yaml")).unwrap();
    use tmm_sheets::drawing::labels::Language;
    for (lang, rise, ret) in [
        (Language::Uz, "uchburchakli, oʻqituvchi chizmasi boʻyicha (5)", "ikki toʻgʻri toʻrtburchak"),
        (Language::Ru, "треугольный, по рисунку преподавателя (5)", "два прямоугольника"),
        (Language::En, "triangular, as the teacher's figure (5)", "two rectangles"),
    ] {
        let mut p = tmm_sheets::pipeline::load(&text).unwrap();
        p.info.language = lang;
        let b = tmm_sheets::pipeline::build(&p, &[3]).unwrap().remove(0);
        let texts: Vec<String> = b.output.scene.texts().map(|t| t.text.clone()).collect();
        let all = texts.join("\n");
        for name in [rise, ret] {
            assert!(all.contains(name), "{lang:?}: the sheet does not name the law {name:?}");
        }
    }
}

/// A corner between the eight divisions is what the chord integration cuts off: warned about
/// at the corner list's line, with the error; corners at the divisions are not.
#[test]
fn a_corner_between_the_divisions_is_warned_about() {
    let on_grid = load(BASE);
    assert!(on_grid.warnings.iter().all(|w| !w.field.starts_with("cam.laws")), "{:?}", on_grid.warnings);
    let off = "[[0, 0], [0.2, 3], [0.4, 0], [0.7, -2], [1, 0]]";
    let text = BASE.replacen("[[0, 2], [0.25, 2], [0.25, -0.6666666666666666], [1, -0.6666666666666666]]", off, 1);
    let p = load(&text);
    let w = p.warnings.iter().find(|w| w.field == "cam.laws.skewed.acceleration").expect("a warning");
    assert_eq!(w.line as usize, text.lines().position(|l| l.contains(off)).unwrap() + 1);
    assert!(w.message.contains("x = 0.2") && w.message.contains("% of the lift"), "{}", w.message);
}
