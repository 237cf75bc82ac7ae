//! Reading one catalogue folder: `task.yaml` (the columns, constants and template),
//! `variants.csv` (the tables as printed) and `errata.csv` (the corrections). A catalogue
//! error names the folder, the file and, where it has one, the line.

use crate::drawing::labels::{Entry, Language};
use serde::Deserialize;
use std::collections::BTreeMap;

/// A task's number as `task.yaml` writes it: `7`, or a practice set's `P1`.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
enum Number {
    Guide(u32),
    Named(String),
}

/// `task.yaml`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Meta {
    task: Number,
    pub name: Entry,
    pub kind: Entry,
    /// Each printed table and the variants it holds ("7.1": "1-15").
    pub tables: BTreeMap<String, String>,
    pub columns: Vec<Column>,
    #[serde(default)]
    pub key_columns: Vec<String>,
    #[serde(default)]
    pub constants: Vec<Constant>,
    /// Values computed from the columns and constants, in order, for the template to use by
    /// name (a scheme's pivot from the printed dimensions, a mass from q·l).
    #[serde(default)]
    pub derived: Vec<Derived>,
    #[serde(default)]
    pub lost: Vec<VariantNote>,
    /// Variants whose printed data the program refuses, and why the guide's data explain it
    /// (a chain that cannot close, a ratio no planetary stage gives).
    #[serde(default)]
    pub refused: Vec<VariantNote>,
    pub template: String,
}

/// A column of the task's tables.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Column {
    pub key: String,
    /// Its heading as printed ("L_O1A").
    pub printed: String,
    pub unit: String,
    pub what: Entry,
}

/// A value the task's notes fix for every variant.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Constant {
    pub key: String,
    /// Its symbol as the guide writes it (default: the key).
    #[serde(default)]
    pub printed: Option<String>,
    pub value: f64,
    pub unit: String,
    pub what: Entry,
    pub source: Entry,
}

/// A value computed from others: `{key: x_o3, expression: "c + l_o2b", what: {…}}`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Derived {
    pub key: String,
    pub expression: String,
    #[serde(default)]
    pub unit: String,
    pub what: Entry,
}

/// A note on some variants: why they lack values, or why the program refuses them as printed.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VariantNote {
    pub variants: String,
    pub why: Entry,
}

/// One variant's row as printed: its table and its cells in the columns' order (`None`
/// where the transcription lost the value).
#[derive(Debug, Clone)]
pub struct Row {
    pub variant: u32,
    pub table: String,
    pub cells: Vec<Option<String>>,
}

/// A correction of a printed cell.
#[derive(Debug, Clone)]
pub struct Erratum {
    pub variant: u32,
    pub column: String,
    pub printed: Option<String>,
    /// `None`: the printed value is refused and nothing replaces it.
    pub corrected: Option<String>,
    pub reason: Entry,
}

impl Meta {
    /// The task's identifier as the command line writes it: "7", "P1".
    pub fn id(&self) -> String {
        match &self.task {
            Number::Guide(n) => n.to_string(),
            Number::Named(s) => s.clone(),
        }
    }
}

/// Parses `task.yaml`.
pub(super) fn meta(text: &str) -> Result<Meta, String> {
    serde_saphyr::from_str(text).map_err(|e| format!("task.yaml: {e}"))
}

/// Parses `variants.csv` against the task's columns: the header must be `variant,table`
/// and the columns' keys in order; every value a number or empty.
pub(super) fn rows(text: &str, columns: &[Column]) -> Result<Vec<Row>, String> {
    let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(text.as_bytes());
    let header: Vec<String> =
        reader.headers().map_err(|e| format!("variants.csv: {e}"))?.iter().map(|h| h.trim().to_string()).collect();
    let expected: Vec<String> =
        ["variant", "table"].iter().map(|s| s.to_string()).chain(columns.iter().map(|c| c.key.clone())).collect();
    if header != expected {
        return Err(format!(
            "variants.csv: the header is `{}`; task.yaml's columns make it `{}`",
            header.join(","),
            expected.join(",")
        ));
    }
    let mut out = Vec::new();
    for (i, record) in reader.records().enumerate() {
        let line = i + 2;
        let record = record.map_err(|e| format!("variants.csv, line {line}: {e}"))?;
        let at = |what: String| format!("variants.csv, line {line}: {what}");
        let variant =
            record[0].trim().parse::<u32>().map_err(|_| at(format!("variant `{}` is not a number", &record[0])))?;
        let mut cells = Vec::new();
        for (k, cell) in record.iter().enumerate().skip(2) {
            let cell = cell.trim();
            if !cell.is_empty() && number(cell).is_none() {
                return Err(at(format!("column {}: `{cell}` is not a number", expected[k])));
            }
            cells.push((!cell.is_empty()).then(|| cell.to_string()));
        }
        out.push(Row { variant, table: record[1].trim().to_string(), cells });
    }
    Ok(out)
}

/// Parses `errata.csv` (empty text: no corrections).
pub(super) fn errata(text: &str) -> Result<Vec<Erratum>, String> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(text.as_bytes());
    let header: Vec<&str> = reader.headers().map_err(|e| format!("errata.csv: {e}"))?.iter().collect();
    let expected = ["variant", "column", "printed", "corrected", "reason_uz", "reason_ru", "reason_en"];
    if header != expected {
        return Err(format!("errata.csv: the header must be `{}`", expected.join(",")));
    }
    let mut out = Vec::new();
    for (i, record) in reader.records().enumerate() {
        let line = i + 2;
        let record = record.map_err(|e| format!("errata.csv, line {line}: {e}"))?;
        let variant = record[0]
            .trim()
            .parse::<u32>()
            .map_err(|_| format!("errata.csv, line {line}: variant `{}`", &record[0]))?;
        let optional = |s: &str| (!s.trim().is_empty()).then(|| s.trim().to_string());
        let corrected = optional(&record[3]);
        if let Some(c) = &corrected
            && number(c).is_none()
        {
            return Err(format!("errata.csv, line {line}: corrected value `{c}` is not a number"));
        }
        out.push(Erratum {
            variant,
            column: record[1].trim().to_string(),
            printed: optional(&record[2]),
            corrected,
            reason: Entry { uz: record[4].to_string(), ru: record[5].to_string(), en: record[6].to_string() },
        });
    }
    Ok(out)
}

/// A cell's number (`0.120`), finite.
pub fn number(cell: &str) -> Option<f64> {
    cell.trim().parse::<f64>().ok().filter(|x| x.is_finite())
}

/// A cell as the guide prints it: a decimal comma in Uzbek and Russian.
pub fn printed(cell: &str, lang: Language) -> String {
    match lang {
        Language::En => cell.to_string(),
        _ => cell.replace('.', ","),
    }
}

/// The variants a range text names ("1-30", "4", "1-15, 31"), or `None` if unreadable.
pub fn range(text: &str) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    for part in text.split(',') {
        let part = part.trim();
        match part.split_once(['-', '–']) {
            Some((a, b)) => {
                let (a, b) = (a.trim().parse::<u32>().ok()?, b.trim().parse::<u32>().ok()?);
                if a > b {
                    return None;
                }
                out.extend(a..=b);
            }
            None => out.push(part.parse().ok()?),
        }
    }
    Some(out)
}
