//! The course's graphical (chord) integration, done in numbers exactly as it is drawn.
//!
//! A phase is cut into n equal divisions. In each, the acceleration analog's ordinate at the
//! middle is carried to the y axis and joined to the pole at distance H1; the chord of the
//! velocity analog over the division is drawn parallel to that ray, so it rises by
//! a_mid·Δφ (the midpoint rule). The displacement is the velocity's chords integrated the
//! same way with pole H2; the chord's middle ordinate is the mean of its ends (the trapezoid
//! rule on the drawn velocity). The sums below are those constructions' ordinates in the
//! quantities' own units; the sheet multiplies by its scales.
//!
//! The return is integrated on from where the drawn rise ended, as a hand drawing goes on
//! (the dwell adds nothing): the rise's error is carried, and for one law on both phases the
//! return's cancels it, so the drawn displacement closes at zero. What is left at the end of
//! the turn is the drawing's closure error ([`closure`]).

use super::laws::Program;
use super::radius::Phase;
use crate::num::tol;

/// The course's divisions of each phase (the guide's eight).
pub const DIVISIONS: usize = 8;

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

/// Integrates one phase of `program` with `n` divisions (n ≥ 1), from the exact values at
/// its start.
pub fn chords(program: &Program, phase: Phase, n: usize) -> Integrated {
    let start = program.at(phase.span(program).0).s;
    chords_from(program, phase, n, (start, 0.0))
}

/// Both phases as one drawing integrates them: the rise from rest at s = 0, the return from
/// the rise's drawn end.
pub fn turn(program: &Program, n: usize) -> [Integrated; 2] {
    let rise = chords(program, Phase::Rise, n);
    let end = (rise.s[rise.s.len() - 1], rise.ds[rise.ds.len() - 1]);
    let ret = chords_from(program, Phase::Return, n, end);
    [rise, ret]
}

/// The drawing's closure: the drawn (s, ds/dφ) at the end of the turn, which the exact law
/// brings back to (0, 0).
pub fn closure(turn: &[Integrated; 2]) -> (f64, f64) {
    let r = &turn[1];
    (r.s[r.s.len() - 1], r.ds[r.ds.len() - 1])
}

/// Integrates one phase with `n` divisions from the drawn (s, ds/dφ) at its start.
pub fn chords_from(program: &Program, phase: Phase, n: usize, start: (f64, f64)) -> Integrated {
    let n = n.max(1);
    let (a, b) = phase.span(program);
    let h = (b - a) / n as f64;
    let phi: Vec<f64> = (0..=n).map(|k| if k == n { b } else { a + h * k as f64 }).collect();
    let mid_dds: Vec<f64> = (0..n).map(|k| program.at(a + h * (k as f64 + 0.5)).dds).collect();
    let mut ds = vec![start.1; n + 1];
    let mut s = vec![start.0; n + 1];
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
            let inside = if k == n { phi - tol::INSIDE_PHASE } else { phi };
            let exact = program.at(inside);
            ds = ds.max((self.ds[k] - exact.ds).abs());
            s = s.max((self.s[k] - exact.s).abs());
        }
        IntegrationError { divisions: n, ds, s }
    }
}
