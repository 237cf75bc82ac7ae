//! The smallest cam, exactly: the centre O nearest to B₀ (the roller centre at the start of
//! the rise) from which every pressure angle is within the allowed one.
//!
//! **Why it is a convex problem.** At each φ the admissible centres form a wedge with apex B′
//! (the velocity-analog point, [`super::follower`]), axis opposite to the motion and half-angle
//! the allowed angle. Seen along a direction `d` that lies strictly inside every wedge (the
//! translating follower's −y; the rocker's −t at mid-swing), each wedge is the region above a
//! convex, piecewise-linear function of the across coordinate u, so the admissible region is
//! the region above W(u) = max_φ f_φ(u), a convex function. The nearest admissible centre in
//! the column at u is at height max(W(u), 0), so r_min² = min_u u² + max(W(u), 0)², a convex
//! function of one variable: golden-section search finds it to the last bits. A translating
//! follower with a given offset e is the column u = e.
//!
//! W(u) itself is the maximum over φ of a smooth function (piecewise, at the laws' joints):
//! sampled on [`SAMPLES`] points a phase, then every sampled local maximum refined by
//! golden-section search between its neighbours.

use super::follower::{Follower, State, pressure_angle};
use super::laws::Program;
use crate::num::digits::sig;
use crate::num::math::{atan2, rotate, tan};
use crate::num::roots::minimise;
use crate::num::tol;
use kurbo::Vec2;

/// Samples of φ per phase before refinement.
pub const SAMPLES: usize = 360;
/// Where the searches stop: φ to [`tol::CAM_ANGLE_SEARCH`], the centre's column to
/// [`tol::CENTRE_SEARCH`].
const PHI_TOL: f64 = tol::CAM_ANGLE_SEARCH;
const U_TOL: f64 = tol::CENTRE_SEARCH;

/// The allowed pressure angles, radians, each in (0, 90°).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Allowed {
    pub rise: f64,
    pub ret: f64,
}

/// Where the cam centre may be.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// Anywhere: the rocker's centre, or a translating follower's with the best offset.
    Free,
    /// A translating follower with this offset, metres (positive toward the side the rise's
    /// analog segments lie on, which lowers the rise's pressure angle).
    Offset(f64),
}

/// The phases the pressure angle is limited on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Phase {
    Rise,
    Return,
}

impl Phase {
    pub const BOTH: [Phase; 2] = [Phase::Rise, Phase::Return];

    /// The phase's cam angles, radians from the start of the rise.
    pub fn span(self, p: &Program) -> (f64, f64) {
        match self {
            Phase::Rise => (0.0, p.rise),
            Phase::Return => (p.rise + p.far_dwell, p.rise + p.far_dwell + p.ret),
        }
    }

    pub fn allowed(self, a: &Allowed) -> f64 {
        match self {
            Phase::Rise => a.rise,
            Phase::Return => a.ret,
        }
    }
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RadiusError {
    #[error("the allowed pressure angle must be between 0° and 90°, not {}°", sig(*.0, 4))]
    Allowed(f64),
    #[error(
        "the swing ({}°) is at least twice the allowed pressure angle ({}°): no cam centre keeps the pressure angle within it over the whole swing",
        sig(*.swing_deg, 4),
        sig(*.allowed_deg, 4)
    )]
    SwingTooLarge { swing_deg: f64, allowed_deg: f64 },
    #[error("a rocker's cam centre is always chosen: an offset applies to a translating follower only")]
    OffsetOfRocker,
}

/// The exact minimum-radius centre.
#[derive(Debug, Clone, PartialEq)]
pub struct Centre {
    /// The cam centre O in the follower frame, metres.
    pub o: Vec2,
    /// r_min = |O − B₀|, the pitch profile's radius at the start of the rise.
    pub r_min: f64,
}

/// The admissible region of the cam centre: the wedges' common part, seen along `d`.
#[derive(Debug, Clone)]
pub struct Region {
    follower: Follower,
    program: Program,
    allowed: Allowed,
    /// The viewing direction (inside every wedge) and the across direction.
    pub d: Vec2,
    pub across: Vec2,
}

/// One φ's wedge of admissible centres in the (u, w) coordinates: its apex B′ and the
/// tangents of its two boundary rays' angles from d (δ ± α, δ the angle of its axis from d,
/// α its half-angle), taken once: a wedge is asked its floor in every column of a nomogram.
#[derive(Debug, Clone, Copy)]
struct Wedge {
    u: f64,
    w: f64,
    /// tan(δ + α): the ray toward +u.
    tan_plus: f64,
    /// tan(δ − α): the ray toward −u.
    tan_minus: f64,
}

impl Wedge {
    fn new(u: f64, w: f64, delta: f64, alpha: f64) -> Wedge {
        Wedge { u, w, tan_plus: tan(delta + alpha), tan_minus: tan(delta - alpha) }
    }

    /// The lowest admissible height w above the column u.
    fn floor(&self, u: f64) -> f64 {
        let du = u - self.u;
        self.w + du / if du >= 0.0 { self.tan_plus } else { self.tan_minus }
    }
}

impl Region {
    pub fn new(follower: Follower, program: &Program, allowed: Allowed) -> Result<Region, RadiusError> {
        for a in [allowed.rise, allowed.ret] {
            if !(a > 0.0 && a < std::f64::consts::FRAC_PI_2) {
                return Err(RadiusError::Allowed(a.to_degrees()));
            }
        }
        let d = match follower {
            Follower::Translating => Vec2::new(0.0, -1.0),
            Follower::Rocker { .. } => {
                let half = program.lift / 2.0;
                let smallest = allowed.rise.min(allowed.ret);
                // d must lie strictly inside every wedge: the motion turns by the swing.
                if half >= smallest * (1.0 - tol::STRICTLY_INSIDE) {
                    return Err(RadiusError::SwingTooLarge {
                        swing_deg: program.lift.to_degrees(),
                        allowed_deg: smallest.to_degrees(),
                    });
                }
                let (sb, cb) = (crate::num::math::sin(half), crate::num::math::cos(half));
                -Vec2::new(sb, cb)
            }
        };
        Ok(Region { follower, program: program.clone(), allowed, d, across: Vec2::new(-d.y, d.x) })
    }

    /// The follower at φ.
    pub fn state(&self, phi: f64) -> State {
        self.follower.state(&self.program, phi)
    }

    /// A point from its (across, along-d) coordinates.
    pub fn point(&self, u: f64, w: f64) -> Vec2 {
        self.across * u + self.d * w
    }

    /// The wedge of `phase` at φ.
    fn wedge(&self, phase: Phase, phi: f64) -> Wedge {
        let s = self.state(phi);
        let axis = -s.t;
        Wedge::new(
            s.analog.dot(self.across),
            s.analog.dot(self.d),
            atan2(axis.dot(self.across), axis.dot(self.d)),
            phase.allowed(&self.allowed),
        )
    }

    /// The lowest admissible height w above the column u for the wedge at φ of `phase`.
    fn floor_at(&self, phase: Phase, phi: f64, u: f64) -> f64 {
        self.wedge(phase, phi).floor(u)
    }

    /// W(u): the region's lower boundary in the column u (the maximum over both phases).
    pub fn floor(&self, u: f64) -> f64 {
        self.sampled(PHI_TOL).floor(u)
    }

    /// W at many columns as a drawing needs it, the wedges sampled once for all of them:
    /// each column's maxima refined to [`tol::CAM_ANGLE_DRAWN`] (W then within 10⁻¹⁴ of its
    /// curvature of [`Region::floor`]'s value, with a third fewer steps).
    pub fn floors(&self, us: &[f64]) -> Vec<f64> {
        let sampled = self.sampled(tol::CAM_ANGLE_DRAWN);
        us.iter().map(|&u| sampled.floor(u)).collect()
    }

    /// Each phase's wedges at the [`grid`]'s angles, sampled once and shared by the columns
    /// asked: the law is evaluated again only to refine a column's local maxima.
    fn sampled(&self, phi_tol: f64) -> Sampled<'_> {
        let of = |ph: Phase| {
            let span = ph.span(&self.program);
            (ph, span, (0..=SAMPLES).map(|k| self.wedge(ph, grid(span, k))).collect())
        };
        Sampled { region: self, phases: Phase::BOTH.map(of), phi_tol }
    }

    /// The nearest admissible centre to B₀ (the origin).
    pub fn nearest(&self, placement: Placement) -> Result<Centre, RadiusError> {
        let sampled = self.sampled(PHI_TOL);
        let column = |u: f64| {
            let w = sampled.floor(u).max(0.0);
            (u * u + w * w, w)
        };
        let u = match (placement, self.follower) {
            (Placement::Offset(_), Follower::Rocker { .. }) => return Err(RadiusError::OffsetOfRocker),
            (Placement::Offset(e), Follower::Translating) => e,
            (Placement::Free, _) => {
                // |u*| ≤ r_min ≤ W(0): the column through B₀ bounds the search.
                let bound = sampled.floor(0.0).max(0.0) * (1.0 + tol::BRACKET_MARGIN) + tol::CENTRE_SEARCH;
                let m = minimise(
                    |u| Ok::<_, ()>(column(u).0),
                    -bound,
                    bound,
                    U_TOL.max(bound * tol::CENTRE_SEARCH_RELATIVE),
                )
                .unwrap_or_else(|_| unreachable!("the column never fails"));
                m.x
            }
        };
        let (r2, w) = column(u);
        Ok(Centre { o: self.point(u, w), r_min: r2.sqrt() })
    }

    /// The largest |pressure angle| of a phase for a centre at `o`, and the φ it is at.
    pub fn max_pressure_angle(&self, phase: Phase, o: Vec2) -> (f64, f64) {
        sup(phase.span(&self.program), |phi| pressure_angle(&self.state(phi), o).abs())
    }

    /// The boundary ray of `phase` on one side (toward −u when `left`) that is the most binding
    /// at `at`: its apex B′, its unit direction (away from the apex) and its φ. These are the
    /// course's limiting lines.
    pub fn limiting_ray(&self, phase: Phase, left: bool, at: Vec2) -> (Vec2, Vec2, f64) {
        let alpha = phase.allowed(&self.allowed);
        let ray = |phi: f64| {
            let s = self.state(phi);
            let axis = -s.t;
            let turn = if left { -alpha } else { alpha };
            let dir = rotate(axis, turn * orientation(self.across, self.d));
            (s.analog, dir)
        };
        // The most binding ray has `at` farthest on its outer side.
        let (phi, _) = sup(phase.span(&self.program), |phi| {
            let (apex, dir) = ray(phi);
            let outward = if left { Vec2::new(dir.y, -dir.x) } else { Vec2::new(-dir.y, dir.x) };
            (at - apex).dot(outward) * orientation(self.across, self.d)
        });
        let (apex, dir) = ray(phi);
        (apex, dir, phi)
    }
}

/// +1 when `across` is `d` turned counter-clockwise, −1 otherwise.
fn orientation(across: Vec2, d: Vec2) -> f64 {
    if d.cross(across) > 0.0 { 1.0 } else { -1.0 }
}

/// The maximum of `f` on [a, b]: sampled, then each sampled local maximum refined between
/// its neighbours. Returns (argmax, max).
pub fn sup(span: (f64, f64), f: impl Fn(f64) -> f64) -> (f64, f64) {
    let vals: Vec<f64> = (0..=SAMPLES).map(|k| f(grid(span, k))).collect();
    refine(span, &vals, f, PHI_TOL)
}

/// A region's wedges sampled on each phase's [`grid`].
struct Sampled<'a> {
    region: &'a Region,
    phases: [(Phase, (f64, f64), Vec<Wedge>); 2],
    /// Where the refinement of a column's maxima stops, radians.
    phi_tol: f64,
}

impl Sampled<'_> {
    /// W(u): every sampled local maximum over each phase refined as [`sup`] does.
    fn floor(&self, u: f64) -> f64 {
        let mut w = f64::NEG_INFINITY;
        for (ph, span, wedges) in &self.phases {
            let vals: Vec<f64> = wedges.iter().map(|wedge| wedge.floor(u)).collect();
            w = w.max(refine(*span, &vals, |phi| self.region.floor_at(*ph, phi, u), self.phi_tol).1);
        }
        w
    }
}

/// The k-th of the [`SAMPLES`] + 1 sample points of `span` (its end exactly).
fn grid((a, b): (f64, f64), k: usize) -> f64 {
    if k == SAMPLES { b } else { a + (b - a) * k as f64 / SAMPLES as f64 }
}

/// The maximum of `f` from its values `vals` at the [`grid`] of `span`: every sampled local
/// maximum refined between its neighbours to `phi_tol`.
fn refine(span: (f64, f64), vals: &[f64], f: impl Fn(f64) -> f64, phi_tol: f64) -> (f64, f64) {
    let (a, n) = (span.0, SAMPLES);
    let at = |k: usize| grid(span, k);
    let mut best = (a, f64::NEG_INFINITY);
    for k in 0..=n {
        let left = k == 0 || vals[k] >= vals[k - 1];
        let right = k == n || vals[k] >= vals[k + 1];
        if !(left && right) {
            continue;
        }
        if vals[k] > best.1 {
            best = (at(k), vals[k]);
        }
        let (lo, hi) = (at(k.saturating_sub(1)), at((k + 1).min(n)));
        if let Ok(m) = minimise(|x| Ok::<_, ()>(-f(x)), lo, hi, phi_tol)
            && -m.fx > best.1
        {
            best = (m.x, -m.fx);
        }
    }
    best
}
