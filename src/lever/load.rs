//! Loads on sliders that depend on where the slider is in its stroke and which way it
//! moves: gas forces read from an indicator diagram, and the resistance of a working stroke.

use crate::num::math::Norm;
use crate::num::tol;
use kurbo::Vec2;

/// A diagram y(s) over the relative stroke s ∈ [0, 1], read by straight lines between its
/// points, as the course draws it from the printed table.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// (s, y) with s strictly increasing from 0 to 1.
    pub points: Vec<(f64, f64)>,
}

impl Curve {
    pub fn constant(y: f64) -> Self {
        Curve { points: vec![(0.0, y), (1.0, y)] }
    }

    /// The diagram's value at `s`, clamped to the stroke.
    pub fn at(&self, s: f64) -> f64 {
        let s = s.clamp(0.0, 1.0);
        let i = self.points.partition_point(|p| p.0 <= s).clamp(1, self.points.len() - 1);
        let ((s0, y0), (s1, y1)) = (self.points[i - 1], self.points[i]);
        y0 + (y1 - y0) * (s - s0) / (s1 - s0)
    }
}

/// What the load models, which decides its labels on the sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadKind {
    /// Gas pressure on a piston (P = p·πd²/4), pushing it away from the cylinder head.
    Gas,
    /// Useful resistance, against the motion on the working stroke.
    Resistance,
}

/// Which stroke a branch of a load diagram is; the sheet names it in its language.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stroke {
    /// The working stroke of a resistance load.
    Working,
    /// The return (idle) stroke of a resistance load.
    Idle,
    /// A compressor's piston moving towards the cylinder head (compression, delivery).
    TowardHead,
    /// A compressor's piston moving away from the head (expansion, suction).
    AwayFromHead,
    /// A four-stroke engine's strokes I–IV.
    Expansion,
    Exhaust,
    Intake,
    Compression,
}

/// One branch of the diagram: the force along [`Load::axis`] is `scale · curve(s)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Branch {
    pub curve: Curve,
    /// Newtons per unit of the curve, signed along the axis.
    pub scale: f64,
    /// Which stroke it is, for the sheet's legend.
    pub name: Stroke,
}

/// A load on the slider `point` of `link`, acting along its guide; or, with `swing`, on a
/// point of a rocker, square to its radius from the rocker's pivot (a jaw crusher's
/// crushing resistance at the jaw's point K).
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    pub kind: LoadKind,
    pub link: usize,
    pub point: usize,
    /// Unit vector along the guide from the stroke's origin (s = 0) to its other end.
    pub axis: Vec2,
    /// A point of the guide line.
    pub through: Vec2,
    /// The rocker the point swings with, for a load on a rocker (`axis` and `through` then
    /// unused).
    pub swing: Option<Swing>,
    /// Whether s is measured from the cylinder head: the stroke end farther from the crank
    /// pivot ([`Load::set_stroke`] turns the axis away from it).
    pub from_head: bool,
    /// Position of the origin extreme on the guide, as the dot product p·axis (m).
    pub origin: f64,
    /// Stroke H, m.
    pub stroke: f64,
    /// `[moving along the axis, moving against it]`.
    pub branches: [Branch; 2],
    /// Line of the project file that defines it (0 when unknown), for error messages.
    pub line: u64,
}

/// A rocker's point's path: the arc about `pivot`, its displacement S the arc's length
/// from `reference` (a unit direction from the pivot), positive in `sense` (+1:
/// counter-clockwise, the working stroke's sense of rotation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Swing {
    pub pivot: Vec2,
    pub reference: Vec2,
    pub sense: f64,
}

/// The load's value at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadValue {
    /// Relative stroke s = S/H.
    pub s: f64,
    /// Which branch applies (0: moving along the axis).
    pub branch: usize,
    /// The force on the slider, N.
    pub force: Vec2,
    /// The force along the path's positive sense at the point (the guide's axis, or the
    /// rocker's tangent turned the working stroke's way), N.
    pub along: f64,
}

impl Load {
    /// The point's displacement coordinate at `p`, m: p·axis along a guide; on a rocker the
    /// arc's length from the swing's reference, in its sense.
    pub fn coordinate(&self, p: Vec2) -> f64 {
        match self.swing {
            None => p.dot(self.axis),
            Some(w) => {
                let r = p - w.pivot;
                w.sense * crate::num::math::atan2(w.reference.cross(r), w.reference.dot(r)) * r.norm()
            }
        }
    }

    /// The unit direction in which the coordinate grows at `p`: the guide's axis, or the
    /// rocker's tangent there (the coordinate's rate is v·direction).
    pub fn direction(&self, p: Vec2) -> Vec2 {
        match self.swing {
            None => self.axis,
            Some(w) => {
                let r = p - w.pivot;
                r.turn_90() * (w.sense / r.norm())
            }
        }
    }

    /// Fixes the stroke from the extremes `lo` < `hi` of the coordinate over a turn.
    pub fn set_stroke(&mut self, lo: f64, hi: f64, crank_pivot: Vec2) {
        let at = |t: f64| self.through + self.axis * (t - self.through.dot(self.axis));
        let (lo, hi) = if self.from_head && (at(hi) - crank_pivot).norm() > (at(lo) - crank_pivot).norm() {
            self.axis = -self.axis;
            (-hi, -lo)
        } else {
            (lo, hi)
        };
        self.origin = lo;
        self.stroke = hi - lo;
    }

    /// The force at slider position `p` moving with velocity `v` (acceleration `a` decides
    /// the branch at a dead point, where the slider is about to move that way).
    pub fn value(&self, p: Vec2, v: Vec2, a: Vec2) -> LoadValue {
        let s = ((self.coordinate(p) - self.origin) / self.stroke).clamp(0.0, 1.0);
        let dir = self.direction(p);
        let speed = v.dot(dir);
        // At a dead centre (speed ≈ 0 on the scale √(a·H)) the slider moves next the way its
        // acceleration points (a rocker's point too: its normal acceleration is nil there).
        let at_rest = speed.abs() <= tol::ZERO_SPEED * (a.norm() * self.stroke).sqrt();
        let going = if at_rest { a.dot(dir) } else { speed };
        let branch = if going >= 0.0 { 0 } else { 1 };
        let b = &self.branches[branch];
        let along = b.scale * b.curve.at(s);
        LoadValue { s, branch, force: dir * along, along }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curve_interpolates_and_clamps() {
        let c = Curve { points: vec![(0.0, 1.0), (0.5, 0.0), (1.0, 0.5)] };
        assert_eq!(c.at(0.25), 0.5);
        assert_eq!(c.at(0.75), 0.25);
        assert_eq!(c.at(1.0), 0.5);
        assert_eq!(c.at(-1.0), 1.0);
        assert_eq!(c.at(2.0), 0.5);
    }

    /// A rocker's point 2 m from the pivot (1, 1), working clockwise from the reference
    /// direction +x: at 30° below it, S = 2·π/6 along the arc, the force square to the
    /// radius, against a clockwise motion (the working stroke) and along a counter-clockwise one.
    #[test]
    fn a_rockers_load_acts_square_to_its_radius_by_the_arcs_travel() {
        let b =
            |scale: f64, name: Stroke| Branch { curve: Curve { points: vec![(0.0, 0.0), (1.0, 1.0)] }, scale, name };
        let swing = Swing { pivot: Vec2::new(1.0, 1.0), reference: Vec2::new(1.0, 0.0), sense: -1.0 };
        let load = Load {
            kind: LoadKind::Resistance,
            link: 0,
            point: 0,
            axis: Vec2::ZERO,
            through: Vec2::ZERO,
            swing: Some(swing),
            from_head: false,
            origin: 0.0,
            stroke: 4.0 * std::f64::consts::PI / 6.0,
            branches: [b(-100.0, Stroke::Working), b(0.0, Stroke::Idle)],
            line: 0,
        };
        let (c, s) = (3f64.sqrt() / 2.0, 0.5);
        let p = Vec2::new(1.0 + 2.0 * c, 1.0 - 2.0 * s);
        assert!((load.coordinate(p) - 2.0 * std::f64::consts::PI / 6.0).abs() < 1e-15);
        // Clockwise: the velocity turned −90° from the radius.
        let cw = Vec2::new(-s, -c);
        let working = load.value(p, cw, Vec2::ZERO);
        assert_eq!(working.branch, 0);
        assert!((working.s - 0.5).abs() < 1e-15);
        assert!((working.force - cw * -50.0).norm() < 1e-12, "{:?}", working.force);
        assert!(working.force.dot(p - swing.pivot).abs() < 1e-12);
        assert!((working.along + 50.0).abs() < 1e-12);
        let idle = load.value(p, -cw, Vec2::ZERO);
        assert_eq!((idle.branch, idle.force.norm()), (1, 0.0));
    }

    #[test]
    fn branch_follows_the_direction_of_motion() {
        let axis = Vec2::new(1.0, 0.0);
        let b = |scale: f64, name: Stroke| Branch { curve: Curve::constant(1.0), scale, name };
        let load = Load {
            kind: LoadKind::Resistance,
            link: 0,
            point: 0,
            axis,
            through: Vec2::ZERO,
            swing: None,
            from_head: false,
            origin: 0.0,
            stroke: 2.0,
            branches: [b(-10.0, Stroke::Working), b(3.0, Stroke::Idle)],
            line: 0,
        };
        let fwd = load.value(Vec2::new(1.0, 0.0), Vec2::new(1.0, 0.0), Vec2::ZERO);
        assert_eq!((fwd.s, fwd.branch, fwd.force.x), (0.5, 0, -10.0));
        let back = load.value(Vec2::new(1.0, 0.0), Vec2::new(-1.0, 0.0), Vec2::ZERO);
        assert_eq!((back.branch, back.force.x), (1, 3.0));
        let dead = load.value(Vec2::new(2.0, 0.0), Vec2::ZERO, Vec2::new(-1.0, 0.0));
        assert_eq!((dead.s, dead.branch), (1.0, 1));
    }
}
