//! How large a cam can be, bounded in closed form before anything is sampled: a wrong unit or
//! a phase written as a thousandth of a degree makes a cam kilometres across, which the centre's
//! search (it works to an absolute 1e-12 m) and the sheet (GOST's smallest scale is 1:10 000)
//! cannot handle. [`check`] refuses such a cam naming what makes it large ([`Cause`]).
//!
//! **The bound.** In the follower frame (origin B₀, [`super::follower`]) let V be the largest
//! |ds/dφ| (a rocker's |dβ/dφ|) over both phases, h·C_v/φ_p with C_v the law's peak analog
//! coefficient, and R the distance from B₀ within which every analog point B′ lies: R = h + V
//! for a translating follower (B′ = (s′, s)), R = l·(2 sin(ψ/2) + V) for a rocker of length l
//! and swing ψ (B within the chord 2l·sin(ψ/2) of B₀, |B′ − B| = l·|dβ/dφ|). Seen along the
//! region's viewing direction ([`super::radius`]), a wedge's floor rises from its apex by at
//! most |u − u_B′|·cot γ, γ the smallest angle of a wedge's side to that direction: α_min for
//! a translating follower, α_min − ψ/2 for a rocker (its wedges turn with it by up to half the
//! swing; the region refuses ψ/2 ≥ α_min first). So
//! - a translating follower's apexes lie at or above B₀ (w = −s ≤ 0) with |u_B′| ≤ V: in the
//!   column of an offset e, W(e) ≤ (|e| + V)·cot α_min and r_min ≤ |e| + (|e| + V)·cot α_min;
//!   `auto` is no larger than e = 0;
//! - a rocker's r_min ≤ max(W(0), 0) ≤ R·(1 + cot γ).
//!
//! Everything the sheet draws round the cam centre O then lies within r_min + max(R, l) of it
//! (the profile, |B − O| ≤ |B − B₀| + r_min; the analog points; a rocker's pivot, l from B₀; a
//! roller, whose radius is below ρ_min, below the profile's largest radius). For a course cam
//! the bound is a few times the real size; it costs a handful of operations, not a sample.

use super::follower::Follower;
use super::laws::{Law, Program};
use super::radius::{Allowed, Phase, Placement};
use crate::num::digits::{sig, written};
use crate::num::math::{sin, tan};
use crate::num::tol;

/// The largest distance from the cam centre of anything the sheet draws, metres: at GOST's
/// smallest scale, 1:10 000, a cam this size is 200 mm across on paper.
pub const SIZE_MAX: f64 = 1e3;

/// What makes a cam large: the input most out of the course's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// The stroke of a translating follower, the length of a rocker.
    Length,
    /// A translating follower's given offset.
    Offset,
    /// A phase so short that the follower's velocity analog is long.
    Phase(Phase),
    /// A law whose peak velocity coefficient is far above the guide's (a custom one).
    Law(Phase),
    /// An allowed pressure angle so small that the centre lies far below the analog points.
    Allowed(Phase),
    /// A rocker's swing that leaves little of the allowed angle.
    Swing,
}

/// The bound's parts, metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Size {
    /// Everything drawn lies within this of the cam centre.
    pub reach: f64,
    /// The bound on r_min.
    pub r_min: f64,
}

/// A cam over [`SIZE_MAX`], with what makes it so and why, in the course's words.
#[derive(Debug, Clone, PartialEq)]
pub struct TooLarge {
    pub size: Size,
    pub cause: Cause,
    pub why: String,
}

impl std::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(
            f,
            "this cam would be too large to draw: up to {} across, r_min up to {} (a sheet draws at most {} across, at 1:10 000): {}; check that lengths are in metres and angles in degrees",
            metres(2.0 * self.size.reach),
            metres(self.size.r_min),
            metres(2.0 * SIZE_MAX),
            self.why
        )
    }
}

impl std::error::Error for TooLarge {}

/// A computed length for a message, three significant digits: kilometres from 1 km.
fn metres(x: f64) -> String {
    if x.abs() >= 1e3 { format!("{} km", sig(x / 1e3, 3)) } else { format!("{} m", sig(x, 3)) }
}

/// What the course's cams are like, for naming the input most out of range: lengths (strokes,
/// rockers, offsets) of about 0.1 m, phases of about a radian, peak velocity coefficients of
/// about 2 (the guide's laws: 1.5–2), allowed angles of 30° or more (cot 30° ≈ 1.7).
const TYPICAL_LENGTH: f64 = 0.1;
const TYPICAL_PHASE: f64 = 1.0;
const TYPICAL_CV: f64 = 2.0;
const TYPICAL_COT: f64 = 1.7;

/// The closed-form bound; `None` when the region itself refuses the cam (an allowed angle
/// outside (0°, 90°), a rocker's swing of twice the allowed angle or more).
pub fn bound(follower: Follower, program: &Program, allowed: Allowed, placement: Placement) -> Option<Size> {
    let gamma = smallest_side_angle(follower, program, allowed)?;
    let v = phase_analog(program, Phase::Rise).max(phase_analog(program, Phase::Return));
    let cot = 1.0 / tan(gamma);
    let (r_min, reach) = match (follower, placement) {
        (Follower::Translating, Placement::Offset(e)) => (e.abs() + (e.abs() + v) * cot, program.lift + v),
        (Follower::Translating, Placement::Free) => (v * cot, program.lift + v),
        (Follower::Rocker { length }, _) => {
            let apexes = length * (2.0 * sin(program.lift / 2.0) + v);
            (apexes * (1.0 + cot), apexes.max(length))
        }
    };
    Some(Size { reach: r_min + reach, r_min })
}

/// Refuses a cam whose [`bound`] exceeds [`SIZE_MAX`] (or is not a number).
pub fn check(follower: Follower, program: &Program, allowed: Allowed, placement: Placement) -> Result<(), TooLarge> {
    let Some(size) = bound(follower, program, allowed, placement) else { return Ok(()) };
    if size.reach <= SIZE_MAX {
        return Ok(());
    }
    let cause = cause(follower, program, allowed, placement);
    let why = explain(cause, follower, program, allowed, placement);
    Err(TooLarge { size, cause, why })
}

/// γ: the smallest angle of a wedge's side to the viewing direction, radians, when positive.
fn smallest_side_angle(follower: Follower, program: &Program, allowed: Allowed) -> Option<f64> {
    let smallest = allowed.rise.min(allowed.ret);
    let half = match follower {
        Follower::Translating => 0.0,
        Follower::Rocker { .. } => program.lift / 2.0,
    };
    let ok = |a: f64| a > 0.0 && a < std::f64::consts::FRAC_PI_2;
    (ok(allowed.rise) && ok(allowed.ret) && half < smallest * (1.0 - tol::STRICTLY_INSIDE)).then_some(smallest - half)
}

/// A phase's law and angle, radians.
fn law_of(program: &Program, phase: Phase) -> (&Law, f64) {
    match phase {
        Phase::Rise => (&program.rise_law, program.rise),
        Phase::Return => (&program.return_law, program.ret),
    }
}

/// A phase's peak |ds/dφ| (or |dβ/dφ|): the lift times the law's C_v over the phase's angle.
fn phase_analog(program: &Program, phase: Phase) -> f64 {
    let (law, angle) = law_of(program, phase);
    program.lift * law.peaks().0 / angle
}

/// The input furthest from a course cam's, each measured as a factor over its typical value.
fn cause(follower: Follower, program: &Program, allowed: Allowed, placement: Placement) -> Cause {
    let short = if program.ret < program.rise { Phase::Return } else { Phase::Rise };
    let cv = |p: Phase| law_of(program, p).0.peaks().0;
    let steep = if cv(Phase::Return) > cv(Phase::Rise) { Phase::Return } else { Phase::Rise };
    let narrow = if allowed.rise <= allowed.ret { Phase::Rise } else { Phase::Return };
    let alpha = allowed.rise.min(allowed.ret);
    let (length, offset, half) = match (follower, placement) {
        (Follower::Translating, Placement::Offset(e)) => (program.lift, e.abs(), 0.0),
        (Follower::Translating, Placement::Free) => (program.lift, 0.0, 0.0),
        (Follower::Rocker { length }, _) => (length, 0.0, program.lift / 2.0),
    };
    // The swing is to blame for a small γ when it takes more than half the allowed angle.
    let angle_cause = if half > alpha / 2.0 { Cause::Swing } else { Cause::Allowed(narrow) };
    let candidates = [
        (length / TYPICAL_LENGTH, Cause::Length),
        (offset / TYPICAL_LENGTH, Cause::Offset),
        (TYPICAL_PHASE / law_of(program, short).1, Cause::Phase(short)),
        (cv(steep) / TYPICAL_CV, Cause::Law(steep)),
        (1.0 / tan(alpha - half) / TYPICAL_COT, angle_cause),
    ];
    candidates.into_iter().fold((f64::NEG_INFINITY, Cause::Length), |m, c| if c.0 > m.0 { c } else { m }).1
}

/// Why the cause makes the cam large, with its numbers.
fn explain(cause: Cause, follower: Follower, program: &Program, allowed: Allowed, placement: Placement) -> String {
    let phase_name = |p: Phase| if p == Phase::Rise { "rise" } else { "return" };
    let analog = |p: Phase| {
        let (name, l) = match follower {
            Follower::Translating => ("ds/dφ", 1.0),
            Follower::Rocker { length } => ("l·dβ/dφ", length),
        };
        format!("the velocity analog {name} reaches {}", metres(l * phase_analog(program, p)))
    };
    let deg = |x: f64| written(x.to_degrees());
    match (cause, follower, placement) {
        (Cause::Length, Follower::Translating, _) => format!("a stroke of {} m", written(program.lift)),
        (Cause::Length, Follower::Rocker { length }, _) => format!("a rocker {} m long", written(length)),
        (Cause::Offset, _, Placement::Offset(e)) => format!("an offset of {} m", written(e)),
        (Cause::Offset, ..) => "the offset".into(),
        (Cause::Phase(p), ..) => {
            format!("over a {} of only {}°, {}", phase_name(p), deg(law_of(program, p).1), analog(p))
        }
        (Cause::Law(p), ..) => {
            let law = law_of(program, p).0;
            format!(
                "the {} law `{}` has a peak velocity coefficient of {} (the guide's: 1.5–2), so {}",
                phase_name(p),
                law.key(),
                sig(law.peaks().0, 3),
                analog(p)
            )
        }
        (Cause::Allowed(p), ..) => {
            let a = if p == Phase::Rise { allowed.rise } else { allowed.ret };
            format!(
                "an allowed pressure angle of {}° puts the centre up to {} times the velocity analog's length from the follower",
                deg(a),
                sig(1.0 / tan(a), 3)
            )
        }
        (Cause::Swing, ..) => {
            let a = allowed.rise.min(allowed.ret);
            format!(
                "a swing of {}° leaves only {}° of the allowed {}° pressure angle at the swing's ends",
                deg(program.lift),
                sig((a - program.lift / 2.0).to_degrees(), 3),
                deg(a)
            )
        }
    }
}
