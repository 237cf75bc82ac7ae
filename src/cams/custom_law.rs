//! A law of motion a project file defines: the acceleration analog s″(x) drawn straight
//! between corners (x, a) over the phase x ∈ [0, 1], as the course draws its laws. Two
//! corners at the same x make a jump (the rectangles of law 1). The velocity and the
//! displacement are its exact integrals, piecewise quadratic and cubic; the corners' a may be
//! in any unit, since the law is scaled so that s(1) = 1 (the shape is what a corner list
//! says, not its size).
//!
//! A shape is refused when it cannot be a rise from rest to rest: the areas above and below
//! the axis differ (the follower would not stop), the net area of the velocity is not
//! positive, or the velocity turns negative (the follower would move back during the rise).

use super::laws::{Derivs, Standard};
use crate::num::digits::sig;
use crate::num::tol;

/// A law given by its acceleration analog's corners, normalised to s(1) = 1.
#[derive(Debug, Clone, PartialEq)]
pub struct Custom {
    key: String,
    /// The built-in law it redefines, if any.
    replaces: Option<Standard>,
    /// The corners, x ascending; a scaled; v and s at each corner.
    x: Vec<f64>,
    a: Vec<f64>,
    v: Vec<f64>,
    s: Vec<f64>,
    peaks: (f64, f64),
}

/// Why a corner list is not a law of motion. `index` counts the corners from 0.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LawError {
    #[error("an acceleration analog needs at least two corners, not {0}")]
    TooFewCorners(usize),
    #[error("corner {index}: ({}, {}) is not a finite number pair", sig(*.x, 6), sig(*.a, 6))]
    NotFinite { index: usize, x: f64, a: f64 },
    #[error("the corners must run from x = 0 to x = 1 (the phase), not from {} to {}", sig(*.first, 6), sig(*.last, 6))]
    Ends { first: f64, last: f64 },
    #[error(
        "corner {index}: x = {} is below the corner before it ({}): x must not decrease",
        sig(*.x, 6),
        sig(*.prev, 6)
    )]
    Decreasing { index: usize, x: f64, prev: f64 },
    #[error("corner {index}: a third corner at x = {}; a jump takes exactly two corners", sig(*.x, 6))]
    TripleCorner { index: usize, x: f64 },
    #[error(
        "the velocity analog does not return to zero at the phase's end: the acceleration's net area is {} against its total area {} ({} of it, at most {}); the areas above and below the axis must be equal",
        sig(*.net, 3), sig(*.total, 6), sig(.net / .total, 2), sig(TOL, 1)
    )]
    VelocityDoesNotClose { net: f64, total: f64 },
    #[error(
        "this acceleration analog does not rise: the displacement it gives at the phase's end is {} (it must be positive; is the sign of a reversed?)",
        sig(*.0, 3)
    )]
    NoRise(f64),
    #[error(
        "the velocity analog is negative at x = {} ({} of the peak): the follower would move back during the rise",
        sig(*.x, 6), sig(*.v, 2)
    )]
    MovesBack { x: f64, v: f64 },
}

/// Relative tolerance of the closure and sign checks: the corners' own rounding, so that a law
/// copied from a figure to 6 significant digits is accepted. Each a written to 6 digits is off
/// by at most half a unit of its 6th digit, 5·10⁻⁶ of |a|; the net area, the integral of a, is
/// then off by at most 5·10⁻⁶ of the total area, the integral of |a|; twice that leaves room
/// for the x's rounding (multiples of 1/8 are exact). A law that speeds up once and slows down
/// once (its total area twice its peak velocity) is then left with at most 5·10⁻⁶ of its peak
/// velocity at the phase's end, which the law sets to zero: nothing a sheet can show.
const TOL: f64 = tol::CUSTOM_LAW_AREA;

impl Custom {
    /// A law from its corners (x, a); `replaces` names the built-in law it stands for.
    pub fn new(key: &str, replaces: Option<Standard>, corners: &[(f64, f64)]) -> Result<Custom, LawError> {
        let n = corners.len();
        if n < 2 {
            return Err(LawError::TooFewCorners(n));
        }
        if let Some(index) = corners.iter().position(|c| !c.0.is_finite() || !c.1.is_finite()) {
            let (x, a) = corners[index];
            return Err(LawError::NotFinite { index, x, a });
        }
        let (first, last) = (corners[0].0, corners[n - 1].0);
        if first != 0.0 || last != 1.0 {
            return Err(LawError::Ends { first, last });
        }
        for i in 1..n {
            let (x, prev) = (corners[i].0, corners[i - 1].0);
            if x < prev {
                return Err(LawError::Decreasing { index: i, x, prev });
            }
            if i >= 2 && x == prev && x == corners[i - 2].0 {
                return Err(LawError::TripleCorner { index: i, x });
            }
        }
        let x: Vec<f64> = corners.iter().map(|c| c.0).collect();
        let a: Vec<f64> = corners.iter().map(|c| c.1).collect();
        let (v, s) = integrate(&x, &a);
        let total: f64 =
            x.windows(2).zip(a.windows(2)).map(|(x, a)| (x[1] - x[0]) * (a[0].abs() + a[1].abs()) / 2.0).sum();
        let net = v[n - 1];
        if total == 0.0 || net.abs() > TOL * total {
            return Err(LawError::VelocityDoesNotClose { net, total });
        }
        let lift = s[n - 1];
        if lift.is_nan() || lift <= 0.0 {
            return Err(LawError::NoRise(lift));
        }
        let mut law = Custom {
            key: key.to_string(),
            replaces,
            a: a.iter().map(|a| a / lift).collect(),
            v: v.iter().map(|v| v / lift).collect(),
            s: s.iter().map(|s| s / lift).collect(),
            x,
            peaks: (0.0, 0.0),
        };
        // The last corner is the end of the rise exactly (the net area's rounding aside).
        law.s[n - 1] = 1.0;
        law.v[n - 1] = 0.0;
        let (v_min, at, v_max) = law.velocity_extremes();
        if v_min < -TOL * v_max {
            return Err(LawError::MovesBack { x: at, v: v_min / v_max });
        }
        law.peaks = (v_max, law.a.iter().fold(0.0f64, |m, a| m.max(a.abs())));
        Ok(law)
    }

    pub fn key(&self) -> &str {
        &self.key
    }

    /// The built-in law this one redefines.
    pub fn replaces(&self) -> Option<Standard> {
        self.replaces
    }

    pub fn guide_number(&self) -> Option<u8> {
        self.replaces.and_then(Standard::guide_number)
    }

    /// The corners as normalised (x, s″).
    pub fn corners(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.x.iter().copied().zip(self.a.iter().copied())
    }

    /// (max |s′|, max |s″|).
    pub fn peaks(&self) -> (f64, f64) {
        self.peaks
    }

    /// s, s′, s″ at x; outside [0, 1] the dwell's values. At a jump, s″ is the value after it.
    pub fn eval(&self, x: f64) -> Derivs {
        if x.is_nan() || x <= 0.0 {
            return Derivs { s: 0.0, ds: 0.0, dds: 0.0 };
        }
        if x >= 1.0 {
            return Derivs { s: 1.0, ds: 0.0, dds: 0.0 };
        }
        // The last corner at or before x: its segment reaches past x (x < 1 = the last x).
        let i = self.x.partition_point(|&c| c <= x) - 1;
        let (t, slope) = (x - self.x[i], self.slope(i));
        let a = self.a[i];
        Derivs {
            s: self.s[i] + self.v[i] * t + a * t * t / 2.0 + slope * t * t * t / 6.0,
            ds: self.v[i] + a * t + slope * t * t / 2.0,
            dds: a + slope * t,
        }
    }

    /// The acceleration's slope on the segment from corner i (0 on a jump).
    fn slope(&self, i: usize) -> f64 {
        let len = self.x[i + 1] - self.x[i];
        if len > 0.0 { (self.a[i + 1] - self.a[i]) / len } else { 0.0 }
    }

    /// The velocity's least value and where, and its largest |value|: at the corners and
    /// where the acceleration crosses zero inside a segment.
    fn velocity_extremes(&self) -> (f64, f64, f64) {
        let mut points: Vec<(f64, f64)> = self.x.iter().copied().zip(self.v.iter().copied()).collect();
        for i in 0..self.x.len() - 1 {
            let slope = self.slope(i);
            if slope != 0.0 {
                let t = -self.a[i] / slope;
                if t > 0.0 && t < self.x[i + 1] - self.x[i] {
                    points.push((self.x[i] + t, self.v[i] + self.a[i] * t / 2.0));
                }
            }
        }
        let (mut lo, mut at, mut hi) = (f64::INFINITY, 0.0, 0.0f64);
        for (x, v) in points {
            if v < lo {
                (lo, at) = (v, x);
            }
            hi = hi.max(v.abs());
        }
        (lo, at, hi)
    }
}

/// The velocity and displacement at each corner, from rest at x = 0: exact integrals of the
/// straight segments (a jump, two corners at one x, adds nothing).
fn integrate(x: &[f64], a: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let (mut v, mut s) = (vec![0.0; x.len()], vec![0.0; x.len()]);
    for i in 0..x.len() - 1 {
        let len = x[i + 1] - x[i];
        v[i + 1] = v[i] + (a[i] + a[i + 1]) / 2.0 * len;
        s[i + 1] = s[i] + v[i] * len + (2.0 * a[i] + a[i + 1]) * len * len / 6.0;
    }
    (v, s)
}
