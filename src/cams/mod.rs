//! The cam of sheet 3, pure and in SI: the follower's laws of motion ([`laws`]), its motion
//! in its own frame ([`follower`]), the exact minimum-radius centre ([`radius`]), the
//! profiles by inversion ([`profile`]) and the course's graphical integration
//! ([`integrate`]). [`design`] runs them in order for one cam, after the closed-form bound on
//! its size ([`size`]).
//!
//! **Memory.** Nothing here allocates by the cam's size or its ratios: the centre's search and
//! every maximum over φ sample a fixed [`radius::SAMPLES`] + 1 points a phase (a few kB each,
//! freed before the next), a custom law holds its corners as written, the integration its
//! [`integrate::DIVISIONS`] + 1 points a phase, and a profile's Bézier fit at most the
//! `max_pieces` its caller asks for a part. A design takes well under a megabyte.
//!
//! Everything is computed for a cam turning clockwise; a counter-clockwise cam is the mirror
//! image, applied by [`Sense::apply`] to finished coordinates.

mod custom_law;
pub mod follower;
pub mod integrate;
pub mod laws;
pub mod profile;
pub mod radius;
pub mod size;

use crate::num::digits::sig;
use crate::num::math::Norm;
use crate::num::tol;
use crate::num::units::{metres, mm};
use follower::Follower;
use laws::Program;
use profile::Profile;
use radius::{Allowed, Centre, Phase, Placement, RadiusError, Region};

/// The cam's sense of rotation (the domain computes a clockwise cam; [`Sense::apply`] turns
/// its points into the picture of a counter-clockwise one).
pub use crate::num::Sense;

/// The roller as asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Roller {
    /// The course's choice: [`AUTO_SHARE`] of r_min, kept below [`CURVATURE_SHARE`] of ρ_min.
    Auto,
    /// This radius, metres.
    Radius(f64),
    /// A knife edge: the working profile is the pitch profile.
    Knife,
}

/// The course's roller: 0.25–0.4 of r_min; the guide takes 0.25.
pub const AUTO_SHARE: f64 = 0.25;
pub const COURSE_SHARE: (f64, f64) = (0.25, 0.4);
/// The roller must stay below the pitch profile's smallest convex radius of curvature; the
/// course keeps a margin (r ≤ 0.8 ρ_min), the automatic choice a wider one.
pub const CURVATURE_SHARE: f64 = 0.7;
pub const CURVATURE_MARGIN: f64 = 0.8;

/// One cam to design.
#[derive(Debug, Clone, PartialEq)]
pub struct CamSpec {
    pub follower: Follower,
    /// The lift is metres for a translating follower, radians of swing for a rocker.
    pub program: Program,
    pub allowed: Allowed,
    pub placement: Placement,
    pub roller: Roller,
    pub sense: Sense,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CamError {
    #[error(transparent)]
    Radius(#[from] RadiusError),
    #[error(transparent)]
    TooLarge(#[from] size::TooLarge),
    #[error(
        "the roller radius {} mm is not below the pitch profile's smallest convex radius of curvature ρ_min = {} mm: the working profile would be undercut",
        sig(*.r_mm, 4),
        sig(*.rho_mm, 4)
    )]
    RollerTooLarge { r_mm: f64, rho_mm: f64 },
    #[error("the roller radius must be positive and finite, not {} m", sig(*.0, 6))]
    Roller(f64),
}

/// What the design chose that its user should know.
#[derive(Debug, Clone, PartialEq)]
pub enum CamWarning {
    /// The automatic roller had to be smaller than the course's share of r_min.
    RollerBelowCourse { r: f64, r_min: f64, rho_min: f64 },
    /// A given roller closer to ρ_min than the course's margin.
    RollerNearCurvature { r: f64, rho_min: f64 },
    /// A given roller outside the course's 0.25–0.4·r_min.
    RollerOutsideCourse { r: f64, r_min: f64 },
}

/// A designed cam.
#[derive(Debug, Clone)]
pub struct Design {
    pub spec: CamSpec,
    pub region: Region,
    pub centre: Centre,
    pub profile: Profile,
    /// The pitch profile's smallest convex radius of curvature, metres, and its φ.
    pub rho_min: f64,
    pub rho_min_phi: f64,
    /// The roller radius, metres (0 for a knife edge).
    pub roller: f64,
    /// The largest |pressure angle| of each phase (rise, return) and its φ, radians, read off
    /// the finished profile.
    pub max_pressure: [(f64, f64); 2],
    pub warnings: Vec<CamWarning>,
}

impl Design {
    /// The rocker's pivot to the cam centre, metres.
    pub fn centre_distance(&self) -> Option<f64> {
        self.spec.follower.pivot().map(|a| (self.centre.o - a).norm())
    }

    /// The rocker's angle at the start of the rise between the pivot→cam-centre line and
    /// the rocker, radians.
    pub fn rocker_start(&self) -> Option<f64> {
        self.spec.follower.pivot().map(|a| {
            let (to_o, to_b) = (self.centre.o - a, -a);
            crate::num::math::atan2(to_o.cross(to_b), to_o.dot(to_b)).abs()
        })
    }

    /// The translating follower's offset (the centre's distance from its axis), metres,
    /// signed as [`Placement::Offset`].
    pub fn offset(&self) -> Option<f64> {
        match self.spec.follower {
            Follower::Translating => Some(self.centre.o.x),
            Follower::Rocker { .. } => None,
        }
    }
}

/// Designs the cam: the exact centre, the profile, the roller, the pressure angles. A cam over
/// [`size::SIZE_MAX`] is refused before anything is sampled.
pub fn design(spec: &CamSpec) -> Result<Design, CamError> {
    crate::num::work::count(crate::num::work::Step::CamDesign);
    let region = Region::new(spec.follower, &spec.program, spec.allowed)?;
    size::check(spec.follower, &spec.program, spec.allowed, spec.placement)?;
    let centre = region.nearest(spec.placement)?;
    let profile = Profile { follower: spec.follower, program: spec.program.clone(), o: centre.o };
    let (rho_min_phi, rho_min) = profile.min_convex_radius();
    let mut warnings = Vec::new();
    let roller = match spec.roller {
        Roller::Knife => 0.0,
        Roller::Auto => {
            let course = round_up_mm(AUTO_SHARE * centre.r_min);
            let limit = CURVATURE_SHARE * rho_min;
            if course <= limit {
                course
            } else {
                let r = round_down_mm(limit);
                warnings.push(CamWarning::RollerBelowCourse { r, r_min: centre.r_min, rho_min });
                r
            }
        }
        Roller::Radius(r) => {
            if !(r.is_finite() && r > 0.0) {
                return Err(CamError::Roller(r));
            }
            if r >= rho_min {
                return Err(CamError::RollerTooLarge { r_mm: mm(r), rho_mm: mm(rho_min) });
            }
            if r > CURVATURE_MARGIN * rho_min {
                warnings.push(CamWarning::RollerNearCurvature { r, rho_min });
            }
            let share = r / centre.r_min;
            if share < COURSE_SHARE.0 - tol::RANGE_EDGE || share > COURSE_SHARE.1 + tol::RANGE_EDGE {
                warnings.push(CamWarning::RollerOutsideCourse { r, r_min: centre.r_min });
            }
            r
        }
    };
    let max_pressure =
        Phase::BOTH.map(|ph| radius::sup(ph.span(&spec.program), |phi| profile.pressure_angle_on_profile(phi)));
    let max_pressure = max_pressure.map(|(phi, a)| (a, phi));
    Ok(Design { spec: spec.clone(), region, centre, profile, rho_min, rho_min_phi, roller, max_pressure, warnings })
}

/// The course's share of r_min rounded up to a whole millimetre (0.1 mm below 2 mm): rounded
/// down it would leave the course's 0.25–0.4·r_min (14 mm = 0.2485·r_min on the worked
/// example); rounded up it stays inside, a step being at most 0.6 of a share of 2 mm or more.
fn round_up_mm(r: f64) -> f64 {
    let r_mm = mm(r);
    let step = if r_mm >= 2.0 { 1.0 } else { 0.1 };
    metres((r_mm / step - tol::WHOLE_STEP).ceil() * step)
}

/// A radius rounded down to a whole millimetre when it is at least 2 mm, to 0.1 mm below.
fn round_down_mm(r: f64) -> f64 {
    let r_mm = mm(r);
    let step = if r_mm >= 2.0 { 1.0 } else { 0.1 };
    metres(((r_mm / step + tol::WHOLE_STEP).floor() * step).max(step.min(r_mm)))
}
