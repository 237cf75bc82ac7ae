//! What sheet 1 needs from the mechanics, computed once: the drawn positions (with the
//! second extreme position), the assigned position, trajectories and structure.

use super::kinetostatics::{self, ForceError, ForceModel, Forces};
use super::linkage::{Mechanism, PointId, Solution, State};
use super::motion::{self, Motion, MotionError, Start};
use super::structure::{self, Structure};
use super::trajectory;
use crate::num::Sense;
use crate::num::digits::{fixed, sig};
use crate::num::math::Norm;
use crate::num::tol;
use crate::num::work::{self, Step};
use kurbo::Vec2;
use std::f64::consts::TAU;

/// Samples per turn of the centre-of-mass trajectories in `results.json` (1° steps).
pub const TRAJECTORY_SAMPLES: usize = 360;

/// How closely the drawn trajectories follow the exact paths ([`tol::TRAJECTORY_FIT`]).
pub use crate::num::tol::TRAJECTORY_FIT;

/// A centre of mass's path over a turn.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    pub point: PointId,
    /// Closed: 361 points at 1° steps of φ from position 0.
    pub samples: Vec<Vec2>,
    /// Cubic pieces within [`TRAJECTORY_FIT`] of the exact path, for drawing.
    pub fitted: trajectory::Fitted,
}

/// What to analyse: the crank's sense, position 0, the drawn positions and φ1.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// The crank's sense of rotation.
    pub sense: Sense,
    pub start: Start,
    /// 12 (every 30°) or 8 (every 45°).
    pub positions: usize,
    /// Course angle φ1 of the assigned (thick) position, degrees (default: position 1).
    pub assigned_deg: Option<f64>,
    /// Positions that get acceleration plans.
    pub acceleration_plans: Vec<usize>,
}

/// One drawn position of the mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// "0" … "11", or "4′" for the second extreme position.
    pub label: String,
    /// Course crank angle from position 0 in the sense of rotation, radians.
    pub phi: f64,
    pub state: State,
    /// An extreme (dead) position of the output link.
    pub extreme: bool,
}

#[derive(Debug, Clone)]
pub struct Kinematics {
    pub motion: Motion,
    /// The regular positions in order, the second extreme inserted where it falls.
    pub positions: Vec<Position>,
    /// The assigned (thick) position.
    pub assigned: Position,
    /// Indices into `positions` of the acceleration plans.
    pub acceleration: Vec<usize>,
    pub trajectories: Vec<Trajectory>,
    pub structure: Structure,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnalysisError {
    #[error(transparent)]
    Motion(#[from] MotionError),
    #[error("force analysis at φ1 = {}°: {error}", fixed(*.phi_deg, 2))]
    Force { phi_deg: f64, error: ForceError },
    #[error(
        "the solution at the course angle φ = {}° is not finite (point {point}); the mechanism is too close to a singular position",
        fixed(*.phi_deg, 2)
    )]
    NotFinite { phi_deg: f64, point: String },
    #[error(
        "the load on slider {point} (line {line} of the project file): the slider does not move (its stroke is {} m), so the load's position in the stroke, S/H, is undefined",
        sig(*.stroke, 3)
    )]
    ZeroStroke { point: String, line: u64, stroke: f64 },
    #[error(
        "force analysis at φ1 = {}°: {what} is not finite; the mechanism is too close to a singular position",
        fixed(*.phi_deg, 2)
    )]
    ForceNotFinite { phi_deg: f64, what: String },
}

fn check_finite(m: &Mechanism, s: &impl Solution, phi: f64) -> Result<(), AnalysisError> {
    for i in 0..m.point_names.len() {
        let k = s.point(i);
        let ok = [k.p, k.v, k.a].iter().all(|v| v.x.is_finite() && v.y.is_finite());
        if !ok {
            return Err(AnalysisError::NotFinite { phi_deg: phi.to_degrees(), point: m.name(i).into() });
        }
    }
    let links_ok =
        (0..m.links.len()).map(|i| s.link(i)).all(|l| l.dir.is_finite() && l.omega.is_finite() && l.eps.is_finite());
    if !links_ok {
        return Err(AnalysisError::NotFinite { phi_deg: phi.to_degrees(), point: "(link)".into() });
    }
    Ok(())
}

fn position(m: &Mechanism, motion: &Motion, phi: f64, label: String, extreme: bool) -> Result<Position, AnalysisError> {
    let state = motion::sample_at(m, motion, phi)?;
    check_finite(m, &state, phi)?;
    Ok(Position { label, phi, state, extreme })
}

pub fn kinematics(m: &Mechanism, s: &Settings) -> Result<Kinematics, AnalysisError> {
    work::count(Step::LinkageAnalysis);
    let motion = motion::analyse_motion(m, s.sense, s.start)?;
    let n = s.positions;
    let step = TAU / n as f64;
    let mut positions = Vec::with_capacity(n + 1);
    for k in 0..n {
        positions.push(position(m, &motion, k as f64 * step, k.to_string(), k == 0 && motion.other_extreme.is_some())?);
    }
    if let Some(e) = motion.other_extreme {
        let k = (e / step).floor() as usize;
        let on_grid =
            (e - k as f64 * step).abs() < tol::SAME_POSITION || (e - (k + 1) as f64 * step).abs() < tol::SAME_POSITION;
        if on_grid {
            let j = ((e / step).round() as usize) % n;
            positions[j].extreme = true;
        } else {
            positions.insert(k + 1, position(m, &motion, e, format!("{k}′"), true)?);
        }
    }
    let assigned = match s.assigned_deg {
        Some(d) => {
            let phi = d.to_radians();
            match positions.iter().find(|p| (p.phi - phi).abs() < tol::SAME_ANGLE) {
                Some(p) => p.clone(),
                None => position(m, &motion, phi, "φ₁".into(), false)?,
            }
        }
        None => positions[1].clone(),
    };
    let acceleration = s
        .acceleration_plans
        .iter()
        .map(|&k| positions.iter().position(|p| p.label == k.to_string()).expect("regular positions exist"))
        .collect();
    let trajectories = trajectories(m, &motion)?;
    Ok(Kinematics { motion, positions, assigned, acceleration, trajectories, structure: structure::analyse(m) })
}

fn trajectories(m: &Mechanism, motion: &Motion) -> Result<Vec<Trajectory>, AnalysisError> {
    let turn = motion::sample(m, motion, TRAJECTORY_SAMPLES)?;
    for (k, st) in turn.positions().enumerate() {
        check_finite(m, &st, TAU * k as f64 / TRAJECTORY_SAMPLES as f64)?;
    }
    // The extent of everything that moves, to make the fit's tolerance relative.
    let all = turn.positions().flat_map(|s| (0..m.point_names.len()).map(move |id| s.point(id).p));
    let (lo, hi) = all.fold((Vec2::splat(f64::MAX), Vec2::splat(f64::MIN)), |(lo, hi), p| {
        (Vec2::new(lo.x.min(p.x), lo.y.min(p.y)), Vec2::new(hi.x.max(p.x), hi.y.max(p.y)))
    });
    let tol = TRAJECTORY_FIT * (hi - lo).norm();
    m.mass_centres
        .iter()
        .map(|&(_, point)| {
            let mut samples: Vec<Vec2> = turn.positions().map(|s| s.point(point).p).collect();
            samples.push(samples[0]);
            let fitted = trajectory::fit(m, motion, point, tol)?;
            Ok(Trajectory { point, samples, fitted })
        })
        .collect()
}

/// The force analysis at the assigned position φ1.
#[derive(Debug, Clone)]
pub struct ForceAnalysis {
    /// The model with every load's stroke fixed.
    pub model: ForceModel,
    pub forces: Forces,
}

/// Fixes each load's stroke from its slider's extremes, then solves the kinetostatics at
/// the assigned position.
pub fn forces(m: &Mechanism, k: &Kinematics, model: &ForceModel) -> Result<ForceAnalysis, AnalysisError> {
    work::count(Step::ForceAnalysis);
    let model = place_loads(m, &k.motion, model)?;
    let phi_deg = k.assigned.phi.to_degrees();
    let forces = kinetostatics::analyse(m, &k.assigned.state, &model)
        .map_err(|error| AnalysisError::Force { phi_deg, error })?;
    check_forces_finite(m, &forces, phi_deg)?;
    Ok(ForceAnalysis { model, forces })
}

/// Every force, moment and balancing value, finite.
fn check_forces_finite(m: &Mechanism, f: &Forces, phi_deg: f64) -> Result<(), AnalysisError> {
    let bad = |what: String| Err(AnalysisError::ForceNotFinite { phi_deg, what });
    for a in &f.applied {
        if !(a.force.is_finite() && a.at.is_finite()) {
            return bad(format!("a force on link {}", m.links[a.on].number));
        }
    }
    for i in &f.inertia {
        if !(i.force.is_finite() && i.moment.is_finite() && i.weight.is_finite()) {
            return bad(format!("the inertia load of link {}", m.links[i.link].number));
        }
    }
    let lever = f.lever.iter().all(|l| l.force.is_finite() && l.image.is_finite())
        && f.lever_moments.iter().all(|x| x.is_finite());
    if ![f.p_m, f.m_m, f.p_m_lever, f.p_m_power].iter().all(|x| x.is_finite()) || !lever {
        return bad("the balancing force".into());
    }
    Ok(())
}

/// The model with every load's stroke (origin and length) fixed from its slider's extremes.
pub fn place_loads(m: &Mechanism, motion: &Motion, model: &ForceModel) -> Result<ForceModel, AnalysisError> {
    let mut model = model.clone();
    let pivot = m.crank().pivot;
    let at = m.frame.iter().find(|f| f.0 == pivot).map_or(Vec2::ZERO, |f| f.1);
    for load in &mut model.loads {
        if let Some(swing) = &mut load.swing {
            // A rocker's arc measured from where the point is at position 0: a rocker swings
            // less than a half turn, so the angle from there never wraps.
            let r = motion::sample_at(m, motion, 0.0)?.points[load.point].p - swing.pivot;
            if r.norm() <= tol::SAME_POINT * m.size {
                return Err(AnalysisError::ZeroStroke {
                    point: m.name(load.point).into(),
                    line: load.line,
                    stroke: 0.0,
                });
            }
            swing.reference = r / r.norm();
        }
        let coordinate = |p: Vec2| load.coordinate(p);
        let rate = |p: Vec2, v: Vec2| v.dot(load.direction(p));
        let (lo, hi) = motion::extremes_of(m, motion, load.point, &coordinate, &rate)?;
        if hi - lo <= tol::SAME_POINT * m.size {
            return Err(AnalysisError::ZeroStroke {
                point: m.name(load.point).into(),
                line: load.line,
                stroke: hi - lo,
            });
        }
        load.set_stroke(lo, hi, at);
    }
    Ok(model)
}
