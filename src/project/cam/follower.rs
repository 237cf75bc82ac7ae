//! The cam's follower as written resolved: a rocker (length, swing) or a translating
//! follower (stroke, offset or `auto`), with where its lift and length were written, and the
//! warnings about a length in the wrong unit or a swing too large.

use super::super::values::Finite;
use super::super::{Refusal, Warning, at, invalid, warning};
use super::spec::{FollowerFileSpec, RockerFileSpec, Scalar, TranslatingFileSpec};
use crate::cams::follower::Follower;
use crate::cams::radius::Placement;
use crate::num::digits::{sig, written};
use crate::num::limits::{LENGTH_LOOKS_LIKE_MM, LENGTH_TINY};
use crate::num::units::{metres, mm};
use serde_saphyr::{Location, Spanned};

/// A swing above this (degrees) is almost surely a mistake.
const SWING_PLAUSIBLE_MAX_DEG: f64 = 60.0;
/// The follower as resolved, with where its lift, its length (the stroke or the rocker's) and
/// a given offset were written.
pub(super) struct FollowerInput {
    pub(super) follower: Follower,
    /// Metres or radians.
    pub(super) lift: f64,
    pub(super) lift_loc: Location,
    pub(super) lift_field: &'static str,
    pub(super) length: (Location, &'static str),
    pub(super) offset_loc: Option<Location>,
    pub(super) placement: Placement,
    pub(super) offset_auto: bool,
}

/// Warns about a length that is almost surely in the wrong unit or a slip.
fn plausible_length(v: &Spanned<Finite>, field: &str, what: &str, warnings: &mut Vec<Warning>) {
    let x = v.value.0;
    if x >= LENGTH_LOOKS_LIKE_MM {
        warnings.push(warning(
            at(v),
            field,
            format!(
                "a {what} of {} m looks like millimetres written as metres: lengths are in metres ({} m?)",
                written(x),
                written(metres(x))
            ),
        ));
    } else if x < LENGTH_TINY {
        warnings.push(warning(
            at(v),
            field,
            format!("a {what} of {} m ({} mm) is implausibly small: lengths are in metres", written(x), sig(mm(x), 4)),
        ));
    }
}

/// The follower: exactly one of a rocker and a translating follower.
pub(super) fn follower(
    spec: &Spanned<FollowerFileSpec>,
    warnings: &mut Vec<Warning>,
) -> Result<FollowerInput, Refusal> {
    match (&spec.value.rocker, &spec.value.translating) {
        (Some(r), None) => rocker(&r.value, warnings),
        (None, Some(t)) => translating(&t.value, warnings),
        (Some(_), Some(_)) => Err(invalid(
            at(spec),
            "cam.follower",
            "both `rocker` and `translating` are given: the follower is exactly one of them",
        )),
        (None, None) => Err(invalid(
            at(spec),
            "cam.follower",
            "no follower: give exactly one of `rocker: {length, swing_deg}` and `translating: {stroke, offset}`",
        )),
    }
}

/// A rocker: its length and its swing (the lift, in radians).
fn rocker(r: &RockerFileSpec, warnings: &mut Vec<Warning>) -> Result<FollowerInput, Refusal> {
    let (length, swing) = (&r.length, &r.swing_deg);
    if length.value.0 <= 0.0 {
        return Err(invalid(
            at(length),
            "cam.follower.rocker.length",
            format!("the rocker's length must be positive (metres), not {}", written(length.value.0)),
        ));
    }
    let s = swing.value.0;
    if s <= 0.0 || s >= 180.0 {
        return Err(invalid(
            at(swing),
            "cam.follower.rocker.swing_deg",
            format!("the swing must be an angle between 0° and 180° (exclusive), not {}°", written(s)),
        ));
    }
    plausible_length(length, "cam.follower.rocker.length", "rocker length", warnings);
    if s > SWING_PLAUSIBLE_MAX_DEG {
        warnings.push(warning(
            at(swing),
            "cam.follower.rocker.swing_deg",
            format!(
                "a swing of {}° is unusually large for a cam's rocker (the course's are below {}°)",
                written(s),
                written(SWING_PLAUSIBLE_MAX_DEG)
            ),
        ));
    }
    Ok(FollowerInput {
        follower: Follower::Rocker { length: length.value.0 },
        lift: s.to_radians(),
        lift_loc: at(swing),
        lift_field: "cam.follower.rocker.swing_deg",
        length: (at(length), "cam.follower.rocker.length"),
        offset_loc: None,
        placement: Placement::Free,
        offset_auto: false,
    })
}

/// A translating follower: its stroke (the lift, in metres) and its offset.
fn translating(t: &TranslatingFileSpec, warnings: &mut Vec<Warning>) -> Result<FollowerInput, Refusal> {
    let stroke = &t.stroke;
    if stroke.value.0 <= 0.0 {
        return Err(invalid(
            at(stroke),
            "cam.follower.translating.stroke",
            format!("the stroke must be positive (metres), not {}", written(stroke.value.0)),
        ));
    }
    plausible_length(stroke, "cam.follower.translating.stroke", "stroke", warnings);
    let (placement, offset_auto) = offset(t.offset.as_ref(), warnings)?;
    Ok(FollowerInput {
        follower: Follower::Translating,
        lift: stroke.value.0,
        lift_loc: at(stroke),
        lift_field: "cam.follower.translating.stroke",
        length: (at(stroke), "cam.follower.translating.stroke"),
        offset_loc: t.offset.as_ref().map(at),
        placement,
        offset_auto,
    })
}

/// A translating follower's offset: none (0), metres, or `auto` (free, and whether it was).
fn offset(spec: Option<&Spanned<Scalar>>, warnings: &mut Vec<Warning>) -> Result<(Placement, bool), Refusal> {
    match spec.map(|o| (&o.value, o.referenced)) {
        None => Ok((Placement::Offset(0.0), false)),
        Some((Scalar::Number(e), loc)) => {
            if e.abs() >= LENGTH_LOOKS_LIKE_MM {
                warnings.push(warning(
                    loc,
                    "cam.follower.translating.offset",
                    format!(
                        "an offset of {} m looks like millimetres written as metres: lengths are in metres",
                        written(*e)
                    ),
                ));
            }
            Ok((Placement::Offset(*e), false))
        }
        Some((Scalar::Word(w), _)) if w.trim() == "auto" => Ok((Placement::Free, true)),
        Some((Scalar::Word(w), loc)) => Err(invalid(
            loc,
            "cam.follower.translating.offset",
            format!("'{w}': give the offset in metres or `auto` (the offset of the smallest cam)"),
        )),
    }
}
