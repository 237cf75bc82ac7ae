//! One tooth's outline as the generating rack cuts it, exact, in the wheel's frame (metres,
//! the tooth centred on the +x axis, angles counter-clockwise).
//!
//! The upper flank runs from the tip down: the involute (closed form in its roll angle t),
//! then the root fillet — the envelope of the rack tip's round as the rack rolls on the pitch
//! circle (the offset of a trochoid, not a circle arc) — then the root circle to the middle
//! of the space. The lower flank is its mirror image in the x axis. When the rack's straight
//! flank passes the foot N of the line of action (x < x_min) the fillet cuts into the
//! involute: the outline then takes the involute down to their crossing only (undercut).

use super::wheel::{PairSpec, Wheel, inv};
use crate::num::math::{Norm, acos, atan2, cos, from_angle, rotate, sin};
use crate::num::tol;
use kurbo::Vec2;
use std::f64::consts::PI;

/// The rack cutter of GOST 13755 in its own frame, relative to the wheel it cuts.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rack {
    /// Pitch radius of the wheel (the rack rolls on it).
    r: f64,
    /// The centre of the tip round of the cutter tooth's right side, rack frame: X along the
    /// rolling line from the cutter tooth's middle, Y up from the rolling line (negative:
    /// toward the wheel).
    centre: Vec2,
    rho: f64,
    alpha: f64,
}

/// The exact outline of one wheel's teeth.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    pub z: u32,
    pub base: f64,
    pub tip: f64,
    pub root: f64,
    /// The involute's origin on the base circle: the upper flank is
    /// r_b·(e(θ0 − t) + t·e(θ0 − t + π/2)), polar angle θ0 − inv α(t).
    pub theta0: f64,
    /// Roll angles of the involute's ends: at the tip, and where the fillet takes over.
    pub t_tip: f64,
    pub t_low: f64,
    /// The fillet's rack parameter φ: from its junction with the involute to the root circle.
    pub phi_join: f64,
    pub phi_root: f64,
    /// Half the angle of the root arc's end, where the fillet meets the root circle, and the
    /// half space angle π/z (the root arc runs between them).
    pub root_from: f64,
    pub undercut: bool,
    rack: Rack,
    /// Rotation from the rack's gap-on-+y frame to the tooth-on-+x frame.
    turn: f64,
}

/// A point of a curve and its derivative with respect to the curve's parameter.
pub type PointTangent = (Vec2, Vec2);

fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

impl Rack {
    fn of(spec: &PairSpec, w: &Wheel) -> Rack {
        let c = super::rack::Cutter::of(spec, w);
        Rack { r: w.pitch, centre: c.centre, rho: c.rho, alpha: c.alpha }
    }

    /// The fillet point generated at rack position φ, rack frame: on the tip round, on the
    /// normal through the pitch point (rφ, 0), on the far side from it; and d/dφ.
    fn fillet_rack(&self, phi: f64) -> PointTangent {
        let p = Vec2::new(self.r * phi, 0.0);
        let d = p - self.centre;
        let n = d.norm();
        let u = d / n;
        let dp = Vec2::new(self.r, 0.0);
        let du = (dp - u * u.dot(dp)) / n;
        (self.centre - u * self.rho, -du * self.rho)
    }

    /// A rack point and its φ-derivative taken into the wheel's frame (gap on +y).
    fn in_wheel_frame(&self, phi: f64, (f, df): PointTangent) -> PointTangent {
        let w = Vec2::new(f.x - self.r * phi, f.y + self.r);
        let dw = df - Vec2::new(self.r, 0.0);
        (rotate(w, -phi), rotate(dw - perp(w), -phi))
    }
}

impl Outline {
    pub fn new(spec: &PairSpec, w: &Wheel) -> Outline {
        let rack = Rack::of(spec, w);
        let alpha = spec.pressure_angle;
        let theta0 = w.tooth_thickness / (2.0 * w.pitch) + inv(alpha);
        let t_tip = roll(w.base, w.tip);
        // The fillet leaves the rack's straight flank where the round touches it.
        let phi_join = (rack.centre.x + rack.centre.y * cos(alpha) / sin(alpha)) / rack.r;
        let phi_root = rack.centre.x / rack.r;
        let z = w.z;
        let turn = -(PI / 2.0 - PI / f64::from(z));
        let mut o = Outline {
            z,
            base: w.base,
            tip: w.tip,
            root: w.root,
            theta0,
            t_tip,
            t_low: roll(w.base, w.form_radius.max(w.base)),
            phi_join,
            phi_root,
            root_from: 0.0,
            undercut: w.undercut,
            rack,
            turn,
        };
        o.root_from = o.fillet(phi_root).0.arg();
        if w.undercut {
            o.cut_by_fillet();
        }
        o
    }

    /// The upper flank's involute at roll angle t, and d/dt.
    pub fn involute(&self, t: f64) -> PointTangent {
        let b = self.theta0 - t;
        let p = (from_angle(b) + perp(from_angle(b)) * t) * self.base;
        (p, from_angle(b) * (self.base * t))
    }

    /// The upper flank's fillet at rack parameter φ, and d/dφ.
    pub fn fillet(&self, phi: f64) -> PointTangent {
        let (p, d) = self.rack.in_wheel_frame(phi, self.rack.fillet_rack(phi));
        (rotate(p, self.turn), rotate(d, self.turn))
    }

    /// The involute's polar angle at radius `r` ≥ r_b.
    pub fn involute_angle(&self, r: f64) -> f64 {
        self.theta0 - inv(acos((self.base / r).min(1.0)))
    }

    /// Half the tooth's angular thickness at the tip.
    /// The radius where the involute begins: the form circle, or where the undercut root's
    /// fillet cuts the involute.
    pub fn lowest_radius(&self) -> f64 {
        self.base * (1.0 + self.t_low * self.t_low).sqrt()
    }

    pub fn tip_half_angle(&self) -> f64 {
        self.involute_angle(self.tip)
    }

    /// Undercut: the fillet crosses the involute above the base circle; the outline keeps
    /// the involute above the crossing and the fillet below it. The crossing is found from
    /// the root side (the fillet's last crossing toward the tip is the outer one).
    fn cut_by_fillet(&mut self) {
        let gap = |phi: f64| {
            let p = self.fillet(phi).0;
            let r = p.norm();
            (r >= self.base).then(|| p.arg() - self.involute_angle(r))
        };
        let n = 2000;
        let step = (self.phi_join - self.phi_root) / n as f64;
        let mut prev: Option<(f64, f64)> = None;
        for i in 0..=n {
            let phi = self.phi_root + step * i as f64;
            let Some(g) = gap(phi) else {
                prev = None;
                continue;
            };
            if let Some((phi0, g0)) = prev
                && g0 * g <= 0.0
            {
                let (mut a, mut b, mut ga) = (phi0, phi, g0);
                for _ in 0..200 {
                    let mid = 0.5 * (a + b);
                    let gm = gap(mid).unwrap_or(ga);
                    if (gm <= 0.0) == (ga <= 0.0) {
                        a = mid;
                        ga = gm;
                    } else {
                        b = mid;
                    }
                    if (b - a).abs() <= tol::LAST_BIT * a.abs().max(tol::LAST_BIT_FLOOR) {
                        break;
                    }
                }
                let phi_x = 0.5 * (a + b);
                self.phi_join = phi_x;
                self.t_low = roll(self.base, self.fillet(phi_x).0.norm());
                return;
            }
            prev = Some((phi, g));
        }
    }
}

/// The roll angle t = tan α_r at which the involute reaches radius `r` (0 inside the base).
pub fn roll(base: f64, r: f64) -> f64 {
    if r <= base { 0.0 } else { ((r / base).powi(2) - 1.0).sqrt() }
}

/// The polar angle of a point, radians in (−π, π].
pub fn polar(p: Vec2) -> f64 {
    atan2(p.y, p.x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gears::pair::Pair;
    use crate::num::math::tan;

    fn outline(z: [u32; 2], x: [f64; 2]) -> (Pair, Outline) {
        let spec = PairSpec { shift: x, ..PairSpec::standard(0.005, z) };
        let pair = Pair::new(&spec).unwrap();
        let o = Outline::new(&spec, &pair.wheels[0]);
        (pair, o)
    }

    #[test]
    fn the_fillet_meets_the_involute_tangentially_and_the_root_circle() {
        for (z, x) in [([20, 40], [0.0, 0.0]), ([17, 19], [0.3, 0.1]), ([30, 30], [-0.3, 0.5])] {
            let (pair, o) = outline(z, x);
            assert!(!o.undercut);
            let (fp, fd) = o.fillet(o.phi_join);
            let (ip, id) = o.involute(o.t_low);
            assert!((fp - ip).norm() < 1e-12, "{z:?}: junction {:e}", (fp - ip).norm());
            let cross = fd.cross(id) / (fd.norm() * id.norm());
            assert!(cross.abs() < 1e-9, "{z:?}: tangents differ by {cross:e}");
            let root = o.fillet(o.phi_root).0;
            assert!((root.norm() - pair.wheels[0].root).abs() < 1e-12);
            // The root circle is tangent there: the fillet's tangent is perpendicular to the radius.
            let d = o.fillet(o.phi_root).1;
            assert!(d.dot(root).abs() / (d.norm() * root.norm()) < 1e-9);
        }
    }

    #[test]
    fn involute_points_lie_on_the_exact_involute() {
        let (_, o) = outline([17, 19], [0.0, 0.0]);
        for i in 0..=20 {
            let t = o.t_tip * f64::from(i) / 20.0;
            let (p, d) = o.involute(t);
            let r = p.norm();
            assert!((polar(p) - o.involute_angle(r)).abs() * r < 1e-15);
            // Its tangent is normal to the base circle's tangent line through the point.
            let foot = from_angle(o.theta0 - t) * o.base;
            assert!(d.dot(p - foot).abs() < 1e-15);
        }
    }

    #[test]
    fn an_undercut_wheel_is_cut_above_its_base_circle() {
        let (pair, o) = outline([10, 40], [0.0, 0.0]);
        assert!(o.undercut && pair.wheels[0].undercut);
        let p = o.fillet(o.phi_join).0;
        assert!(p.norm() > o.base, "crossing at {} vs base {}", p.norm(), o.base);
        let miss = polar(p) - o.involute_angle(p.norm());
        assert!(miss.abs() < 1e-12, "{miss:e} at {}", p.norm());
    }

    #[test]
    fn two_pieces_per_involute_stray_under_a_micrometre() {
        use crate::num::bezier;
        for (z, x) in [([17, 19], [0.0, 0.0]), ([12, 40], [0.5, 0.0]), ([60, 80], [0.0, 0.0])] {
            let (_, o) = outline(z, x);
            let inv = |t: f64| o.involute(t);
            let c = bezier::fit(&inv, o.t_low, o.t_tip, 2);
            let dev = bezier::deviation(&inv, o.t_low, o.t_tip, &c);
            eprintln!("{z:?}: {:.3e} m", dev);
            assert!(dev < 1e-6, "{z:?}: {dev:e} m");
        }
    }

    /// The outline against brute force: the rack cutter (flank, tip round, tip flat) placed at
    /// 20 000 positions as dense points; at each radius the tooth ends where the nearest rack
    /// point is. Independent of the envelope formulas; checks the undercut crossing too.
    #[test]
    fn the_outline_is_what_the_rack_leaves() {
        for (z, x) in [([10u32, 40u32], 0.0), ([12, 40], 0.0), ([17, 40], 0.0), ([14, 40], 0.3)] {
            let spec = PairSpec { shift: [x, 0.0], ..PairSpec::standard(1.0, z) };
            let pair = Pair::new(&spec).unwrap();
            let w = &pair.wheels[0];
            let o = Outline::new(&spec, w);
            let rack = Rack::of(&spec, w);
            let a = spec.pressure_angle;
            // The right side of the cutter tooth, rack frame.
            let mut pts = Vec::new();
            let t_y = rack.centre.y - rack.rho * sin(a);
            for i in 0..=400 {
                let y = t_y + (x + 1.0 - t_y) * f64::from(i) / 400.0;
                pts.push(Vec2::new(PI / 4.0 + (y - x) * tan(a), y));
            }
            for i in 0..=400 {
                let th = -PI / 2.0 + (PI / 2.0 - a) * f64::from(i) / 400.0;
                pts.push(rack.centre + Vec2::new(cos(th), sin(th)) * rack.rho);
            }
            let bins = 200;
            let (r_lo, r_hi) = (w.root + 0.02, w.tip - 0.02);
            let mut edge = vec![f64::INFINITY; bins];
            let n = 20_000;
            for k in 0..=n {
                let phi = -1.2 + 2.4 * f64::from(k) / f64::from(n);
                for &pt in &pts {
                    let q = rotate(rotate(Vec2::new(pt.x - rack.r * phi, pt.y + rack.r), -phi), o.turn);
                    let r = q.norm();
                    if r < r_lo || r >= r_hi {
                        continue;
                    }
                    let b = ((r - r_lo) / (r_hi - r_lo) * bins as f64) as usize;
                    edge[b.min(bins - 1)] = edge[b.min(bins - 1)].min(polar(q));
                }
            }
            let cross = o.fillet(o.phi_join).0.norm();
            let mut worst: f64 = 0.0;
            for (b, &e) in edge.iter().enumerate() {
                // The tooth narrows outward, so the rack's nearest point in a bin is at its top.
                let r = r_lo + (b as f64 + 1.0) * (r_hi - r_lo) / bins as f64;
                let ours = if r >= cross {
                    o.involute_angle(r)
                } else {
                    // The fillet's point at this radius (its radius grows toward the junction).
                    let (mut lo, mut hi) = (o.phi_root, o.phi_join);
                    for _ in 0..100 {
                        let m = 0.5 * (lo + hi);
                        if o.fillet(m).0.norm() < r { lo = m } else { hi = m }
                    }
                    polar(o.fillet(lo).0)
                };
                worst = worst.max(((e - ours) * r).abs());
            }
            // The bins are 0.01·m wide and the points 1/400 of a flank apart: a few thousandths of m.
            assert!(worst < 4e-3, "{z:?}, x = {x}: the outline is {worst:e}·m from what the rack leaves");
        }
    }
}
