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

/// An SVG group's body, up to its first closing tag (the parts hold no nested groups).
fn group<'a>(svg: &'a str, id: &str) -> &'a str {
    let open = format!("<g id=\"{id}\">");
    let start = svg.find(&open).unwrap_or_else(|| panic!("no group {id}"));
    &svg[start..start + svg[start..].find("</g>").unwrap()]
}

/// The SVG group `id` and its parts drawn apart (a force polygon's enlargements of its
/// short sides, `id.T`), one after another.
fn group_and_parts(svg: &str, id: &str) -> String {
    let mut out = group(svg, id).to_string();
    let part = format!("<g id=\"{id}.");
    for (start, _) in svg.match_indices(&part) {
        out.push_str(&svg[start..start + svg[start..].find("</g>").unwrap()]);
    }
    out
}

/// The lengths of the straight `vector`, `thin`, `dashed` and `contour` paths in one SVG group
/// and its parts.
fn drawn_lengths(svg: &str, id: &str) -> Vec<f64> {
    group_and_parts(svg, id)
        .lines()
        .filter(|l| {
            ["vector", "thin", "dashed", "contour"].iter().any(|c| l.starts_with(&format!("<path class=\"{c}\"")))
        })
        .filter_map(|l| {
            let d = l.split("d=\"").nth(1)?.split('"').next()?;
            let nums: Vec<f64> = d.trim_start_matches('M').split(['L', ' ']).filter_map(|x| x.parse().ok()).collect();
            (nums.len() == 4).then(|| ((nums[2] - nums[0]).powi(2) + (nums[3] - nums[1]).powi(2)).sqrt())
        })
        .collect()
}

/// The radii of the circles and circular arcs in one SVG group.
fn drawn_radii(svg: &str, id: &str) -> Vec<f64> {
    let mut out = Vec::new();
    for l in group(svg, id).lines() {
        if l.starts_with("<circle") {
            out.extend(l.split(" r=\"").nth(1).and_then(|r| r.split('"').next()?.parse::<f64>().ok()));
        } else if let Some(d) = l.split("d=\"").nth(1) {
            let d = d.split('"').next().unwrap();
            out.extend(d.split('A').skip(1).filter_map(|a| a.split(' ').next()?.parse::<f64>().ok()));
        }
    }
    out
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
                    // A segment is a magnitude; the note may sign it (P_m against v_A).
                    let exact = answers[q].abs();
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
    // The links as the project file gives them (m): OA 0.12, AB 0.46, BC 0.39, BD 1.5; the
    // rigid pairs only, centres of mass left out.
    let links: Vec<(&str, f64)> = b
        .output
        .segments
        .iter()
        .filter(|s| s.id.starts_with("mechanism."))
        .map(|s| (s.name.as_str(), s.value))
        .collect();
    assert_eq!(links.len(), 4, "{links:?}");
    for (name, metres) in [("l_OA", 0.12), ("l_AB", 0.46), ("l_CB", 0.39), ("l_BD", 1.5)] {
        let mm = links.iter().find(|l| l.0 == name).unwrap_or_else(|| panic!("{name}: {links:?}")).1;
        assert!((mm - metres * 1e3).abs() < 1e-9, "{name} = {mm} mm");
    }
    // v_B at position 3 from the closed form the guide's crank-rocker obeys: pb = v_B / μ_v.
    assert!((pb.length_mm - pb.value / pb.scale).abs() < 1e-12);
}

#[test]
fn every_drawn_segment_is_drawn_at_its_length() {
    let mut seen = 0;
    for name in ["worked-example", "kulisa", "crank-slider-axial", "jaw-crusher", "gears/undercut"] {
        let built = pipeline::build(&fixture(name), &[]).unwrap();
        for b in &built {
            let sheet = format!("sheet{}", b.output.number);
            for s in b.output.segments.iter().filter(|s| s.length_mm > 5.0) {
                let (part, last) = s.id.rsplit_once('.').unwrap();
                // A circle: the compass is set to its radius (3 decimals in the SVG).
                if b.output.number == 2 && (s.name.starts_with("r_") || s.name == "a_H") {
                    let radii = drawn_radii(&b.svg, &format!("{sheet}.{part}"));
                    assert!(
                        radii.iter().any(|r| (r - s.length_mm).abs() < 0.0015),
                        "{name}: {} ({:.3} mm) not among {radii:?}",
                        s.id,
                        s.length_mm
                    );
                    seen += 1;
                    continue;
                }
                // Straight: the plans' and polygons' vectors, the load's ordinate, g_α (B1B2).
                // Not drawn as one line: a centre of mass's distance from the pole (a point on
                // its plan), the lever's arms, S/H, and the mesh's other lengths (arcs, the
                // extended lines of centres and of action).
                let centre = last.trim_start_matches(['p']).trim_start_matches("i").starts_with('s')
                    && part.starts_with("plan.");
                let straight = (part.starts_with("plan.") && !centre)
                    || part.starts_with("forces.group")
                    || part == "forces.crank"
                    || (part.starts_with("forces.load") && !last.starts_with("S_H"))
                    || s.name == "g_alpha"
                    || s.id == "nomogram.r_min";
                if !straight {
                    continue;
                }
                let lengths = drawn_lengths(&b.svg, &format!("{sheet}.{part}"));
                // Drawn as a line and its arrowhead: the line stops short of the tip by the head.
                let drawn = lengths.iter().any(|l| (s.length_mm - l) > -0.002 && (s.length_mm - l) < 3.5);
                assert!(drawn, "{name}: {} ({:.3} mm) is not drawn in {part}: {lengths:?}", s.id, s.length_mm);
                seen += 1;
            }
        }
    }
    assert!(seen > 300, "only {seen} segments found drawn");
}

#[test]
fn every_segment_is_drawn_at_a_scale_its_sheet_states() {
    let built = pipeline::build(&fixture("worked-example"), &[]).unwrap();
    for b in &built {
        let r = &b.output.results;
        let f = |path: &[&str]| path.iter().fold(r, |v, k| &v[*k]).as_f64().unwrap_or_else(|| panic!("{path:?}"));
        // The sheet's scales as results.json states them, in the units the segments use.
        let stated: Vec<f64> = match b.output.number {
            1 => {
                let plans = ["velocity_plans", "acceleration_plans"]
                    .iter()
                    .flat_map(|k| r["scales"][*k].as_array().unwrap().iter().map(|p| p["mu"].as_f64().unwrap()));
                let scales = &r["forces"]["scales"];
                let forces = ["mu_p", "mu_p_enlarged"]
                    .into_iter()
                    .flat_map(|k| scales[k].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()));
                let mechanism = 1e3 * f(&["scales", "mu_l"]);
                plans.chain(forces).chain([f(&["forces", "scales", "mu_lever"]), mechanism]).collect()
            }
            2 => vec![1e3 * f(&["drawing", "mu_l"]), 1e3 * f(&["drawing", "planetary_mu_l"])],
            _ => {
                // The worked example's cam is a rocker: its swing in degrees, its analogs plain.
                let sc = |k: &str| f(&["scales", k]);
                vec![
                    sc("mu_s").to_degrees(),
                    sc("mu_ds"),
                    sc("mu_dds"),
                    1e3 * f(&["nomogram_mu"]),
                    1e3 * f(&["profile_mu_l"]),
                ]
            }
        };
        for s in &b.output.segments {
            // The load diagram's own μ_P and S/H's axis are stated on the diagram only.
            if s.id.starts_with("forces.load") {
                continue;
            }
            assert!(
                stated.iter().any(|m| (m - s.scale).abs() <= 1e-12 * m),
                "sheet {}: {} at {} is at none of {stated:?}",
                b.output.number,
                s.id,
                s.scale
            );
        }
    }
}
