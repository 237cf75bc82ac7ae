//! Paths of the scene: lines, cubic Béziers and circular arcs in paper millimetres, in
//! kurbo's vocabulary (`Point`, `CubicBez`, `Arc`). A backend writes them as SVG `L`, `C` and
//! `A` commands; layout code measures them through [`Path::to_bez`].
//!
//! Every approximation of a curve by these pieces states its accuracy in paper mm where it
//! is made (a trajectory's fit, an arc never: arcs are exact).

use crate::num::math;
use crate::num::tol;
use kurbo::{Arc, BezPath, CubicBez, ParamCurve, ParamCurveArclen, ParamCurveExtrema, PathSeg, Point, Rect};

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

    /// Whether no piece is an arc: its lines and cubics can be cut ([`Path::outside_rects`]).
    pub fn has_no_arc(&self) -> bool {
        self.segs.iter().all(|s| !matches!(s, Seg::Arc(_)))
    }

    /// The path without its parts inside the boxes `gaps`, as the runs left in order, each
    /// of lines and cubics (a closed path's closing line included); `None` where no box
    /// takes anything off it, or it has an arc.
    pub fn outside_rects(&self, gaps: &[Rect]) -> Option<Vec<Path>> {
        if !self.has_no_arc() {
            return None;
        }
        // A closed path's segments end with its closing line.
        let mut cut = false;
        let mut runs: Vec<Path> = Vec::new();
        for seg in self.to_bez().segments() {
            for kept in seg_outside_rects(seg, gaps, &mut cut) {
                match runs.last_mut() {
                    Some(run) if (run.end() - kept.start()).hypot2() < 1e-18 => run.segs.push(seg_of(kept)),
                    _ => {
                        let mut run = Path::new(kept.start());
                        run.segs.push(seg_of(kept));
                        runs.push(run);
                    }
                }
            }
        }
        cut.then_some(runs)
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

    /// The path's length along its pieces (mm, within [`tol::ARC_MEASURE`]).
    pub fn length(&self) -> f64 {
        self.to_bez().segments().map(|s| s.arclen(tol::ARC_MEASURE)).sum()
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

/// The parts of `seg` outside every box of `gaps`; `cut` is set when a part is left out.
fn seg_outside_rects(seg: PathSeg, gaps: &[Rect], cut: &mut bool) -> Vec<PathSeg> {
    let near: Vec<Rect> = gaps.iter().copied().filter(|g| g.overlaps(seg.bounding_box())).collect();
    if near.is_empty() {
        return vec![seg];
    }
    let mut ts = vec![0.0, 1.0];
    for g in &near {
        let corners = [(g.x0, g.y0), (g.x1, g.y0), (g.x1, g.y1), (g.x0, g.y1), (g.x0, g.y0)].map(Point::from);
        for side in corners.windows(2) {
            ts.extend(
                seg.intersect_line(kurbo::Line::new(side[0], side[1])).iter().map(|i| i.segment_t.clamp(0.0, 1.0)),
            );
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    let mut kept = Vec::new();
    for w in ts.windows(2) {
        let mid = seg.eval((w[0] + w[1]) / 2.0);
        if near.iter().any(|g| g.contains(mid)) {
            *cut = true;
        } else if w[1] > w[0] {
            kept.push(seg.subsegment(w[0]..w[1]));
        }
    }
    kept
}

/// A line or cubic piece as the path's own (it starts where the run before it ends).
fn seg_of(s: PathSeg) -> Seg {
    match s {
        PathSeg::Line(l) => Seg::Line(l.p1),
        PathSeg::Quad(q) => {
            let c = q.raise();
            Seg::Cubic(c.p1, c.p2, c.p3)
        }
        PathSeg::Cubic(c) => Seg::Cubic(c.p1, c.p2, c.p3),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::math::Norm;

    /// A closed triangle and a cubic cut by a box: what lies in the box is gone, the rest is
    /// kept in runs that join where the path did (the corner the box misses stays one run).
    #[test]
    fn a_path_cut_by_boxes_keeps_exactly_what_lies_outside_them() {
        let tri = Path::polyline(&[Point::new(0.0, 0.0), Point::new(10.0, 0.0), Point::new(10.0, 10.0)], true);
        let gap = Rect::new(4.0, -1.0, 6.0, 1.0);
        let runs = tri.outside_rects(&[gap]).expect("cut");
        assert_eq!(runs.len(), 2);
        assert_eq!(runs[0].start, Point::new(0.0, 0.0));
        assert_eq!(runs[0].end(), Point::new(4.0, 0.0));
        assert_eq!(runs[1].start, Point::new(6.0, 0.0));
        assert_eq!(runs[1].end(), Point::new(0.0, 0.0), "through both far corners and back to the start");
        assert_eq!(runs[1].segs.len(), 3);
        assert!(tri.outside_rects(&[Rect::new(20.0, 20.0, 30.0, 30.0)]).is_none(), "a box off it cuts nothing");
        let c = Path::cubics(&[CubicBez::new((0.0, 0.0), (0.0, 10.0), (10.0, 10.0), (10.0, 0.0))]);
        let runs = c.outside_rects(&[Rect::new(3.0, 5.0, 7.0, 9.0)]).expect("cut");
        assert_eq!(runs.len(), 2);
        for run in &runs {
            for s in run.to_bez().segments() {
                let mid = s.eval(0.5);
                assert!(!Rect::new(3.0, 5.0, 7.0, 9.0).inflate(-1e-9, -1e-9).contains(mid), "{mid:?} kept in the box");
            }
        }
        assert_eq!(runs[0].start, Point::new(0.0, 0.0));
        assert_eq!(runs[1].end(), Point::new(10.0, 0.0));
    }

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
