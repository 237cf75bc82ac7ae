//! The `cam` section: sheet 3's cam in the course's terms (lengths in metres, angles in
//! degrees), resolved into the cams domain in SI. The cam is designed here once (centre,
//! profile, roller, pressure angles), so that an impossible angle or a roller that undercuts
//! the profile is an error at its line, not a failed sheet. Every refusal names its field
//! and line; input that builds but is almost surely a mistake gives a [`Warning`].
//!
//! ```yaml
//! cam:
//!   follower: {rocker: {length: 0.105, swing_deg: 25}}   # or {translating: {stroke: 0.04, offset: 0}}
//!   roller: auto                                       # `auto`, a radius in metres, or `knife`
//!   phases_deg: {rise: 70, far_dwell: 10, return: 70}  # the near dwell is the rest of 360°
//!   law: sine                                          # or 4, or {rise: cosine, return: 4}
//!   laws:                                              # optional: redefine or add laws
//!     5: {name: "…", acceleration: [[0, 0], [0.25, 1], [0.75, -1], [1, 0]]}
//!   pressure_angle_deg: 45                             # or {rise: 30, return: 45}
//!   sense: ccw                                         # cw or ccw
//!   assumptions: []
//! ```

mod angles;
mod design;
mod follower;
mod laws;
mod roller;
mod spec;

pub use spec::*;

use super::text;
use super::values::LocalText;
use super::{Refusal, Warning, at, invalid, warning};
use crate::cams::laws::{Law, Program, ProgramError};
use crate::cams::{CamSpec, Roller, Sense};
use serde_saphyr::Spanned;

/// Everything sheet 3 needs.
#[derive(Debug, Clone)]
pub struct CamProject {
    /// The designed cam (centre, profile, roller, pressure angles) — built here once so that
    /// a bad roller or an impossible angle is an error at its line.
    pub design: crate::cams::Design,
    /// The law's choice for each phase, as the file named it (for the sheet's text).
    pub laws: (Law, Law),
    /// The names the file gives the laws of its `laws` table, by key.
    pub law_names: Vec<(String, LocalText)>,
    /// Whether the roller was `auto`.
    pub roller_auto: bool,
    /// Whether the translating follower's offset was `auto`.
    pub offset_auto: bool,
    /// Printed on the sheet, like gears' `assumptions`.
    pub assumptions: Vec<LocalText>,
}

const FIELD: &str = "cam";

/// Resolves the section and designs the cam.
pub fn resolve(spec: &Spanned<CamSpecFile>, warnings: &mut Vec<Warning>) -> Result<CamProject, Refusal> {
    let c = &spec.value;
    let f = follower::follower(&c.follower, warnings)?;
    let phases = angles::phases(&c.phases_deg)?;
    let table = laws::law_table(c.laws.as_ref(), warnings)?;
    let laws = laws::laws(&c.law, &table)?;
    let allowed = angles::allowed(&c.pressure_angle_deg, warnings)?;
    let (roller, roller_loc) = roller::roller(c.roller.as_ref(), spec.referenced)?;
    let sense = c.sense.as_ref().map_or(Sense::Ccw, |s| s.value);
    let program = Program::new(phases.rise, phases.far_dwell, phases.ret, laws.clone(), f.lift).map_err(|e| {
        let (loc, field) = match &e {
            ProgramError::Phase { phase: "rise", .. } => (at(&c.phases_deg.value.rise), "cam.phases_deg.rise"),
            ProgramError::Phase { .. } => (at(&c.phases_deg.value.ret), "cam.phases_deg.return"),
            ProgramError::Dwell(_) => {
                (c.phases_deg.value.far_dwell.as_ref().map_or(at(&c.phases_deg), at), "cam.phases_deg.far_dwell")
            }
            ProgramError::OverTurn(_) => (at(&c.phases_deg), "cam.phases_deg"),
            ProgramError::Lift(_) => (f.lift_loc, f.lift_field),
        };
        invalid(loc, field, e.to_string())
    })?;
    let cam = CamSpec { follower: f.follower, program, allowed, placement: f.placement, roller, sense };
    let design = design::design(spec, &cam, &f, roller_loc)?;
    for w in &design.warnings {
        warnings.push(warning(roller_loc, "cam.roller", roller::cam_warning(w)));
    }
    let assumptions = text::assumptions(FIELD, &c.assumptions)?;
    let law_names = table.into_iter().filter_map(|u| Some((u.law.key().to_string(), u.name?))).collect();
    Ok(CamProject {
        design,
        laws,
        law_names,
        roller_auto: matches!(roller, Roller::Auto),
        offset_auto: f.offset_auto,
        assumptions,
    })
}
