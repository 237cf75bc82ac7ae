//! One wheel of an external involute pair: the spec as given, each wheel's radii and
//! thicknesses in closed form, and the involute function with its inverse.

use crate::num::math::{acos, cbrt, cos, sin, tan};
use std::f64::consts::PI;

/// A shift this close below the course's limit is at it (5/17 computed two ways).
const AT_THE_LIMIT: f64 = 1e-12;

/// The involute function inv α = tan α − α.
pub fn inv(alpha: f64) -> f64 {
    tan(alpha) - alpha
}

/// The angle α in [0, π/2) whose involute function is `v` ≥ 0, to the last bit: Newton's
/// method from a cube-root start (inv α ≈ α³/3 near 0) converges monotonically because inv
/// is convex there; a bisection safeguard keeps it in the bracket.
pub fn inv_inverse(v: f64) -> Option<f64> {
    if !(v.is_finite() && v >= 0.0) {
        return None;
    }
    if v == 0.0 {
        return Some(0.0);
    }
    let (mut lo, mut hi) = (0.0_f64, PI / 2.0);
    let mut a = cbrt(3.0 * v).min(1.5);
    for _ in 0..100 {
        let f = inv(a) - v;
        if f > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        // d inv/dα = tan² α.
        let t = tan(a);
        let next = a - f / (t * t);
        let next = if next > lo && next < hi { next } else { 0.5 * (lo + hi) };
        if next == a || hi - lo <= f64::EPSILON * hi {
            return Some(next);
        }
        a = next;
    }
    Some(a)
}

/// The pair as the project file gives it, in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct PairSpec {
    /// Module m, metres.
    pub module: f64,
    pub z: [u32; 2],
    /// Profile shift coefficients x1, x2.
    pub shift: [f64; 2],
    /// α, radians.
    pub pressure_angle: f64,
    /// h_a*.
    pub addendum: f64,
    /// c*.
    pub clearance: f64,
}

impl PairSpec {
    /// The standard rack (α = 20°, h_a* = 1, c* = 0.25), no shift.
    pub fn standard(module: f64, z: [u32; 2]) -> PairSpec {
        PairSpec { module, z, shift: [0.0, 0.0], pressure_angle: 20f64.to_radians(), addendum: 1.0, clearance: 0.25 }
    }

    /// The rack cutter's tip radius coefficient ρ_f*: the largest round that leaves the
    /// cutter's straight flank reaching h_a*·m below its reference line, c*/(1 − sin α)
    /// (0.38 for the standard rack, as GOST 13755 gives).
    pub fn tip_round(&self) -> f64 {
        self.clearance / (1.0 - sin(self.pressure_angle))
    }

    /// The smallest shift without undercut for `z` teeth: h_a* − z·sin²α/2 (the straight
    /// flank of the rack ends at h_a*·m below its reference line and must not pass the
    /// foot N of the line of action). The course rounds the limit z = 2h_a*/sin²α = 17.1 to 17.
    pub fn x_min(&self, z: u32) -> f64 {
        let s = sin(self.pressure_angle);
        self.addendum - f64::from(z) * s * s / 2.0
    }

    /// The course's rule for the least shift: x_min = h_a*·(z_min − z)/z_min with z_min the
    /// whole number of teeth at or below 2h_a*/sin²α (17 for α = 20°, h_a* = 1). It is what
    /// the sheet tabulates, notes and `shift: auto` chooses; at z = 17, x = 0 (the guide's
    /// pinion) the exact rule [`PairSpec::x_min`] finds an undercut of a hair the course
    /// ignores.
    pub fn x_min_course(&self, z: u32) -> f64 {
        let s = sin(self.pressure_angle);
        let z_min = (2.0 * self.addendum / (s * s)).floor().max(1.0);
        self.addendum * (z_min - f64::from(z)) / z_min
    }
}

/// One wheel of the pair, metres.
#[derive(Debug, Clone, PartialEq)]
pub struct Wheel {
    pub z: u32,
    pub shift: f64,
    /// Pitch (reference) radius r = m·z/2.
    pub pitch: f64,
    pub base: f64,
    pub tip: f64,
    pub root: f64,
    /// Working pitch radius r_w = r_b / cos α_w.
    pub working: f64,
    /// Tooth thickness on the pitch circle, s = m(π/2 + 2x·tan α).
    pub tooth_thickness: f64,
    /// Tooth thickness on the tip circle (chordal arc length), s_a.
    pub tip_thickness: f64,
    /// The smallest shift without undercut, exact: the drawn outline follows it.
    pub x_min: f64,
    /// The course's least shift ([`PairSpec::x_min_course`]): the tables and notes use it.
    pub x_min_course: f64,
    /// Undercut by the exact rule (x < x_min): the outline is cut where fillet and involute
    /// cross.
    pub undercut: bool,
    /// The radius where the involute begins (the rack's straight flank ends there); the
    /// root fillet is below it. Equal to the base radius at the undercut limit.
    pub form_radius: f64,
}

impl Wheel {
    /// Below the course's least shift (what the sheet notes and tabulates); a shift this
    /// close below it is at it (1e-12: 5/17 computed two ways).
    pub fn undercut_by_course(&self) -> bool {
        self.shift < self.x_min_course - AT_THE_LIMIT
    }
}

pub(super) fn wheel(spec: &PairSpec, i: usize, delta_y: f64, alpha_w: f64) -> Wheel {
    let m = spec.module;
    let alpha = spec.pressure_angle;
    let z = spec.z[i];
    let x = spec.shift[i];
    let r = m * f64::from(z) / 2.0;
    let r_b = r * cos(alpha);
    let r_a = r + m * (spec.addendum + x - delta_y);
    let r_f = r - m * (spec.addendum + spec.clearance - x);
    let s = m * (PI / 2.0 + 2.0 * x * tan(alpha));
    let alpha_a = acos((r_b / r_a).min(1.0));
    let s_a = 2.0 * r_a * (s / (2.0 * r) + inv(alpha) - inv(alpha_a));
    let x_min = spec.x_min(z);
    // The rack's straight flank ends δ = (h_a* − x)·m inside the pitch circle; the point of
    // the wheel it generates lies on the line of action at r·sin α − δ/sin α from N.
    let delta = (spec.addendum - x) * m;
    let along = r * sin(alpha) - delta / sin(alpha);
    Wheel {
        z,
        shift: x,
        pitch: r,
        base: r_b,
        tip: r_a,
        root: r_f,
        working: r_b / cos(alpha_w),
        tooth_thickness: s,
        tip_thickness: s_a,
        x_min,
        x_min_course: spec.x_min_course(z),
        undercut: x < x_min,
        form_radius: (r_b * r_b + along.max(0.0) * along.max(0.0)).sqrt(),
    }
}
