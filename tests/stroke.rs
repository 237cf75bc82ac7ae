//! The slider's stroke H on sheet 1, against the worked example's stroke computed here from
//! the project file's numbers alone: O at the origin, OA = 0.12 m, C at (0.33, 0.06),
//! AB = 0.46, BC = 0.39, BD = 1.5 with D on the line y = 0.06 ahead of B.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::fixture;
use tmm_sheets::pipeline;

/// D's x over a full crank turn (10⁵ steps), with B on either side of AC; H is its range.
fn strokes() -> [f64; 2] {
    let (c, ab, bc, bd, y) = ((0.33f64, 0.06f64), 0.46f64, 0.39f64, 1.5f64, 0.06f64);
    let mut out = [0.0; 2];
    for (side, h) in [1.0f64, -1.0].into_iter().zip(out.iter_mut()) {
        let (mut lo, mut hi) = (f64::MAX, f64::MIN);
        for k in 0..100_000 {
            let phi = k as f64 / 100_000.0 * std::f64::consts::TAU;
            let a = (0.12 * phi.cos(), 0.12 * phi.sin());
            // B: the circles about A (AB) and about C (BC) meet.
            let (dx, dy) = (c.0 - a.0, c.1 - a.1);
            let d = dx.hypot(dy);
            let along = (ab * ab - bc * bc + d * d) / (2.0 * d);
            let across = (ab * ab - along * along).sqrt();
            let b = (a.0 + along * dx / d - side * across * dy / d, a.1 + along * dy / d + side * across * dx / d);
            let x = b.0 + (bd * bd - (y - b.1).powi(2)).sqrt();
            lo = lo.min(x);
            hi = hi.max(x);
        }
        *h = hi - lo;
    }
    out
}

#[test]
fn the_worked_examples_stroke_is_dimensioned_as_computed_from_its_lengths() {
    let b = &pipeline::build(&fixture("worked-example"), &[1]).unwrap()[0];
    let texts: Vec<String> = b.output.scene.texts().map(|t| t.plain()).collect();
    let h = texts.iter().find_map(|t| t.strip_prefix("H = ")).unwrap_or_else(|| panic!("no H: {texts:?}"));
    let mm: f64 = h.trim_end_matches(" mm").replace(',', ".").parse().unwrap_or_else(|_| panic!("{h}"));
    let [one, other] = strokes().map(|s| s * 1e3);
    // Four significant digits on the sheet: 0.05 mm.
    assert!((mm - one).abs() < 0.06 || (mm - other).abs() < 0.06, "H = {mm} mm; computed {one:.3} or {other:.3} mm");
    // And the slider's positions are numbered along the guide: 0 … 7 twice (crank and slider).
    for n in ["0", "1", "2", "3", "5", "6", "7"] {
        assert!(texts.iter().filter(|t| t.as_str() == n).count() >= 2, "position {n} numbered once only");
    }
}

/// Task 6 variant 2: the stroke's dimension line runs between the guide and the rods' lines,
/// and its middle has no room for the value on either side. The value is written along the
/// line further toward an end, where it has room (it hung 76.4 mm off on a leader), in every
/// language: upright text along a vertical line, no leader over 20 mm on the sheet.
#[test]
fn a_strokes_value_slides_along_its_line_to_where_it_has_room() {
    for lang in tmm_sheets::drawing::labels::Language::ALL {
        let out = common::catalogue_sheet1("6", 2, lang);
        let mech = out.scene.groups.iter().find(|g| g.id == "mechanism").unwrap();
        let h = mech.texts().find(|t| t.text == "H").unwrap_or_else(|| panic!("{lang:?}: no H"));
        assert_eq!(h.rotate.abs(), 90.0, "{lang:?}: H written along its vertical line");
        let longest = out.results["layout"]["longest_leader_mm"].as_f64().unwrap();
        assert!(longest <= 20.0, "{lang:?}: a leader of {longest} mm");
    }
}
