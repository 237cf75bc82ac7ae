//! Closed-form solutions of the crank and the three class-II Assur dyads.
//!
//! Every function takes the already known points as [`Kin`] (position, velocity,
//! acceleration in SI units) and returns the new point together with the angular
//! motion of the dyad's links. Velocities and accelerations come from the analytic
//! derivative equations (2×2 linear systems), never from finite differences.
//!
//! Each dyad is a closed form over any [`Real`] (one crank angle, or several side by side in
//! SIMD lanes: [`super::lanes`]) that assumes the dyad assembles and returns what decides
//! whether it does, and a check of that (`…Shape::check`) on one angle. The dyad's lengths
//! and what follows from them alone are its shape, computed once.

use super::kin::{Kin, LinkKin};
use super::lanes::{KinOf, LinkOf, Real, V2};
use crate::num::digits::sig;
use crate::num::math;
use crate::num::tol::DEAD_POINT_SIN;
use kurbo::Vec2;

/// Why a dyad has no solution at the requested configuration.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DyadFailure {
    /// The two circles (or the circle and the guide line) do not meet.
    #[error(
        "the joints are {} m apart, the links reach only {}…{} m",
        sig(*.distance, 4),
        sig(*.reach_min, 4),
        sig(*.reach_max, 4)
    )]
    NoIntersection { distance: f64, reach_min: f64, reach_max: f64 },
    /// The dyad is exactly at a dead point (transmission angle 0° or 180°).
    #[error("transmission angle {}°", sig(*.transmission_deg, 3))]
    DeadPoint { transmission_deg: f64 },
    /// The slider block of a kulisa passes through the kulisa's pivot.
    #[error("the block is {} m from the kulisa pivot", sig(*.distance, 3))]
    BlockAtPivot { distance: f64 },
}

/// Result of an RRR or RRP dyad: the new point and its two links.
#[derive(Debug, Clone, Copy)]
pub struct DyadSolution {
    pub point: Kin,
    pub link_first: LinkKin,
    pub link_second: LinkKin,
}

/// A dyad's new point and its two links, for any [`Real`].
#[derive(Debug, Clone, Copy)]
pub struct Solved<T> {
    pub point: KinOf<T>,
    pub first: LinkOf<T>,
    pub second: LinkOf<T>,
}

impl From<Solved<f64>> for DyadSolution {
    #[inline(always)]
    fn from(s: Solved<f64>) -> Self {
        DyadSolution { point: s.point.into(), link_first: s.first.into(), link_second: s.second.into() }
    }
}

/// Crank `pivot → pin` of length `length` at absolute angle `theta` turning with the
/// constant signed angular velocity `omega` (counter-clockwise positive, ε = 0).
#[inline(always)]
pub fn crank(pivot: &Kin, length: f64, theta: f64, omega: f64) -> (Kin, LinkKin) {
    let (pin, link) = crank_of(&(*pivot).into(), length, 1.0 / length, theta, omega);
    (pin.into(), link.into())
}

/// [`crank`] for any [`Real`]; `inv_length` is `1 / length`.
#[inline(always)]
pub fn crank_of<T: Real>(
    pivot: &KinOf<T>,
    length: f64,
    inv_length: f64,
    theta: T,
    omega: f64,
) -> (KinOf<T>, LinkOf<T>) {
    let (sin, cos) = theta.sin_cos();
    let r = V2::new(cos, sin) * T::splat(length);
    let w = T::splat(omega);
    let pin = KinOf { p: pivot.p + r, v: pivot.v + r.turn_90() * w, a: pivot.a - r * T::splat(omega * omega) };
    // r / length as kurbo divides, by the reciprocal
    (pin, LinkOf { dir: r * T::splat(inv_length), omega: w, eps: T::splat(0.0) })
}

/// Solves `x·e1 + y·e2 = rhs` by Cramer's rule; `inv_det` is `1 / (e1 × e2)`, already
/// checked to be finite.
#[inline(always)]
fn solve2<T: Real>(e1: V2<T>, e2: V2<T>, rhs: V2<T>, inv_det: T) -> (T, T) {
    (rhs.cross(e2) * inv_det, e1.cross(rhs) * inv_det)
}

/// An RRR dyad's lengths and the constants its closed form takes from them.
#[derive(Debug, Clone, Copy)]
pub struct RrrShape {
    l_pb: f64,
    l_qb: f64,
    branch: f64,
    /// The reach: |l_pb − l_qb| and l_pb + l_qb, and their squares.
    lo: f64,
    hi: f64,
    lo2: f64,
    hi2: f64,
    l_pb2: f64,
    /// l_pb² − l_qb²
    diff2: f64,
    /// The smallest |r1 × r2| away from a dead point.
    dead: f64,
    inv_l_pb: f64,
    inv_l_qb: f64,
}

impl RrrShape {
    pub fn new(l_pb: f64, l_qb: f64, branch: f64) -> Self {
        let (lo, hi) = ((l_pb - l_qb).abs(), l_pb + l_qb);
        RrrShape {
            l_pb,
            l_qb,
            branch,
            lo,
            hi,
            lo2: lo * lo,
            hi2: hi * hi,
            l_pb2: l_pb * l_pb,
            diff2: l_pb * l_pb - l_qb * l_qb,
            dead: DEAD_POINT_SIN * l_pb * l_qb,
            inv_l_pb: 1.0 / l_pb,
            inv_l_qb: 1.0 / l_qb,
        }
    }

    /// Whether the dyad assembles, from [`rrr_of`]'s d² = |PQ|² and r1 × r2.
    #[inline(always)]
    pub fn check(&self, d2: f64, cross: f64) -> Result<(), DyadFailure> {
        if d2.is_nan() || d2 <= 0.0 || d2 > self.hi2 || d2 < self.lo2 {
            return Err(DyadFailure::NoIntersection { distance: d2.sqrt(), reach_min: self.lo, reach_max: self.hi });
        }
        if cross.abs() < self.dead {
            let sin_mu = cross / (self.l_pb * self.l_qb);
            return Err(DyadFailure::DeadPoint { transmission_deg: math::asin(sin_mu).to_degrees() });
        }
        Ok(())
    }
}

/// RRR dyad: point B joined to known P by a link of length `l_pb` and to known Q by
/// a link of length `l_qb`. `branch` is +1 when B lies to the left of the directed
/// line P→Q, −1 to the right. Links are returned as (P–B, Q–B) with angles of P→B and Q→B.
#[inline(always)]
pub fn rrr(p: &Kin, q: &Kin, l_pb: f64, l_qb: f64, branch: f64) -> Result<DyadSolution, DyadFailure> {
    let shape = RrrShape::new(l_pb, l_qb, branch);
    let (sol, d2, cross) = rrr_of(&(*p).into(), &(*q).into(), &shape);
    shape.check(d2, cross)?;
    Ok(sol.into())
}

/// [`rrr`] for any [`Real`], assuming it assembles; with d² and r1 × r2 for
/// [`RrrShape::check`].
#[inline(always)]
pub fn rrr_of<T: Real>(p: &KinOf<T>, q: &KinOf<T>, s: &RrrShape) -> (Solved<T>, T, T) {
    let pq = q.p - p.p;
    // In units of d = |PQ| (d² and 1/d², no square root of d on the way to B: the
    // solver's time is the chain of square roots and divisions from the crank to the last
    // dyad), B is `along` ahead of P on PQ and `high` off it.
    let d2 = pq.hypot2();
    let inv_d2 = T::splat(1.0) / d2;
    let along = T::splat(0.5) + T::splat(s.diff2) * (T::splat(0.5) * inv_d2);
    let high = (T::splat(s.l_pb2) * inv_d2 - along * along).max(T::splat(0.0)).sqrt();
    let b = p.p + pq * along + pq.turn_90() * (T::splat(s.branch) * high);
    let (r1, r2) = (b - p.p, b - q.p);
    let cross = r1.cross(r2); // l_pb·l_qb·sin(transmission angle)
    let inv_det = T::splat(-1.0) / cross; // reciprocal of the determinant of [perp r1, −perp r2]
    // v_P + ω1·perp(r1) = v_Q + ω2·perp(r2)
    let (w1, w2) = solve2(r1.turn_90(), -r2.turn_90(), q.v - p.v, inv_det);
    // a_P + ε1·perp(r1) − ω1²·r1 = a_Q + ε2·perp(r2) − ω2²·r2
    let rhs = (q.a - r2 * (w2 * w2)) - (p.a - r1 * (w1 * w1));
    let (e1, e2) = solve2(r1.turn_90(), -r2.turn_90(), rhs, inv_det);
    let point = KinOf { p: b, v: p.v + r1.turn_90() * w1, a: p.a + r1.turn_90() * e1 - r1 * (w1 * w1) };
    let first = LinkOf { dir: r1 * T::splat(s.inv_l_pb), omega: w1, eps: e1 };
    let second = LinkOf { dir: r2 * T::splat(s.inv_l_qb), omega: w2, eps: e2 };
    (Solved { point, first, second }, d2, cross)
}

/// An RRP dyad's rod, guide and branch, and the constants its closed form takes from them.
#[derive(Debug, Clone, Copy)]
pub struct RrpShape {
    l: f64,
    l2: f64,
    through: Vec2,
    dir: Vec2,
    branch: f64,
    /// The smallest |r · dir| away from a dead point.
    dead: f64,
    inv_l: f64,
}

impl RrpShape {
    pub fn new(l: f64, through: Vec2, dir: Vec2, branch: f64) -> Self {
        RrpShape { l, l2: l * l, through, dir, branch, dead: DEAD_POINT_SIN * l, inv_l: 1.0 / l }
    }

    /// Whether the dyad assembles, from [`rrp_of`]'s distance of P from the guide and the
    /// rod's projection on it.
    #[inline(always)]
    pub fn check(&self, h: f64, along: f64) -> Result<(), DyadFailure> {
        if h.abs() > self.l {
            return Err(DyadFailure::NoIntersection { distance: h.abs(), reach_min: 0.0, reach_max: self.l });
        }
        if along.abs() < self.dead {
            return Err(DyadFailure::DeadPoint { transmission_deg: math::asin(along / self.l).to_degrees() });
        }
        Ok(())
    }
}

/// RRP dyad: slider point D on a fixed guide line (through `through`, unit direction
/// `dir`) joined to the known point P by a rod of length `l`. `branch` is +1 when D lies
/// ahead of P's foot on the guide (along `dir`), −1 behind. Links: (rod P→D, slider).
#[inline(always)]
pub fn rrp(p: &Kin, l: f64, through: Vec2, dir: Vec2, branch: f64) -> Result<DyadSolution, DyadFailure> {
    let shape = RrpShape::new(l, through, dir, branch);
    let (sol, h, along) = rrp_of(&(*p).into(), &shape);
    shape.check(h, along)?;
    Ok(sol.into())
}

/// [`rrp`] for any [`Real`], assuming it assembles; with what [`RrpShape::check`] takes.
#[inline(always)]
pub fn rrp_of<T: Real>(p: &KinOf<T>, s: &RrpShape) -> (Solved<T>, T, T) {
    let (through, dir) = (V2::splat(s.through), V2::splat(s.dir));
    let w = p.p - through;
    let h = w.cross(dir); // signed distance of P from the guide
    let x = w.dot(dir) + T::splat(s.branch) * (T::splat(s.l2) - h * h).sqrt();
    let d = through + dir * x;
    let r = d - p.p;
    let along = r.dot(dir); // l·sin(transmission): a rod perpendicular to its guide is the dead point
    let inv_det = T::splat(-1.0) / along; // reciprocal of the determinant of [u, −perp r] = −u·r
    // ṡ·u − ω·perp(r) = v_P ;  s̈·u − ε·perp(r) = a_P − ω²·r
    let (sd, w) = solve2(dir, -r.turn_90(), p.v, inv_det);
    let (sdd, eps) = solve2(dir, -r.turn_90(), p.a - r * (w * w), inv_det);
    let point = KinOf { p: d, v: dir * sd, a: dir * sdd };
    let first = LinkOf { dir: r * T::splat(s.inv_l), omega: w, eps };
    let second = LinkOf { dir, omega: T::splat(0.0), eps: T::splat(0.0) };
    (Solved { point, first, second }, h, along)
}

/// RPR dyad (kulisa): a block pinned at the known point A slides along a kulisa that
/// turns about the known point C. Returns the kulisa's motion, the image point A3
/// (the point of the kulisa under A), and the relative sliding of the block.
#[derive(Debug, Clone, Copy)]
pub struct KulisaSolution {
    pub kulisa: LinkKin,
    pub a3: Kin,
    /// Distance C→A along the kulisa and its first and second time derivatives.
    pub slide: (f64, f64, f64),
}

/// [`KulisaSolution`] for any [`Real`].
#[derive(Debug, Clone, Copy)]
pub struct KulisaOf<T> {
    pub kulisa: LinkOf<T>,
    pub a3: KinOf<T>,
    pub slide: (T, T, T),
}

/// Whether the kulisa's direction is defined, from [`rpr_of`]'s distance C→A: `min_distance`
/// (m) is how close to the pivot the block may come.
#[inline(always)]
pub fn rpr_check(d: f64, min_distance: f64) -> Result<(), DyadFailure> {
    if d.is_nan() || d < min_distance {
        return Err(DyadFailure::BlockAtPivot { distance: d });
    }
    Ok(())
}

/// `min_distance` (m) is how close to the pivot the block may come before the kulisa's
/// direction is undefined.
#[inline(always)]
pub fn rpr(a: &Kin, c: &Kin, min_distance: f64) -> Result<KulisaSolution, DyadFailure> {
    let (sol, d) = rpr_of(&(*a).into(), &(*c).into());
    rpr_check(d, min_distance)?;
    Ok(KulisaSolution { kulisa: sol.kulisa.into(), a3: sol.a3.into(), slide: sol.slide })
}

/// [`rpr`] for any [`Real`], assuming the block is off the pivot; with the distance C→A for
/// [`rpr_check`].
#[inline(always)]
pub fn rpr_of<T: Real>(a: &KinOf<T>, c: &KinOf<T>) -> (KulisaOf<T>, T) {
    let ca = a.p - c.p;
    let d = ca.hypot2().sqrt();
    let e = ca / d;
    let n = e.turn_90();
    let (dv, da) = (a.v - c.v, a.a - c.a);
    let d_dot = dv.dot(e);
    let w = dv.dot(n) / d;
    let eps = (da.dot(n) - T::splat(2.0) * d_dot * w) / d;
    let d_ddot = da.dot(e) + d * w * w;
    let a3 = KinOf { p: a.p, v: c.v + n * (w * d), a: c.a + n * (eps * d) - e * (w * w * d) };
    (KulisaOf { kulisa: LinkOf { dir: e, omega: w, eps }, a3, slide: (d, d_dot, d_ddot) }, d)
}

/// A point fixed to a link: `distance` from a joint along the direction to another joint,
/// turned by an angle (see `Step::Attach`), with its sine and cosine found once.
#[derive(Debug, Clone, Copy)]
pub struct AttachShape {
    distance: f64,
    ratio: Option<f64>,
    /// sin and cos of the angle, None for 0: a point on the line of the joints stays exactly on it.
    turn: Option<(f64, f64)>,
}

impl AttachShape {
    pub fn new(distance: f64, angle: f64, ratio: Option<f64>) -> Self {
        AttachShape { distance, ratio, turn: (angle != 0.0).then(|| math::sin_cos(angle)) }
    }
}

/// The point of `link` placed by `shape` from the joint `base` toward the joint at `toward`.
#[inline(always)]
pub fn attach_of<T: Real>(base: &KinOf<T>, toward: V2<T>, link: &LinkOf<T>, shape: &AttachShape) -> KinOf<T> {
    let d = toward - base.p;
    let along = match shape.ratio {
        Some(k) => d * T::splat(k),
        None => d * (T::splat(shape.distance) / d.hypot2().sqrt()),
    };
    // math::rotate, its sine and cosine found once
    let r = match shape.turn {
        None => along,
        Some((s, c)) => {
            let (s, c) = (T::splat(s), T::splat(c));
            V2::new(c * along.x - s * along.y, s * along.x + c * along.y)
        }
    };
    KinOf {
        p: base.p + r,
        v: base.v + r.turn_90() * link.omega,
        a: base.a + r.turn_90() * link.eps - r * (link.omega * link.omega),
    }
}
