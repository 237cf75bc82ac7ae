//! The `cam` section's cam designed ([`crate::cams::design`]), each refusal of the design
//! named by the field it stems from and where that is written: a roller that undercuts the
//! profile at `roller`, a swing no centre can serve at `swing_deg`, a cam too large to draw at
//! the input that makes it so (a phase, a stroke, an allowed angle, …).

use super::super::{Kind, Refusal, at, invalid};
use super::follower::FollowerInput;
use super::spec::{CamSpecFile, PerPhase};
use crate::cams::radius::{Phase, RadiusError};
use crate::cams::size::Cause;
use crate::cams::{CamError, CamSpec, Design};
use crate::num::digits::sig;
use serde_saphyr::{Location, Spanned};

/// Designs `cam`, resolved from `spec`; `f` and `roller` say where the follower and the roller
/// were written.
pub(super) fn design(
    spec: &Spanned<CamSpecFile>,
    cam: &CamSpec,
    f: &FollowerInput,
    roller: Location,
) -> Result<Design, Refusal> {
    let c = &spec.value;
    let design = crate::cams::design(cam).map_err(|e| {
        let (loc, field) = match &e {
            CamError::RollerTooLarge { .. } | CamError::Roller(_) => (roller, "cam.roller".to_string()),
            CamError::Radius(RadiusError::SwingTooLarge { .. }) => (f.lift_loc, f.lift_field.to_string()),
            CamError::Radius(RadiusError::Allowed(_)) => (at(&c.pressure_angle_deg), "cam.pressure_angle_deg".into()),
            CamError::Radius(RadiusError::OffsetOfRocker) => (at(&c.follower), "cam.follower".into()),
            CamError::TooLarge(t) => cause_site(c, f, t.cause),
        };
        let kind = if matches!(e, CamError::Roller(_)) { Kind::Value } else { Kind::Design };
        invalid(loc, field, e.to_string()).kind(kind)
    })?;
    if !(design.centre.r_min.is_finite() && design.centre.r_min > 0.0 && !design.rho_min.is_nan()) {
        return Err(invalid(
            spec.referenced,
            "cam",
            format!(
                "the cam cannot be designed from this input (r_min = {} m, ρ_min = {} m): check the phases, the lift and the pressure angle",
                sig(design.centre.r_min, 4),
                sig(design.rho_min, 4)
            ),
        )
        .kind(Kind::Design));
    }
    Ok(design)
}

/// Where the input a too-large cam is blamed on was written, and its field.
fn cause_site(c: &CamSpecFile, f: &FollowerInput, cause: Cause) -> (Location, String) {
    match cause {
        Cause::Length => (f.length.0, f.length.1.to_string()),
        Cause::Offset => (f.offset_loc.unwrap_or(at(&c.follower)), "cam.follower.translating.offset".into()),
        Cause::Swing => (f.lift_loc, f.lift_field.to_string()),
        Cause::Phase(Phase::Rise) => (at(&c.phases_deg.value.rise), "cam.phases_deg.rise".into()),
        Cause::Phase(Phase::Return) => (at(&c.phases_deg.value.ret), "cam.phases_deg.return".into()),
        Cause::Law(p) => per_phase(&c.law, "cam.law", p),
        Cause::Allowed(p) => per_phase(&c.pressure_angle_deg, "cam.pressure_angle_deg", p),
    }
}

/// A value written for both phases or for each: where `phase`'s is, and its field.
fn per_phase(v: &Spanned<PerPhase>, field: &str, phase: Phase) -> (Location, String) {
    match (&v.value, phase) {
        (PerPhase::Both(_), _) => (at(v), field.to_string()),
        (PerPhase::Each { rise, .. }, Phase::Rise) => (at(rise), format!("{field}.rise")),
        (PerPhase::Each { ret, .. }, Phase::Return) => (at(ret), format!("{field}.return")),
    }
}
