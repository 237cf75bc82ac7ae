//! The phase angles on sheet 3's profile, as the inversion lays them off from O: each working
//! phase's arc has its arrowheads on the lines of the phase's ends, the phase's angle apart
//! at O, and its value written φ = …° — against the phases the project file gives, for a
//! rocker (the worked example) and a translating follower with an offset, whose arcs end on
//! its axes, not on rays through O. And ω's arrow at O turned clear of r_min's radius.
#![allow(clippy::disallowed_methods)]

use kurbo::Point;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::path::Seg;
use tmm_sheets::drawing::scene::{Group, Item};
use tmm_sheets::pipeline;

mod common;

fn profile_group(text: &str, lang: Language) -> Group {
    let mut p = pipeline::load(text).unwrap();
    p.info.language = lang;
    let b = pipeline::build(&p, &[3]).unwrap().remove(0);
    b.output.scene.groups.into_iter().find(|g| g.id == "profile").expect("a profile group")
}

/// O on paper: the centre of the largest circle drawn (the base circle, or the offset circle
/// round it; the rollers are smaller).
fn centre(g: &Group) -> (Point, f64) {
    g.items
        .iter()
        .filter_map(|i| match i {
            Item::Circle { c, r, .. } => Some((*c, *r)),
            _ => None,
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap()
}

/// The arrowheads' tips well inside the base circle, as (distance from O, angle in degrees
/// counter-clockwise on paper), grouped by distance: one arc's tips are at one radius.
fn tips_by_radius(g: &Group, o: Point, base_r: f64) -> Vec<(f64, Vec<f64>)> {
    let mut groups: Vec<(f64, Vec<f64>)> = Vec::new();
    for i in &g.items {
        let Item::Fill { path } = i else { continue };
        let d = path.start - o;
        let r = d.hypot();
        if r > base_r - 2.0 {
            continue;
        }
        let deg = (-d.y).atan2(d.x).to_degrees().rem_euclid(360.0);
        match groups.iter_mut().find(|(gr, _)| (gr - r).abs() < 1e-3) {
            Some((_, v)) => v.push(deg),
            None => groups.push((r, vec![deg])),
        }
    }
    groups
}

/// The straight lines drawn (a path's line pieces).
fn straight_pieces(g: &Group) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    for i in &g.items {
        let Item::Path { path, .. } = i else { continue };
        let mut at = path.start;
        for s in &path.segs {
            if let Seg::Line(q) = s {
                out.push((at, *q));
                at = *q;
            } else {
                break;
            }
        }
    }
    out
}

fn distance_to_piece(p: Point, (a, b): (Point, Point)) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.hypot2()).clamp(0.0, 1.0);
    (p - (a + ab * t)).hypot()
}

/// Every phase angle in `phases` is the angle at O between two tips at one radius, and
/// every tip inside the base circle stands on a straight line drawn.
fn assert_phases_at_o(name: &str, g: &Group, phases: &[f64]) {
    let (o, base_r) = centre(g);
    let tips = tips_by_radius(g, o, base_r);
    let lines = straight_pieces(g);
    for i in &g.items {
        let Item::Fill { path } = i else { continue };
        let r = (path.start - o).hypot();
        // The phases' arcs: inside the base circle, beyond ω's arrow (the nearest O).
        let nearest = tips.iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
        if r > base_r - 2.0 || r <= nearest + 1e-3 {
            continue;
        }
        let off = lines.iter().map(|&l| distance_to_piece(path.start, l)).fold(f64::INFINITY, f64::min);
        assert!(off < 0.05, "{name}: an arrowhead at {:?} stands {off:.3} mm off every line", path.start);
    }
    for &phase in phases {
        let found = tips.iter().any(|(_, angles)| {
            angles.iter().any(|a| {
                angles.iter().any(|b| {
                    let gap = (b - a).rem_euclid(360.0);
                    (gap - phase).abs() < 0.05 || (360.0 - gap - phase).abs() < 0.05
                })
            })
        });
        assert!(found, "{name}: no arc of {phase}° at O; tips by radius: {tips:?}");
    }
}

/// The values written on the profile after "φ" and the phase's subscript (" = 70°").
fn phase_values(g: &Group) -> Vec<String> {
    g.items
        .iter()
        .filter_map(|i| match i {
            Item::Text(t) if t.text == "φ" && t.tail.ends_with('°') => Some(t.tail.clone()),
            _ => None,
        })
        .collect()
}

#[test]
fn the_worked_examples_profile_marks_its_phases_at_o() {
    // The guide's rocker: rise 70°, far dwell 10°, return 70°.
    for lang in Language::ALL {
        let g = profile_group(pipeline::DEFAULT_PROJECT, lang);
        assert_phases_at_o(&format!("worked example {lang:?}"), &g, &[70.0, 10.0, 70.0]);
        let values = phase_values(&g);
        assert_eq!(values.len(), 3, "{lang:?}: {values:?}");
        for v in ["70°", "10°"] {
            assert!(values.iter().any(|t| t.ends_with(&format!("= {v}"))), "{lang:?}: {v} not written: {values:?}");
        }
    }
}

#[test]
fn a_translating_followers_phase_arcs_end_on_its_axes() {
    let text = std::fs::read_to_string(common::root().join("fixtures/cams/translating-offset-auto.yaml")).unwrap();
    // rise 120°, far dwell 30°, return 90° (the fixture's phases_deg).
    let g = profile_group(&text, Language::Ru);
    assert_phases_at_o("translating-offset-auto", &g, &[120.0, 30.0, 90.0]);
    assert_eq!(phase_values(&g).len(), 3, "{:?}", phase_values(&g));
}

/// Whether the segments a–b and c–d cross.
fn cross((a, b): (Point, Point), (c, d): (Point, Point)) -> bool {
    let side = |p: Point, q: Point, r: Point| (q - p).cross(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// The arc round O nearest it (ω's arrow, the phases' arcs lying further out), as a polyline.
fn omega_arc(g: &Group, o: Point) -> Vec<Point> {
    let arcs = g.items.iter().filter_map(|i| match i {
        Item::Path { path, .. } => match path.segs.as_slice() {
            [Seg::Arc(a)] if (a.center - o).hypot() < 1e-6 => Some(*a),
            _ => None,
        },
        _ => None,
    });
    let a = arcs.min_by(|x, y| x.radii.x.total_cmp(&y.radii.x)).expect("ω's arc");
    (0..=48)
        .map(|k| {
            let t = a.start_angle + a.sweep_angle * f64::from(k) / 48.0;
            o + kurbo::Vec2::new(t.cos(), t.sin()) * a.radii.x
        })
        .collect()
}

#[test]
fn omegas_arrow_crosses_no_line_round_a_rockers_cam() {
    // Inside a rocker's cam only r_min's radius and the phases' rays run to O: the arrow
    // has room clear of them all (it crossed r_min's radius beside its head).
    let knife = std::fs::read_to_string(common::root().join("fixtures/cams/knife-rocker.yaml")).unwrap();
    for (name, text) in [("worked example", pipeline::DEFAULT_PROJECT), ("knife-rocker", knife.as_str())] {
        for lang in Language::ALL {
            let g = profile_group(text, lang);
            let (o, _) = centre(&g);
            let arc = omega_arc(&g, o);
            let lines = straight_pieces(&g);
            for w in arc.windows(2) {
                let hit = lines.iter().find(|&&l| cross((w[0], w[1]), l));
                assert!(hit.is_none(), "{name} {lang:?}: ω's arrow crosses the line {hit:?}");
            }
        }
    }
}
