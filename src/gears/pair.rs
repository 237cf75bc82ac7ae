//! The external involute pair, exact: every radius, thickness and the contact ratio in
//! closed form, the working pressure angle from inv α_w solved to full double precision.
//!
//! Shifted gears follow the standard (GOST 16532) system: the generating rack of
//! GOST 13755 (α, h_a*, c*) moved x·m away from the wheel's centre; the wheels are then
//! set at the centre distance of zero backlash, and their tips shortened by Δy·m so that the
//! radial clearance stays c*·m.

pub use super::wheel::{PairSpec, Wheel, inv, inv_inverse};

use super::tooth::Outline;
use super::wheel::wheel;
use crate::num::digits::{fixed, sig};
use crate::num::math::{cos, sin, tan};
use crate::num::units::mm;
use std::f64::consts::PI;

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
    /// Whether wheel i's tip reaches past where the other wheel's involute begins (the
    /// active line is then cut there: the tip meets the other wheel's root fillet).
    pub interference: [bool; 2],
    /// The radius where each wheel's involute begins, as the rack cuts it: the form circle,
    /// or higher where an undercut root's fillet cuts the involute away; the base circle at
    /// the undercut limit.
    pub involute_from: [f64; 2],
    /// Each wheel's tooth outline as the rack cuts it: computed once here (the active line
    /// needs where its involute begins) and drawn by the sheet.
    pub outlines: [Outline; 2],
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
        // Each wheel's involute begins at `involute_from` (the form circle, or where an
        // undercut root's fillet cuts it), r_b·t from its N along the line. A tip reaching
        // past that point meets the other wheel below its involute: the involute contact,
        // and so the active line, ends there (at N when the involute reaches the base circle).
        let outlines = [0, 1].map(|i| Outline::new(spec, &wheels[i]));
        let lowest = [0, 1].map(|i| outlines[i].t_low * wheels[i].base);
        let reachable = [line - lowest[1], line - lowest[0]];
        let interference = [reach(&wheels[0]) > reachable[0], reach(&wheels[1]) > reachable[1]];
        let recess = reach(&wheels[0]).min(reachable[0]) - wheels[0].base * tan(alpha_w);
        let approach = reach(&wheels[1]).min(reachable[1]) - wheels[1].base * tan(alpha_w);
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
            involute_from: [0, 1].map(|i| outlines[i].lowest_radius()),
            outlines,
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
    /// Wheel `wheel`'s tip reaches past where the other wheel's involute begins: contact
    /// there is off the involute (the other wheel's root fillet, undercut or not).
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
