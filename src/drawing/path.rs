//! Paths of the scene: lines, cubic Béziers and circular arcs in paper millimetres, in
//! kurbo's vocabulary (`Point`, `CubicBez`, `Arc`). A backend writes them as SVG `L`, `C` and
//! `A` commands; layout code measures them through [`Path::to_bez`].
//!
//! Every approximation of a curve by these pieces states its accuracy in paper mm where it
//! is made (a trajectory's fit, an arc never: arcs are exact).

use crate::num::math;
use crate::num::tol;
use kurbo::{Arc, BezPath, CubicBez, ParamCurveExtrema, Point, Rect};

/// One piece of a path, starting where the previous one ends.
#[derive(Debug, Clone, PartialEq)]
pub enum Seg {
    Line(Point),
    Cubic(Point, Point, Point),
    /// A circular arc (equal radii, no rotation); it starts at the previous end.
    Arc(Arc),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Path {
    pub start: Point,
    pub segs: Vec<Seg>,
    pub closed: bool,
}

/// A point on a circle of `center` and radius `r` at `angle` (paper angles: y down, so a
/// growing angle turns clockwise on the sheet).
pub fn on_circle(center: Point, r: f64, angle: f64) -> Point {
    center + math::from_angle(angle) * r
}

impl Path {
    pub fn new(start: Point) -> Path {
        Path { start, segs: Vec::new(), closed: false }
    }

    /// Straight lines through `pts` (at least one point).
    pub fn polyline(pts: &[Point], closed: bool) -> Path {
        let mut p = Path::new(pts[0]);
        p.segs.extend(pts[1..].iter().map(|&q| Seg::Line(q)));
        p.closed = closed;
        p
    }

    /// Cubic pieces joined end to end; the first starts at `pieces[0].p0`.
    pub fn cubics(pieces: &[CubicBez]) -> Path {
        let mut p = Path::new(pieces[0].p0);
        p.segs.extend(pieces.iter().map(|c| Seg::Cubic(c.p1, c.p2, c.p3)));
        p
    }

    /// An arc of a circle from `start_angle` through `sweep` (radians, paper angles).
    pub fn arc(center: Point, r: f64, start_angle: f64, sweep: f64) -> Path {
        let mut p = Path::new(on_circle(center, r, start_angle));
        p.segs.push(Seg::Arc(Arc::new(center, (r, r), start_angle, sweep, 0.0)));
        p
    }

    pub fn end(&self) -> Point {
        match self.segs.last() {
            None => self.start,
            Some(Seg::Line(p)) | Some(Seg::Cubic(_, _, p)) => *p,
            Some(Seg::Arc(a)) => on_circle(a.center, a.radii.x, a.start_angle + a.sweep_angle),
        }
    }

    /// The path as kurbo Béziers (arcs within [`tol::ARC_MEASURE`]), for measuring.
    pub fn to_bez(&self) -> BezPath {
        let mut b = BezPath::new();
        b.move_to(self.start);
        for s in &self.segs {
            match s {
                Seg::Line(p) => b.line_to(*p),
                Seg::Cubic(p1, p2, p3) => b.curve_to(*p1, *p2, *p3),
                Seg::Arc(a) => a.append_iter(tol::ARC_MEASURE).for_each(|el| b.push(el)),
            }
        }
        if self.closed {
            b.close_path();
        }
        b
    }

    /// The box of the path's pieces and its start: a piece of no length (an arc of zero
    /// sweep: a circle's part inside a region when none is) adds no segment, and a path of
    /// only its start must be boxed there, not at the origin.
    pub fn bbox(&self) -> Rect {
        self.to_bez().segments().fold(Rect::from_points(self.start, self.start), |r, s| r.union(s.bounding_box()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::math::Norm;

    #[test]
    fn an_arc_ends_where_its_sweep_takes_it_and_is_bounded_by_its_circle() {
        let p = Path::arc(Point::new(10.0, 10.0), 5.0, 0.0, std::f64::consts::FRAC_PI_2);
        assert!((p.end() - Point::new(10.0, 15.0)).norm() < 1e-12);
        let bb = p.bbox();
        assert!((bb.x1 - 15.0).abs() < 1e-3 && (bb.y1 - 15.0).abs() < 1e-3 && (bb.x0 - 10.0).abs() < 1e-3, "{bb:?}");
    }

    /// An arc of zero sweep (the part of a wheel's circle inside a region that holds none of
    /// it) is boxed at its point on the circle, not at the page's corner (found by the stress
    /// sweep: z = [318, 155] reported a mesh item at (0, 0)).
    #[test]
    fn an_arc_of_no_sweep_is_boxed_at_its_point() {
        let p = Path::arc(Point::new(232.0, 4523.0), 3967.0, -std::f64::consts::FRAC_PI_2, 0.0);
        let bb = p.bbox();
        assert!((bb.center() - Point::new(232.0, 556.0)).norm() < 1e-9 && bb.area() == 0.0, "{bb:?}");
    }

    #[test]
    fn polyline_and_cubic_boxes_are_exact() {
        let p = Path::polyline(&[Point::new(0.0, 0.0), Point::new(3.0, -1.0), Point::new(1.0, 4.0)], true);
        assert_eq!(p.bbox(), Rect::new(0.0, -1.0, 3.0, 4.0));
        let c = Path::cubics(&[CubicBez::new((0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (4.0, 0.0))]);
        assert!((c.bbox().y1 - 3.0).abs() < 1e-12, "a cubic's box is its extremum, not its control polygon");
    }
}
