//! `tmm check`: a student's values against the exact answers. Pure: the reference (every
//! answer key and measured segment of the built sheets) and the student's rows in, one
//! verdict per row out; reading the file is [`read`], the units [`units`], the writers
//! [`mod@write`].
//!
//! Tolerances: the course's where it states one (the contact ratio measured on the drawing
//! against the analytic one: 10 %), else 2 % of the exact value or 0.5 mm on the paper,
//! whichever is larger — the paper's millimetre at the student's scale when they give their
//! lengths, else at the reference sheet's scale when the quantity is drawn there; a value
//! whose exact answer is 0 with no scale known is allowed 2 % of the largest value of its
//! row (the same quantity at the other positions), the size its drawing has.

pub mod read;
pub mod units;
pub mod write;

use crate::report::{Answer, Segment};
use std::collections::BTreeMap;

/// The course's relative tolerance where it states none.
pub const RELATIVE: f64 = 0.02;
/// A percentage's tolerance, percentage points.
pub const PERCENT_POINT: f64 = 1.0;
/// What a ruler on paper is good for, mm.
pub const PAPER_MM: f64 = 0.5;
/// Answers the course gives its own tolerance: the contact ratio drawn vs analytic.
const COURSE: &[(&str, f64)] = &[(".pair.epsilon", 0.10), (".pair.epsilon_drawn", 0.10)];

/// What the student's values are checked against.
#[derive(Debug, Clone, Default)]
pub struct Reference {
    /// Every answer key of every built sheet.
    pub answers: Vec<Answer>,
    /// Every measured segment, under its full id (`sheet1.plan.v.3.pb`).
    pub segments: Vec<(String, Segment)>,
    /// The project's sheets that could not be built, and why: a value of one of them is
    /// named as such, not as unknown.
    pub missing: Vec<(u32, String)>,
}

/// One row of the student's file.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The file's line.
    pub line: u64,
    /// As the student wrote it: an answer key, a segment id or a course name ("v_B.3", "pb").
    pub name: String,
    pub given: Given,
    pub tolerance: Option<Tolerance>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Given {
    /// A physical value in `unit` (empty: the answer's own).
    Value { value: f64, unit: String },
    /// A length on the student's drawing, mm, and the scale they drew it at (in the answer's
    /// unit per mm, or `unit` per mm); without a scale, a segment's length on the reference
    /// sheet is compared.
    Paper { mm: f64, scale: Option<f64>, unit: String },
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// A share of the exact value (0.05 for 5 %).
    Relative(f64),
    /// In the answer's unit.
    Absolute(f64),
}

/// One value checked.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Verdict {
    pub line: u64,
    /// The identifier it was matched to.
    pub id: String,
    /// As the student wrote it.
    pub name: String,
    pub unit: String,
    pub exact: f64,
    pub student: f64,
    /// student − exact, in `unit`.
    pub deviation: f64,
    /// The deviation allowed, in `unit`.
    pub tolerance: f64,
    /// Where the tolerance comes from.
    pub rule: Rule,
    pub pass: bool,
}

impl Verdict {
    /// The deviation as a report prints it: a difference of rounding (a student's value
    /// written with twelve digits) is none.
    pub fn deviation_shown(&self) -> f64 {
        if self.deviation.abs() <= 1e-9 * self.exact.abs().max(self.tolerance) { 0.0 } else { self.deviation }
    }
}

/// Where a value's tolerance comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// The file's `tolerance` column or `--tolerance`.
    Given,
    /// The course states it (the drawn contact ratio: 10 %).
    Course,
    /// A percentage, to one point.
    PercentPoint,
    /// 0.5 mm on the paper.
    Paper,
    /// 2 % of the value.
    Relative,
    /// 2 % of the row's largest value (the exact value is 0).
    RowRelative,
}

impl Rule {
    /// As the terminal, Markdown and CSV reports write it.
    pub const fn as_str(self) -> &'static str {
        match self {
            Rule::Given => "given",
            Rule::Course => "course",
            Rule::PercentPoint => "1 point",
            Rule::Paper => "0.5 mm",
            Rule::Relative => "2 %",
            Rule::RowRelative => "2 % of the row",
        }
    }
}

impl std::fmt::Display for Rule {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl serde::Serialize for Rule {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckError {
    #[error("line {line}: '{name}' is not a value of these sheets{}", hint(close))]
    Unknown { line: u64, name: String, close: Vec<String> },
    #[error("line {line}: '{name}' could be any of {}; write more of its identifier (its position: v_B.3; its plan: v.3.ab)", ids.join(", "))]
    Ambiguous { line: u64, name: String, ids: Vec<String> },
    #[error("line {line}: '{unit}' is not a unit of {id} (write it in {expected})")]
    Unit { line: u64, unit: String, id: String, expected: String },
    #[error("line {line}: {name} is a value, not a drawn segment: give the scale you drew it at (a 'scale' column)")]
    NoScale { line: u64, name: String },
    #[error("line {line}: '{name}' is on sheet {sheet}, which this project cannot build: {reason}")]
    NotBuilt { line: u64, name: String, sheet: u32, reason: String },
}

fn hint(close: &[String]) -> String {
    if close.is_empty() { String::new() } else { format!("; did you mean {}?", close.join(", ")) }
}

/// What a name can stand for: an answer, or a segment (its length and the answer it draws).
#[derive(Debug, Clone)]
struct Target {
    id: String,
    value: f64,
    unit: &'static str,
    /// Its drawing's scale on the reference sheet, unit per mm.
    scale: Option<f64>,
    /// A segment's length on the reference sheet, mm.
    length_mm: Option<f64>,
    /// The largest |value| of its row (the same quantity at every position).
    row_max: f64,
    /// A jump's value after its position, as right as `value` (see [`Answer::after`]).
    after: Option<f64>,
}

impl Reference {
    fn targets(&self) -> Vec<Target> {
        // A row: the id without its last part, and its unit (a one-column table's "row"
        // is the whole table: only its values of the same unit share a size).
        let row = |a: &Answer| format!("{} {}", a.id.rsplit_once('.').map_or(a.id.as_str(), |(r, _)| r), a.unit);
        let mut row_max: BTreeMap<String, f64> = BTreeMap::new();
        for a in &self.answers {
            let m = row_max.entry(row(a)).or_insert(0.0);
            *m = m.max(a.value.abs());
        }
        let drawn: BTreeMap<&str, f64> =
            self.segments.iter().filter_map(|(_, s)| Some((s.quantity.as_deref()?, s.scale))).collect();
        let answers = self.answers.iter().map(|a| Target {
            id: a.id.clone(),
            value: a.value,
            unit: a.unit,
            scale: drawn.get(a.id.as_str()).copied(),
            length_mm: None,
            row_max: row_max[&row(a)],
            after: a.after,
        });
        let segments = self.segments.iter().map(|(id, s)| Target {
            id: id.clone(),
            value: s.value,
            unit: s.unit,
            scale: Some(s.scale),
            length_mm: Some(s.length_mm),
            row_max: s.value.abs(),
            after: None,
        });
        answers.chain(segments).collect()
    }
}

/// A name reduced for matching: no sheet prefix, case and underscores ignored, Greek
/// letters by their names ("ω_2" = "omega2" = "OMEGA_2").
fn folded(name: &str) -> String {
    // A prime typed as an apostrophe (or Word's ’): 4' is 4′.
    let name: String = name.trim().chars().map(|c| if matches!(c, '\'' | '’' | 'ʼ' | '`') { '′' } else { c }).collect();
    let key = crate::report::ascii_key(&name);
    key.chars().filter(|&c| c != '_').flat_map(char::to_lowercase).collect()
}

/// The target a student's name stands for: the whole id; or the id's end after a dot
/// (`v_B.3`, `plan.v.3.pb`); or, ignoring case, underscores and Greek spelling, the same.
fn resolve<'a>(targets: &'a [Target], missing: &[(u32, String)], m: &Measured) -> Result<&'a Target, CheckError> {
    let name = m.name.trim();
    // A segment's position comes before its name (plan.v.3.pb): "pb.3" is that too, at the
    // same rank — "ab.3" is v_BA's segment ab of plan 3, not a_B.3 spelled loosely.
    let swapped = name.rsplit_once('.').map(|(n, position)| format!("{position}.{n}"));
    let spellings: Vec<&str> = [Some(name), swapped.as_deref()].into_iter().flatten().collect();
    let found = (0..RANKS)
        .map(|rank| {
            let mut all: Vec<&Target> = spellings.iter().flat_map(|n| matching(targets, n, rank)).collect();
            all.dedup_by(|a, b| a.id == b.id);
            all
        })
        .find(|f| !f.is_empty())
        .unwrap_or_default();
    // A name both an answer and a segment have (an_BA.3): a length is the segment's, a value
    // in a unit of the quantity the answer's.
    let paper = match &m.given {
        Given::Paper { .. } => true,
        Given::Value { unit, .. } => units::factor(unit, "mm") == Some(1.0),
    };
    let preferred: Vec<&Target> = found.iter().copied().filter(|t| t.length_mm.is_some() == paper).collect();
    let found = if found.len() > 1 && preferred.len() == 1 { preferred } else { found };
    match found.as_slice() {
        [one] => Ok(one),
        [] => Err(match missing.iter().find(|(n, _)| name.starts_with(&format!("sheet{n}."))) {
            Some((sheet, reason)) => {
                CheckError::NotBuilt { line: m.line, name: name.into(), sheet: *sheet, reason: reason.clone() }
            }
            None => CheckError::Unknown { line: m.line, name: name.into(), close: close_names(targets, name) },
        }),
        many => Err(CheckError::Ambiguous {
            line: m.line,
            name: name.into(),
            ids: many.iter().take(6).map(|t| t.id.clone()).collect(),
        }),
    }
}

/// How many ways of matching a name there are, tried in order: the whole id, an end of
/// it, an end of it spelled loosely, a quantity without its position.
const RANKS: usize = 4;

/// The targets `name` stands for at `rank` (see [`resolve`]).
fn matching<'a>(targets: &'a [Target], name: &str, rank: usize) -> Vec<&'a Target> {
    let by = |f: &dyn Fn(&Target) -> bool| targets.iter().filter(|t| f(t)).collect::<Vec<_>>();
    match rank {
        0 => by(&|t| t.id == name),
        1 => by(&|t| t.id.ends_with(&format!(".{name}"))),
        2 => {
            let want = folded(name);
            by(&|t| {
                let parts: Vec<&str> = t.id.split('.').collect();
                (1..parts.len()).any(|i| folded(&parts[i..].join(".")) == want)
            })
        }
        // A quantity without its position or column ("v_B"): every one of its row, so that
        // the message lists them.
        _ => by(&|t| t.id.rsplit_once('.').is_some_and(|(row, _)| row.ends_with(&format!(".{name}")))),
    }
}

/// Up to five known names nearest to `name` (by edit distance on their folded forms).
fn close_names(targets: &[Target], name: &str) -> Vec<String> {
    let want = folded(name);
    let mut scored: Vec<(usize, &str)> = targets
        .iter()
        .map(|t| {
            let parts: Vec<&str> = t.id.split('.').collect();
            let best = (1..parts.len())
                .map(|i| crate::num::edit_distance(&folded(&parts[i..].join(".")), &want))
                .min()
                .unwrap_or(usize::MAX);
            (best, t.id.as_str())
        })
        .collect();
    scored.sort();
    let limit = (want.len() / 3).max(2);
    scored.into_iter().filter(|(d, _)| *d <= limit).take(5).map(|(_, id)| id.to_string()).collect()
}

/// Checks every row: a verdict each, or every row that cannot be checked (all at once, so
/// that one run shows the student every name and unit to mend).
pub fn check(reference: &Reference, rows: &[Measured], over: Option<Tolerance>) -> Result<Vec<Verdict>, Unchecked> {
    let targets = reference.targets();
    let (verdicts, errors): (Vec<_>, Vec<_>) =
        rows.iter().map(|m| verdict(&targets, &reference.missing, m, over)).partition(Result::is_ok);
    if errors.is_empty() {
        Ok(verdicts.into_iter().map(|v| v.expect("partitioned")).collect())
    } else {
        Err(Unchecked(errors.into_iter().map(|e| e.expect_err("partitioned")).collect()))
    }
}

/// The rows that cannot be checked, in the file's order; one line each.
#[derive(Debug, Clone, PartialEq)]
pub struct Unchecked(pub Vec<CheckError>);

impl std::fmt::Display for Unchecked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let lines: Vec<String> = self.0.iter().map(ToString::to_string).collect();
        f.write_str(&lines.join("\n"))
    }
}

impl std::error::Error for Unchecked {}

fn verdict(
    targets: &[Target],
    missing: &[(u32, String)],
    m: &Measured,
    over: Option<Tolerance>,
) -> Result<Verdict, CheckError> {
    let t = resolve(targets, missing, m)?;
    let convert = |unit: &str| {
        units::factor(unit, t.unit).ok_or_else(|| CheckError::Unit {
            line: m.line,
            unit: unit.into(),
            id: t.id.clone(),
            expected: units::spelled(t.unit),
        })
    };
    // (exact, student, unit, the paper's scale for the 0.5 mm rule)
    // A segment's value in mm (or without a unit) is its length on the paper — unless the
    // segment stands for a length itself (a gear's radius: mm are its value) or for a number
    // (an analog of a rocker's law: no unit is its own); their paper lengths come in the `mm`
    // column.
    let length_itself = t.unit == "mm";
    let number_itself = |unit: &str| t.unit.is_empty() && unit.trim().is_empty();
    let given = match &m.given {
        Given::Value { value, unit }
            if t.length_mm.is_some()
                && !length_itself
                && !number_itself(unit)
                && units::factor(unit, "mm") == Some(1.0) =>
        {
            Given::Paper { mm: *value, scale: None, unit: String::new() }
        }
        other => other.clone(),
    };
    let (exact, student, unit, paper) = match &given {
        Given::Value { value, unit } => (t.value, value * convert(unit)?, t.unit.to_string(), t.scale),
        Given::Paper { mm, scale: Some(s), unit } => {
            let mu = s * convert(unit)?;
            (t.value, mm * mu, t.unit.to_string(), Some(mu))
        }
        Given::Paper { mm, scale: None, .. } => match t.length_mm {
            Some(l) => (l, *mm, "mm".to_string(), Some(1.0)),
            None => return Err(CheckError::NoScale { line: m.line, name: m.name.clone() }),
        },
    };
    // At a jump the value after it is as right as the one before: the nearer is judged.
    let exact = t.after.filter(|a| (student - a).abs() < (student - exact).abs()).unwrap_or(exact);
    // The exact value as the tables print it: a zero computed as 1e-13 is 0.
    let exact = if exact.abs() <= 1e-9 * t.row_max.max(1.0) { 0.0 } else { exact };
    let course = COURSE.iter().find(|(end, _)| t.id.ends_with(end)).map(|&(_, r)| r);
    let (tolerance, rule) = match (m.tolerance.or(over), course) {
        (Some(Tolerance::Relative(r)), _) => (r * exact.abs(), Rule::Given),
        (Some(Tolerance::Absolute(a)), _) => (a, Rule::Given),
        (None, Some(r)) => (r * exact.abs(), Rule::Course),
        (None, None) if t.unit == "%" => {
            // A percentage (Δ between two methods, an integration's error) to a point.
            ((RELATIVE * exact.abs()).max(PERCENT_POINT), Rule::PercentPoint)
        }
        (None, None) => default_tolerance(exact, paper, t.row_max),
    };
    let deviation = student - exact;
    // A hair of rounding on top: a value exactly at the limit passes.
    let pass = deviation.abs() <= tolerance * (1.0 + 1e-9) + 1e-12;
    Ok(Verdict {
        line: m.line,
        id: t.id.clone(),
        name: m.name.clone(),
        unit,
        exact,
        student,
        deviation,
        tolerance,
        rule,
        pass,
    })
}

/// 2 % of the value or 0.5 mm on the paper at `paper` (unit per mm), whichever is larger;
/// with no scale and an exact 0, 2 % of the row's largest value.
fn default_tolerance(exact: f64, paper: Option<f64>, row_max: f64) -> (f64, Rule) {
    let relative = RELATIVE * exact.abs();
    match paper {
        Some(mu) if PAPER_MM * mu > relative => (PAPER_MM * mu, Rule::Paper),
        Some(_) => (relative, Rule::Relative),
        None if relative > 0.0 => (relative, Rule::Relative),
        None => (RELATIVE * row_max, Rule::RowRelative),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference() -> Reference {
        let answer = |id: &str, value| Answer { id: id.into(), value, unit: "m/s", after: None };
        Reference {
            answers: vec![answer("sheet1.velocities.v_B.0", 0.0), answer("sheet1.velocities.v_B.3", 1.0)],
            segments: vec![(
                "sheet1.plan.v.3.pb".into(),
                Segment {
                    id: "plan.v.3.pb".into(),
                    name: "pb".into(),
                    length_mm: 20.0,
                    quantity: Some("sheet1.velocities.v_B.3".into()),
                    value: 1.0,
                    unit: "m/s",
                    scale: 0.05,
                },
            )],
            missing: vec![(3, "cam.phases: the phases exceed a turn".into())],
        }
    }

    #[test]
    fn a_value_of_a_sheet_not_built_is_named_with_the_reason() {
        let m = Measured {
            line: 4,
            name: "sheet3.results.r_min".into(),
            given: Given::Value { value: 50.0, unit: "mm".into() },
            tolerance: None,
        };
        let e = check(&reference(), &[m], None).unwrap_err().to_string();
        assert_eq!(
            e,
            "line 4: 'sheet3.results.r_min' is on sheet 3, which this project cannot build: cam.phases: the phases exceed a turn"
        );
    }

    fn one(name: &str, given: Given) -> Verdict {
        let m = Measured { line: 2, name: name.into(), given, tolerance: None };
        check(&reference(), &[m], None).unwrap().remove(0)
    }

    #[test]
    fn the_larger_of_two_percent_and_half_a_millimetre_at_the_drawings_scale() {
        // Drawn at 0.05 (m/s)/mm: 0.5 mm is 0.025 m/s, more than 2 % of 1 m/s.
        let v = one("v_B.3", Given::Value { value: 1.024, unit: String::new() });
        assert!((v.tolerance - 0.025).abs() < 1e-15 && v.pass && v.rule == Rule::Paper);
        // The student's own scale, 0.01 (m/s)/mm: 0.5 mm is 0.005, so 2 % rules.
        let v = one("pb.3", Given::Paper { mm: 102.5, scale: Some(0.01), unit: String::new() });
        assert!((v.tolerance - 0.02).abs() < 1e-15 && !v.pass && v.rule == Rule::Relative);
        // A length compared with the reference sheet's segment: 0.5 mm.
        let v = one("plan.v.3.pb", Given::Paper { mm: 20.4, scale: None, unit: String::new() });
        assert!(v.pass && v.unit == "mm" && (v.exact - 20.0).abs() < 1e-15);
    }

    #[test]
    fn an_exact_zero_is_allowed_two_percent_of_its_row() {
        let v = one("v_B.0", Given::Value { value: 0.015, unit: String::new() });
        assert!((v.tolerance - 0.02).abs() < 1e-15 && v.pass, "{v:?}");
        let v = one("v_B.0", Given::Value { value: 0.03, unit: String::new() });
        assert!(!v.pass);
    }

    #[test]
    fn names_in_any_spelling_resolve_and_an_unknown_one_suggests() {
        let targets = reference().targets();
        let m = |name: &str| Measured {
            line: 2,
            name: name.into(),
            given: Given::Value { value: 1.0, unit: String::new() },
            tolerance: None,
        };
        for name in ["sheet1.velocities.v_B.3", "velocities.v_B.3", "v_B.3", "V_B.3", "vb.3", "pb.3", "3.pb"] {
            let t = resolve(&targets, &[], &m(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(t.id.ends_with(".3") || t.id.ends_with(".pb"), "{name} → {}", t.id);
        }
        match resolve(&targets, &[], &m("v_C.3")) {
            Err(CheckError::Unknown { close, .. }) => assert!(close.contains(&"sheet1.velocities.v_B.3".to_string())),
            other => panic!("{other:?}"),
        }
    }
}
