//! The external involute pair, exact: every radius, thickness and the contact ratio in
//! closed form, the working pressure angle from inv α_w solved to full double precision.
//!
//! Shifted gears follow the standard (GOST 16532) system: the generating rack of
//! GOST 13755 (α, h_a*, c*) moved x·m away from the wheel's centre; the wheels are then
//! set at the centre distance of zero backlash, and their tips shortened by Δy·m so that the
//! radial clearance stays c*·m.

use crate::num::digits::{fixed, sig};
use crate::num::math::{acos, cbrt, cos, sin, tan};
use crate::num::units::mm;
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

/// The pair, exact.
#[derive(Debug, Clone, PartialEq)]
pub struct Pair {
    pub spec: PairSpec,
    pub wheels: [Wheel; 2],
    /// α_w, radians.
    pub working_pressure_angle: f64,
    /// a_w, metres.
    pub centre_distance: f64,
    /// a = m(z1 + z2)/2.
    pub reference_centre_distance: f64,
    /// Centre-distance coefficient y = (a_w − a)/m.
    pub y: f64,
    /// Tip shortening coefficient Δy = x1 + x2 − y.
    pub delta_y: f64,
    /// u = z2/z1.
    pub ratio: f64,
    /// p = π·m.
    pub pitch: f64,
    /// p_b = π·m·cos α.
    pub base_pitch: f64,
    /// h = r_a − r_f (the same on both wheels).
    pub tooth_height: f64,
    /// The theoretical line of action N1N2 = a_w·sin α_w.
    pub line_of_action: f64,
    /// The active part B1B2 between the tip circles.
    pub active_length: f64,
    /// Distances from the pitch point P along the line of action to B1 (toward N1) and B2
    /// (toward N2), metres; B1B2 = both.
    pub approach: f64,
    pub recess: f64,
    /// ε_α = B1B2 / p_b.
    pub contact_ratio: f64,
    /// Whether wheel i's tip reaches past the other wheel's N (the active line is then cut
    /// at N and the other wheel must be undercut to turn).
    pub interference: [bool; 2],
}

/// Why a pair cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PairError {
    #[error("z{wheel} = {z}: a wheel needs at least 5 teeth")]
    TooFewTeeth { wheel: usize, z: u32 },
    #[error("the module must be positive and finite, not {} m", sig(*.0, 6))]
    Module(f64),
    #[error("{field} = {} is outside {range}", sig(*.value, 6))]
    Parameter { field: &'static str, value: f64, range: &'static str },
    #[error(
        "the shifts x1 + x2 = {} give inv α_w = {} < 0: the wheels cannot mesh without backlash at any centre distance (raise x1 + x2 above {})",
        sig(*.sum, 6),
        sig(*.inv_w, 4),
        fixed(*.limit, 4)
    )]
    NoWorkingAngle { sum: f64, inv_w: f64, limit: f64 },
    #[error(
        "wheel {wheel}'s teeth are pointed: the tip thickness is {} mm (lower x{wheel} = {})",
        fixed(*.s_a_mm, 3),
        sig(*.x, 6)
    )]
    Pointed { wheel: usize, s_a_mm: f64, x: f64 },
    #[error(
        "the contact ratio is {} < 1: the mesh is not continuous (B1B2 shorter than the base pitch)",
        fixed(*.eps, 3)
    )]
    NotContinuous { eps: f64 },
}

impl Pair {
    pub fn new(spec: &PairSpec) -> Result<Pair, PairError> {
        crate::num::work::count(crate::num::work::Step::GearPair);
        validate(spec)?;
        let m = spec.module;
        let alpha = spec.pressure_angle;
        let [z1, z2] = spec.z.map(f64::from);
        let sum_x = spec.shift[0] + spec.shift[1];
        let inv_w = 2.0 * sum_x * tan(alpha) / (z1 + z2) + inv(alpha);
        let alpha_w = inv_inverse(inv_w).ok_or(PairError::NoWorkingAngle {
            sum: sum_x,
            inv_w,
            limit: -inv(alpha) * (z1 + z2) / (2.0 * tan(alpha)),
        })?;
        let a = m * (z1 + z2) / 2.0;
        let a_w = a * cos(alpha) / cos(alpha_w);
        let y = (a_w - a) / m;
        let delta_y = sum_x - y;
        let wheel = |i: usize| wheel(spec, i, delta_y, alpha_w);
        let wheels = [wheel(0), wheel(1)];
        for (i, w) in wheels.iter().enumerate() {
            if w.tip_thickness <= 0.0 {
                return Err(PairError::Pointed { wheel: i + 1, s_a_mm: mm(w.tip_thickness), x: w.shift });
            }
        }
        let line = a_w * sin(alpha_w);
        // Along the line of action from P: N1 at −r_b1·tan α_w, N2 at +r_b2·tan α_w; the tip
        // circle of wheel 2 cuts it at B1 (approach), that of wheel 1 at B2 (recess).
        let reach = |w: &Wheel| (w.tip * w.tip - w.base * w.base).sqrt();
        // A tip reaching past the other wheel's N meets it below the involute (undercut
        // root): the involute contact, and so the active line, ends at N.
        let interference = [reach(&wheels[0]) > line, reach(&wheels[1]) > line];
        let recess = reach(&wheels[0]).min(line) - wheels[0].base * tan(alpha_w);
        let approach = reach(&wheels[1]).min(line) - wheels[1].base * tan(alpha_w);
        let base_pitch = PI * m * cos(alpha);
        let active = approach + recess;
        let contact_ratio = active / base_pitch;
        if contact_ratio < 1.0 {
            return Err(PairError::NotContinuous { eps: contact_ratio });
        }
        Ok(Pair {
            spec: spec.clone(),
            interference,
            tooth_height: wheels[0].tip - wheels[0].root,
            wheels,
            working_pressure_angle: alpha_w,
            centre_distance: a_w,
            reference_centre_distance: a,
            y,
            delta_y,
            ratio: z2 / z1,
            pitch: PI * m,
            base_pitch,
            line_of_action: line,
            active_length: active,
            approach,
            recess,
            contact_ratio,
        })
    }

    /// Things the sheet must say about this pair: undercut, thin tips, a low contact ratio.
    pub fn warnings(&self) -> Vec<PairWarning> {
        let mut out = Vec::new();
        for (i, w) in self.wheels.iter().enumerate() {
            // By the course's rule; the exact limit is information (the note gives both).
            if w.undercut_by_course() {
                out.push(PairWarning::Undercut { wheel: i + 1, x: w.shift, x_min: w.x_min_course, exact: w.x_min });
            }
            if w.tip_thickness < 0.25 * self.spec.module {
                out.push(PairWarning::ThinTip { wheel: i + 1, s_a: w.tip_thickness, limit: 0.25 * self.spec.module });
            }
        }
        for (i, &hit) in self.interference.iter().enumerate() {
            if hit {
                out.push(PairWarning::Interference { wheel: i + 1 });
            }
        }
        if self.contact_ratio < 1.2 {
            out.push(PairWarning::LowContactRatio { eps: self.contact_ratio });
        }
        out
    }
}

/// Input that builds a pair a designer would not accept without a second look.
#[derive(Debug, Clone, PartialEq)]
pub enum PairWarning {
    /// Below the course's least shift `x_min`; `exact` is the exact limit.
    Undercut { wheel: usize, x: f64, x_min: f64, exact: f64 },
    /// s_a < 0.25·m.
    ThinTip { wheel: usize, s_a: f64, limit: f64 },
    /// ε < 1.2.
    LowContactRatio { eps: f64 },
    /// Wheel `wheel`'s tip reaches past the other wheel's N: contact there is off the
    /// involute (the other wheel's undercut root).
    Interference { wheel: usize },
}

fn validate(spec: &PairSpec) -> Result<(), PairError> {
    if !(spec.module.is_finite() && spec.module > 0.0) {
        return Err(PairError::Module(spec.module));
    }
    for (i, &z) in spec.z.iter().enumerate() {
        if z < 5 {
            return Err(PairError::TooFewTeeth { wheel: i + 1, z });
        }
    }
    let checks = [
        ("pressure_angle_deg", spec.pressure_angle.to_degrees(), 10.0, 35.0, "10°…35°"),
        ("addendum", spec.addendum, 0.5, 1.5, "0.5…1.5"),
        ("clearance", spec.clearance, 0.05, 0.5, "0.05…0.5"),
        ("shift[0]", spec.shift[0], -1.5, 2.0, "−1.5…2"),
        ("shift[1]", spec.shift[1], -1.5, 2.0, "−1.5…2"),
    ];
    for (field, value, lo, hi, range) in checks {
        if !(value.is_finite() && value >= lo && value <= hi) {
            return Err(PairError::Parameter { field, value, range });
        }
    }
    Ok(())
}

fn wheel(spec: &PairSpec, i: usize, delta_y: f64, alpha_w: f64) -> Wheel {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inv_inverse_returns_the_angle_to_the_last_bits() {
        // tan α − α cancels (by a factor 3/α² at small α), so the solve is exact when its
        // residual is within the rounding of tan α and of α itself (inv changes by tan² α per unit of α).
        for deg in [0.5, 5.0, 14.5, 20.0, 26.0886, 40.0, 60.0, 80.0] {
            let a = f64::to_radians(deg);
            let v = inv(a);
            let back = inv_inverse(v).unwrap();
            let t = tan(back);
            assert!(
                (inv(back) - v).abs() <= 2.0 * f64::EPSILON * (t + t * t * back),
                "{deg}: residual {:e}",
                inv(back) - v
            );
            assert!((back - a).abs() <= 1e-11 * a, "{deg}: {back} vs {a}");
        }
        assert_eq!(inv_inverse(-1e-3), None);
        assert_eq!(inv_inverse(f64::NAN), None);
    }
}
