//! What the backends that draw outlines themselves (PDF, PNG) share about the scene's
//! shapes: paths and circles as lines and cubic Béziers, the GOST dash patterns, and the check
//! that every number is finite. The SVG writer's semantics are the reference: a circle starts
//! at its rightmost point and runs the way angles grow (clockwise on paper), as an SVG
//! `<circle>` does, so a dash pattern starts in the same place.

use super::BackendError;
use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::{Item, LineType, Pen, Scene, Text};
use crate::num::math;
use kurbo::{Arc, BezPath, Point};
use std::f64::consts::{FRAC_PI_2, TAU};

/// How far the cubic pieces of an arc or circle may stray from it, mm: a tenth of the
/// SVG's 1 µm resolution, and far below a pixel at any resolution the CLI allows.
pub const ARC_TOLERANCE: f64 = 1e-4;

/// The dash pattern of a line type (strokes and gaps, mm); `None`: solid.
pub fn dash_array(line: LineType) -> Option<&'static [f64]> {
    line.dashes()
}

/// A path's lines, cubics and arcs as lines and cubics (arcs within [`ARC_TOLERANCE`]).
pub fn bez_path(p: &Path) -> BezPath {
    let mut b = BezPath::new();
    b.move_to(p.start);
    for s in &p.segs {
        match s {
            Seg::Line(q) => b.line_to(*q),
            Seg::Cubic(p1, p2, p3) => b.curve_to(*p1, *p2, *p3),
            Seg::Arc(a) => append_arc(&mut b, a),
        }
    }
    if p.closed {
        b.close_path();
    }
    b
}

/// A whole circle, starting at its rightmost point as an SVG `<circle>` does.
pub fn circle(c: Point, r: f64) -> BezPath {
    let mut b = BezPath::new();
    b.move_to(Point::new(c.x + r, c.y));
    append_arc(&mut b, &Arc::new(c, (r, r), 0.0, TAU, 0.0));
    b.close_path();
    b
}

/// Appends an arc as cubic pieces; it starts at the path's current point, as an SVG `A` does.
fn append_arc(b: &mut BezPath, a: &Arc) {
    let r = a.radii.x;
    let n = arc_pieces(r, a.sweep_angle);
    let step = a.sweep_angle / n as f64;
    // Control points along the tangents at 4/3·tan(θ/4) of the radius: the usual cubic arc.
    let k = 4.0 / 3.0 * math::tan(step / 4.0) * r;
    let at = |angle: f64| math::from_angle(angle);
    for i in 0..n {
        let (a0, a1) = (a.start_angle + step * i as f64, a.start_angle + step * (i + 1) as f64);
        let (u0, u1) = (at(a0), at(a1));
        let (p0, p3) = (a.center + u0 * r, a.center + u1 * r);
        let (t0, t1) = (kurbo::Vec2::new(-u0.y, u0.x), kurbo::Vec2::new(-u1.y, u1.x));
        b.curve_to(p0 + t0 * k, p3 - t1 * k, p3);
    }
}

/// The fewest equal pieces, none over a quarter turn, whose cubics stay within
/// [`ARC_TOLERANCE`] of the arc: the radial error of one piece of angle θ is
/// r·(4/27)·sin⁶(θ/4)/cos²(θ/4).
fn arc_pieces(r: f64, sweep: f64) -> usize {
    let mut n = (sweep.abs() / FRAC_PI_2).ceil().max(1.0) as usize;
    loop {
        let (s, c) = math::sin_cos(sweep.abs() / n as f64 / 4.0);
        let s3 = s * s * s;
        if r * 4.0 / 27.0 * s3 * s3 / (c * c) <= ARC_TOLERANCE || n >= 1 << 12 {
            return n;
        }
        n += 1;
    }
}

/// Refuses a scene with a NaN or an infinity anywhere, naming the group and the item, as
/// the SVG writer does.
pub fn check_finite(scene: &Scene) -> Result<(), BackendError> {
    let size = [scene.width, scene.height];
    if let Some(&value) = size.iter().find(|x| !x.is_finite()) {
        return Err(BackendError::NonFinite { group: String::new(), value, item: "the sheet's size".into() });
    }
    for g in &scene.groups {
        for item in &g.items {
            if let Some(value) = numbers(item).into_iter().find(|x| !x.is_finite()) {
                return Err(BackendError::NonFinite { group: g.id.clone(), value, item: format!("{item:?}") });
            }
        }
    }
    Ok(())
}

/// Every number an item is drawn with.
fn numbers(item: &Item) -> Vec<f64> {
    let pen = |p: &Pen| p.width;
    match item {
        Item::Path { path, pen: p } => {
            let mut v = path_numbers(path);
            v.push(pen(p));
            v
        }
        Item::Fill { path } => path_numbers(path),
        Item::Circle { c, r, pen: p, .. } => vec![c.x, c.y, *r, pen(p)],
        Item::Text(Text { at, h, rotate, stretch, .. }) => vec![at.x, at.y, *h, *rotate, *stretch],
    }
}

fn path_numbers(p: &Path) -> Vec<f64> {
    let mut v = vec![p.start.x, p.start.y];
    for s in &p.segs {
        match s {
            Seg::Line(q) => v.extend([q.x, q.y]),
            Seg::Cubic(a, b, c) => v.extend([a.x, a.y, b.x, b.y, c.x, c.y]),
            Seg::Arc(a) => v.extend([a.center.x, a.center.y, a.radii.x, a.start_angle, a.sweep_angle]),
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::math::Norm;
    use kurbo::{ParamCurve, PathSeg};

    /// The largest distance of the cubics' points from the circle, sampled densely.
    fn radial_error(b: &BezPath, c: Point, r: f64) -> f64 {
        let mut worst: f64 = 0.0;
        for seg in b.segments() {
            if let PathSeg::Cubic(cb) = seg {
                for i in 0..=200 {
                    worst = worst.max(((cb.eval(f64::from(i) / 200.0) - c).norm() - r).abs());
                }
            }
        }
        worst
    }

    #[test]
    fn arcs_stay_within_the_tolerance_and_end_where_they_should() {
        for (r, sweep) in [(1.0, 0.3), (50.0, -4.0), (400.0, 1.0), (1000.0, TAU)] {
            let p = Path::arc(Point::new(10.0, 20.0), r, 0.7, sweep);
            let b = bez_path(&p);
            let err = radial_error(&b, Point::new(10.0, 20.0), r);
            assert!(err <= ARC_TOLERANCE, "r {r}, sweep {sweep}: {err} mm off the arc");
            let end = b.segments().last().unwrap().end();
            assert!((end - p.end()).norm() < 1e-9, "r {r}: ends at {end:?}, not {:?}", p.end());
        }
    }

    #[test]
    fn a_circle_starts_at_its_right_and_turns_clockwise_on_paper() {
        let b = circle(Point::new(0.0, 0.0), 10.0);
        let first = b.segments().next().unwrap();
        assert_eq!(first.start(), Point::new(10.0, 0.0));
        // y points down on paper, so clockwise goes down first.
        assert!(first.eval(0.1).y > 0.0);
        assert!(radial_error(&b, Point::ORIGIN, 10.0) <= ARC_TOLERANCE);
    }

    #[test]
    fn dash_patterns_are_the_svg_writers() {
        assert_eq!(dash_array(LineType::Solid), None);
        assert_eq!(dash_array(LineType::Dashed), Some(&[4.0, 1.5][..]));
        assert_eq!(dash_array(LineType::DashDot), Some(&[10.0, 1.5, 0.5, 1.5][..]));
    }
}
