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

use super::cam_design;
use super::text::{self, Lines};
use super::values::{Finite, LocalText};
use super::{Refusal, Warning, at, invalid, warning};
use crate::cams::follower::Follower;
use crate::cams::integrate;
use crate::cams::laws::{Custom, Law, LawError, Program, ProgramError, Standard};
use crate::cams::radius::{Allowed, Phase, Placement};
use crate::cams::{CamSpec, CamWarning, Roller, Sense};
use crate::num::limits::{LENGTH_LOOKS_LIKE_MM, LENGTH_TINY};
use serde::Deserialize;
use serde::de::{self, Deserializer, IntoDeserializer, MapAccess, Visitor};
use serde_saphyr::{Location, Spanned};
use std::fmt;

/// The `cam` section as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CamSpecFile {
    /// Exactly one of `{rocker: {length, swing_deg}}` and `{translating: {stroke, offset}}`.
    pub follower: Spanned<FollowerFileSpec>,
    /// `auto` (default: the course's 0.25·r_min, kept below the profile's curvature), a
    /// radius in metres, or `knife` (a knife edge).
    #[serde(default)]
    pub roller: Option<Spanned<Scalar>>,
    /// The phases, degrees of cam angle: `rise`, `far_dwell` (default 0) and `return`; the
    /// near dwell is the rest of the turn.
    pub phases_deg: Spanned<PhasesFileSpec>,
    /// The law of motion: a key (`cosine`, `sine`, `polynomial-345`, …) or the guide's
    /// number 1–6, for both phases, or `{rise: …, return: …}`.
    pub law: Spanned<PerPhase>,
    /// The law table's additions and replacements: by a key (a built-in one or the guide's
    /// number 1–6 replaces that law; another adds one), the acceleration analog's corners.
    #[serde(default)]
    pub laws: Option<Spanned<LawTable>>,
    /// The allowed pressure angle, degrees, in (0°, 90°) (the course: 30–50°): one for both
    /// phases, or `{rise: …, return: …}`.
    pub pressure_angle_deg: Spanned<PerPhase>,
    /// The cam's sense of rotation: `cw` or `ccw` (default).
    #[serde(default)]
    pub sense: Option<Spanned<String>>,
    /// Printed on the sheet: what was assumed where the source is silent or contradicts itself.
    #[serde(default)]
    /// Each one text, or one per language.
    pub assumptions: Vec<Spanned<LocalText>>,
}

/// The `laws` table as written: (key, definition) in the file's order.
#[derive(Debug, Clone, Default)]
pub struct LawTable(pub Vec<(Spanned<String>, Spanned<LawFileSpec>)>);

/// One law of the table: the acceleration analog s″ straight between corners `[x, a]` over
/// the phase (x from 0 to 1, two corners at one x for a jump; a in any unit, the law is
/// scaled to the lift), and the name the sheet prints.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LawFileSpec {
    /// One text, or one per language; default: the replaced law's name, or the key.
    #[serde(default)]
    pub name: Option<Spanned<LocalText>>,
    pub acceleration: Spanned<Vec<Spanned<(Finite, Finite)>>>,
}

/// A law table's key: a word, or the guide's number written as a number.
struct LawKey(String);

impl<'de> Deserialize<'de> for LawKey {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match d.deserialize_any(ScalarVisitor)? {
            Scalar::Word(w) => Ok(LawKey(w)),
            Scalar::Number(x) => Ok(LawKey(format!("{x}"))),
        }
    }
}

struct LawTableVisitor;

impl<'de> Visitor<'de> for LawTableVisitor {
    type Value = LawTable;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a table of laws: `key: {name: …, acceleration: [[x, a], …]}`")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<LawTable, A::Error> {
        let mut out = Vec::new();
        while let Some(key) = map.next_key::<Spanned<LawKey>>()? {
            let key = Spanned { value: key.value.0, referenced: key.referenced, defined: key.defined };
            out.push((key, map.next_value()?));
        }
        Ok(LawTable(out))
    }
}

impl<'de> Deserialize<'de> for LawTable {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_map(LawTableVisitor)
    }
}

/// The follower: exactly one of the two kinds.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FollowerFileSpec {
    /// An oscillating follower.
    #[serde(default)]
    pub rocker: Option<Spanned<RockerFileSpec>>,
    /// A translating (reciprocating) follower.
    #[serde(default)]
    pub translating: Option<Spanned<TranslatingFileSpec>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RockerFileSpec {
    /// The rocker's length, pivot to roller centre, metres.
    pub length: Spanned<Finite>,
    /// The swing, degrees (the lift of a rocker).
    pub swing_deg: Spanned<Finite>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TranslatingFileSpec {
    /// The stroke, metres (the lift of a translating follower).
    pub stroke: Spanned<Finite>,
    /// The cam centre's distance from the follower's axis, metres (default 0; positive toward
    /// the side that lowers the rise's pressure angle), or `auto`: the offset of the smallest
    /// cam.
    #[serde(default)]
    pub offset: Option<Spanned<Scalar>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhasesFileSpec {
    pub rise: Spanned<Finite>,
    #[serde(default)]
    pub far_dwell: Option<Spanned<Finite>>,
    #[serde(rename = "return")]
    pub ret: Spanned<Finite>,
}

/// A scalar that is a number (finite, within the file's limit) or a word.
#[derive(Debug, Clone, PartialEq)]
pub enum Scalar {
    Number(f64),
    Word(String),
}

/// One value for both phases, or one for each.
#[derive(Debug, Clone, PartialEq)]
pub enum PerPhase {
    Both(Scalar),
    Each { rise: Spanned<Scalar>, ret: Spanned<Scalar> },
}

struct ScalarVisitor;

impl<'de> Visitor<'de> for ScalarVisitor {
    type Value = Scalar;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number or a word")
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<Scalar, E> {
        // The same checks as every number of the file (finite, within its limit).
        let d: de::value::F64Deserializer<E> = x.into_deserializer();
        Finite::deserialize(d).map(|f| Scalar::Number(f.0))
    }

    fn visit_i64<E: de::Error>(self, x: i64) -> Result<Scalar, E> {
        self.visit_f64(x as f64)
    }

    fn visit_u64<E: de::Error>(self, x: u64) -> Result<Scalar, E> {
        self.visit_f64(x as f64)
    }

    fn visit_str<E: de::Error>(self, s: &str) -> Result<Scalar, E> {
        Ok(Scalar::Word(s.to_owned()))
    }
}

impl<'de> Deserialize<'de> for Scalar {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ScalarVisitor)
    }
}

struct PerPhaseVisitor;

impl<'de> Visitor<'de> for PerPhaseVisitor {
    type Value = PerPhase;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a value for both phases, or `{rise: …, return: …}`")
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<PerPhase, E> {
        ScalarVisitor.visit_f64(x).map(PerPhase::Both)
    }

    fn visit_i64<E: de::Error>(self, x: i64) -> Result<PerPhase, E> {
        ScalarVisitor.visit_i64(x).map(PerPhase::Both)
    }

    fn visit_u64<E: de::Error>(self, x: u64) -> Result<PerPhase, E> {
        ScalarVisitor.visit_u64(x).map(PerPhase::Both)
    }

    fn visit_str<E: de::Error>(self, s: &str) -> Result<PerPhase, E> {
        ScalarVisitor.visit_str(s).map(PerPhase::Both)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<PerPhase, A::Error> {
        const FIELDS: &[&str] = &["rise", "return"];
        let (mut rise, mut ret) = (None, None);
        while let Some(key) = map.next_key::<String>()? {
            let slot = match key.as_str() {
                "rise" => &mut rise,
                "return" => &mut ret,
                other => return Err(de::Error::unknown_field(other, FIELDS)),
            };
            if slot.is_some() {
                return Err(de::Error::duplicate_field(FIELDS[usize::from(key == "return")]));
            }
            *slot = Some(map.next_value::<Spanned<Scalar>>()?);
        }
        let rise = rise.ok_or_else(|| de::Error::missing_field("rise"))?;
        let ret = ret.ok_or_else(|| de::Error::missing_field("return"))?;
        Ok(PerPhase::Each { rise, ret })
    }
}

impl<'de> Deserialize<'de> for PerPhase {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(PerPhaseVisitor)
    }
}

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

/// The course's range of allowed pressure angles, degrees.
const COURSE_ALLOWED_DEG: (f64, f64) = (30.0, 50.0);
/// A swing above this (degrees) is almost surely a mistake.
const SWING_PLAUSIBLE_MAX_DEG: f64 = 60.0;
/// The follower as resolved, with where its lift, its length (the stroke or the rocker's) and
/// a given offset were written.
pub(super) struct FollowerInput {
    follower: Follower,
    /// Metres or radians.
    lift: f64,
    pub(super) lift_loc: Location,
    pub(super) lift_field: &'static str,
    pub(super) length: (Location, &'static str),
    pub(super) offset_loc: Option<Location>,
    placement: Placement,
    offset_auto: bool,
}

/// Resolves the section and designs the cam.
pub fn resolve(spec: &Spanned<CamSpecFile>, warnings: &mut Vec<Warning>) -> Result<CamProject, Refusal> {
    let c = &spec.value;
    let f = follower(&c.follower, warnings)?;
    let phases = phases(&c.phases_deg)?;
    let table = law_table(c.laws.as_ref(), warnings)?;
    let laws = laws(&c.law, &table)?;
    let allowed = allowed(&c.pressure_angle_deg, warnings)?;
    let (roller, roller_loc) = roller(c.roller.as_ref(), spec.referenced)?;
    let sense = match c.sense.as_ref().map(|s| (s.value.trim(), s.referenced)) {
        None | Some(("ccw", _)) => Sense::Ccw,
        Some(("cw", _)) => Sense::Cw,
        Some((other, loc)) => {
            return Err(invalid(
                loc,
                "cam.sense",
                format!("unknown sense '{other}': the cam turns `cw` (clockwise) or `ccw` (counter-clockwise)"),
            ));
        }
    };
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
    let design = cam_design::design(spec, &cam, &f, roller_loc)?;
    for w in &design.warnings {
        warnings.push(warning(roller_loc, "cam.roller", cam_warning(w)));
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

fn cam_warning(w: &CamWarning) -> String {
    match *w {
        CamWarning::RollerBelowCourse { r, r_min, rho_min } => format!(
            "the automatic roller is {:.1} mm, below the course's 0.25·r_min = {:.3} mm (r_min = {:.3} mm), to stay under 0.7·ρ_min (ρ_min = {:.3} mm, the pitch profile's smallest convex radius of curvature)",
            r * 1e3,
            0.25 * r_min * 1e3,
            r_min * 1e3,
            rho_min * 1e3
        ),
        CamWarning::RollerNearCurvature { r, rho_min } => format!(
            "the roller ({:.3} mm) is above 0.8·ρ_min = {:.3} mm (ρ_min = {:.3} mm, the pitch profile's smallest convex radius of curvature): the working profile is nearly pointed there",
            r * 1e3,
            0.8 * rho_min * 1e3,
            rho_min * 1e3
        ),
        CamWarning::RollerOutsideCourse { r, r_min } => format!(
            "the roller ({:.3} mm) is {:.3}·r_min, outside the course's 0.25–0.4·r_min = {:.3}–{:.3} mm (r_min = {:.3} mm)",
            r * 1e3,
            r / r_min,
            0.25 * r_min * 1e3,
            0.4 * r_min * 1e3,
            r_min * 1e3
        ),
    }
}

/// Warns about a length that is almost surely in the wrong unit or a slip.
fn plausible_length(v: &Spanned<Finite>, field: &str, what: &str, warnings: &mut Vec<Warning>) {
    let x = v.value.0;
    if x >= LENGTH_LOOKS_LIKE_MM {
        warnings.push(warning(
            at(v),
            field,
            format!(
                "a {what} of {x} m looks like millimetres written as metres: lengths are in metres ({} m?)",
                x * 1e-3
            ),
        ));
    } else if x < LENGTH_TINY {
        warnings.push(warning(
            at(v),
            field,
            format!("a {what} of {x} m ({} mm) is implausibly small: lengths are in metres", x * 1e3),
        ));
    }
}

fn follower(spec: &Spanned<FollowerFileSpec>, warnings: &mut Vec<Warning>) -> Result<FollowerInput, Refusal> {
    match (&spec.value.rocker, &spec.value.translating) {
        (Some(r), None) => {
            let (length, swing) = (&r.value.length, &r.value.swing_deg);
            if length.value.0 <= 0.0 {
                return Err(invalid(
                    at(length),
                    "cam.follower.rocker.length",
                    format!("the rocker's length must be positive (metres), not {}", length.value.0),
                ));
            }
            let s = swing.value.0;
            if s <= 0.0 || s >= 180.0 {
                return Err(invalid(
                    at(swing),
                    "cam.follower.rocker.swing_deg",
                    format!("the swing must be an angle between 0° and 180° (exclusive), not {s}°"),
                ));
            }
            plausible_length(length, "cam.follower.rocker.length", "rocker length", warnings);
            if s > SWING_PLAUSIBLE_MAX_DEG {
                warnings.push(warning(
                    at(swing),
                    "cam.follower.rocker.swing_deg",
                    format!(
                        "a swing of {s}° is unusually large for a cam's rocker (the course's are below {SWING_PLAUSIBLE_MAX_DEG}°)"
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
        (None, Some(t)) => {
            let stroke = &t.value.stroke;
            if stroke.value.0 <= 0.0 {
                return Err(invalid(
                    at(stroke),
                    "cam.follower.translating.stroke",
                    format!("the stroke must be positive (metres), not {}", stroke.value.0),
                ));
            }
            plausible_length(stroke, "cam.follower.translating.stroke", "stroke", warnings);
            let (placement, offset_auto) = match t.value.offset.as_ref().map(|o| (&o.value, o.referenced)) {
                None => (Placement::Offset(0.0), false),
                Some((Scalar::Number(e), loc)) => {
                    if e.abs() >= LENGTH_LOOKS_LIKE_MM {
                        warnings.push(warning(
                            loc,
                            "cam.follower.translating.offset",
                            format!(
                                "an offset of {e} m looks like millimetres written as metres: lengths are in metres"
                            ),
                        ));
                    }
                    (Placement::Offset(*e), false)
                }
                Some((Scalar::Word(w), _)) if w.trim() == "auto" => (Placement::Free, true),
                Some((Scalar::Word(w), loc)) => {
                    return Err(invalid(
                        loc,
                        "cam.follower.translating.offset",
                        format!("'{w}': give the offset in metres or `auto` (the offset of the smallest cam)"),
                    ));
                }
            };
            Ok(FollowerInput {
                follower: Follower::Translating,
                lift: stroke.value.0,
                lift_loc: at(stroke),
                lift_field: "cam.follower.translating.stroke",
                length: (at(stroke), "cam.follower.translating.stroke"),
                offset_loc: t.value.offset.as_ref().map(at),
                placement,
                offset_auto,
            })
        }
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

/// The phases in radians.
struct Phases {
    rise: f64,
    far_dwell: f64,
    ret: f64,
}

fn phases(spec: &Spanned<PhasesFileSpec>) -> Result<Phases, Refusal> {
    let p = &spec.value;
    for (v, field, name) in [(&p.rise, "cam.phases_deg.rise", "rise"), (&p.ret, "cam.phases_deg.return", "return")] {
        if v.value.0 <= 0.0 {
            return Err(invalid(
                at(v),
                field,
                format!("the {name} phase must be a positive angle (degrees), not {}°", v.value.0),
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
            format!("the far dwell must be an angle ≥ 0 (degrees; 0 or absent for none), not {dwell}°"),
        ));
    }
    let total = p.rise.value.0 + dwell + p.ret.value.0;
    if total > 360.0 {
        return Err(invalid(
            at(spec),
            "cam.phases_deg",
            format!(
                "rise + far dwell + return = {} + {dwell} + {} = {total}° exceeds a turn (360°); the near dwell is the rest of the turn",
                p.rise.value.0, p.ret.value.0
            ),
        ));
    }
    Ok(Phases { rise: p.rise.value.0.to_radians(), far_dwell: dwell.to_radians(), ret: p.ret.value.0.to_radians() })
}

/// A law of the file's `laws` table, with its name.
struct UserLaw {
    law: Law,
    name: Option<LocalText>,
}

/// Resolves the `laws` table: each key to the built-in law it replaces (by key or the guide's
/// number) or to a new key, each corner list to a law.
fn law_table(spec: Option<&Spanned<LawTable>>, warnings: &mut Vec<Warning>) -> Result<Vec<UserLaw>, Refusal> {
    let Some(spec) = spec else { return Ok(Vec::new()) };
    let mut out: Vec<UserLaw> = Vec::new();
    for (spanned_key, def) in &spec.value.0 {
        let key = &spanned_key.value;
        let field = format!("cam.laws.{}", key.escape_debug());
        let replaces = Standard::by_key(key);
        let canonical = replaces.map_or(key.trim().to_string(), |s| s.key().to_string());
        // A new law's key is printed on the sheet when it has no name.
        text::check(&field, spanned_key, Lines::One)?;
        if replaces.is_none() {
            new_law_key(key).map_err(|why| invalid(at(spanned_key), &field, why))?;
        }
        if out.iter().any(|u| u.law.key() == canonical) {
            return Err(invalid(
                at(spanned_key),
                &field,
                format!("the law `{canonical}` is defined twice in `cam.laws`"),
            ));
        }
        let acc = &def.value.acceleration;
        let corners: Vec<(f64, f64)> = acc.value.iter().map(|c| (c.value.0.0, c.value.1.0)).collect();
        let law = Custom::new(&canonical, replaces, &corners).map_err(|e| {
            let (loc, field) = match e {
                LawError::Decreasing { index, .. } | LawError::TripleCorner { index, .. } => {
                    (at(&acc.value[index]), format!("{field}.acceleration[{index}]"))
                }
                _ => (at(acc), format!("{field}.acceleration")),
            };
            invalid(loc, field, e.to_string())
        })?;
        if let Some(n) = &def.value.name {
            text::check_local(&format!("{field}.name"), n, Lines::One)?;
        }
        if let Some(w) = corner_between_divisions(&law) {
            warnings.push(warning(at(acc), format!("{field}.acceleration"), w));
        }
        out.push(UserLaw { law: law.into(), name: def.value.name.as_ref().map(|n| n.value.clone()) });
    }
    Ok(out)
}

/// A corner between the course's divisions of the phase is cut off by the chord
/// integration (it samples s″ at the divisions' middles): says so with the error it makes.
fn corner_between_divisions(law: &Custom) -> Option<String> {
    let n = integrate::DIVISIONS as f64;
    let (x, _) = law.corners().find(|(x, _)| ((x * n).round() - x * n).abs() > 1e-9)?;
    let program = Program::new(1.0, 0.0, 1.0, (law.clone(), law.clone()), 1.0).ok()?;
    let error = integrate::chords(&program, Phase::Rise, integrate::DIVISIONS).error(&program).s;
    Some(format!(
        "a corner at x = {x} lies between the course's {n} divisions of the phase (multiples of 1/{n}): the graphical integration cuts it off and misses the displacement by up to {:.1} % of the lift; corners at the divisions are drawn exactly",
        error * 100.0
    ))
}

/// A new law's key: a word of letters, digits, `-` and `_` that is not a number (numbers
/// are the guide's, 1–6).
fn new_law_key(key: &str) -> Result<(), String> {
    let k = key.trim();
    if k.parse::<f64>().is_ok() {
        return Err(format!("'{k}': the guide numbers its laws 1–6; give a new law a name"));
    }
    if k.is_empty() || !k.chars().all(|c| c.is_alphanumeric() || c == '-' || c == '_') {
        return Err(format!("'{k}': a law's key is a word of letters, digits, `-` and `_`"));
    }
    Ok(())
}

/// The accepted law keys and numbers, for an error message.
fn known_laws(table: &[UserLaw]) -> String {
    let mut keys: Vec<String> = Standard::ALL
        .iter()
        .map(|l| match l.guide_number() {
            Some(n) => format!("{} ({n})", l.key()),
            None => l.key().to_string(),
        })
        .collect();
    keys.extend(
        table
            .iter()
            .filter(|u| u.law.guide_number().is_none() && Standard::by_key(u.law.key()).is_none())
            .map(|u| u.law.key().to_string()),
    );
    format!("known: {}; or the guide's number 1–6", keys.join(", "))
}

fn law(v: &Scalar, loc: Location, field: &str, table: &[UserLaw]) -> Result<Law, Refusal> {
    let key = match v {
        Scalar::Word(w) => Some(w.trim().to_string()),
        Scalar::Number(x) if x.fract() == 0.0 && (1.0..=6.0).contains(x) => Some(format!("{x}")),
        Scalar::Number(_) => None,
    };
    // A built-in key or number names the built-in law, or the table's replacement of it.
    let canonical = key.map(|k| Standard::by_key(&k).map_or(k, |s| s.key().to_string()));
    let found = canonical.and_then(|k| match table.iter().find(|u| u.law.key() == k) {
        Some(u) => Some(u.law.clone()),
        None => Standard::by_key(&k).map(Law::Standard),
    });
    found.ok_or_else(|| {
        let shown = match v {
            Scalar::Word(w) => format!("'{w}'"),
            Scalar::Number(x) => format!("{x}"),
        };
        invalid(loc, field, format!("unknown law {shown} ({})", known_laws(table)))
    })
}

fn laws(spec: &Spanned<PerPhase>, table: &[UserLaw]) -> Result<(Law, Law), Refusal> {
    match &spec.value {
        PerPhase::Both(v) => {
            let l = law(v, at(spec), "cam.law", table)?;
            Ok((l.clone(), l))
        }
        PerPhase::Each { rise, ret } => {
            Ok((law(&rise.value, at(rise), "cam.law.rise", table)?, law(&ret.value, at(ret), "cam.law.return", table)?))
        }
    }
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
            format!("the allowed pressure angle must lie between 0° and 90° (exclusive), not {a}°"),
        ));
    }
    let (lo, hi) = COURSE_ALLOWED_DEG;
    if !(lo..=hi).contains(&a) {
        warnings.push(warning(
            loc,
            field,
            format!("an allowed pressure angle of {a}° is outside the course's {lo}–{hi}°"),
        ));
    }
    Ok(a.to_radians())
}

fn allowed(spec: &Spanned<PerPhase>, warnings: &mut Vec<Warning>) -> Result<Allowed, Refusal> {
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

/// The roller asked for, and where (the section's line when it is the default).
fn roller(spec: Option<&Spanned<Scalar>>, section: Location) -> Result<(Roller, Location), Refusal> {
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
                format!("the roller radius must be positive (metres), not {r}; `knife` for a knife edge"),
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
