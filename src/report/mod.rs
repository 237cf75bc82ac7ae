//! The tables of the explanatory note as numbers, and their writers: CSV (full precision,
//! for programs) and Markdown (for the note). [`lever`] builds the lever sheet's tables.

pub mod cam;
pub mod gears;
pub mod lever;

use serde::Serialize;
use std::fmt::Write;

/// One row of a table: a symbol with a subscript, its unit and a value per column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub symbol: String,
    pub sub: String,
    pub unit: String,
    pub values: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NumTable {
    pub name: String,
    /// Column headings (position labels, link numbers, components).
    pub columns: Vec<String>,
    pub rows: Vec<Row>,
}

pub(crate) fn row(symbol: &str, sub: impl Into<String>, unit: &str, values: Vec<f64>) -> Row {
    Row { symbol: symbol.into(), sub: sub.into(), unit: unit.into(), values }
}

/// A table of a sheet's note: the file stem it is written under, and its title, column
/// headings and units in the sheet's language (for the Markdown; the CSV stays in SI).
#[derive(Debug, Clone, PartialEq)]
pub struct NoteTable {
    /// "velocities" → `sheet1-velocities.csv`.
    pub stem: &'static str,
    pub title: String,
    pub table: NumTable,
    /// The headings of the symbol and unit columns ("Величина", "Единица").
    pub headings: [String; 2],
    /// Each row's unit as the sheet writes it.
    pub units: Vec<String>,
    /// Whether numbers take a decimal comma (Uzbek, Russian) rather than a point.
    pub decimal_comma: bool,
    /// The value columns' headings in the sheet's language for the Markdown (empty: the
    /// table's own, which the CSV keeps stable for programs).
    pub column_titles: Vec<String>,
    /// Whether whole numbers print without decimals (tooth numbers, a centre distance of
    /// 90 mm, 1 for a condition met); otherwise every value has four significant digits.
    pub whole_numbers: bool,
}

/// A row's quantity as `symbol_sub`, or the symbol alone.
fn quantity(r: &Row) -> String {
    if r.sub.is_empty() { r.symbol.clone() } else { format!("{}_{}", r.symbol, r.sub) }
}

/// Full-precision numbers (9 decimals), fields quoted by the `csv` crate where needed.
pub fn csv(t: &NumTable) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    let header = ["quantity", "unit"].into_iter().map(str::to_string).chain(t.columns.iter().cloned());
    w.write_record(header).expect("writing to memory");
    for r in &t.rows {
        let cells = [quantity(r), r.unit.clone()].into_iter().chain(r.values.iter().map(|v| format!("{v:.9}")));
        w.write_record(cells).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("writing to memory")).expect("the cells are UTF-8")
}

/// Escapes text for a Markdown table cell: the cell separator, emphasis and HTML.
pub fn md_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '\\' | '|' | '*' | '_' | '`' | '[' | ']' | '#' | '~' => {
                out.push('\\');
                out.push(c);
            }
            '\n' | '\r' | '\t' => out.push(' '),
            _ => out.push(c),
        }
    }
    out
}

/// A table as Markdown in the sheet's language with its title as a heading; values with
/// four significant figures, as on the sheet.
pub fn markdown(n: &NoteTable) -> String {
    let t = &n.table;
    let [quantity, unit] = &n.headings;
    let mut s = format!("### {}\n\n| {} | {} |", md_escape(&n.title), md_escape(quantity), md_escape(unit));
    let titles = if n.column_titles.len() == t.columns.len() { &n.column_titles } else { &t.columns };
    for c in titles {
        let _ = write!(s, " {} |", md_escape(c));
    }
    s.push_str("\n|---|---|");
    s.push_str(&"---:|".repeat(t.columns.len()));
    s.push('\n');
    for (r, unit) in t.rows.iter().zip(&n.units) {
        let sub = if r.sub.is_empty() { String::new() } else { format!("<sub>{}</sub>", md_escape(&r.sub)) };
        let _ = write!(s, "| {}{sub} | {} |", md_escape(&r.symbol), md_escape(unit));
        for &v in &r.values {
            let whole = n.whole_numbers && v.fract() == 0.0 && v.abs() < 1e9;
            let v = if whole { format!("{v:.0}") } else { crate::num::digits::significant(v) }.replace('-', "−");
            let _ = write!(s, " {} |", if n.decimal_comma { v.replace('.', ",") } else { v });
        }
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(column: &str, sub: &str) -> NumTable {
        NumTable { name: "t".into(), columns: vec![column.into()], rows: vec![row("v", sub, "m/s", vec![1.0])] }
    }

    #[test]
    fn csv_quotes_fields_with_separators_and_quotes() {
        let s = csv(&table("a,\"b\"", "B,A"));
        assert_eq!(s, "quantity,unit,\"a,\"\"b\"\"\"\n\"v_B,A\",m/s,1.000000000\n");
    }

    fn note(t: NumTable, title: &str) -> NoteTable {
        let units = t.rows.iter().map(|r| r.unit.clone()).collect();
        NoteTable {
            stem: "t",
            title: title.into(),
            table: t,
            headings: ["q".into(), "u".into()],
            units,
            decimal_comma: true,
            column_titles: Vec::new(),
            whole_numbers: false,
        }
    }

    #[test]
    fn markdown_cells_cannot_break_the_table() {
        let s = markdown(&note(table("x|y", "<b>*"), "T | 1"));
        assert!(s.starts_with("### T \\| 1\n"), "{s}");
        assert!(s.contains("| x\\|y |") && s.contains("<sub>&lt;b&gt;\\*</sub>") && s.contains("| 1,000 |"), "{s}");
        for line in s.lines().skip(2) {
            let unescaped = line.replace("\\|", "");
            assert_eq!(unescaped.matches('|').count(), 4, "{line}");
        }
    }
}
