//! A force polygon at its own round μ_P: the chain of forces from its start, the inner
//! reaction dashed, labels outside the polygon.

use super::ForcesInput;
use super::group::GroupLayout;
use super::inset;
use super::legend::force_label;
use crate::drawing::place::Labels;
use crate::drawing::scene::{DASHED, Group, THIN, VECTOR};
use crate::drawing::symbols::vector;
use crate::drawing::view::View;
use crate::lever::kinetostatics::Polygon;
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Line, ParamCurve, ParamCurveNearest, Point, Rect, Vec2};

/// Extent of a polygon's chain of vectors, in newtons, from its start.
pub(super) fn chain(poly: &Polygon) -> Vec<Vec2> {
    let mut pts = vec![Vec2::ZERO];
    for t in &poly.terms {
        pts.push(*pts.last().expect("starts with the origin") + t.force);
    }
    pts
}

pub(super) fn bbox_of(pts: &[Vec2]) -> Rect {
    pts.iter().fold(Rect::from_points(Point::ZERO, Point::ZERO), |r, p| r.union_pt(p.to_point()))
}

pub(super) fn draw_polygon(
    g: &mut Group,
    labels: &mut Labels,
    inp: &ForcesInput,
    (poly, layout): (&Polygon, &GroupLayout),
    named: inset::Named,
    r: Rect,
) {
    let view = View::centred(layout.chain_box, r, layout.mu_p);
    let p = |v: Vec2| view.p(v);
    let pts = &layout.chain;
    // Labels stand outside the polygon: beside each side, away from the vertices' centre.
    let centre = {
        let n = pts.len().max(1) as f64;
        let c = pts.iter().fold(Vec2::ZERO, |acc, &v| acc + v) / n;
        p(c)
    };
    let outward = |a: Point, b: Point| {
        let n = (b - a).turn_90();
        if n.dot(a.midpoint(b) - centre) < 0.0 { -n } else { n }
    };
    // The last side drawn at least SIDE_MIN long, to set beside it a side that starts on
    // it and runs back over it: the short sides between are drawn again enlarged (the
    // compressors' P_g3 ran back over P_i3 past a G₃ of a millimetre or two).
    let mut before: Option<Line> = None;
    for (k, t) in poly.terms.iter().enumerate() {
        let (a, b) = (p(pts[k]), p(pts[k + 1]));
        if (b - a).norm() < tol::PAPER_INVISIBLE {
            continue;
        }
        // Sides under SIDE_MIN are drawn again enlarged, where they are read.
        let measured = (b - a).norm() >= inset::SIDE_MIN && !inset::labelled_elsewhere(&layout.insets, k);
        let follows = |side: &Line| side.nearest(a, 0.0).distance_sq < ON_SIDE * ON_SIDE;
        let back = before.filter(|side| measured && follows(side) && runs_back(side.p1 - side.p0, b - a));
        let shift = back.map_or(Vec2::ZERO, |_| outward(a, b) / (b - a).norm() * BESIDE_SIDE);
        if (b - a).norm() >= inset::SIDE_MIN {
            before = Some(Line::new(a, b));
        }
        let (a, b) = if shift == Vec2::ZERO {
            (a, b)
        } else {
            // Joined to its true ends by thin lines, the chain reads unbroken.
            g.line(a, a + shift, THIN);
            g.line(b + shift, b, THIN);
            (a + shift, b + shift)
        };
        vector(g, a, b, VECTOR);
        if !inset::labelled_elsewhere(&layout.insets, k) {
            labels.add_side((a, b), outward(a, b), force_label(inp, t.kind, t.on), 3.5);
        }
    }
    inset::ring(g, labels, &view, pts, named);
    if let Some(inner) = &poly.inner {
        let (a, b) = (p(pts[poly.split]), p(pts[0]));
        if (b - a).norm() >= tol::PAPER_INVISIBLE {
            // On a side (R32 ≈ −R12 when link 2's own forces are small) it would hide under
            // it: set beside it, away from that side, as a free vector may be.
            let sides: Vec<Line> = (0..poly.terms.len()).map(|k| Line::new(p(pts[k]), p(pts[k + 1]))).collect();
            let shift = side_under(a, b, &sides).map_or(Vec2::ZERO, |side| away_from(a, b, side, centre) * BESIDE_SIDE);
            let (a, b) = (a + shift, b + shift);
            vector(g, a, b, DASHED);
            // The inner reaction runs inside the polygon: its label beside it, either side.
            labels.add_side((a, b), (b - a).turn_90(), force_label(inp, inner.kind, inner.on), 3.5);
        }
    }
    g.dot(p(pts[0]), 0.5);
}

/// How far an inner reaction lying on a side, or a side running back over the one before
/// it, is set beside it, mm: clear of the side's 0.5 mm stroke by twice GOST 2.303's least
/// gap between parallel lines.
const BESIDE_SIDE: f64 = 1.8;

/// Whether a side along `next` runs back over the side along `before` drawn just before
/// it (within 12°; the order of a link's own loads avoids that where it can, `order.rs`):
/// a slider's weight down and its inertia force up along one guide drew one line with a
/// head at each end, neither measurable (the offset crank-slider's G₃ and P_i3).
fn runs_back(before: Vec2, next: Vec2) -> bool {
    -before.dot(next) > crate::num::math::cos(RUNS_BACK_DEG.to_radians()) * before.norm() * next.norm()
}

/// See [`runs_back`].
const RUNS_BACK_DEG: f64 = 12.0;

/// A segment within this of a side over most of its length reads as lying on it, mm: a
/// dashed line converging on a thick one at a small angle is as hidden as one on it.
const ON_SIDE: f64 = 1.2;

/// The side the segment a–b runs along for most of its length (more than half of its inner
/// sample points within [`ON_SIDE`] of it), if any.
fn side_under(a: Point, b: Point, sides: &[Line]) -> Option<Line> {
    let samples: Vec<Point> = (1..8).map(|k| a.lerp(b, k as f64 / 8.0)).collect();
    let near = |side: &Line| samples.iter().filter(|&&q| side.nearest(q, 0.0).distance_sq < ON_SIDE * ON_SIDE).count();
    sides
        .iter()
        .map(|side| (near(side), *side))
        .filter(|(n, _)| 2 * n > samples.len())
        .max_by_key(|(n, _)| *n)
        .map(|(_, s)| s)
}

/// The unit normal of a–b pointing away from `side` (toward `centre` where a–b's middle is
/// on the side's line).
fn away_from(a: Point, b: Point, side: Line, centre: Point) -> Vec2 {
    let n = (b - a).turn_90() / (b - a).norm();
    let mid = a.midpoint(b);
    let from_side = mid - side.eval(side.nearest(mid, 0.0).t);
    let toward = if from_side.norm() > tol::PAPER { from_side } else { centre - mid };
    if n.dot(toward) < 0.0 { -n } else { n }
}

/// The shortest side [`draw_polygon`] labels on the polygon, and the shortest its
/// enlargements label, mm.
pub(super) fn shortest_sides(poly: &Polygon, layout: &GroupLayout) -> (Option<f64>, Option<f64>) {
    let inner = poly.inner.iter().map(|t| t.force.norm());
    let on_polygon = poly
        .terms
        .iter()
        .enumerate()
        .filter(|(k, _)| !inset::labelled_elsewhere(&layout.insets, *k))
        .map(|(_, t)| t.force.norm())
        .chain(inner)
        .map(|f| f / layout.mu_p)
        .filter(|&side| side >= tol::PAPER_INVISIBLE)
        .reduce(f64::min);
    (on_polygon, inset::shortest_side(poly, &layout.insets))
}
