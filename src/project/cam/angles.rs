//! The cam's angles as written: the phases (rise, far dwell, return, in degrees, within a
//! turn) and the allowed pressure angles, in radians, each refusal at its own line.

use super::super::{Refusal, Warning, at, invalid, warning};
use super::spec::{PerPhase, PhasesFileSpec, Scalar};
use crate::cams::radius::Allowed;
use crate::num::digits::written;
use serde_saphyr::{Location, Spanned};

/// The course's range of allowed pressure angles, degrees.
const COURSE_ALLOWED_DEG: (f64, f64) = (30.0, 50.0);

/// The phases in radians.
pub(super) struct Phases {
    pub(super) rise: f64,
    pub(super) far_dwell: f64,
    pub(super) ret: f64,
}

pub(super) fn phases(spec: &Spanned<PhasesFileSpec>) -> Result<Phases, Refusal> {
    let p = &spec.value;
    for (v, field, name) in [(&p.rise, "cam.phases_deg.rise", "rise"), (&p.ret, "cam.phases_deg.return", "return")] {
        if v.value.0 <= 0.0 {
            return Err(invalid(
                at(v),
                field,
                format!("the {name} phase must be a positive angle (degrees), not {}°", written(v.value.0)),
            ));
        }
    }
    let dwell = p.far_dwell.as_ref().map_or(0.0, |d| d.value.0);
    if let Some(d) = &p.far_dwell
        && dwell < 0.0
    {
        return Err(invalid(
            at(d),
            "cam.phases_deg.far_dwell",
            format!("the far dwell must be an angle ≥ 0 (degrees; 0 or absent for none), not {}°", written(dwell)),
        ));
    }
    let total = p.rise.value.0 + dwell + p.ret.value.0;
    if total > 360.0 {
        return Err(invalid(
            at(spec),
            "cam.phases_deg",
            format!(
                "rise + far dwell + return = {} + {} + {} = {}° exceeds a turn (360°); the near dwell is the rest of the turn",
                written(p.rise.value.0),
                written(dwell),
                written(p.ret.value.0),
                written(total)
            ),
        ));
    }
    Ok(Phases { rise: p.rise.value.0.to_radians(), far_dwell: dwell.to_radians(), ret: p.ret.value.0.to_radians() })
}

fn allowed_angle(v: &Scalar, loc: Location, field: &str, warnings: &mut Vec<Warning>) -> Result<f64, Refusal> {
    let a = match v {
        Scalar::Number(a) => *a,
        Scalar::Word(w) => {
            return Err(invalid(
                loc,
                field,
                format!("'{w}': give the allowed pressure angle in degrees, or `{{rise: …, return: …}}`"),
            ));
        }
    };
    if !(a > 0.0 && a < 90.0) {
        return Err(invalid(
            loc,
            field,
            format!("the allowed pressure angle must lie between 0° and 90° (exclusive), not {}°", written(a)),
        ));
    }
    let (lo, hi) = COURSE_ALLOWED_DEG;
    if !(lo..=hi).contains(&a) {
        warnings.push(warning(
            loc,
            field,
            format!(
                "an allowed pressure angle of {}° is outside the course's {}–{}°",
                written(a),
                written(lo),
                written(hi)
            ),
        ));
    }
    Ok(a.to_radians())
}

pub(super) fn allowed(spec: &Spanned<PerPhase>, warnings: &mut Vec<Warning>) -> Result<Allowed, Refusal> {
    match &spec.value {
        PerPhase::Both(v) => {
            let a = allowed_angle(v, at(spec), "cam.pressure_angle_deg", warnings)?;
            Ok(Allowed { rise: a, ret: a })
        }
        PerPhase::Each { rise, ret } => Ok(Allowed {
            rise: allowed_angle(&rise.value, at(rise), "cam.pressure_angle_deg.rise", warnings)?,
            ret: allowed_angle(&ret.value, at(ret), "cam.pressure_angle_deg.return", warnings)?,
        }),
    }
}
