//! The crank's motion over a full turn: course angle φ, the extreme positions of the
//! output link (found exactly), assembly over the whole turn, sampled positions.
//!
//! The course measures the crank angle φ from position 0 (an extreme position of the
//! output link) in the sense of rotation, so the absolute angle is `θ = θ0 + sense·φ`.
//! Messages name both, each as such: φ (the course angle) once position 0 is known, θ (the
//! absolute angle, counter-clockwise from the x axis) always.

use super::dyads::DyadFailure;
use super::linkage::{Mechanism, Output, PointId, Solution, State, StepFailure};
use super::turn::{At, Turn};
use crate::num::Sense;
use crate::num::digits::fixed;
use crate::num::math::{self, Norm};
use crate::num::roots::{self, RootError};
use crate::num::tol;
use crate::num::tol::ANGLE_RESOLUTION;
use kurbo::Vec2;
use std::convert::Infallible;
use std::f64::consts::TAU;

/// Samples per turn used to bracket extremes and to check assembly over a full turn. A
/// lock-up window narrower than a step is found by minimising each group's reach margin
/// around its sampled minima ([`analyse_motion`]).
const SCAN_SAMPLES: usize = 720;

/// Which extreme of the output coordinate is position 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    Min,
    Max,
    /// A fixed absolute crank angle in radians (for outputs without extremes).
    Angle(f64),
}

/// Absolute crank angles θ (degrees, counter-clockwise from the x axis) as the crank passes
/// them, and the matching course angles φ when position 0 is known.
#[derive(Debug, Clone, PartialEq)]
pub struct Angles {
    pub theta_deg: (f64, f64),
    pub phi_deg: Option<(f64, f64)>,
    /// The crank's sense: a range runs the way the crank turns.
    pub sense: Sense,
}

impl std::fmt::Display for Angles {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let deg = |x: f64| fixed(x, 2);
        let (a, b) = self.theta_deg;
        if a == b {
            write!(f, "the absolute crank angle θ = {}° (from the x axis, counter-clockwise)", deg(a))?;
        } else {
            let turning = self.sense.word();
            write!(
                f,
                "absolute crank angles θ from {}° to {}° as the crank turns {turning} (θ from the x axis, counter-clockwise)",
                deg(a),
                deg(b)
            )?;
        }
        match self.phi_deg {
            Some((a, b)) if a == b => write!(f, ", the course angle φ = {}° from position 0", deg(a)),
            Some((a, b)) => write!(f, ", course angles φ = {}° to {}° from position 0", deg(a), deg(b)),
            None => Ok(()),
        }
    }
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MotionError {
    // `index`: the Assur group's place in the mechanism's list (None: the crank).
    #[error("{group} cannot be assembled at any crank angle ({detail} at {angles})")]
    NeverAssembles { group: String, index: Option<usize>, angles: Angles, detail: String },
    #[error("{group} cannot be assembled for {angles}: {detail}")]
    CannotAssemble { group: String, index: Option<usize>, angles: Angles, detail: String },
    #[error("{group} passes through a dead point at {angles} ({detail}): its velocities are unbounded there")]
    DeadPoint { group: String, index: Option<usize>, angles: Angles, detail: String },
    #[error("the output ({output}) has no extreme position over a full crank turn; give `start_deg` to fix position 0")]
    NoExtreme { output: String },
    #[error("finding {what}: {detail}")]
    Search { what: String, detail: String },
}

/// The crank's rotation and the frame of course angles.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// Absolute crank angle of position 0, radians.
    pub theta0: f64,
    /// The crank's sense of rotation.
    pub sense: Sense,
    /// Course angle of the other extreme position, when the output has extremes.
    pub other_extreme: Option<f64>,
    /// Absolute crank angles (radians) of every extreme position of the output over a turn.
    /// A slider or rocker driven as the course assumes has two; more mean a scheme that is
    /// almost surely not the one meant.
    pub extremes: Vec<f64>,
}

impl Motion {
    pub fn theta(&self, phi: f64) -> f64 {
        self.theta0 + self.sense.sign() * phi
    }
}

/// Names a failed step in the words of the note: "group 1 (RRR, links 2–3)".
pub fn describe_step(m: &Mechanism, step: usize) -> String {
    match m.group_of_step(step) {
        Some(g) => {
            let grp = &m.groups[g];
            let (a, b) = (m.links[grp.links[0]].number, m.links[grp.links[1]].number);
            let at = if grp.line > 0 { format!(", line {}", grp.line) } else { String::new() };
            format!("Assur group {} ({}, links {a} and {b}{at})", g + 1, grp.kind.code())
        }
        None => format!("step {}", step + 1),
    }
}

/// Checks that the mechanism assembles over a whole turn and finds position 0.
pub fn analyse_motion(m: &Mechanism, sense: Sense, start: Start) -> Result<Motion, MotionError> {
    // Scan in u from absolute θ = 0 in the sense of rotation: θ = sense·u.
    let theta_of = |u: f64| sense.sign() * u;
    let fail = |f: StepFailure, u: f64| assembly_error(m, f, u, sense, start);
    let us: Vec<f64> = (0..SCAN_SAMPLES).map(|k| TAU * k as f64 / SCAN_SAMPLES as f64).collect();
    let thetas: Vec<f64> = us.iter().map(|&u| theta_of(u)).collect();
    let mut turn = Turn::default();
    if let Err((k, f)) = m.solve_turn(&thetas, &mut turn) {
        return Err(fail(f, us[k]));
    }
    let states: Vec<(f64, At)> = us.into_iter().zip(turn.positions()).collect();
    if let Some((f, u)) = narrow_lock_up(m, &states, &theta_of) {
        return Err(fail(f, u));
    }
    let reference = swing_reference(m, &states);
    let vel = |s: &dyn Solution| m.output_value(s).1;
    let value = |s: &dyn Solution| output_coordinate(m, s, reference);
    let what = || format!("the extreme positions of {}", output_name(m));
    let roots = extremes(&states, &|u| m.solve(theta_of(u)), &vel, &value, &what)?;
    let all: Vec<f64> = roots.iter().map(|&(u, _)| theta_of(u).rem_euclid(TAU)).collect();
    let other_of = |theta0: f64| {
        roots
            .iter()
            .map(|&(u, _)| (sense.sign() * (theta_of(u) - theta0)).rem_euclid(TAU))
            .find(|d| d.abs() > tol::SAME_ANGLE && (TAU - d).abs() > tol::SAME_ANGLE)
    };
    let theta0 = match start {
        Start::Angle(t) => return Ok(Motion { theta0: t, sense, other_extreme: None, extremes: all }),
        Start::Min | Start::Max => {
            let pick = roots.iter().min_by(|a, b| {
                let (x, y) = if start == Start::Min { (a.1, b.1) } else { (b.1, a.1) };
                x.total_cmp(&y)
            });
            match pick {
                Some(&(u, _)) => theta_of(u),
                None => return Err(MotionError::NoExtreme { output: output_name(m) }),
            }
        }
    };
    Ok(Motion { theta0, sense, other_extreme: other_of(theta0), extremes: all })
}

/// A lock-up window narrower than the scan step: each group's reach margin is minimised
/// around every sampled local minimum; a failed solve there is the window.
fn narrow_lock_up(m: &Mechanism, states: &[(f64, At)], theta_of: &dyn Fn(f64) -> f64) -> Option<(StepFailure, f64)> {
    let per_state: Vec<Vec<f64>> = states.iter().map(|(_, s)| m.margins(s).map(|(_, x)| x).collect()).collect();
    let groups = per_state.first().map_or(0, Vec::len);
    let n = states.len();
    let step = TAU / n as f64;
    for g in 0..groups {
        let margin_of: Vec<f64> = per_state.iter().map(|ms| ms[g]).collect();
        for i in 0..n {
            let (prev, here, next) = (margin_of[(i + n - 1) % n], margin_of[i], margin_of[(i + 1) % n]);
            if !(here < prev && here <= next) {
                continue;
            }
            let u = states[i].0;
            let margin = |x: f64| m.solve(theta_of(x)).map(|s| m.margins(&s).nth(g).map_or(f64::INFINITY, |(_, y)| y));
            match roots::minimise(margin, u - step, u + step, ANGLE_RESOLUTION) {
                Err((x, f)) => return Some((f, x.rem_euclid(TAU))),
                Ok(min) if min.fx <= 0.0 => {
                    // A margin of exactly zero is a dead point: the solver reports it.
                    if let Err(f) = m.solve(theta_of(min.x)) {
                        return Some((f, min.x.rem_euclid(TAU)));
                    }
                }
                Ok(_) => {}
            }
        }
    }
    None
}

pub fn output_name(m: &Mechanism) -> String {
    match m.output {
        Output::Slider { point, .. } => format!("slider point {}", m.name(point)),
        Output::Rocker { link } => format!("link {}", m.links[link].number),
    }
}

/// For a rocker output: the mean direction of its swing, from which its angle is measured
/// so that min and max do not depend on where atan2 wraps (±180°).
fn swing_reference(m: &Mechanism, states: &[(f64, At)]) -> Vec2 {
    match m.output {
        Output::Rocker { link } => {
            let sum = states.iter().fold(Vec2::ZERO, |acc, (_, s)| acc + s.link(link).dir);
            // A sum of unit vectors that cancels out: the link turns fully, any reference does.
            if sum.norm() > tol::SAME_POINT * states.len() as f64 { sum.unit() } else { Vec2::new(1.0, 0.0) }
        }
        Output::Slider { .. } => Vec2::new(1.0, 0.0),
    }
}

/// The output coordinate: the slider's displacement, or the rocker's angle from `reference`.
fn output_coordinate(m: &Mechanism, s: &dyn Solution, reference: Vec2) -> f64 {
    match m.output {
        Output::Rocker { link } => {
            let d = s.link(link).dir;
            math::atan2(reference.cross(d), reference.dot(d))
        }
        Output::Slider { .. } => m.output_value(s).0,
    }
}

type Solve<'a> = dyn Fn(f64) -> Result<State, StepFailure> + 'a;

/// Roots of `vel` over a turn of scanned `states` (u, its angle's results), each bracketed
/// by a sign change between neighbours and found by bisection: (u, `value` there).
fn extremes(
    states: &[(f64, At)],
    solve: &Solve,
    vel: &dyn Fn(&dyn Solution) -> f64,
    value: &dyn Fn(&dyn Solution) -> f64,
    what: &dyn Fn() -> String,
) -> Result<Vec<(f64, f64)>, MotionError> {
    let mut roots = Vec::new();
    let search_error = |e: RootError<StepFailure>| MotionError::Search { what: what(), detail: e.to_string() };
    let largest = states.iter().map(|(_, s)| vel(s).abs()).fold(0.0, f64::max);
    let zero = |v: f64| v.abs() <= tol::EXTREME_SPEED * largest;
    for i in 0..states.len() {
        let (u0, s0) = &states[i];
        let (u1, s1) = &states[(i + 1) % states.len()];
        let u1 = if i + 1 == states.len() { u1 + TAU } else { *u1 };
        let (v0, v1) = (vel(s0), vel(s1));
        if zero(v0) {
            roots.push((*u0, value(s0)));
            continue;
        }
        if v0.signum() == v1.signum() || zero(v1) {
            continue;
        }
        let u = roots::bisect(|u| solve(u).map(|s| vel(&s)), *u0, u1, ANGLE_RESOLUTION).map_err(search_error)?;
        let s = solve(u).map_err(|f| search_error(RootError::Evaluation { x: u, error: f, log: vec![] }))?;
        roots.push((u.rem_euclid(TAU), value(&s)));
    }
    Ok(roots)
}

/// Turns a failure at scan parameter `u` (θ = sense·u) into an error naming the group and
/// the range of angles, found by bisection, over which it fails.
fn assembly_error(m: &Mechanism, f: StepFailure, u: f64, sense: Sense, start: Start) -> MotionError {
    let s = sense.sign();
    let ok = |x: f64| m.solve(s * x).is_ok();
    let step = TAU / SCAN_SAMPLES as f64;
    // +1 where it assembles, −1 where it does not: the edge is a sign change.
    let edge = |good: f64, bad: f64| {
        let sign = |x: f64| Ok::<_, Infallible>(if ok(x) { 1.0 } else { -1.0 });
        roots::bisect(sign, good, bad, ANGLE_RESOLUTION).unwrap_or(bad)
    };
    let mut from = u;
    while from > u - TAU && !ok(from - step) {
        from -= step;
    }
    let mut to = u;
    while to < u + TAU && !ok(to + step) {
        to += step;
    }
    let (group, index) = (describe_step(m, f.step), m.group_of_step(f.step));
    let detail = f.why.to_string();
    let theta_deg = |x: f64| (s * x).rem_euclid(TAU).to_degrees();
    let phi_deg = |x: f64| match start {
        Start::Angle(t0) => Some((s * (s * x - t0)).rem_euclid(TAU).to_degrees()),
        _ => None,
    };
    let angles =
        |a: f64, b: f64| Angles { theta_deg: (theta_deg(a), theta_deg(b)), phi_deg: phi_deg(a).zip(phi_deg(b)), sense };
    if to - from >= TAU - step {
        return MotionError::NeverAssembles { group, index, angles: angles(u, u), detail };
    }
    if matches!(f.why, DyadFailure::DeadPoint { .. }) {
        return MotionError::DeadPoint { group, index, angles: angles(u, u), detail };
    }
    let (from, to) = (edge(from - step, from), edge(to + step, to));
    MotionError::CannotAssemble { group, index, angles: angles(from, to), detail }
}

/// The smallest and largest value of p·`axis` that `point` reaches over a turn (a slider's
/// stroke ends), exact to the bisection's resolution.
pub fn extremes_along(m: &Mechanism, motion: &Motion, point: PointId, axis: Vec2) -> Result<(f64, f64), MotionError> {
    extremes_of(m, motion, point, &|p| p.dot(axis), &|_, v| v.dot(axis))
}

/// The smallest and largest value of `coordinate`(p) that `point` reaches over a turn,
/// `rate`(p, v) being its time derivative (a rocker's point: the arc's length and v along
/// the tangent), exact to the bisection's resolution.
pub fn extremes_of(
    m: &Mechanism,
    motion: &Motion,
    point: PointId,
    coordinate: &dyn Fn(Vec2) -> f64,
    rate: &dyn Fn(Vec2, Vec2) -> f64,
) -> Result<(f64, f64), MotionError> {
    let turn = sample(m, motion, SCAN_SAMPLES)?;
    let phis = (0..SCAN_SAMPLES).map(|k| TAU * k as f64 / SCAN_SAMPLES as f64);
    let states: Vec<(f64, At)> = phis.zip(turn.positions()).collect();
    let solve = |phi: f64| m.solve(motion.theta(phi));
    let what = || format!("the stroke ends of {}", m.name(point));
    let vel = |s: &dyn Solution| {
        let k = s.point(point);
        rate(k.p, k.v)
    };
    let value = |s: &dyn Solution| coordinate(s.point(point).p);
    let roots = extremes(&states, &solve, &vel, &value, &what)?;
    let values = roots.iter().map(|r| r.1).chain(states.iter().map(|(_, s)| value(s)));
    Ok(values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x))))
}

/// Solves the mechanism at `n` equally spaced course angles starting at position 0, the
/// whole turn at once.
pub fn sample(m: &Mechanism, motion: &Motion, n: usize) -> Result<Turn, MotionError> {
    let phis: Vec<f64> = (0..n).map(|k| TAU * k as f64 / n as f64).collect();
    let thetas: Vec<f64> = phis.iter().map(|&phi| motion.theta(phi)).collect();
    let mut turn = Turn::default();
    m.solve_turn(&thetas, &mut turn).map_err(|(k, f)| sample_error(m, motion, phis[k], f))?;
    Ok(turn)
}

/// Solves the mechanism at the course angle `phi`.
pub fn sample_at(m: &Mechanism, motion: &Motion, phi: f64) -> Result<State, MotionError> {
    m.solve(motion.theta(phi)).map_err(|f| sample_error(m, motion, phi, f))
}

/// The failure `f` at the course angle `phi`, in the words of the note.
fn sample_error(m: &Mechanism, motion: &Motion, phi: f64, f: StepFailure) -> MotionError {
    let theta = motion.theta(phi).rem_euclid(TAU).to_degrees();
    let phi = phi.to_degrees();
    let angles = Angles { theta_deg: (theta, theta), phi_deg: Some((phi, phi)), sense: motion.sense };
    let (group, detail) = (describe_step(m, f.step), f.why.to_string());
    let index = m.group_of_step(f.step);
    match f.why {
        DyadFailure::DeadPoint { .. } => MotionError::DeadPoint { group, index, angles, detail },
        _ => MotionError::CannotAssemble { group, index, angles, detail },
    }
}
