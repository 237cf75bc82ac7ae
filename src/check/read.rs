//! The student's file: CSV with a header row, comma- or semicolon-separated (a spreadsheet
//! in a Russian or Uzbek locale saves with semicolons and decimal commas), `#` comments.
//!
//! Columns (any order, headers in English, Russian or Uzbek, case ignored):
//! - `id` (or `name`, `key`) — an answer key, a segment id, or a course name (`v_B.3`, `pb`);
//! - `position` (optional) — appended to the name: `v_B` at position `3` is `v_B.3`, and
//!   segment `pb` at `3` is `plan.?.3.pb`;
//! - `value` and `unit` — a physical value (the unit may be left empty: the answer's);
//! - or `mm` and `scale` — a length on the student's drawing and the scale they drew it at
//!   (unit per mm; `unit` names the scale's unit when given);
//! - `tolerance` (optional) — `5 %` relative, or a number in the answer's unit.

use super::{Given, Measured, Tolerance};

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReadError {
    #[error("the file has no values to check (a header row and one row per value)")]
    Empty,
    #[error("line 1: no column {0} (the header row names the columns: id, value, unit — or id, mm, scale)")]
    Missing(&'static str),
    #[error(
        "line 1: column '{0}' is not one this reads: id, position, value, unit, mm, scale, tolerance (or their Russian or Uzbek names)"
    )]
    UnknownColumn(String),
    #[error("line {line}: {column}: '{text}' is not a number")]
    Number { line: u64, column: &'static str, text: String },
    #[error("line {line}: {reason}")]
    Row { line: u64, reason: String },
    #[error("line {line}: {reason}")]
    Csv { line: u64, reason: String },
}

/// The file's text: UTF-8 (with or without a byte-order mark), else UTF-16 with its mark,
/// else Windows-1251 — what Excel on a Russian or Uzbek Windows saves "CSV" as; the second
/// value names a code page other than UTF-8, for a note to the user.
pub fn decode(bytes: &[u8]) -> (String, Option<&'static str>) {
    if let Ok(text) = std::str::from_utf8(bytes) {
        return (text.to_string(), None);
    }
    if let Some((encoding, _)) = encoding_rs::Encoding::for_bom(bytes) {
        let (text, _, _) = encoding.decode(bytes);
        return (text.into_owned(), Some(encoding.name()));
    }
    let (text, _, _) = encoding_rs::WINDOWS_1251.decode(bytes);
    (text.into_owned(), Some(encoding_rs::WINDOWS_1251.name()))
}

/// The columns a header may name, with the words it may name them by.
const COLUMNS: &[(&str, &[&str])] = &[
    ("id", &["id", "name", "key", "quantity", "nomi", "belgi", "имя", "обозначение", "величина", "kattalik"]),
    ("position", &["position", "pos", "holat", "положение", "позиция", "пол"]),
    ("value", &["value", "qiymat", "значение", "знач"]),
    ("unit", &["unit", "units", "birlik", "единица", "единицы", "ед", "едизм", "единицаизмерения"]),
    ("mm", &["mm", "length_mm", "length", "мм", "uzunlik", "длина", "длинамм", "uzunlikmm"]),
    ("scale", &["scale", "mu", "μ", "masshtab", "масштаб"]),
    ("tolerance", &["tolerance", "tol", "допуск", "chetlanish", "ruxsat"]),
];

/// The file's rows and the lines of rows left without a value (skipped), or why it cannot
/// be read.
pub fn measured(text: &str) -> Result<(Vec<Measured>, Vec<u64>), ReadError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    // Comments blanked rather than left to the reader, so that every row keeps its line.
    let text: String = text
        .split('\n')
        .map(|l| if l.trim_start().starts_with('#') { "" } else { l.trim_end_matches('\r') })
        .collect::<Vec<_>>()
        .join("\n");
    let text = text.as_str();
    let first = text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with('#')).ok_or(ReadError::Empty)?;
    let delimiter = if first.matches(';').count() > first.matches(',').count() { b';' } else { b',' };
    let mut r =
        csv::ReaderBuilder::new().delimiter(delimiter).flexible(true).trim(csv::Trim::All).from_reader(text.as_bytes());
    let header = r.headers().map_err(|e| ReadError::Csv { line: 1, reason: e.to_string() })?.clone();
    // A header compared without case, spaces and dots: "Ед. изм." is "едизм".
    let plain = |h: &str| {
        h.chars()
            .filter(|c| c.is_alphanumeric() || *c == '_' || *c == 'μ')
            .flat_map(char::to_lowercase)
            .collect::<String>()
    };
    let known = |h: &str| COLUMNS.iter().any(|(_, words)| words.contains(&plain(h).as_str()));
    if let Some(unknown) = header.iter().find(|h| !h.trim().is_empty() && !known(h)) {
        // A column dropped unread would change the verdicts (a unit, a position).
        return Err(ReadError::UnknownColumn(unknown.trim().to_string()));
    }
    let column = |name: &str| {
        let words = COLUMNS.iter().find(|(c, _)| *c == name).map(|(_, w)| *w).unwrap_or(&[]);
        header.iter().position(|h| words.contains(&plain(h).as_str()))
    };
    let id = column("id").ok_or(ReadError::Missing("id"))?;
    let (value, mm) = (column("value"), column("mm"));
    if value.is_none() && mm.is_none() {
        return Err(ReadError::Missing("value (or mm)"));
    }
    let (position, unit, scale, tolerance) = (column("position"), column("unit"), column("scale"), column("tolerance"));
    let (mut out, mut skipped) = (Vec::new(), Vec::new());
    for record in r.records() {
        let record = record.map_err(|e| ReadError::Csv {
            line: e.position().map_or(0, |p| line_at(text, p)),
            reason: e.to_string(),
        })?;
        let line = record.position().map_or(0, |p| line_at(text, p));
        let cell = |c: Option<usize>| c.and_then(|i| record.get(i)).unwrap_or("").trim();
        if record.iter().all(|c| c.trim().is_empty()) {
            continue;
        }
        let mut name = cell(Some(id)).to_string();
        if name.is_empty() {
            return Err(ReadError::Row { line, reason: "the id is empty".into() });
        }
        if !cell(position).is_empty() {
            name = format!("{name}.{}", cell(position));
        }
        let number = |c: Option<usize>, column: &'static str| -> Result<Option<f64>, ReadError> {
            let t = cell(c);
            if t.is_empty() {
                return Ok(None);
            }
            parse_number(t).map(Some).ok_or_else(|| ReadError::Number { line, column, text: t.into() })
        };
        let unit_text = cell(unit).to_string();
        let given = match (number(value, "value")?, number(mm, "mm")?) {
            (Some(v), None) => Given::Value { value: v, unit: unit_text },
            (None, Some(l)) => Given::Paper { mm: l, scale: number(scale, "scale")?, unit: unit_text },
            (Some(_), Some(_)) => {
                return Err(ReadError::Row { line, reason: "give a value or a length in mm, not both".into() });
            }
            (None, None) => {
                skipped.push(line);
                continue;
            }
        };
        let tolerance = match cell(tolerance) {
            "" => None,
            t => Some(parse_tolerance(t).ok_or_else(|| ReadError::Number {
                line,
                column: "tolerance",
                text: t.into(),
            })?),
        };
        out.push(Measured { line, name, given, tolerance });
    }
    if out.is_empty() {
        return Err(ReadError::Empty);
    }
    Ok((out, skipped))
}

/// The line a record starts on, counted from its byte offset past the blank lines the reader
/// skipped before it (its own line count leaves them out).
fn line_at(text: &str, p: &csv::Position) -> u64 {
    let start = (p.byte() as usize).min(text.len());
    let at = start + text[start..].len() - text[start..].trim_start().len();
    text.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count() as u64 + 1
}

/// A finite number, with a decimal point or comma, spaces between thousands allowed.
pub fn parse_number(t: &str) -> Option<f64> {
    let s: String = t.chars().filter(|c| !c.is_whitespace() && *c != '\u{a0}').collect();
    let s = s.replace('−', "-");
    let s = if s.contains('.') { s } else { s.replace(',', ".") };
    s.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// `5 %` (relative) or a number (absolute); negative tolerances are not.
pub fn parse_tolerance(t: &str) -> Option<Tolerance> {
    let (number, relative) = match t.trim().strip_suffix('%') {
        Some(n) => (n, true),
        None => (t, false),
    };
    let v = parse_number(number).filter(|v| *v >= 0.0)?;
    Some(if relative { Tolerance::Relative(v / 100.0) } else { Tolerance::Absolute(v) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_russian_excel_file_is_read_as_windows_1251() {
        // "Величина;Значение\nv_B.3;1,04" as Excel on a Russian Windows saves it.
        let bytes = encoding_rs::WINDOWS_1251.encode("Величина;Значение\nv_B.3;1,04\n").0.into_owned();
        assert!(std::str::from_utf8(&bytes).is_err());
        let (text, page) = decode(&bytes);
        assert_eq!((text.as_str(), page), ("Величина;Значение\nv_B.3;1,04\n", Some("windows-1251")));
        let (rows, _) = measured(&text).unwrap();
        assert_eq!(rows[0].name, "v_B.3");
        assert_eq!(decode("v_B.3".as_bytes()), ("v_B.3".to_string(), None));
    }

    #[test]
    fn commas_semicolons_comments_and_every_kind_of_row() {
        let text = "# measured by A. Student\r\nid;position;value;unit;mm;scale;tolerance\r\n# two\r\n\r\nv_B;3;1,04;m/s;;;\r\n# three\r\npb;3;;;52;0,02;5 %\r\nv_A;3;;;;;\r\n\r\n";
        let (rows, skipped) = measured(text).unwrap();
        assert_eq!(skipped, [8]);
        assert_eq!(rows[0].line, 5);
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].name, "v_B.3");
        assert_eq!(rows[0].given, Given::Value { value: 1.04, unit: "m/s".into() });
        assert_eq!(rows[1].given, Given::Paper { mm: 52.0, scale: Some(0.02), unit: String::new() });
        assert_eq!(rows[1].tolerance, Some(Tolerance::Relative(0.05)));
        assert_eq!(rows[1].line, 7);
        assert_eq!(
            measured("Обозначение;Положение;Значение;Ед. изм.\nv_B;3;1040,8;мм/с\n").unwrap().0[0].name,
            "v_B.3"
        );
        assert_eq!(measured("id;value;Bemerkung\nv_B.3;1;x\n"), Err(ReadError::UnknownColumn("Bemerkung".into())));
    }

    #[test]
    fn an_empty_file_a_missing_column_and_a_bad_number_are_refused_with_their_line() {
        assert_eq!(measured(""), Err(ReadError::Empty));
        assert_eq!(measured("id,value\nv_B.3,\n"), Err(ReadError::Empty));
        assert_eq!(measured("id,value\n"), Err(ReadError::Empty));
        assert_eq!(measured("# nothing\n\n"), Err(ReadError::Empty));
        assert_eq!(measured("name,unit\nv_B,m/s\n"), Err(ReadError::Missing("value (or mm)")));
        assert_eq!(measured("value\n1\n"), Err(ReadError::Missing("id")));
        let e = measured("id,value\nv_B.3,1.0\nv_A.3,abc\n").unwrap_err();
        assert_eq!(e, ReadError::Number { line: 3, column: "value", text: "abc".into() });
        assert!(matches!(measured("id,value\nv_B.3,NaN\n"), Err(ReadError::Number { line: 2, .. })));
        assert!(matches!(measured("id,value\nv_B.3,1e999\n"), Err(ReadError::Number { line: 2, .. })));
    }
}
