//! The teeth of the mesh: each wheel's half-flank fitted once (the involute in a stated
//! number of Bézier pieces, the fillet within a tolerance), three teeth per wheel as one path
//! from the middle of a space to the middle of a space, the active flanks thick.

use crate::drawing::path::{Path, Seg};
use crate::drawing::scene::{Group, LineType, Pen};
use crate::drawing::view::View;
use crate::gears::tooth::Outline;
use crate::num::bezier;
use crate::num::math::{from_angle, rotate};
use crate::num::tol;

/// Active profiles and the active line of action (the mesh view draws the line with it).
pub(super) const ACTIVE: Pen = Pen { width: 1.2, line: LineType::Solid };
use kurbo::{Arc, CubicBez, Point, Vec2};
use std::f64::consts::PI;

/// Cubic pieces per involute flank (the measured deviation is stated on the sheet).
pub const INVOLUTE_PIECES: usize = 2;

/// One wheel's fitted half-flank (upper, in the tooth frame, from the root up to the tip).
pub(super) struct Flank {
    pub(super) fillet: Vec<CubicBez>,
    pub(super) involute: Vec<CubicBez>,
}

pub(super) fn flank(o: &Outline) -> (Flank, f64, f64) {
    let inv = |t: f64| o.involute(t);
    let fil = |phi: f64| o.fillet(phi);
    let involute = bezier::fit(&inv, o.t_low, o.t_tip, INVOLUTE_PIECES);
    let dev_i = bezier::deviation(&inv, o.t_low, o.t_tip, &involute);
    let f = bezier::fit_within(&fil, o.phi_root, o.phi_join, tol::FILLET_FIT, 64);
    (Flank { fillet: f.cubics, involute }, dev_i, f.deviation)
}

pub(super) fn map_cubic(c: &CubicBez, f: impl Fn(Vec2) -> Point) -> CubicBez {
    CubicBez::new(f(c.p0.to_vec2()), f(c.p1.to_vec2()), f(c.p2.to_vec2()), f(c.p3.to_vec2()))
}

fn reversed(cs: &[CubicBez]) -> Vec<CubicBez> {
    cs.iter().rev().map(|c| CubicBez::new(c.p3, c.p2, c.p1, c.p0)).collect()
}

/// Appends an arc about world centre `c` (radius r) from world angle a0 to a1.
fn push_arc(path: &mut Path, v: View, c: Vec2, r: f64, a0: f64, a1: f64) {
    if (a1 - a0).abs() < tol::ANGLE_ROUND_OFF {
        return;
    }
    path.segs.push(Seg::Arc(Arc::new(v.p(c), (v.len(r), v.len(r)), -a0, -(a1 - a0), 0.0)));
}

fn push_cubics(path: &mut Path, cs: &[CubicBez]) {
    path.segs.extend(cs.iter().map(|c| Seg::Cubic(c.p1, c.p2, c.p3)));
}

/// The outline of the teeth centred at world angles `centres` (ascending) of a wheel at `c`:
/// one path from the middle of the space before the first to the middle after the last.
pub(super) fn teeth_path(v: View, c: Vec2, o: &Outline, fl: &Flank, centres: &[f64]) -> Path {
    let half_space = PI / f64::from(o.z);
    let psi_a = o.tip_half_angle();
    let first = centres[0] - half_space;
    let mut path = Path::new(v.p(c + from_angle(first) * o.root));
    let mut at = first;
    for &cc in centres {
        let world = |mirror: bool| move |p: Vec2| v.p(c + rotate(if mirror { Vec2::new(p.x, -p.y) } else { p }, cc));
        push_arc(&mut path, v, c, o.root, at, cc - o.root_from);
        let lower = |cs: &[CubicBez]| cs.iter().map(|x| map_cubic(x, world(true))).collect::<Vec<_>>();
        push_cubics(&mut path, &lower(&fl.fillet));
        push_cubics(&mut path, &lower(&fl.involute));
        push_arc(&mut path, v, c, o.tip, cc - psi_a, cc + psi_a);
        let upper = |cs: &[CubicBez]| reversed(cs).iter().map(|x| map_cubic(x, world(false))).collect::<Vec<_>>();
        push_cubics(&mut path, &upper(&fl.involute));
        push_cubics(&mut path, &upper(&fl.fillet));
        at = cc + o.root_from;
        push_arc(&mut path, v, c, o.root, at, cc + half_space);
        at = cc + half_space;
    }
    path
}

/// The active part of the upper flanks (from radius `r_low` to the tip), thick.
pub(super) fn active_flanks(g: &mut Group, v: View, c: Vec2, o: &Outline, r_low: f64, centres: &[f64]) {
    let t0 = crate::gears::tooth::roll(o.base, r_low).max(o.t_low);
    let inv = |t: f64| o.involute(t);
    let cs = bezier::fit(&inv, t0, o.t_tip, INVOLUTE_PIECES);
    for &cc in centres {
        let pieces: Vec<CubicBez> = cs.iter().map(|x| map_cubic(x, |p| v.p(c + rotate(p, cc)))).collect();
        g.curve(Path::cubics(&pieces), ACTIVE);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gears::pair::{Pair, PairSpec};
    use crate::num::math::Norm;

    #[test]
    fn the_teeth_outline_is_one_continuous_path() {
        let spec = PairSpec::standard(0.005, [17, 19]);
        let pair = Pair::new(&spec).unwrap();
        let o = Outline::new(&spec, &pair.wheels[0]);
        let (fl, _, _) = flank(&o);
        let v = View::new(Point::new(400.0, 390.0), 1.0 / 6000.0);
        let path = teeth_path(v, Vec2::ZERO, &o, &fl, &[1.2, 1.57, 1.94]);
        let mut end = path.start;
        for s in &path.segs {
            if let Seg::Arc(a) = s {
                let start = crate::drawing::path::on_circle(a.center, a.radii.x, a.start_angle);
                assert!((start - end).norm() < 1e-9, "an arc starts {:e} mm off", (start - end).norm());
            }
            end = match s {
                Seg::Line(p) | Seg::Cubic(_, _, p) => *p,
                Seg::Arc(a) => crate::drawing::path::on_circle(a.center, a.radii.x, a.start_angle + a.sweep_angle),
            };
        }
    }
}
