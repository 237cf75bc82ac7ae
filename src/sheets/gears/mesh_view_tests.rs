//! The mesh drawing checked against the exact outlines: no interpenetration, the drawn
//! contact ratio, the dimensions' values and points.

use super::*;
use crate::gears::pair::PairSpec;

/// A pair of module 5 mm with shifts `x` and its wheels' exact outlines.
fn pair_of(z: [u32; 2], x: [f64; 2]) -> (Pair, [Outline; 2]) {
    let spec = PairSpec { shift: x, ..PairSpec::standard(0.005, z) };
    let pair = Pair::new(&spec).unwrap();
    let outlines = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
    (pair, outlines)
}

fn input<'a>(pair: &'a Pair, outlines: &'a [Outline; 2]) -> MeshInput<'a> {
    MeshInput { pair, outlines: [&outlines[0], &outlines[1]], lang: crate::drawing::labels::Language::En }
}

/// The mesh drawn as the sheet draws it, its labels placed, in a 420 × 580 mm group: the
/// group and the mesh's view.
fn drawn(inp: &MeshInput) -> (Group, View) {
    let area = Rect::new(2.0, 10.0, 418.0, 540.0);
    let mut g = Group::new("m", Rect::new(0.0, 0.0, 420.0, 580.0));
    let mut labels = Labels::new();
    let d = draw_mesh(&mut g, area, inp, &mut labels);
    labels.place(&mut g, area);
    let (v, _) = placement(inp.pair, area, d.mu);
    (g, v)
}

/// Half the angular thickness of a wheel's tooth at radius `r` (root ≤ r ≤ tip), exact:
/// the involute above the junction, the fillet below (its radius grows monotonically
/// from the root to the junction, so a bisection finds the point).
fn half_angle(o: &Outline, r: f64) -> f64 {
    let join = o.fillet(o.phi_join).0.norm();
    if r >= join {
        return o.involute_angle(r);
    }
    let (mut a, mut b) = (o.phi_root, o.phi_join);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if o.fillet(m).0.norm() < r { a = m } else { b = m }
    }
    polar(o.fillet(0.5 * (a + b)).0)
}

/// How deep a point lies inside a wheel's material (m; negative: outside), exactly.
fn depth(o: &Outline, centre: Vec2, tooth_centre: f64, q: Vec2) -> f64 {
    let d = q - centre;
    let r = d.norm();
    if r > o.tip {
        return o.tip - r;
    }
    if r < o.root {
        return o.root - r;
    }
    let step = TAU / f64::from(o.z);
    let rel = (polar(d) - tooth_centre).rem_euclid(step);
    let off = rel.min(step - rel); // angle from the nearest tooth's middle
    (half_angle(o, r) - off) * r
}

#[test]
fn the_drawn_flanks_of_the_two_wheels_never_interpenetrate() {
    for (z, x) in [
        ([17u32, 19u32], [0.0, 0.0]),
        ([12, 30], [0.299, 0.0]),
        ([12, 24], [0.6, 0.36]),
        ([10, 27], [0.0, 0.0]),
        ([40, 60], [0.0, 0.0]),
    ] {
        let spec = PairSpec { shift: x, ..PairSpec::standard(0.005, z) };
        let pair = Pair::new(&spec).unwrap();
        let outlines = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
        let inp = MeshInput {
            pair: &pair,
            outlines: [&outlines[0], &outlines[1]],
            lang: crate::drawing::labels::Language::En,
        };
        let centres = tooth_centres(&inp);
        let o = [Vec2::ZERO, Vec2::new(0.0, pair.centre_distance)];
        let mut allowance = 1e-12;
        let mut worst: f64 = f64::NEG_INFINITY;
        let mut touch: f64 = f64::INFINITY;
        for i in 0..2 {
            let (fl, dev, fdev) = flank(&outlines[i]);
            allowance += dev.max(fdev);
            let j = 1 - i;
            for &cc in &centres[i] {
                for mirror in [false, true] {
                    for c in fl.involute.iter().chain(&fl.fillet) {
                        for k in 0..=200 {
                            let p = kurbo::ParamCurve::eval(c, f64::from(k) / 200.0).to_vec2();
                            let p = if mirror { Vec2::new(p.x, -p.y) } else { p };
                            let q = o[i] + rotate(p, cc);
                            let d = depth(&outlines[j], o[j], centres[j][1], q);
                            worst = worst.max(d);
                            touch = touch.min(-d);
                        }
                    }
                }
            }
        }
        assert!(
            worst <= allowance,
            "{z:?} {x:?}: a drawn flank lies {worst:e} m inside the other wheel (allowance {allowance:e})"
        );
        // And they do touch: the pair is drawn in mesh, not apart.
        assert!(touch.abs() <= allowance, "{z:?}: the nearest flanks are {touch:e} m apart");
    }
}

#[test]
fn the_contact_ratio_measured_on_the_drawing_agrees_with_the_closed_form() {
    for z in [[17u32, 19u32], [12, 30], [40, 60]] {
        let spec = PairSpec::standard(0.005, z);
        let pair = Pair::new(&spec).unwrap();
        let outlines = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
        let mut g = Group::new("m", Rect::new(0.0, 0.0, 420.0, 580.0));
        let mut labels = Labels::new();
        let d = draw_mesh(
            &mut g,
            Rect::new(2.0, 10.0, 418.0, 540.0),
            &MeshInput {
                pair: &pair,
                outlines: [&outlines[0], &outlines[1]],
                lang: crate::drawing::labels::Language::En,
            },
            &mut labels,
        );
        // The drawn ends are rounded to 1 µm on paper, about 20 mm from each other.
        assert!(
            (d.contact_ratio_drawn - pair.contact_ratio).abs() < 1e-4,
            "{z:?}: {} vs {}",
            d.contact_ratio_drawn,
            pair.contact_ratio
        );
        assert!(d.tooth_height_mm > 50.0);
        assert!(d.involute_deviation < 1e-6, "{z:?}: {:e}", d.involute_deviation);
    }
}

/// Each of s, e and p reads as its own arc's value: its text (wherever the placer set it)
/// is nearer its own dimension arc than the other one — s's value once sat under p's arc
/// with a leader, and read as p's; and p's value stands over its arc as GOST 2.307 writes
/// it (it stood under, toward the wheel's body, on every pair: a teacher's mark), unless
/// s's or e's is under theirs.
#[test]
fn each_mesh_dimension_value_is_nearest_its_own_arc() {
    use super::super::mesh_dimensions::{P_INSIDE_ROOT, S_INSIDE_ROOT};
    for (z, x) in [
        ([17u32, 19u32], [0.0, 0.0]),
        ([12, 30], [0.295, 0.0]),
        ([12, 24], [0.6, 0.36]),
        ([10, 27], [0.0, 0.0]),
        ([25, 60], [0.2, 0.0]),
    ] {
        let (pair, outlines) = pair_of(z, x);
        let inp = input(&pair, &outlines);
        let (g, v) = drawn(&inp);
        let o1 = v.p(Vec2::ZERO);
        let root = v.len(pair.wheels[0].root);
        let (r_s, r_p) = (root - S_INSIDE_ROOT, root - P_INSIDE_ROOT);
        let (mut found, mut over) = (0, Vec::new());
        // s, e and p (a_w, h_a1 and h_f1 are written too, with subscripts).
        let arc_value =
            |t: &&crate::drawing::scene::Text| ["s", "e", "p"].contains(&t.text.as_str()) && t.sub.is_empty();
        for t in g.texts().filter(|t| t.tail.starts_with(" = ")).filter(arc_value) {
            let d = (t.core_box().center() - o1).norm();
            let (own, other) = if t.text == "p" { (r_p, r_s) } else { (r_s, r_p) };
            assert!(
                (d - own).abs() < (d - other).abs(),
                "{z:?}: “{}” {d:.1} mm from O1, arcs at {own:.1} and {other:.1}",
                t.plain()
            );
            over.push((t.text.clone(), d > own));
            found += 1;
        }
        assert_eq!(found, 3, "{z:?}: s, e and p are written");
        // p's value over its arc (GOST 2.307), but under it where s's or e's went under
        // theirs, into the band between the arcs, where the two would read as one stack.
        let band = over.iter().any(|(name, up)| name != "p" && !up);
        let p_over = over.iter().any(|(name, up)| name == "p" && *up);
        assert_eq!(p_over, !band, "{z:?}: p's value over its arc: {p_over}, {over:?}");
        // The worked example's mesh has room for all three over their arcs.
        if z == [17, 19] {
            assert!(over.iter().all(|(_, up)| *up), "{z:?}: {over:?}");
        }
    }
}

/// p_b is dimensioned between two points of wheel 1's drawn flanks (each on its outline,
/// exactly: depth zero within the flank's fit) on one tangent to its base circle (the
/// line's distance from O1 is r_b), p_b apart, clear of the line of action (a thin line on
/// the bold one is lost in it); the value names it.
#[test]
fn the_base_pitch_spans_two_flanks_of_wheel_1_along_a_normal() {
    use crate::drawing::obstacles::segments;
    for (z, x) in [
        ([17u32, 19u32], [0.0, 0.0]),
        ([12, 30], [0.295, 0.0]),
        ([40, 60], [0.0, 0.0]),
        ([25, 50], [0.2, 0.1]),
        ([18, 36], [0.0, 0.0]),
    ] {
        let (pair, outlines) = pair_of(z, x);
        let inp = input(&pair, &outlines);
        let (g, v) = drawn(&inp);
        assert!(g.texts().any(|t| t.text == "p" && t.sub == "b" && t.tail.starts_with(" = ")), "{z:?}: p_b's value");
        let length = v.len(pair.base_pitch);
        let lines: Vec<_> =
            g.items.iter().flat_map(segments).filter(|(a, b)| ((*b - *a).norm() - length).abs() < 1e-9).collect();
        assert_eq!(lines.len(), 1, "{z:?}: one line p_b long");
        let (a, b) = lines[0];
        let world = |q: kurbo::Point| Vec2::new((q.x - v.p(Vec2::ZERO).x) * v.mu, -(q.y - v.p(Vec2::ZERO).y) * v.mu);
        let (fl, dev, fdev) = flank(&outlines[0]);
        let _ = fl;
        let centre = tooth_centres(&inp)[0][1];
        for q in [a, b] {
            let depth = depth(&outlines[0], Vec2::ZERO, centre, world(q));
            assert!(depth.abs() <= dev.max(fdev) + 1e-9, "{z:?}: an arrow {depth:e} m off wheel 1's outline");
        }
        let (wa, wb) = (world(a), world(b));
        let u = (wb - wa) / (wb - wa).norm();
        let off = wa.cross(u).abs();
        assert!(
            (off - pair.wheels[0].base).abs() < 1e-9,
            "{z:?}: the line is {off} m from O1, r_b {}",
            pair.wheels[0].base
        );
        // The line of action: through P, on O1O2 at r_w1 = r_b1 / cos α_w from O1, at α_w to
        // the common tangent there.
        let aw = pair.working_pressure_angle;
        let p = Vec2::new(0.0, pair.wheels[0].base / crate::num::math::cos(aw));
        let along = Vec2::new(crate::num::math::cos(aw), -crate::num::math::sin(aw));
        let from_action = |q: Vec2| v.len((q - p).cross(along).abs());
        let farther_end = from_action(wa).max(from_action(wb));
        assert!(farther_end >= 3.0, "{z:?}: p_b's line {farther_end} mm from the line of action at its farther end");
    }
}
