//! The crank's motion over a full turn: course angle φ, the extreme positions of the
//! output link (found exactly), the drawn positions and sampled trajectories.
//!
//! The course measures the crank angle φ from position 0 (an extreme position of the
//! output link) in the sense of rotation, so the absolute angle is `θ = θ0 + sense·φ`.

use super::dyads::DyadFailure;
use super::linkage::{Mechanism, State, StepFailure};
use std::f64::consts::TAU;

/// Samples per turn used to bracket extremes and to check assembly over a full turn.
const SCAN_SAMPLES: usize = 720;

/// Which extreme of the output coordinate is position 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    Min,
    Max,
    /// A fixed absolute crank angle in radians (for outputs without extremes).
    Angle(f64),
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MotionError {
    #[error(
        "{group} cannot be assembled for crank angles θ ≈ {from_deg:.1}°…{to_deg:.1}° from the x axis, counter-clockwise ({detail})"
    )]
    CannotAssemble { group: String, from_deg: f64, to_deg: f64, detail: String },
    #[error(
        "{group} passes through a dead point at the crank angle θ ≈ {at_deg:.3}° from the x axis ({detail}): its velocities are unbounded there"
    )]
    DeadPoint { group: String, at_deg: f64, detail: String },
    #[error("the output ({output}) has no extreme position over a full crank turn; give `start_deg` to fix position 0")]
    NoExtreme { output: String },
}

/// The crank's rotation and the frame of course angles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Absolute crank angle of position 0, radians.
    pub theta0: f64,
    /// +1 counter-clockwise, −1 clockwise.
    pub sense: f64,
    /// Course angle of the other extreme position, when the output has extremes.
    pub other_extreme: Option<f64>,
}

impl Motion {
    pub fn theta(&self, phi: f64) -> f64 {
        self.theta0 + self.sense * phi
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

fn describe_failure(why: &DyadFailure) -> String {
    match why {
        DyadFailure::NoIntersection { distance, reach_min, reach_max } => {
            format!("the joints are {distance:.4} m apart, the links reach only {reach_min:.4}…{reach_max:.4} m")
        }
        DyadFailure::DeadPoint { transmission_deg } => {
            format!("transmission angle {transmission_deg:.2e}°")
        }
        DyadFailure::BlockAtPivot { distance } => {
            format!("the block is {distance:.2e} m from the kulisa pivot")
        }
    }
}

/// Checks that the mechanism assembles over a whole turn and finds position 0.
pub fn analyse_motion(m: &Mechanism, sense: f64, start: Start) -> Result<Motion, MotionError> {
    let theta_of = |k: f64| sense * k; // scan from absolute 0 in the sense of rotation
    let mut states = Vec::with_capacity(SCAN_SAMPLES);
    for k in 0..SCAN_SAMPLES {
        let phi = TAU * k as f64 / SCAN_SAMPLES as f64;
        match m.solve(theta_of(phi)) {
            Ok(s) => states.push((phi, s)),
            Err(f) => return Err(assembly_error(m, f, phi, sense, |p| m.solve(theta_of(p)).is_ok())),
        }
    }
    let reference = swing_reference(m, &states);
    let roots = output_extremes(m, &states, reference, &|p| m.solve(theta_of(p)));
    let other_of = |theta0: f64| {
        roots
            .iter()
            .map(|&(phi, _)| (sense * (theta_of(phi) - theta0)).rem_euclid(TAU))
            .find(|d| d.abs() > 1e-9 && (TAU - d).abs() > 1e-9)
    };
    let theta0 = match start {
        Start::Angle(t) => return Ok(Motion { theta0: t, sense, other_extreme: None }),
        Start::Min | Start::Max => {
            let pick = roots.iter().min_by(|a, b| {
                let (x, y) = if start == Start::Min { (a.1, b.1) } else { (b.1, a.1) };
                x.total_cmp(&y)
            });
            match pick {
                Some(&(phi, _)) => theta_of(phi),
                None => return Err(MotionError::NoExtreme { output: output_name(m) }),
            }
        }
    };
    Ok(Motion { theta0, sense, other_extreme: other_of(theta0) })
}

pub fn output_name(m: &Mechanism) -> String {
    match m.output {
        super::linkage::Output::Slider { point, .. } => format!("slider point {}", m.name(point)),
        super::linkage::Output::Rocker { link } => format!("link {}", m.links[link].number),
    }
}

/// For a rocker output: the mean direction of its swing, from which its angle is measured
/// so that min and max do not depend on where atan2 wraps (±180°).
fn swing_reference(m: &Mechanism, states: &[(f64, State)]) -> kurbo::Vec2 {
    match m.output {
        super::linkage::Output::Rocker { link } => {
            let sum = states.iter().fold(kurbo::Vec2::ZERO, |acc, (_, s)| acc + s.links[link].dir);
            if sum.hypot() > 1e-9 { sum.normalize() } else { kurbo::Vec2::new(1.0, 0.0) }
        }
        super::linkage::Output::Slider { .. } => kurbo::Vec2::new(1.0, 0.0),
    }
}

/// The output coordinate: the slider's displacement, or the rocker's angle from `reference`.
fn output_coordinate(m: &Mechanism, s: &State, reference: kurbo::Vec2) -> f64 {
    match m.output {
        super::linkage::Output::Rocker { link } => {
            let d = s.links[link].dir;
            reference.cross(d).atan2(reference.dot(d))
        }
        super::linkage::Output::Slider { .. } => m.output_value(s).0,
    }
}

/// Roots of the output's velocity over a turn, refined by bisection: (φ, output value).
fn output_extremes(
    m: &Mechanism,
    states: &[(f64, State)],
    reference: kurbo::Vec2,
    solve: &dyn Fn(f64) -> Result<State, StepFailure>,
) -> Vec<(f64, f64)> {
    let vel = |s: &State| m.output_value(s).1;
    let value = |s: &State| output_coordinate(m, s, reference);
    extremes(states, solve, &vel, &value)
}

/// Roots of `vel` over a turn of scanned `states`, refined by bisection: (φ, `value` there).
fn extremes(
    states: &[(f64, State)],
    solve: &dyn Fn(f64) -> Result<State, StepFailure>,
    vel: &dyn Fn(&State) -> f64,
    value: &dyn Fn(&State) -> f64,
) -> Vec<(f64, f64)> {
    let mut roots = Vec::new();
    for i in 0..states.len() {
        let (p0, s0) = &states[i];
        let (p1, s1) = &states[(i + 1) % states.len()];
        let p1 = if i + 1 == states.len() { p1 + TAU } else { *p1 };
        let (v0, v1) = (vel(s0), vel(s1));
        if v0 == 0.0 {
            roots.push((*p0, value(s0)));
            continue;
        }
        if v0.signum() == v1.signum() || v1 == 0.0 {
            continue;
        }
        let (mut lo, mut hi, mut vlo) = (*p0, p1, v0);
        let mut last = s0.clone();
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            let Ok(sm) = solve(mid) else { break };
            let vm = vel(&sm);
            if vm.signum() == vlo.signum() {
                lo = mid;
                vlo = vm;
            } else {
                hi = mid;
            }
            last = sm;
        }
        roots.push(((0.5 * (lo + hi)).rem_euclid(TAU), value(&last)));
    }
    roots
}

/// Turns the first failing scan sample into an error naming the group and the range of
/// crank angles (refined by bisection) where it fails.
fn assembly_error(m: &Mechanism, f: StepFailure, phi: f64, sense: f64, ok: impl Fn(f64) -> bool) -> MotionError {
    let step = TAU / SCAN_SAMPLES as f64;
    let edge = |mut good: f64, mut bad: f64| {
        for _ in 0..50 {
            let mid = 0.5 * (good + bad);
            if ok(mid) { good = mid } else { bad = mid }
        }
        bad
    };
    let group = describe_step(m, f.step);
    let detail = describe_failure(&f.why);
    let deg = |p: f64| (sense * p).rem_euclid(TAU).to_degrees();
    // The scan starts at an absolute angle of 0 that is unrelated to position 0, so the
    // angles are reported as absolute crank angles (counter-clockwise from +x).
    let from = if phi == 0.0 { phi } else { edge(phi - step, phi) };
    let mut to = phi;
    while to < phi + TAU && !ok(to) {
        to += step;
    }
    let to = if to >= phi + TAU { phi + TAU } else { edge(to, to - step) };
    if matches!(f.why, DyadFailure::DeadPoint { .. }) {
        return MotionError::DeadPoint { group, at_deg: deg(phi), detail };
    }
    MotionError::CannotAssemble { group, from_deg: deg(from), to_deg: deg(to), detail }
}

/// The smallest and largest value of p·`axis` that `point` reaches over a turn (a slider's
/// stroke ends), exact to the bisection's resolution.
pub fn extremes_along(
    m: &Mechanism,
    motion: &Motion,
    point: super::linkage::PointId,
    axis: kurbo::Vec2,
) -> Result<(f64, f64), MotionError> {
    let states: Vec<(f64, State)> = (0..SCAN_SAMPLES)
        .map(|k| TAU * k as f64 / SCAN_SAMPLES as f64)
        .map(|phi| sample_at(m, motion, phi).map(|s| (phi, s)))
        .collect::<Result<_, _>>()?;
    let solve = |phi: f64| m.solve(motion.theta(phi));
    let roots = extremes(&states, &solve, &|s| s.points[point].v.dot(axis), &|s| s.points[point].p.dot(axis));
    let values = roots.iter().map(|r| r.1).chain(states.iter().map(|(_, s)| s.points[point].p.dot(axis)));
    Ok(values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x))))
}

/// Solves the mechanism at `n` equally spaced course angles starting at position 0.
pub fn sample(m: &Mechanism, motion: &Motion, n: usize) -> Result<Vec<State>, MotionError> {
    (0..n).map(|k| sample_at(m, motion, TAU * k as f64 / n as f64)).collect()
}

/// Solves the mechanism at the course angle `phi`.
pub fn sample_at(m: &Mechanism, motion: &Motion, phi: f64) -> Result<State, MotionError> {
    m.solve(motion.theta(phi)).map_err(|f| MotionError::CannotAssemble {
        group: describe_step(m, f.step),
        from_deg: phi.to_degrees(),
        to_deg: phi.to_degrees(),
        detail: describe_failure(&f.why),
    })
}
