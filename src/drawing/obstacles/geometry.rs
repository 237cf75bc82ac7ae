//! The plane geometry the index answers with: whether a segment meets a box or another
//! segment, where it runs inside a box, how far it passes from one.

use crate::num::math::Norm;
use kurbo::{Point, Rect};

/// Whether the box `r` reaches inside the disc of centre `c` and radius `rad`.
pub(super) fn disc_meets_rect(c: Point, rad: f64, r: Rect) -> bool {
    let nearest = Point::new(c.x.clamp(r.x0, r.x1), c.y.clamp(r.y0, r.y1));
    (nearest - c).norm() < rad
}

/// Whether segments `a`–`b` and `c`–`d` share a point.
pub fn segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let orient = |p: Point, q: Point, r: Point| (q - p).cross(r - p);
    // `c` and `d` strictly on one side of the line `a`–`b` (most of the strokes a leader is
    // tested against): the segments share no point, and `a` and `b` about `c`–`d` need not be
    // found (a fifth of building sheet 1's label tests). The orientations are
    // `math::orientations`' own; the tests below could only differ where `a` or `b` lies
    // exactly on `c`–`d` though `c` and `d` are strictly on one side of `a`–`b`, which exact
    // arithmetic rules out and rounding does not reach on any sheet of the fixtures.
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if (d3 > 0.0 && d4 > 0.0) || (d3 < 0.0 && d4 < 0.0) {
        return false;
    }
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    let on = |p: Point, q: Point, r: Point, o: f64| {
        o == 0.0 && r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// The distance between the rectangle `r` and the segment `a`–`b`, mm (0 where they meet):
/// the least of the ends' distances to the rectangle and the corners' to the segment.
pub fn rect_segment_distance(r: Rect, (a, b): (Point, Point)) -> f64 {
    if segment_meets_rect(a, b, r) {
        return 0.0;
    }
    let to_rect = |p: Point| (p - Point::new(p.x.clamp(r.x0, r.x1), p.y.clamp(r.y0, r.y1))).norm();
    let line = kurbo::Line::new(a, b);
    let corners = [(r.x0, r.y0), (r.x1, r.y0), (r.x0, r.y1), (r.x1, r.y1)];
    let to_segment = corners.map(|(x, y)| {
        use kurbo::ParamCurveNearest;
        line.nearest(Point::new(x, y), 0.0).distance_sq.sqrt()
    });
    to_segment.into_iter().fold(to_rect(a).min(to_rect(b)), f64::min)
}

/// Whether the segment `a`–`b` has a point inside or on the rectangle `r` (Liang–Barsky).
/// The test of bounds that answers most calls (a box's cells list many segments beside
/// it) is inlined into the callers; the clipping is not.
#[inline]
pub fn segment_meets_rect(a: Point, b: Point, r: Rect) -> bool {
    !wholly_beyond(a, b, r) && clipped_meets(a, b, r)
}

#[inline(never)]
fn clipped_meets(a: Point, b: Point, r: Rect) -> bool {
    segment_span_in_rect(a, b, r).is_some()
}

/// Whether the segment `a`–`b` lies wholly beyond one side of `r`, by far more than
/// rounding (the clipping answers the same for it: no common point).
#[inline(always)]
fn wholly_beyond(a: Point, b: Point, r: Rect) -> bool {
    const APART: f64 = 1e-6;
    a.x.max(b.x) < r.x0 - APART
        || a.x.min(b.x) > r.x1 + APART
        || a.y.max(b.y) < r.y0 - APART
        || a.y.min(b.y) > r.y1 + APART
}

/// The part of the segment `a`–`b` inside or on the rectangle `r`, as the parameters
/// `(t0, t1)` of `a + t·(b − a)` (Liang–Barsky), or `None` when they do not meet.
#[inline]
pub fn segment_span_in_rect(a: Point, b: Point, r: Rect) -> Option<(f64, f64)> {
    if r.width() < 0.0 || r.height() < 0.0 {
        return None;
    }
    // A segment wholly beyond one side (by far more than rounding: the clipping below
    // answers the same) is answered without it.
    if wholly_beyond(a, b, r) {
        return None;
    }
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, a.x - r.x0), (d.x, r.x1 - a.x), (-d.y, a.y - r.y0), (d.y, r.y1 - a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return None;
            }
        }
    }
    Some((t0, t1))
}
