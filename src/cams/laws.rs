//! The follower's laws of motion, exact: each a normalised rise s(x) over the phase
//! x = φ/φ_phase ∈ [0, 1] with s(0) = 0, s(1) = 1, and its derivatives s′, s″ with respect
//! to x (a caller scales: ds/dφ = h·s′/φ_p, d²s/dφ² = h·s″/φ_p²). The return phase is the
//! mirror 1 − s(x).
//!
//! The guide numbers six acceleration-analog laws in an appendix whose figure is lost; this
//! table defines them (every one is antisymmetric about the middle of the phase, so the
//! second half is the first mirrored: s(1 − x) = 1 − s(x)):
//!
//! | no. | key | acceleration s″ on the first half | C_v = max s′ | C_a = max s″ |
//! |---|---|---|---|---|
//! | 1 | `uniform-acceleration` | constant 4 | 2 | 4 |
//! | 2 | `linearly-decreasing` | 6(1 − 2x), from +6 to −6 | 1.5 | 6 |
//! | 3 | `cosine` | (π²/2)·cos πx | π/2 | π²/2 |
//! | 4 | `sine` (cycloidal) | 2π·sin 2πx | 2 | 2π |
//! | 5 | `triangular` | up to 8 at x = ¼, down to 0 at ½ | 2 | 8 |
//! | 6 | `trapezoid` | up over [0, ⅛], 16/3 over [⅛, ⅜], down to 0 at ½ | 2 | 16/3 |
//! | – | `polynomial-345` | 60x − 180x² + 120x³ | 1.875 | 10/√3 |
//! | – | `modified-trapezoid` | A·sin 4πx to ⅛, A to ⅜, A·cos 4π(x − ⅜) to ½ | 2 | 8π/(2 + π) |
//! | – | `modified-sine` | A·sin 4πx to ⅛, A·cos ⁴⁄₃π(x − ⅛) to ½ | 4π/(π + 4) | 4π²/(π + 4) |
//!
//! Each plateau or amplitude A is fixed by s(½) = ½; integrating the pieces gives
//! s(½) = A·(2 + π)/(16π) for the modified trapezoid and A·(π + 4)/(8π²) for the modified sine.
//!
//! The peaks follow from the closed forms (tested against these values and numerically).
//!
//! A project file may redefine any of these, or add its own, as an acceleration analog drawn
//! through corners ([`Custom`]): the figure of the guide's appendix is lost, so a teacher
//! whose appendix shows another law 5 can give it. [`Law`] is either kind.

use crate::num::digits::sig;
use crate::num::math::{cos, sin};
use crate::num::tol;
use std::f64::consts::PI;
use std::sync::Arc;

pub use super::custom_law::{Custom, LawError};

/// A law of the built-in table, by its key in a project file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Standard {
    UniformAcceleration,
    LinearlyDecreasing,
    Cosine,
    Sine,
    Triangular,
    Trapezoid,
    Polynomial345,
    ModifiedTrapezoid,
    ModifiedSine,
}

/// s, s′ and s″ at one x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derivs {
    pub s: f64,
    pub ds: f64,
    pub dds: f64,
}

/// Usual names of the laws, written as [`normalised`] leaves them.
const SYNONYMS: [(&str, Standard); 39] = [
    ("uniformly-accelerated", Standard::UniformAcceleration),
    ("constant-acceleration", Standard::UniformAcceleration),
    ("parabolic", Standard::UniformAcceleration),
    ("tekis-tezlanuvchan", Standard::UniformAcceleration),
    ("равноускоренный", Standard::UniformAcceleration),
    ("параболический", Standard::UniformAcceleration),
    ("linearly-decreasing-acceleration", Standard::LinearlyDecreasing),
    ("chiziqli-kamayuvchi", Standard::LinearlyDecreasing),
    ("линейно-убывающий", Standard::LinearlyDecreasing),
    ("cosinusoidal", Standard::Cosine),
    ("simple-harmonic", Standard::Cosine),
    ("harmonic", Standard::Cosine),
    ("garmonik", Standard::Cosine),
    ("гармонический", Standard::Cosine),
    ("kosinusoidal", Standard::Cosine),
    ("косинусоидальный", Standard::Cosine),
    ("косинусный", Standard::Cosine),
    ("cycloidal", Standard::Sine),
    ("sine-cycloidal", Standard::Sine),
    ("sinusoidal", Standard::Sine),
    ("sikloidal", Standard::Sine),
    ("синусоидальный", Standard::Sine),
    ("циклоидальный", Standard::Sine),
    ("uchburchakli", Standard::Triangular),
    ("треугольный", Standard::Triangular),
    ("trapezoidal", Standard::Trapezoid),
    ("trapetsiyali", Standard::Trapezoid),
    ("трапецеидальный", Standard::Trapezoid),
    ("трапециевидный", Standard::Trapezoid),
    ("3-4-5-polynomial", Standard::Polynomial345),
    ("3-4-5", Standard::Polynomial345),
    ("3-4-5-polinomial", Standard::Polynomial345),
    ("полином-3-4-5", Standard::Polynomial345),
    ("modifikatsiyalangan-trapetsiya", Standard::ModifiedTrapezoid),
    ("модифицированная-трапеция", Standard::ModifiedTrapezoid),
    ("modifikatsiyalangan-sinusoida", Standard::ModifiedSine),
    ("модифицированная-синусоида", Standard::ModifiedSine),
    ("modified-sinusoidal", Standard::ModifiedSine),
    ("modified-trapezoidal", Standard::ModifiedTrapezoid),
];

/// A law's name as looked up: trimmed, lower case, words joined by single `-` (a comma
/// between them too: the English sheet prints "sine, cycloidal").
fn normalised(key: &str) -> String {
    let lower = key.trim().to_lowercase();
    let words = lower.split(|c: char| c.is_whitespace() || c == '_' || c == '-' || c == ',').filter(|w| !w.is_empty());
    words.collect::<Vec<_>>().join("-")
}

/// The trapezoid's plateau: s(½) = ½ fixes it at 16/3.
const TRAPEZOID_A: f64 = 16.0 / 3.0;
/// The modified trapezoid's plateau, 8π/(2 + π) ≈ 4.888.
const MOD_TRAPEZOID_A: f64 = 8.0 * PI / (2.0 + PI);
/// The modified sine's amplitude, 4π²/(π + 4) ≈ 5.528.
const MOD_SINE_A: f64 = 4.0 * PI * PI / (PI + 4.0);

impl Standard {
    pub const ALL: [Standard; 9] = [
        Standard::UniformAcceleration,
        Standard::LinearlyDecreasing,
        Standard::Cosine,
        Standard::Sine,
        Standard::Triangular,
        Standard::Trapezoid,
        Standard::Polynomial345,
        Standard::ModifiedTrapezoid,
        Standard::ModifiedSine,
    ];

    pub fn key(self) -> &'static str {
        match self {
            Standard::UniformAcceleration => "uniform-acceleration",
            Standard::LinearlyDecreasing => "linearly-decreasing",
            Standard::Cosine => "cosine",
            Standard::Sine => "sine",
            Standard::Triangular => "triangular",
            Standard::Trapezoid => "trapezoid",
            Standard::Polynomial345 => "polynomial-345",
            Standard::ModifiedTrapezoid => "modified-trapezoid",
            Standard::ModifiedSine => "modified-sine",
        }
    }

    /// The guide's number (1–6), none for the laws beyond the course.
    pub fn guide_number(self) -> Option<u8> {
        Standard::ALL[..6].iter().position(|&l| l == self).map(|i| i as u8 + 1)
    }

    /// A law by its key, the guide's number ("1"…"6") or a usual name in Uzbek, Russian or
    /// English (the names the sheets print among them: "cycloidal", "uniformly accelerated",
    /// "синусоидальный"), whatever its case and with spaces or `_` for `-`. A name as the
    /// sheet prints it, with the guide's number after it in brackets
    /// ("синусоидальный (4)"), is found when the number is that law's.
    pub fn by_key(key: &str) -> Option<Standard> {
        if let Some((name, number)) = key.trim().strip_suffix(')').and_then(|k| k.rsplit_once('(')) {
            let law = Standard::by_name(name)?;
            return law.guide_number().is_some_and(|n| number.trim() == n.to_string()).then_some(law);
        }
        Standard::by_name(key)
    }

    /// [`Standard::by_key`] without the guide's number in brackets.
    fn by_name(key: &str) -> Option<Standard> {
        let key = normalised(key);
        Standard::ALL
            .into_iter()
            .find(|l| l.key() == key || l.guide_number().is_some_and(|n| n.to_string() == key))
            .or_else(|| SYNONYMS.iter().find(|(name, _)| *name == key).map(|&(_, l)| l))
    }

    /// s, s′, s″ at x; outside [0, 1] the dwell's values (s = 0 or 1, s′ = s″ = 0).
    pub fn eval(self, x: f64) -> Derivs {
        if x.is_nan() || x <= 0.0 {
            return Derivs { s: 0.0, ds: 0.0, dds: 0.0 };
        }
        if x >= 1.0 {
            return Derivs { s: 1.0, ds: 0.0, dds: 0.0 };
        }
        if x <= 0.5 {
            self.first_half(x)
        } else {
            let d = self.first_half(1.0 - x);
            Derivs { s: 1.0 - d.s, ds: d.ds, dds: -d.dds }
        }
    }

    /// The closed form on [0, ½].
    fn first_half(self, x: f64) -> Derivs {
        let d = |s, ds, dds| Derivs { s, ds, dds };
        match self {
            Standard::UniformAcceleration => d(2.0 * x * x, 4.0 * x, 4.0),
            Standard::LinearlyDecreasing => d(x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x), 6.0 - 12.0 * x),
            Standard::Cosine => d((1.0 - cos(PI * x)) / 2.0, PI / 2.0 * sin(PI * x), PI * PI / 2.0 * cos(PI * x)),
            Standard::Sine => {
                let w = 2.0 * PI * x;
                d(x - sin(w) / (2.0 * PI), 1.0 - cos(w), 2.0 * PI * sin(w))
            }
            Standard::Triangular => {
                if x <= 0.25 {
                    d(16.0 * x * x * x / 3.0, 16.0 * x * x, 32.0 * x)
                } else {
                    // From the middle: u = ½ − x, s″ = 32u, s′ = 2 − 16u², s = ½ − 2u + 16u³/3.
                    let u = 0.5 - x;
                    d(0.5 - 2.0 * u + 16.0 * u * u * u / 3.0, 2.0 - 16.0 * u * u, 32.0 * u)
                }
            }
            Standard::Trapezoid => {
                let a = TRAPEZOID_A;
                if x <= 0.125 {
                    d(4.0 * a * x * x * x / 3.0, 4.0 * a * x * x, 8.0 * a * x)
                } else if x <= 0.375 {
                    let t = x - 0.125;
                    d(a / 384.0 + a / 16.0 * t + a * t * t / 2.0, a / 16.0 + a * t, a)
                } else {
                    let u = 0.5 - x;
                    d(0.5 - 2.0 * u + 4.0 * a * u * u * u / 3.0, 2.0 - 4.0 * a * u * u, 8.0 * a * u)
                }
            }
            Standard::Polynomial345 => {
                let (x2, x3) = (x * x, x * x * x);
                d(
                    x3 * (10.0 - 15.0 * x + 6.0 * x2),
                    30.0 * x2 * (1.0 - x) * (1.0 - x),
                    60.0 * x * (1.0 - x) * (1.0 - 2.0 * x),
                )
            }
            Standard::ModifiedTrapezoid => {
                let a = MOD_TRAPEZOID_A;
                let k = 4.0 * PI;
                // The end of the first sine ramp, where the plateau starts.
                let (v1, s1) = (a / k, a * (1.0 / (8.0 * k) - 1.0 / (k * k)));
                if x <= 0.125 {
                    d(a * (x / k - sin(k * x) / (k * k)), a * (1.0 - cos(k * x)) / k, a * sin(k * x))
                } else if x <= 0.375 {
                    let t = x - 0.125;
                    d(s1 + v1 * t + a * t * t / 2.0, v1 + a * t, a)
                } else {
                    let (v2, s2) = (v1 + a / 4.0, s1 + v1 / 4.0 + a / 32.0);
                    let t = x - 0.375;
                    d(s2 + v2 * t + a * (1.0 - cos(k * t)) / (k * k), v2 + a * sin(k * t) / k, a * cos(k * t))
                }
            }
            Standard::ModifiedSine => {
                let a = MOD_SINE_A;
                let k = 4.0 * PI;
                if x <= 0.125 {
                    d(a * (x / k - sin(k * x) / (k * k)), a * (1.0 - cos(k * x)) / k, a * sin(k * x))
                } else {
                    let (v1, s1) = (a / k, a * (1.0 / (8.0 * k) - 1.0 / (k * k)));
                    let (q, t) = (k / 3.0, x - 0.125);
                    d(s1 + v1 * t + a * (1.0 - cos(q * t)) / (q * q), v1 + a * sin(q * t) / q, a * cos(q * t))
                }
            }
        }
    }

    /// The peak coefficients (max |s′|, max |s″|), from the closed forms.
    pub fn peaks(self) -> (f64, f64) {
        match self {
            Standard::UniformAcceleration => (2.0, 4.0),
            Standard::LinearlyDecreasing => (1.5, 6.0),
            Standard::Cosine => (PI / 2.0, PI * PI / 2.0),
            Standard::Sine => (2.0, 2.0 * PI),
            Standard::Triangular => (2.0, 8.0),
            Standard::Trapezoid => (2.0, TRAPEZOID_A),
            // s″ peaks where 6x² − 6x + 1 = 0: x = ½ − √3/6, value 10/√3.
            Standard::Polynomial345 => (1.875, 10.0 / 3f64.sqrt()),
            Standard::ModifiedTrapezoid => (2.0, MOD_TRAPEZOID_A),
            Standard::ModifiedSine => (4.0 * PI / (PI + 4.0), MOD_SINE_A),
        }
    }
}

/// A law of motion: one of the built-in table's, or one a project file defines.
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    Standard(Standard),
    Custom(Arc<Custom>),
}

impl From<Standard> for Law {
    fn from(s: Standard) -> Law {
        Law::Standard(s)
    }
}

impl From<Custom> for Law {
    fn from(c: Custom) -> Law {
        Law::Custom(Arc::new(c))
    }
}

impl Law {
    /// The key a project file names it by.
    pub fn key(&self) -> &str {
        match self {
            Law::Standard(s) => s.key(),
            Law::Custom(c) => c.key(),
        }
    }

    /// The guide's number (1–6), if it is (or redefines) one of the guide's laws.
    pub fn guide_number(&self) -> Option<u8> {
        match self {
            Law::Standard(s) => s.guide_number(),
            Law::Custom(c) => c.guide_number(),
        }
    }

    /// s, s′, s″ at x; outside [0, 1] the dwell's values (s = 0 or 1, s′ = s″ = 0).
    pub fn eval(&self, x: f64) -> Derivs {
        match self {
            Law::Standard(s) => s.eval(x),
            Law::Custom(c) => c.eval(x),
        }
    }

    /// The peak coefficients (max |s′|, max |s″|).
    pub fn peaks(&self) -> (f64, f64) {
        match self {
            Law::Standard(s) => s.peaks(),
            Law::Custom(c) => c.peaks(),
        }
    }
}

/// The follower's program over a turn: rise, far dwell, return, near dwell (the rest).
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// Phase angles, radians.
    pub rise: f64,
    pub far_dwell: f64,
    pub ret: f64,
    pub rise_law: Law,
    pub return_law: Law,
    /// The lift: metres (translating follower) or radians of swing (rocker).
    pub lift: f64,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProgramError {
    #[error("the {phase} phase must be a positive angle, not {}°", sig(*.deg, 6))]
    Phase { phase: &'static str, deg: f64 },
    #[error("the far dwell must be an angle ≥ 0, not {}°", sig(*.0, 6))]
    Dwell(f64),
    #[error("rise + far dwell + return = {}° exceeds a turn (360°)", sig(*.0, 6))]
    OverTurn(f64),
    #[error("the lift must be positive and finite, not {}", sig(*.0, 6))]
    Lift(f64),
}

impl Program {
    pub fn new(
        rise: f64,
        far_dwell: f64,
        ret: f64,
        laws: (impl Into<Law>, impl Into<Law>),
        lift: f64,
    ) -> Result<Program, ProgramError> {
        for (phase, a) in [("rise", rise), ("return", ret)] {
            if !(a.is_finite() && a > 0.0) {
                return Err(ProgramError::Phase { phase, deg: a.to_degrees() });
            }
        }
        if !(far_dwell.is_finite() && far_dwell >= 0.0) {
            return Err(ProgramError::Dwell(far_dwell.to_degrees()));
        }
        let total = rise + far_dwell + ret;
        if total > 2.0 * PI + tol::ANGLE_ROUND_OFF {
            return Err(ProgramError::OverTurn(total.to_degrees()));
        }
        if !(lift.is_finite() && lift > 0.0) {
            return Err(ProgramError::Lift(lift));
        }
        Ok(Program { rise, far_dwell, ret, rise_law: laws.0.into(), return_law: laws.1.into(), lift })
    }

    /// s(φ), ds/dφ, d²s/dφ² in the lift's unit (per radian), φ taken modulo a turn from the
    /// start of the rise.
    pub fn at(&self, phi: f64) -> Derivs {
        let phi = if phi.is_finite() { phi.rem_euclid(2.0 * PI) } else { 0.0 };
        let h = self.lift;
        let scale = |d: Derivs, p: f64, sign: f64, base: f64| Derivs {
            s: base + sign * h * d.s,
            ds: sign * h * d.ds / p,
            dds: sign * h * d.dds / (p * p),
        };
        let back = self.rise + self.far_dwell;
        if phi < self.rise {
            scale(self.rise_law.eval(phi / self.rise), self.rise, 1.0, 0.0)
        } else if phi < back {
            Derivs { s: h, ds: 0.0, dds: 0.0 }
        } else if phi < back + self.ret {
            scale(self.return_law.eval((phi - back) / self.ret), self.ret, -1.0, h)
        } else {
            Derivs { s: 0.0, ds: 0.0, dds: 0.0 }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Standard::{self, *};

    #[test]
    fn the_names_the_sheets_print_are_keys_too() {
        for (name, law) in [
            ("cycloidal", Sine),
            ("Uniformly accelerated", UniformAcceleration),
            ("синусоидальный", Sine),
            ("Трапецеидальный", Trapezoid),
            ("tekis tezlanuvchan", UniformAcceleration),
            ("3-4-5 polynomial", Polynomial345),
            ("modified_sine", ModifiedSine),
            (" 4 ", Sine),
            ("SINE", Sine),
        ] {
            assert_eq!(Standard::by_key(name), Some(law), "{name}");
        }
        assert_eq!(Standard::by_key("cycloid-ish"), None);
    }
}
