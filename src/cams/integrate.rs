//! The course's graphical (chord) integration, done in numbers exactly as it is drawn.
//!
//! A phase is cut into n equal divisions. In each, the acceleration analog's ordinate at the
//! middle is carried to the y axis and joined to the pole at distance H1; the chord of the
//! velocity analog over the division is drawn parallel to that ray, so it rises by
//! a_mid·Δφ (the midpoint rule). The displacement is the velocity's chords integrated the
//! same way with pole H2; the chord's middle ordinate is the mean of its ends (the trapezoid
//! rule on the drawn velocity). The sums below are those constructions' ordinates in the
//! quantities' own units; the sheet multiplies by its scales.

use super::laws::Program;
use super::radius::Phase;

/// One phase integrated: the values at the n + 1 division points.
#[derive(Debug, Clone, PartialEq)]
pub struct Integrated {
    pub phase: Phase,
    /// φ at each division point, radians from the start of the rise.
    pub phi: Vec<f64>,
    /// d²s/dφ² at each division's middle (the ordinates the rays are drawn from).
    pub mid_dds: Vec<f64>,
    /// The integrated ds/dφ and s at the division points.
    pub ds: Vec<f64>,
    pub s: Vec<f64>,
}

/// The largest errors of the integrated curves against the exact law at the division points.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IntegrationError {
    pub divisions: usize,
    /// max |ds/dφ − exact|, in the lift's unit per radian.
    pub ds: f64,
    /// max |s − exact|, in the lift's unit.
    pub s: f64,
}

/// Integrates one phase of `program` with `n` divisions (n ≥ 1).
pub fn chords(program: &Program, phase: Phase, n: usize) -> Integrated {
    let n = n.max(1);
    let (a, b) = phase.span(program);
    let h = (b - a) / n as f64;
    let phi: Vec<f64> = (0..=n).map(|k| if k == n { b } else { a + h * k as f64 }).collect();
    let mid_dds: Vec<f64> = (0..n).map(|k| program.at(a + h * (k as f64 + 0.5)).dds).collect();
    let mut ds = vec![0.0; n + 1];
    let mut s = vec![program.at(a).s; n + 1];
    for k in 0..n {
        ds[k + 1] = ds[k] + mid_dds[k] * h;
        s[k + 1] = s[k] + (ds[k] + ds[k + 1]) / 2.0 * h;
    }
    Integrated { phase, phi, mid_dds, ds, s }
}

impl Integrated {
    /// The errors against the exact law. Each division point's exact value is the law's limit
    /// from inside the phase (the far-dwell side of the rise's end is the same value).
    pub fn error(&self, program: &Program) -> IntegrationError {
        let n = self.phi.len() - 1;
        let (mut ds, mut s) = (0.0f64, 0.0f64);
        for (k, &phi) in self.phi.iter().enumerate() {
            // Just inside the phase at its end: `at` belongs to the next part there.
            let inside = if k == n { phi - 1e-12 } else { phi };
            let exact = program.at(inside);
            ds = ds.max((self.ds[k] - exact.ds).abs());
            s = s.max((self.s[k] - exact.s).abs());
        }
        IntegrationError { divisions: n, ds, s }
    }
}
