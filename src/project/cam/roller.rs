//! The cam's roller as written (`auto`, a radius in metres, or `knife`) and the design's
//! warnings about it in the course's words.

use super::super::{Refusal, at, invalid};
use super::spec::Scalar;
use crate::cams::{CamWarning, Roller};
use crate::num::digits::{fixed, written};
use crate::num::units::mm;
use serde_saphyr::{Location, Spanned};

/// The roller asked for, and where (the section's line when it is the default).
pub(super) fn roller(spec: Option<&Spanned<Scalar>>, section: Location) -> Result<(Roller, Location), Refusal> {
    let Some(s) = spec else {
        return Ok((Roller::Auto, section));
    };
    let loc = at(s);
    let roller = match &s.value {
        Scalar::Number(r) if *r > 0.0 => Roller::Radius(*r),
        Scalar::Number(r) => {
            return Err(invalid(
                loc,
                "cam.roller",
                format!("the roller radius must be positive (metres), not {}; `knife` for a knife edge", written(*r)),
            ));
        }
        Scalar::Word(w) => match w.trim() {
            "auto" => Roller::Auto,
            "knife" => Roller::Knife,
            _ => {
                return Err(invalid(
                    loc,
                    "cam.roller",
                    format!("'{w}': give `auto`, a radius in metres, or `knife` (a knife edge)"),
                ));
            }
        },
    };
    Ok((roller, loc))
}

/// The design's warning about the roller, for the project's warnings.
pub(super) fn cam_warning(w: &CamWarning) -> String {
    match *w {
        CamWarning::RollerBelowCourse { r, r_min, rho_min } => format!(
            "the automatic roller is {} mm, below the course's 0.25·r_min = {} mm (r_min = {} mm), to stay under 0.7·ρ_min (ρ_min = {} mm, the pitch profile's smallest convex radius of curvature)",
            fixed(mm(r), 1),
            fixed(mm(0.25 * r_min), 3),
            fixed(mm(r_min), 3),
            fixed(mm(rho_min), 3)
        ),
        CamWarning::RollerNearCurvature { r, rho_min } => format!(
            "the roller ({} mm) is above 0.8·ρ_min = {} mm (ρ_min = {} mm, the pitch profile's smallest convex radius of curvature): the working profile is nearly pointed there",
            fixed(mm(r), 3),
            fixed(mm(0.8 * rho_min), 3),
            fixed(mm(rho_min), 3)
        ),
        CamWarning::RollerOutsideCourse { r, r_min } => format!(
            "the roller ({} mm) is {}·r_min, outside the course's 0.25–0.4·r_min = {}–{} mm (r_min = {} mm)",
            fixed(mm(r), 3),
            fixed(r / r_min, 3),
            fixed(mm(0.25 * r_min), 3),
            fixed(mm(0.4 * r_min), 3),
            fixed(mm(r_min), 3)
        ),
    }
}
