//! Paths as DXF shapes: the y flip, polylines with bulges, arcs, outlines and the triangles of a fill.

use super::*;
use crate::drawing::path::{Path, Seg};
use kurbo::{Arc, BezPath, PathEl};

/// A vertex of a polyline: its point (DXF coordinates) and the bulge of the segment from
/// it to the next (tan of a quarter of the arc's counter-clockwise sweep; 0 straight).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Vertex {
    pub(super) p: Point,
    pub(super) bulge: f64,
}

/// A path as the DXF entity it becomes.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Shape {
    Line(Point, Point),
    /// Centre, radius, start and end angles (degrees, counter-clockwise from start to end).
    Arc(Point, f64, f64, f64),
    Circle(Point, f64),
    Poly(Vec<Vertex>, bool),
}

/// The writer's geometry: paper mm to DXF coordinates.
pub(super) struct Flip {
    pub(super) height: f64,
}

impl Flip {
    pub(super) fn p(&self, p: Point) -> Point {
        Point::new(p.x, self.height - p.y)
    }

    /// An arc's DXF form: a paper angle θ is −θ in DXF (y flipped), and a paper sweep s
    /// (clockwise on the sheet when positive) runs counter-clockwise from −(θ+s) to −θ.
    pub(super) fn arc(&self, a: &Arc) -> (Point, f64, f64, f64) {
        let (s0, s1) = (a.start_angle, a.start_angle + a.sweep_angle);
        let (lo, hi) = if s0 <= s1 { (s0, s1) } else { (s1, s0) };
        (self.p(a.center), a.radii.x, degrees(-hi.to_degrees()), degrees(-lo.to_degrees()))
    }

    /// What a path becomes: a LINE, an ARC or CIRCLE, or a polyline.
    pub(super) fn shape(&self, path: &Path) -> Option<Shape> {
        if path.segs.is_empty() {
            return None;
        }
        if !path.closed && path.segs.len() == 1 {
            match &path.segs[0] {
                Seg::Line(q) => return Some(Shape::Line(self.p(path.start), self.p(*q))),
                Seg::Arc(a) if a.radii.x > 0.0 && a.sweep_angle.abs() >= TAU - 1e-9 => {
                    return Some(Shape::Circle(self.p(a.center), a.radii.x));
                }
                Seg::Arc(a) if a.radii.x > 0.0 && a.sweep_angle != 0.0 => {
                    let (c, r, start, end) = self.arc(a);
                    return Some(Shape::Arc(c, r, start, end));
                }
                _ => {}
            }
        }
        let v = self.vertices(path);
        (v.len() >= 2).then_some(Shape::Poly(v, path.closed))
    }

    /// A path's polyline vertices: lines as they are, arcs as bulges (pieces of at most half
    /// a turn), cubics flattened within [`FLATTEN_MM`]. A closed path's last vertex, back at
    /// its first, is left out (the closing segment takes its place).
    pub(super) fn vertices(&self, path: &Path) -> Vec<Vertex> {
        let mut v = vec![Vertex { p: self.p(path.start), bulge: 0.0 }];
        let mut cur = path.start;
        let to = |v: &mut Vec<Vertex>, q: Point, bulge: f64| {
            if let Some(last) = v.last_mut() {
                last.bulge = bulge;
            }
            v.push(Vertex { p: self.p(q), bulge: 0.0 });
        };
        for s in &path.segs {
            match s {
                Seg::Line(q) => {
                    to(&mut v, *q, 0.0);
                    cur = *q;
                }
                Seg::Cubic(p1, p2, p3) => {
                    let mut b = BezPath::new();
                    b.move_to(cur);
                    b.curve_to(*p1, *p2, *p3);
                    let mut pts = Vec::new();
                    kurbo::flatten(b, FLATTEN_MM, |el| {
                        if let PathEl::LineTo(q) = el {
                            pts.push(q);
                        }
                    });
                    for q in pts {
                        to(&mut v, q, 0.0);
                    }
                    cur = *p3;
                }
                Seg::Arc(a) => {
                    let r = a.radii.x;
                    let start = a.center + math::from_angle(a.start_angle) * r;
                    if (start - cur).hypot2() > 1e-12 {
                        to(&mut v, start, 0.0);
                    }
                    let n = (a.sweep_angle.abs() / PI).ceil().max(1.0) as usize;
                    let step = a.sweep_angle / n as f64;
                    // A positive paper sweep turns clockwise on the sheet: a negative bulge.
                    let bulge = -math::tan(step / 4.0);
                    for i in 1..=n {
                        let q = a.center + math::from_angle(a.start_angle + step * i as f64) * r;
                        to(&mut v, q, bulge);
                    }
                    cur = a.center + math::from_angle(a.start_angle + a.sweep_angle) * r;
                }
            }
        }
        if path.closed && v.len() > 2 && (v[v.len() - 1].p - v[0].p).hypot2() < 1e-12 {
            v.pop();
        }
        v
    }
}

/// A closed outline flattened to points (DXF coordinates), for the triangles of R12.
pub(super) fn outline_points(b: &BezPath, flip: &Flip) -> Vec<Point> {
    let mut pts: Vec<Point> = Vec::new();
    kurbo::flatten(b.iter(), FLATTEN_MM, |el| match el {
        PathEl::MoveTo(p) | PathEl::LineTo(p) => {
            let q = flip.p(p);
            if pts.last().is_none_or(|l| (*l - q).hypot2() > 1e-12) {
                pts.push(q);
            }
        }
        _ => {}
    });
    while pts.len() > 1 && (pts[pts.len() - 1] - pts[0]).hypot2() < 1e-12 {
        pts.pop();
    }
    pts
}

/// A simple polygon as triangles by ear clipping (a convex one as a fan from its first
/// corner); an outline of fewer than three points gives none.
pub(super) fn triangles(pts: &[Point]) -> Vec<[Point; 3]> {
    let area2: f64 = (0..pts.len()).map(|i| pts[i].to_vec2().cross(pts[(i + 1) % pts.len()].to_vec2())).sum();
    let ccw = area2 >= 0.0;
    let mut idx: Vec<usize> = (0..pts.len()).collect();
    let mut out = Vec::new();
    let turn = |a: Point, b: Point, c: Point| {
        let t = (b - a).cross(c - b);
        if ccw { t } else { -t }
    };
    let inside =
        |p: Point, a: Point, b: Point, c: Point| turn(a, b, p) > 0.0 && turn(b, c, p) > 0.0 && turn(c, a, p) > 0.0;
    while idx.len() >= 3 {
        let n = idx.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (pts[idx[(i + n - 1) % n]], pts[idx[i]], pts[idx[(i + 1) % n]]);
            turn(a, b, c) > 0.0 && idx.iter().all(|&j| [a, b, c].contains(&pts[j]) || !inside(pts[j], a, b, c))
        });
        // A degenerate remainder (collinear points): clip the first corner all the same.
        let i = ear.unwrap_or(1 % n);
        let (a, b, c) = (pts[idx[(i + n - 1) % n]], pts[idx[i]], pts[idx[(i + 1) % n]]);
        if turn(a, b, c).abs() > 1e-12 {
            out.push([a, b, c]);
        }
        idx.remove(i);
    }
    out
}
