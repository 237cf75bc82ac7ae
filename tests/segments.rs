//! The measured segments: each stands for its answer (length × scale = the table's value),
//! and each is drawn on the sheet at its length (a vector of that length in its plan's group).
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture, fixture_names};
use std::collections::BTreeMap;
use tmm_sheets::pipeline::{self, Built};

fn answers(b: &Built) -> BTreeMap<String, f64> {
    let prefix = format!("sheet{}", b.output.number);
    b.output.tables.iter().flat_map(|t| t.answers(&prefix)).map(|a| (a.id, a.value)).collect()
}

/// The lengths of the straight `vector`, `thin` and `dashed` paths in one SVG group.
fn drawn_lengths(svg: &str, id: &str) -> Vec<f64> {
    let open = format!("<g id=\"{id}\">");
    let start = svg.find(&open).unwrap_or_else(|| panic!("no group {id}"));
    let body = &svg[start..start + svg[start..].find("</g>").unwrap()];
    body.lines()
        .filter(|l| {
            l.starts_with("<path class=\"vector\"")
                || l.starts_with("<path class=\"thin\"")
                || l.starts_with("<path class=\"dashed\"")
        })
        .filter_map(|l| {
            let d = l.split("d=\"").nth(1)?.split('"').next()?;
            let nums: Vec<f64> = d.trim_start_matches('M').split(['L', ' ']).filter_map(|x| x.parse().ok()).collect();
            (nums.len() == 4).then(|| ((nums[2] - nums[0]).powi(2) + (nums[3] - nums[1]).powi(2)).sqrt())
        })
        .collect()
}

#[test]
fn each_segment_is_its_answer_at_its_scale() {
    let mut tied = 0;
    for name in fixture_names() {
        for b in pipeline::build(&fixture(&name), &[]).unwrap() {
            let answers = answers(&b);
            for s in &b.output.segments {
                assert!(s.length_mm.is_finite() && s.scale > 0.0, "{name}: {}", s.id);
                let value = s.length_mm * s.scale;
                assert!((value - s.value).abs() <= 1e-12 * s.value.max(1.0), "{name}: {}", s.id);
                if let Some(q) = &s.quantity {
                    let exact = answers[q];
                    assert!(
                        (value - exact).abs() <= 1e-9 * exact.max(1e-3),
                        "{name}: {} is {value}, {q} is {exact}",
                        s.id
                    );
                    tied += 1;
                }
            }
        }
    }
    assert!(tied > 500, "only {tied} segments tied to answers");
}

#[test]
fn the_worked_examples_segments_are_named_as_the_course_writes_them() {
    let b = &pipeline::build(&fixture("worked-example"), &[1]).unwrap()[0];
    let by_id: BTreeMap<&str, _> = b.output.segments.iter().map(|s| (s.id.as_str(), s)).collect();
    let pb = by_id["plan.v.3.pb"];
    assert_eq!((pb.name.as_str(), pb.quantity.as_deref()), ("pb", Some("sheet1.velocities.v_B.3")));
    assert_eq!(by_id["plan.v.3.ab"].quantity.as_deref(), Some("sheet1.velocities.v_BA.3"));
    assert_eq!(by_id["plan.a.5.pib"].name, "πb");
    assert_eq!(by_id["plan.v.3.ps2"].quantity.as_deref(), Some("sheet1.velocities.v_S2.3"));
    assert_eq!(by_id["plan.a.5.pis4"].name, "πs4");
    assert_eq!(by_id["plan.a.5.an_BA"].quantity.as_deref(), Some("sheet1.accelerations.an_BA.5"));
    // C is a point of the frame: the normal component of a_BC starts at the pole.
    assert_eq!(by_id["plan.a.5.pin_BC"].name, "πn_BC");
    assert_eq!(by_id["plan.a.5.n_BCb"].quantity.as_deref(), Some("sheet1.accelerations.at_BC.5"));
    // v_B at position 3 from the closed form the guide's crank-rocker obeys: pb = v_B / μ_v.
    assert!((pb.length_mm - pb.value / pb.scale).abs() < 1e-12);
}

#[test]
fn every_segment_of_a_plan_is_drawn_at_its_length() {
    for name in ["worked-example", "kulisa", "crank-slider-axial", "jaw-crusher"] {
        let Ok(built) = pipeline::build(&fixture(name), &[1]) else { continue };
        let b = &built[0];
        let svg = &b.svg;
        // A centre of mass is a point on its plan (ps2), not a drawn vector.
        let centre = |n: &str| n.trim_start_matches(['p', 'π']).starts_with('s');
        for s in b.output.segments.iter().filter(|s| s.length_mm > 5.0 && !centre(&s.name)) {
            let plan = s.id.rsplit_once('.').unwrap().0;
            let lengths = drawn_lengths(svg, &format!("sheet1.{plan}"));
            // Drawn as a line and its arrowhead: the line stops short of the tip by the head.
            let drawn = lengths.iter().any(|l| (s.length_mm - l) > -0.002 && (s.length_mm - l) < 3.5);
            assert!(drawn, "{name}: {} ({:.3} mm) is not drawn in {plan}: {lengths:?}", s.id, s.length_mm);
        }
    }
}
