//! Cubic Bézier pieces for an exact parametric curve, with their deviation measured.
//!
//! Each piece passes through the curve's exact end points with its exact end tangent
//! directions; the two tangent lengths are the least-squares fit to the curve at interior
//! samples (linear in the lengths, so a 2×2 solve). This is several times more accurate than
//! plain Hermite lengths (h/3) and keeps the joins G1. The deviation is then measured, never
//! assumed: the largest distance from densely sampled exact points to the nearest point of
//! the pieces.

use super::math::Norm;
use super::tol;
use kurbo::{CubicBez, ParamCurveNearest, Point, Vec2};

/// The exact curve: its point and derivative at a parameter.
pub trait Exact: Fn(f64) -> (Vec2, Vec2) {}
impl<F: Fn(f64) -> (Vec2, Vec2)> Exact for F {}

/// Interior samples per piece for the tangent lengths.
const FIT_SAMPLES: usize = 16;
/// Exact samples per piece for measuring the deviation.
const MEASURE_SAMPLES: usize = 64;

/// The curve on [a, b] as `pieces` cubics of equal parameter length.
pub fn fit(exact: &impl Exact, a: f64, b: f64, pieces: usize) -> Vec<CubicBez> {
    let n = pieces.max(1);
    let h = (b - a) / n as f64;
    (0..n).map(|i| piece(exact, a + h * i as f64, if i + 1 == n { b } else { a + h * (i + 1) as f64 })).collect()
}

/// Rounds of re-matching the samples to their nearest points on the piece (Schneider's
/// reparameterisation): the fit then minimises geometric distance, not distance at equal
/// parameters (a quarter circle: 4e-3 → 3e-4 of its radius).
const REFITS: usize = 4;

fn piece(exact: &impl Exact, a: f64, b: f64) -> CubicBez {
    let h = b - a;
    let (p0, d0) = exact(a);
    let (p3, d3) = exact(b);
    let (t0, t1) = (d0 * h, d3 * h);
    let samples: Vec<Vec2> = (1..FIT_SAMPLES).map(|k| exact(a + h * k as f64 / FIT_SAMPLES as f64).0).collect();
    let mut us: Vec<f64> = (1..FIT_SAMPLES).map(|k| k as f64 / FIT_SAMPLES as f64).collect();
    let build = |(alpha, beta): (f64, f64)| {
        CubicBez::new(p0.to_point(), (p0 + t0 * alpha).to_point(), (p3 - t1 * beta).to_point(), p3.to_point())
    };
    let mut c = build(lengths(p0, p3, t0, t1, &samples, &us));
    for _ in 0..REFITS {
        for (u, s) in us.iter_mut().zip(&samples) {
            *u = nearest_from(&c, s.to_point(), *u, tol::NEAREST).0;
        }
        c = build(lengths(p0, p3, t0, t1, &samples, &us));
    }
    c
}

/// The tangent lengths (as fractions of the end derivatives × h) that fit `samples` at
/// the parameters `us` in least squares.
fn lengths(p0: Vec2, p3: Vec2, t0: Vec2, t1: Vec2, samples: &[Vec2], us: &[f64]) -> (f64, f64) {
    let bern = |u: f64| {
        let v = 1.0 - u;
        [v * v * v, 3.0 * v * v * u, 3.0 * v * u * u, u * u * u]
    };
    // R(u) = E − [(b0 + b1)·P0 + (b2 + b3)·P3] = α·b1·T0 − β·b2·T1 in least squares.
    let (mut m00, mut m01, mut m11, mut r0, mut r1) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (&u, &e) in us.iter().zip(samples) {
        let [b0, b1, b2, b3] = bern(u);
        let res = e - (p0 * (b0 + b1) + p3 * (b2 + b3));
        let (ca, cb) = (t0 * b1, -(t1 * b2));
        m00 += ca.dot(ca);
        m01 += ca.dot(cb);
        m11 += cb.dot(cb);
        r0 += ca.dot(res);
        r1 += cb.dot(res);
    }
    let det = m00 * m11 - m01 * m01;
    let scale = m00.max(m11).max(f64::MIN_POSITIVE);
    let third = 1.0 / 3.0;
    let (alpha, beta) = if det > tol::SINGULAR * scale * scale {
        ((r0 * m11 - r1 * m01) / det, (m00 * r1 - m01 * r0) / det)
    } else if m11 > tol::SINGULAR * scale {
        // A zero tangent at the start (the involute's cusp): only β is free.
        (third, r1 / m11)
    } else if m00 > tol::SINGULAR * scale {
        (r0 / m00, third)
    } else {
        (third, third)
    };
    // A negative or runaway length would loop the piece: keep Hermite's then.
    let ok = |x: f64| x.is_finite() && x > 0.0 && x < 1.0;
    if ok(alpha) && ok(beta) { (alpha, beta) } else { (third, third) }
}

/// The largest distance from the exact curve (sampled densely on [a, b]) to the pieces, which
/// are [`fit`]'s: of equal parameter length, in order.
///
/// A sample is measured to its own piece and the two beside it (a joint's sample may be
/// nearest either side), not to every piece: the search was quadratic in the pieces. The
/// nearest of fewer pieces is never nearer, so the measure stays an upper bound. Each
/// distance is first found by Newton's steps from the sample's own parameter, which can
/// only find it larger; only a sample that would raise the largest so far is searched
/// globally (kurbo solves a quintic), so the result is the global search's.
pub fn deviation(exact: &impl Exact, a: f64, b: f64, cubics: &[CubicBez]) -> f64 {
    let n = MEASURE_SAMPLES * cubics.len().max(1);
    (0..=n).fold(0.0, |largest: f64, k| {
        let p = exact(a + (b - a) * k as f64 / n as f64).0.to_point();
        let own = k / MEASURE_SAMPLES;
        let near = &cubics[own.saturating_sub(1).min(cubics.len())..(own + 2).min(cubics.len())];
        let s = (k % MEASURE_SAMPLES) as f64 / MEASURE_SAMPLES as f64;
        let at =
            |i: usize, s: f64| cubics.get(i).map_or(f64::INFINITY, |c| nearest_from(c, p, s, tol::NEAREST_MEASURE).1);
        let before = own.checked_sub(1).map_or(f64::INFINITY, |i| at(i, 1.0));
        let newton = at(own, s).min(before).min(at(own + 1, 0.0));
        if newton <= largest { largest } else { largest.max(nearest_globally(near, p)) }
    })
}

/// The distance from `p` to the nearest point of the pieces, by kurbo's global search.
fn nearest_globally(cubics: &[CubicBez], p: Point) -> f64 {
    cubics.iter().map(|c| c.nearest(p, tol::NEAREST_MEASURE).distance_sq).fold(f64::INFINITY, f64::min).sqrt()
}

/// Newton's steps on the squared distance from the piece's parameter `s` at most.
const NEWTON_STEPS: usize = 16;

/// The parameter of the piece `c`'s point nearest `p` and its distance, found by Newton's
/// method on the squared distance from the parameter `s` (a sample's own, or its previous
/// match: a fitted piece follows the curve's parameter closely), kept within the piece;
/// kurbo's global search, to `accuracy`, where the steps do not settle on a minimum. A
/// local minimum is never nearer than the global one. (The global search solves a quintic;
/// done for every sample, it took half of sheet 3's time.)
fn nearest_from(c: &CubicBez, p: Point, mut s: f64, accuracy: f64) -> (f64, f64) {
    use kurbo::{ParamCurve, ParamCurveDeriv};
    let (d1, d2) = (c.deriv(), c.deriv().deriv());
    for _ in 0..NEWTON_STEPS {
        let off = c.eval(s) - p;
        let (v, a) = (d1.eval(s).to_vec2(), d2.eval(s).to_vec2());
        let (slope, curvature) = (off.dot(v), v.dot(v) + off.dot(a));
        if (s <= 0.0 && slope > 0.0) || (s >= 1.0 && slope < 0.0) {
            return (s, off.norm());
        }
        if curvature.is_nan() || curvature <= 0.0 {
            break;
        }
        let next = (s - slope / curvature).clamp(0.0, 1.0);
        if (next - s).abs() <= tol::NEWTON_PARAMETER {
            return (next, (c.eval(next) - p).norm());
        }
        s = next;
    }
    let found = c.nearest(p, accuracy);
    (found.t, found.distance_sq.sqrt())
}

/// A fit and its measured deviation.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    pub cubics: Vec<CubicBez>,
    pub deviation: f64,
}

/// The fewest pieces (1, 2, 4, … up to `max_pieces`) whose measured deviation is within `tol`.
pub fn fit_within(exact: &impl Exact, a: f64, b: f64, tol: f64, max_pieces: usize) -> Fitted {
    let mut n = 1;
    loop {
        let cubics = fit(exact, a, b, n);
        let dev = deviation(exact, a, b, &cubics);
        if dev <= tol || n >= max_pieces {
            return Fitted { cubics, deviation: dev };
        }
        n *= 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::math::{cos, sin};

    #[test]
    fn a_quarter_circle_fits_within_the_known_bound_and_better_than_hermite() {
        let circle = |t: f64| (Vec2::new(cos(t), sin(t)), Vec2::new(-sin(t), cos(t)));
        let q = std::f64::consts::FRAC_PI_2;
        let c = fit(&circle, 0.0, q, 1);
        let dev = deviation(&circle, 0.0, q, &c);
        // The best cubic for a quarter circle strays 2.7e-4 of the radius; Hermite's 1/3
        // lengths (0.5236 vs the optimal 0.5519) about 2.7e-3.
        assert!(dev < 6e-4, "{dev:e}");
        assert!(fit_within(&circle, 0.0, q, 1e-7, 64).deviation <= 1e-7);
    }

    /// The deviation measured piece by piece with Newton's steps against the plain
    /// definition: every sample's distance to the nearest point of all the pieces, by
    /// kurbo's global search. Never smaller (an upper bound), and equal to round-off.
    #[test]
    fn the_measured_deviation_is_the_global_nearest_distance() {
        let spiral = |t: f64| {
            let r = 1.0 + 0.3 * t;
            (Vec2::new(r * cos(t), r * sin(t)), Vec2::new(0.3 * cos(t) - r * sin(t), 0.3 * sin(t) + r * cos(t)))
        };
        for pieces in [1, 2, 3, 8, 32] {
            let c = fit(&spiral, 0.0, 5.0, pieces);
            let n = MEASURE_SAMPLES * pieces;
            let global = (0..=n)
                .map(|k| {
                    let p = spiral(5.0 * k as f64 / n as f64).0.to_point();
                    c.iter().map(|c| c.nearest(p, 1e-14).distance_sq).fold(f64::INFINITY, f64::min).sqrt()
                })
                .fold(0.0, f64::max);
            let measured = deviation(&spiral, 0.0, 5.0, &c);
            assert!(measured >= global * (1.0 - 1e-9), "{pieces}: {measured:e} < {global:e}");
            assert!(measured <= global * (1.0 + 1e-9) + 1e-15, "{pieces}: {measured:e} vs {global:e}");
        }
    }
}
