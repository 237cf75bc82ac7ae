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
//!
//! The course's eight divisions leave a steep law's displacement off by several percent of
//! the lift (a 3-4-5 polynomial return after a cosine rise ended 4.5 % below the axis, a
//! negative lift no follower has, a teacher's review); the error falls as the square of the
//! chords, so where it is over [`CLOSE_ENOUGH`] each division is integrated in up to
//! [`MOST_CHORDS`] chords ([`turn_within`]), the positions staying every `chords`-th point.

use super::laws::Program;
use super::radius::Phase;
use crate::num::tol;

/// The course's divisions of each phase (the guide's eight).
pub const DIVISIONS: usize = 8;

/// The most chords a division is integrated in ([`turn_within`]).
pub const MOST_CHORDS: usize = 4;

/// The largest error of the drawn displacement [`turn_within`] accepts, a share of the lift:
/// a millimetre where the lift is drawn 100 mm high.
pub const CLOSE_ENOUGH: f64 = 0.01;

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
    /// Chords a division: the positions are every `chords`-th point, the first and the last
    /// included.
    pub chords: usize,
}

/// The largest errors of the integrated curves against the exact law at the division points.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IntegrationError {
    pub divisions: usize,
    /// Chords a division.
    pub chords: usize,
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
    turn_in_chords(program, n, 1)
}

/// [`turn`] with `n` divisions a phase, each integrated in `k` chords (k ≥ 1).
pub fn turn_in_chords(program: &Program, n: usize, k: usize) -> [Integrated; 2] {
    let k = k.max(1);
    let rise = chords(program, Phase::Rise, n * k);
    let end = (rise.s[rise.s.len() - 1], rise.ds[rise.ds.len() - 1]);
    let ret = chords_from(program, Phase::Return, n * k, end);
    [rise, ret].map(|i| Integrated { chords: k, ..i })
}

/// The turn with `n` divisions a phase in the fewest chords a division, up to
/// [`MOST_CHORDS`], whose drawn displacement is nowhere more than [`CLOSE_ENOUGH`] of the
/// lift off the exact law (the rise's error carried into the return counted).
pub fn turn_within(program: &Program, n: usize) -> [Integrated; 2] {
    let off = |t: &[Integrated; 2]| t.iter().map(|i| i.error(program).s).fold(0.0, f64::max);
    let mut t = turn(program, n);
    for k in 2..=MOST_CHORDS {
        if off(&t) <= CLOSE_ENOUGH * program.lift {
            break;
        }
        t = turn_in_chords(program, n, k);
    }
    t
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
    Integrated { phase, phi, mid_dds, ds, s, chords: 1 }
}

impl Integrated {
    /// The indices of the positions' points (every [`Integrated::chords`]-th).
    pub fn positions(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.phi.len()).step_by(self.chords.max(1))
    }

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
        IntegrationError { divisions: n / self.chords.max(1), chords: self.chords, ds, s }
    }
}
