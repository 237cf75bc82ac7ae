//! The `cam` section as written: serde types that deny unknown keys, each value spanned so
//! that a refusal names its line; a scalar that is a number or a word, a value for both
//! phases or for each, the `laws` table in the file's order.

use super::super::values::{Finite, LocalText};
use crate::num::Sense;
use serde::Deserialize;
use serde::de::{self, Deserializer, IntoDeserializer, MapAccess, Visitor};
use serde_saphyr::Spanned;
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
    pub sense: Option<Spanned<Sense>>,
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
            // A whole number as written (the guide's 1–6); another number in scientific
            // notation, exact and short for 1e-300 (a number is refused as a new law's key).
            Scalar::Number(x) if x.fract() == 0.0 && x.abs() < 1e15 => Ok(LawKey(format!("{x}"))),
            Scalar::Number(x) => Ok(LawKey(format!("{x:e}"))),
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
