//! The verdicts as a teacher reads them: an aligned table for the terminal, Markdown for a
//! note, CSV for a spreadsheet. Numbers with four significant digits (the sheets'), the
//! deviation also in percent of the exact value.

use super::Verdict;
use crate::num::digits;

const HEAD: [&str; 8] = ["line", "id", "exact", "student", "unit", "deviation", "allowed", "result"];

/// A number as every report prints it: four significant digits (the sheets').
pub fn number(x: f64) -> String {
    digits::sig(x, 4)
}

/// The deviation signed, with its percent of the exact value ("+0.003064 (+0.0 %)").
pub fn deviation(v: &Verdict) -> String {
    let share = v.deviation_shown() / v.exact.abs() * 100.0;
    let percent = match share {
        _ if v.exact == 0.0 => String::new(),
        s if s.abs() > 999.0 => format!(" ({}999 %)", if s > 0.0 { ">+" } else { "<-" }),
        s => format!(" ({s:+.1} %)"),
    };
    format!("{}{percent}", signed(v.deviation_shown()))
}

/// What the value was matched to, and the student's name for it when it differs.
pub fn quantity(v: &Verdict) -> String {
    if v.name == v.id { v.id.clone() } else { format!("{} ({})", v.id, v.name) }
}

fn cells(v: &Verdict) -> [String; 8] {
    [
        v.line.to_string(),
        quantity(v),
        number(v.exact),
        number(v.student),
        v.unit.clone(),
        deviation(v),
        format!("±{} ({})", number(v.tolerance), v.rule),
        if v.pass { "pass" } else { "FAIL" }.to_string(),
    ]
}

fn signed(x: f64) -> String {
    let s = number(x);
    if x > 0.0 { format!("+{s}") } else { s }
}

/// "12 of 14 values pass".
pub fn summary(verdicts: &[Verdict]) -> String {
    let passed = verdicts.iter().filter(|v| v.pass).count();
    format!("{passed} of {} values pass", verdicts.len())
}

/// An aligned plain-text table and the summary line.
pub fn text(verdicts: &[Verdict]) -> String {
    let rows: Vec<[String; 8]> = verdicts.iter().map(cells).collect();
    let width = |c: usize| rows.iter().map(|r| r[c].chars().count()).chain([HEAD[c].len()]).max().unwrap_or(0);
    let widths: Vec<usize> = (0..8).map(width).collect();
    let line = |r: &[String]| {
        let padded: Vec<String> =
            r.iter().zip(&widths).map(|(c, &w)| format!("{c}{}", " ".repeat(w - c.chars().count()))).collect();
        padded.join("  ").trim_end().to_string() + "\n"
    };
    let mut out = line(&HEAD.map(String::from));
    for r in &rows {
        out.push_str(&line(r));
    }
    out + &summary(verdicts) + "\n"
}

/// A Markdown table and the summary.
pub fn markdown(verdicts: &[Verdict]) -> String {
    let mut out = format!("| {} |\n|{}\n", HEAD.join(" | "), "---|".repeat(8));
    for v in verdicts {
        out.push_str(&format!("| {} |\n", cells(v).map(|c| c.replace('|', "\\|")).join(" | ")));
    }
    out + "\n" + &summary(verdicts) + "\n"
}

/// CSV, full precision, one row a value.
pub fn csv(verdicts: &[Verdict]) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["line", "id", "name", "exact", "student", "unit", "deviation", "tolerance", "rule", "pass"])
        .expect("writing to memory");
    for v in verdicts {
        w.write_record([
            v.line.to_string(),
            v.id.clone(),
            v.name.clone(),
            format!("{:.9}", v.exact),
            format!("{:.9}", v.student),
            v.unit.clone(),
            format!("{:.9}", v.deviation),
            format!("{:.9}", v.tolerance),
            v.rule.to_string(),
            v.pass.to_string(),
        ])
        .expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("flushing to memory")).expect("UTF-8")
}
