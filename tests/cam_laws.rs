//! The cam's laws of motion against what each must be, computed here: boundary values,
//! continuity, derivatives by finite differences, integrals by Simpson's rule, peak
//! coefficients from the literature, and the whole-turn program.
#![allow(clippy::disallowed_methods)]

use proptest::prelude::*;
use std::f64::consts::PI;
use tmm_sheets::cams::laws::{Program, ProgramError, Standard as Law};

/// Breakpoints where a law's pieces meet (s″ may jump there).
const BREAKS: [f64; 7] = [0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875];

#[test]
fn every_law_rises_from_0_to_1_at_rest_velocity() {
    for law in Law::ALL {
        let (a, b) = (law.eval(0.0), law.eval(1.0));
        assert_eq!((a.s, b.s), (0.0, 1.0), "{law:?}");
        // Just inside the phase: s and s′ start from rest (every law here has s′(0) = 0).
        let e = 1e-7;
        let (a, b) = (law.eval(e), law.eval(1.0 - e));
        assert!(a.s.abs() < 1e-12 && (1.0 - b.s).abs() < 1e-12, "{law:?}");
        assert!(a.ds.abs() < 1e-5 && b.ds.abs() < 1e-5, "{law:?}: s′ = {} and {}", a.ds, b.ds);
        // Symmetric: s(1 − x) = 1 − s(x).
        for x in [0.1, 0.3, 0.45] {
            assert!((law.eval(1.0 - x).s - (1.0 - law.eval(x).s)).abs() < 1e-14, "{law:?}");
        }
    }
}

#[test]
fn s_and_its_first_derivative_are_continuous_at_every_breakpoint() {
    for law in Law::ALL {
        for b in BREAKS {
            let (l, r) = (law.eval(b - 1e-12), law.eval(b + 1e-12));
            assert!((l.s - r.s).abs() < 1e-10 && (l.ds - r.ds).abs() < 1e-9, "{law:?} at {b}: {l:?} vs {r:?}");
        }
    }
}

#[test]
fn the_derivatives_are_the_derivatives() {
    let h = 1e-6;
    for law in Law::ALL {
        for i in 1..200 {
            let x = f64::from(i) / 200.0;
            if BREAKS.iter().any(|b| (x - b).abs() < 2e-3) {
                continue;
            }
            let (m, p, c) = (law.eval(x - h), law.eval(x + h), law.eval(x));
            let ds = (p.s - m.s) / (2.0 * h);
            let dds = (p.ds - m.ds) / (2.0 * h);
            assert!((ds - c.ds).abs() < 1e-6, "{law:?} at {x}: s′ {} vs {}", c.ds, ds);
            assert!((dds - c.dds).abs() < 1e-5, "{law:?} at {x}: s″ {} vs {}", c.dds, dds);
        }
    }
}

/// Simpson's rule on [0, 1] with n (even) intervals, piecewise across the breakpoints.
fn simpson(f: impl Fn(f64) -> f64) -> f64 {
    let edges = [0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0];
    let n = 400;
    edges
        .windows(2)
        .map(|w| {
            let h = (w[1] - w[0]) / n as f64;
            // Ends taken from inside the piece: s″ may jump at a breakpoint.
            let mut s = f(w[0] + 1e-13) + f(w[1] - 1e-13);
            for k in 1..n {
                s += f(w[0] + h * k as f64) * if k % 2 == 1 { 4.0 } else { 2.0 };
            }
            s * h / 3.0
        })
        .sum()
}

#[test]
fn the_acceleration_integrates_to_rest_and_the_velocity_to_the_lift() {
    for law in Law::ALL {
        let eval = |x: f64| law.eval(x.clamp(1e-15, 1.0 - 1e-15));
        let a = simpson(|x| eval(x).dds);
        let v = simpson(|x| eval(x).ds);
        assert!(a.abs() < 1e-9, "{law:?}: ∫s″ = {a}");
        assert!((v - 1.0).abs() < 1e-9, "{law:?}: ∫s′ = {v}");
    }
}

#[test]
fn peak_coefficients_are_the_known_ones() {
    let known = [
        (Law::UniformAcceleration, 2.0, 4.0),
        (Law::LinearlyDecreasing, 1.5, 6.0),
        (Law::Cosine, PI / 2.0, PI * PI / 2.0),
        (Law::Sine, 2.0, 2.0 * PI),
        (Law::Triangular, 2.0, 8.0),
        (Law::Trapezoid, 2.0, 16.0 / 3.0),
        (Law::Polynomial345, 1.875, 5.773_502_691_896_258),
        // The handbooks' four-digit values (Rothbart, Cam Design Handbook, table 2.2).
        (Law::ModifiedTrapezoid, 2.0, 4.8881),
        (Law::ModifiedSine, 1.7596, 5.5280),
    ];
    for (law, cv, ca) in known {
        let (v, a) = law.peaks();
        assert!((v - cv).abs() < 1e-4 && (a - ca).abs() < 1e-4, "{law:?}: {v}, {a}");
        // And the closed forms reach them (sampled finely).
        let (mut vm, mut am) = (0.0f64, 0.0f64);
        for i in 1..100_000 {
            let d = law.eval(f64::from(i) / 100_000.0);
            vm = vm.max(d.ds.abs());
            am = am.max(d.dds.abs());
        }
        assert!((vm - v).abs() < 1e-6 && (am - a).abs() < 1e-3, "{law:?}: sampled {vm}, {am}");
    }
}

#[test]
fn laws_are_found_by_key_and_by_the_guides_number() {
    for (i, law) in Law::ALL.iter().take(6).enumerate() {
        assert_eq!(Law::by_key(&(i + 1).to_string()), Some(*law));
        assert_eq!(law.guide_number(), Some(i as u8 + 1));
    }
    assert_eq!(Law::by_key("sine"), Some(Law::Sine));
    assert_eq!(Law::by_key("polynomial-345"), Some(Law::Polynomial345));
    assert_eq!(Law::Polynomial345.guide_number(), None);
    assert_eq!(Law::by_key("7"), None);
    assert_eq!(Law::by_key("spline"), None);
}

#[test]
fn every_law_name_a_sheet_prints_is_found_as_that_law() {
    // A student copies the law's name off a sheet into the project file: "sine, cycloidal
    // (4)" was refused. Every name of templates/labels/cam.yaml in every language, with its
    // number in brackets and without it; a number that is not the law's is refused.
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/templates/labels/cam.yaml")).unwrap();
    let mut names = 0;
    for line in text.lines().filter(|l| l.starts_with("law_") && l.contains("{uz:")) {
        let (id, rest) = line.split_once(':').unwrap();
        let Some(law) = Law::ALL.into_iter().find(|l| l.key().replace('-', "_") == id["law_".len()..]) else {
            continue;
        };
        for printed in rest.split('"').skip(1).step_by(2) {
            names += 1;
            assert_eq!(Law::by_key(printed), Some(law), "{printed:?}");
            let bare = printed.rsplit_once(" (").map_or(printed, |(name, _)| name);
            assert_eq!(Law::by_key(bare), Some(law), "{bare:?}");
            assert_eq!(Law::by_key(&format!("{bare} (9)")), None, "{bare:?} (9)");
        }
    }
    assert_eq!(names, 27, "9 laws × 3 languages");
    assert_eq!(Law::by_key("гармонический"), Some(Law::Cosine));
    assert_eq!(Law::by_key("cosine (4)"), None);
}

fn guide_program() -> Program {
    let r = f64::to_radians;
    Program::new(r(70.0), r(10.0), r(70.0), (Law::Cosine, Law::Cosine), r(25.0)).unwrap()
}

#[test]
fn the_program_is_continuous_over_the_turn_and_mirrors_the_return() {
    let p = guide_program();
    let r = f64::to_radians;
    for b in [0.0, 70.0, 80.0, 150.0, 360.0] {
        let (l, h) = (p.at(r(b) - 1e-9), p.at(r(b) + 1e-9));
        assert!((l.s - h.s).abs() < 1e-9 && (l.ds - h.ds).abs() < 1e-6, "at {b}°: {l:?} vs {h:?}");
    }
    assert!((p.at(r(75.0)).s - r(25.0)).abs() < 1e-15);
    // The return is the rise backwards: s(80° + t) = s(70° − t).
    for t in [5.0, 20.0, 35.0] {
        assert!((p.at(r(80.0 + t)).s - p.at(r(70.0 - t)).s).abs() < 1e-12);
        assert!((p.at(r(80.0 + t)).ds + p.at(r(70.0 - t)).ds).abs() < 1e-12);
    }
    assert_eq!(p.at(r(200.0)).s, 0.0);
    assert!((p.at(r(30.0) + 4.0 * PI).s - p.at(r(30.0)).s).abs() < 1e-12, "modulo a turn");
    // ds/dφ = h·s′/φ_p at the middle of the rise: h·(π/2)/φ_r for the cosine law.
    assert!((p.at(r(35.0)).ds - r(25.0) * PI / 2.0 / r(70.0)).abs() < 1e-12);
}

#[test]
fn bad_programs_are_errors() {
    let r = f64::to_radians;
    let laws = (Law::Sine, Law::Sine);
    assert!(matches!(Program::new(0.0, 0.0, r(70.0), laws, 0.01), Err(ProgramError::Phase { phase: "rise", .. })));
    assert!(matches!(Program::new(r(70.0), 0.0, -1.0, laws, 0.01), Err(ProgramError::Phase { phase: "return", .. })));
    assert!(matches!(Program::new(r(70.0), -0.1, r(70.0), laws, 0.01), Err(ProgramError::Dwell(_))));
    assert!(matches!(Program::new(r(200.0), r(10.0), r(160.0), laws, 0.01), Err(ProgramError::OverTurn(_))));
    assert!(Program::new(r(200.0), 0.0, r(160.0), laws, 0.01).is_ok(), "exactly a turn");
    for lift in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(Program::new(r(70.0), 0.0, r(70.0), laws, lift), Err(ProgramError::Lift(_))));
    }
    assert!(matches!(Program::new(f64::NAN, 0.0, r(70.0), laws, 0.01), Err(ProgramError::Phase { .. })));
}

proptest! {
    #[test]
    fn any_x_and_split_gives_finite_values_within_the_lift(x in -2.0f64..3.0, rise in 1.0f64..170.0, dwell in 0.0f64..20.0, ret in 1.0f64..170.0, phi in -1000.0f64..1000.0) {
        for law in Law::ALL {
            let d = law.eval(x);
            prop_assert!(d.s.is_finite() && d.ds.is_finite() && d.dds.is_finite());
            prop_assert!((-1e-15..=1.0 + 1e-15).contains(&d.s));
        }
        let r = f64::to_radians;
        let p = Program::new(r(rise), r(dwell), r(ret), (Law::Trapezoid, Law::Polynomial345), 0.04).unwrap();
        let d = p.at(phi);
        prop_assert!(d.s.is_finite() && d.ds.is_finite() && d.dds.is_finite());
        prop_assert!((-1e-15..=0.04 + 1e-15).contains(&d.s));
    }
}
