//! Closed-form solutions of the crank and the three class-II Assur dyads.
//!
//! Every function takes the already known points as [`Kin`] (position, velocity,
//! acceleration in SI units) and returns the new point together with the angular
//! motion of the dyad's links. Velocities and accelerations come from the analytic
//! derivative equations (2×2 linear systems), never from finite differences.

use super::kin::{Kin, LinkKin};
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

/// Crank `pivot → pin` of length `length` at absolute angle `theta` turning with the
/// constant signed angular velocity `omega` (counter-clockwise positive, ε = 0).
#[inline(always)]
pub fn crank(pivot: &Kin, length: f64, theta: f64, omega: f64) -> (Kin, LinkKin) {
    let r = math::from_angle(theta) * length;
    let pin = Kin { p: pivot.p + r, v: pivot.v + r.turn_90() * omega, a: pivot.a - r * (omega * omega) };
    (pin, LinkKin { dir: r / length, omega, eps: 0.0 })
}

/// Solves `x·e1 + y·e2 = rhs` by Cramer's rule; `inv_det` is `1 / (e1 × e2)`, already
/// checked to be finite.
fn solve2(e1: Vec2, e2: Vec2, rhs: Vec2, inv_det: f64) -> (f64, f64) {
    (rhs.cross(e2) * inv_det, e1.cross(rhs) * inv_det)
}

/// RRR dyad: point B joined to known P by a link of length `l_pb` and to known Q by
/// a link of length `l_qb`. `branch` is +1 when B lies to the left of the directed
/// line P→Q, −1 to the right. Links are returned as (P–B, Q–B) with angles of P→B and Q→B.
#[inline(always)]
pub fn rrr(p: &Kin, q: &Kin, l_pb: f64, l_qb: f64, branch: f64) -> Result<DyadSolution, DyadFailure> {
    let pq = q.p - p.p;
    // In units of d = |PQ| (d² and 1/d², no square root of d on the way to B: the
    // solver's time is the chain of square roots and divisions from the crank to the last
    // dyad), B is `along` ahead of P on PQ and `high` off it.
    let d2 = pq.hypot2();
    let (lo, hi) = ((l_pb - l_qb).abs(), l_pb + l_qb);
    if d2.is_nan() || d2 <= 0.0 || d2 > hi * hi || d2 < lo * lo {
        return Err(DyadFailure::NoIntersection { distance: d2.sqrt(), reach_min: lo, reach_max: hi });
    }
    let inv_d2 = 1.0 / d2;
    let along = 0.5 + (l_pb * l_pb - l_qb * l_qb) * (0.5 * inv_d2);
    let high = (l_pb * l_pb * inv_d2 - along * along).max(0.0).sqrt();
    let b = p.p + pq * along + pq.turn_90() * (branch * high);
    let (r1, r2) = (b - p.p, b - q.p);
    let cross = r1.cross(r2); // l_pb·l_qb·sin(transmission angle)
    if cross.abs() < DEAD_POINT_SIN * l_pb * l_qb {
        let sin_mu = cross / (l_pb * l_qb);
        return Err(DyadFailure::DeadPoint { transmission_deg: math::asin(sin_mu).to_degrees() });
    }
    let inv_det = -1.0 / cross; // reciprocal of the determinant of [perp r1, −perp r2]
    // v_P + ω1·perp(r1) = v_Q + ω2·perp(r2)
    let (w1, w2) = solve2(r1.turn_90(), -r2.turn_90(), q.v - p.v, inv_det);
    // a_P + ε1·perp(r1) − ω1²·r1 = a_Q + ε2·perp(r2) − ω2²·r2
    let rhs = (q.a - r2 * (w2 * w2)) - (p.a - r1 * (w1 * w1));
    let (e1, e2) = solve2(r1.turn_90(), -r2.turn_90(), rhs, inv_det);
    let point = Kin { p: b, v: p.v + r1.turn_90() * w1, a: p.a + r1.turn_90() * e1 - r1 * (w1 * w1) };
    Ok(DyadSolution {
        point,
        link_first: LinkKin { dir: r1 / l_pb, omega: w1, eps: e1 },
        link_second: LinkKin { dir: r2 / l_qb, omega: w2, eps: e2 },
    })
}

/// RRP dyad: slider point D on a fixed guide line (through `through`, unit direction
/// `dir`) joined to the known point P by a rod of length `l`. `branch` is +1 when D lies
/// ahead of P's foot on the guide (along `dir`), −1 behind. Links: (rod P→D, slider).
#[inline(always)]
pub fn rrp(p: &Kin, l: f64, through: Vec2, dir: Vec2, branch: f64) -> Result<DyadSolution, DyadFailure> {
    let w = p.p - through;
    let h = w.cross(dir); // signed distance of P from the guide
    if h.abs() > l {
        return Err(DyadFailure::NoIntersection { distance: h.abs(), reach_min: 0.0, reach_max: l });
    }
    let s = w.dot(dir) + branch * (l * l - h * h).sqrt();
    let d = through + dir * s;
    let r = d - p.p;
    let along = r.dot(dir); // l·sin(transmission): a rod perpendicular to its guide is the dead point
    if along.abs() < DEAD_POINT_SIN * l {
        return Err(DyadFailure::DeadPoint { transmission_deg: math::asin(along / l).to_degrees() });
    }
    let inv_det = -1.0 / along; // reciprocal of the determinant of [u, −perp r] = −u·r
    // ṡ·u − ω·perp(r) = v_P ;  s̈·u − ε·perp(r) = a_P − ω²·r
    let (sd, w) = solve2(dir, -r.turn_90(), p.v, inv_det);
    let (sdd, eps) = solve2(dir, -r.turn_90(), p.a - r * (w * w), inv_det);
    let point = Kin { p: d, v: dir * sd, a: dir * sdd };
    Ok(DyadSolution {
        point,
        link_first: LinkKin { dir: r / l, omega: w, eps },
        link_second: LinkKin { dir, omega: 0.0, eps: 0.0 },
    })
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

/// `min_distance` (m) is how close to the pivot the block may come before the kulisa's
/// direction is undefined.
#[inline(always)]
pub fn rpr(a: &Kin, c: &Kin, min_distance: f64) -> Result<KulisaSolution, DyadFailure> {
    let ca = a.p - c.p;
    let d = ca.hypot2().sqrt();
    if d.is_nan() || d < min_distance {
        return Err(DyadFailure::BlockAtPivot { distance: d });
    }
    let e = ca / d;
    let n = e.turn_90();
    let (dv, da) = (a.v - c.v, a.a - c.a);
    let d_dot = dv.dot(e);
    let w = dv.dot(n) / d;
    let eps = (da.dot(n) - 2.0 * d_dot * w) / d;
    let d_ddot = da.dot(e) + d * w * w;
    let a3 = Kin { p: a.p, v: c.v + n * (w * d), a: c.a + n * (eps * d) - e * (w * w * d) };
    Ok(KulisaSolution { kulisa: LinkKin { dir: e, omega: w, eps }, a3, slide: (d, d_dot, d_ddot) })
}
