//! A resistance on a rocker's point: the jaw crusher's crushing force at the jaw's point K
//! (the guide's task 5), square to the jaw, against its motion on the working stroke, in
//! proportion to K's travel. Checked against the positions the build reports, with the
//! geometry written here.

mod common;

use serde_json::Value;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline;

fn xy(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn norm(a: [f64; 2]) -> f64 {
    dot(a, a).sqrt()
}

/// The angle from `a` to `b`, counter-clockwise positive.
fn angle(a: [f64; 2], b: [f64; 2]) -> f64 {
    tmm_sheets::num::math::atan2(a[0] * b[1] - a[1] * b[0], dot(a, b))
}

/// Task 5's variants with the assumed 150 kN at K, rising from 0 over the working stroke
/// (the jaw turning clockwise, position 0 the stroke's start).
#[test]
fn the_crushing_force_acts_square_to_the_jaw_against_its_motion_in_proportion_to_ks_travel() {
    for variant in [2, 7, 21, 29] {
        let out = common::catalogue_sheet1("5", variant, Language::Ru);
        let r = &out.results;
        check_crushing_force(r, Sense::Cw, &format!("variant {variant}"));
        // K's travel from position 0 (the stroke's start) over the whole swing (position
        // 4′, the other extreme), measured about O3.
        let positions = r["positions"].as_array().unwrap();
        let point = |pos: &Value, name: &str| xy(&pos["points"][name]["p"]);
        let o3 = point(&positions[0], "O3");
        let k0 = point(&positions[0], "K");
        let other = positions.iter().skip(1).find(|p| p["extreme"] == true).expect("the other extreme");
        let k_end = point(other, "K");
        let s = angle(sub(k0, o3), sub(point(&r["assigned"], "K"), o3)) / angle(sub(k0, o3), sub(k_end, o3));
        let printed = r["forces"]["loads"][0]["stroke_fraction"].as_f64().unwrap();
        assert!((s - printed).abs() <= 1e-9, "variant {variant}: S/H {printed} against {s}");
    }
}

/// The jaw crusher fixture, its jaw on the other side of the rod: the working stroke is
/// counter-clockwise there, and the force at φ₁ (on that stroke) is checked the same way.
#[test]
fn the_fixtures_crushing_force_works_counter_clockwise() {
    let p = common::fixture("jaw-crusher");
    let out = pipeline::build(&p, &[1]).unwrap().remove(0).output;
    let s = out.results["forces"]["loads"][0]["stroke_fraction"].as_f64().unwrap();
    assert!(s > 0.05, "the analysed position is on the working stroke: S/H = {s}");
    check_crushing_force(&out.results, Sense::Ccw, "the fixture");
}

/// The jaw's working sense of rotation.
#[derive(Clone, Copy, PartialEq)]
enum Sense {
    Cw,
    Ccw,
}

/// The crushing force at K in the sheet's results `r`: square to O3K, against K's motion,
/// the jaw turning the working way at φ₁, that way away from the rod BC, 150 kN times the
/// printed S/H, and P_m the same three ways.
fn check_crushing_force(r: &Value, sense: Sense, case: &str) {
    let point = |pos: &Value, name: &str| xy(&pos["points"][name]["p"]);
    let assigned = &r["assigned"];
    let o3 = point(assigned, "O3");
    let k = point(assigned, "K");
    let v_k = xy(&assigned["points"]["K"]["v"]);
    let load = &r["forces"]["loads"][0];
    let f = xy(&load["force"]);
    let radius = sub(k, o3);
    // Square to the jaw's radius O3K.
    assert!(dot(f, radius).abs() <= 1e-9 * norm(f) * norm(radius), "{case}: F·O3K = {}", dot(f, radius));
    // Against the motion: the working stroke is the jaw turning away from BC.
    assert!(dot(f, v_k) < 0.0, "{case}: F·v_K = {}", dot(f, v_k));
    let ccw = radius[0] * v_k[1] - radius[1] * v_k[0] > 0.0;
    assert_eq!(ccw, sense == Sense::Ccw, "{case}: the jaw turns the other way at φ1");
    let (c, b) = (point(assigned, "C"), point(assigned, "B"));
    let working_tangent = match sense {
        Sense::Cw => [sub(c, o3)[1], -sub(c, o3)[0]],
        Sense::Ccw => [-sub(c, o3)[1], sub(c, o3)[0]],
    };
    assert!(dot(working_tangent, sub(c, b)) > 0.0, "{case}: the working stroke runs toward BC");
    let s = load["stroke_fraction"].as_f64().unwrap();
    assert!((norm(f) - 150e3 * s).abs() <= 1e-6 * 150e3, "{case}: |F| = {} against {}", norm(f), 150e3 * s);
    // The balancing force three ways: the groups, Zhukovsky's lever, the power balance.
    let forces = &r["forces"];
    let p_m = forces["balancing_force"].as_f64().unwrap();
    for other in ["balancing_force_lever", "balancing_force_power"] {
        let x = forces[other].as_f64().unwrap();
        assert!((x - p_m).abs() <= 1e-6 * p_m.abs(), "{case}: {other} {x} against {p_m}");
    }
    // The crushing force dominates: P_m well over what weights and inertia alone need.
    assert!(p_m.abs() > 10e3 * s, "{case}: P_m = {p_m}");
}

/// A rocker's sense of rotation on a slider, a slider's direction on a rocker's point, and
/// a rocker's pivot itself are refused, naming the field and its line.
#[test]
fn a_working_stroke_that_does_not_fit_its_point_is_refused() {
    let text = common::catalogue_text("5", 7, Language::En);
    let line = text.lines().position(|l| l.contains("resistance: {point: K")).unwrap() + 1;
    for (from, to, says) in [
        ("working: cw", "working: forward", "not the slider point"),
        ("point: K, working: cw", "point: O3, working: cw", "not a point of a rocker"),
        ("point: K, working: cw", "point: A, working: cw", "not a point of a rocker"),
    ] {
        let bad = text.replace(from, to);
        let e = pipeline::load_for(&bad, &[1]).map(|_| ()).unwrap_err().to_string();
        assert!(e.contains("forces.loads[0].resistance.point"), "{to}: {e}");
        assert!(e.contains(says), "{to}: {e}");
        assert!(e.contains(&format!("line {line}")), "{to}: {e}");
    }
}
