//! The cam's laws as written: the `laws` table (each key a built-in law it replaces or a new
//! one, each corner list a [`Custom`] law) and the law of each phase by key or the guide's
//! number.

use super::super::text::{self, Lines};
use super::super::values::LocalText;
use super::super::{Refusal, Warning, at, invalid, warning};
use super::spec::{LawTable, PerPhase, Scalar};
use crate::cams::integrate;
use crate::cams::laws::{Custom, Law, LawError, Program, Standard};
use crate::num::digits::{fixed, written};
use serde_saphyr::{Location, Spanned};

/// A law of the file's `laws` table, with its name.
pub(super) struct UserLaw {
    pub(super) law: Law,
    pub(super) name: Option<LocalText>,
}

/// Resolves the `laws` table: each key to the built-in law it replaces (by key or the guide's
/// number) or to a new key, each corner list to a law.
pub(super) fn law_table(
    spec: Option<&Spanned<LawTable>>,
    warnings: &mut Vec<Warning>,
) -> Result<Vec<UserLaw>, Refusal> {
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

/// A corner between the chords the sheet integrates the phase in is cut off by the chord
/// integration (it samples s″ at the chords' middles): says so with the error it makes. The
/// chords are the course's divisions, each in as many chords as the sheet takes for this
/// law on both phases ([`integrate::turn_within`]).
fn corner_between_divisions(law: &Custom) -> Option<String> {
    let divisions = integrate::DIVISIONS;
    let program = Program::new(1.0, 0.0, 1.0, (law.clone(), law.clone()), 1.0).ok()?;
    let turn = integrate::turn_within(&program, divisions);
    let chords = divisions * turn[0].chords;
    let n = chords as f64;
    let (x, _) = law.corners().find(|(x, _)| ((x * n).round() - x * n).abs() > 1e-9)?;
    let error = turn[0].error(&program).s;
    let each =
        if turn[0].chords > 1 { format!(", each integrated in {} chords", turn[0].chords) } else { String::new() };
    Some(format!(
        "a corner at x = {} lies between the integration's {chords} chords of the phase (the course's {divisions} divisions{each}; multiples of 1/{chords}): the graphical integration cuts it off and misses the displacement by up to {} % of the lift; corners at the chords' ends are drawn exactly",
        written(x),
        fixed(error * 100.0, 1)
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
            Scalar::Number(x) => written(*x),
        };
        invalid(loc, field, format!("unknown law {shown} ({})", known_laws(table)))
    })
}

pub(super) fn laws(spec: &Spanned<PerPhase>, table: &[UserLaw]) -> Result<(Law, Law), Refusal> {
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
