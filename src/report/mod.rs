//! The tables of the explanatory note as numbers, and their writers: CSV (full precision,
//! for programs) and Markdown (for the note). [`lever`] builds the lever sheet's tables.

pub mod cam;
pub mod gears;
pub mod lever;
pub mod segments;

mod table;

pub use segments::{AnswerKeys, Segment, segments_csv};
pub use table::{
    Column, ForceKind, NumTable, Quantity, Row, Sub, SubWord, Unit, ascii_key, share_decimals, share_decimals_within,
    share_exact_decimals,
};

use std::fmt::Write;

/// A table of a sheet's note in the sheet's language: the typed table, its title, its
/// column headings and each row's symbol, subscript and unit as printed.
#[derive(Debug, Clone, PartialEq)]
pub struct NoteTable {
    pub table: NumTable,
    pub title: String,
    /// The headings of the symbol and unit columns ("Величина", "Единица").
    pub headings: [String; 2],
    /// Each row's symbol and subscript as the sheet prints them (P, и2; a condition's name).
    pub printed: Vec<(String, String)>,
    /// Each row's unit as the sheet writes it.
    pub units: Vec<String>,
    /// The value columns' headings in the sheet's language.
    pub column_titles: Vec<String>,
    /// Whether numbers take a decimal comma (Uzbek, Russian) rather than a point.
    pub decimal_comma: bool,
    /// Whether whole numbers print without decimals (tooth numbers, a centre distance of
    /// 90 mm, 1 for a condition met); otherwise every value has four significant digits.
    pub whole_numbers: bool,
}

/// One value of a table under its identifier (`sheet2.pair.epsilon`), in the table's unit.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Answer {
    #[serde(skip)]
    pub id: String,
    pub value: f64,
    pub unit: &'static str,
    /// Where the quantity jumps at the cell's position, its value just after (`value` is
    /// the one before): either is right (see [`Row::jumps`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub after: Option<f64>,
}

impl NoteTable {
    /// Row `r`'s values as the note and the sheet print them alike (see [`Row::printed`]):
    /// whole numbers without decimals in a count's row or a table that asks for them so.
    pub fn printed_values(&self, r: &Row) -> Vec<String> {
        r.printed(r.count || self.whole_numbers)
    }

    /// A row's quantity as `symbol_sub`, or the symbol alone.
    fn quantity(&self, r: usize) -> String {
        let (symbol, sub) = &self.printed[r];
        if sub.is_empty() { symbol.clone() } else { format!("{symbol}_{sub}") }
    }

    /// Every value under its identifier, `prefix` naming the sheet ("sheet1").
    pub fn answers(&self, prefix: &str) -> Vec<Answer> {
        let t = &self.table;
        let cells = t.rows.iter().flat_map(|r| r.values.iter().enumerate().map(move |(c, &v)| (r, c, v)));
        cells
            .map(|(r, c, value)| Answer { id: t.cell_id(prefix, r, c), value, unit: r.unit.si(), after: r.jump_at(c) })
            .collect()
    }
}

/// A number as the CSV writes it: nine decimals, a rounded-off zero without its sign.
fn csv_number(v: f64) -> String {
    let s = format!("{v:.9}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') { s[1..].to_string() } else { s }
}

/// Full-precision numbers (9 decimals), each row under its identifier (`prefix.table.row`;
/// a value's is that and its column's key, the header's), fields quoted by the `csv` crate
/// where needed.
pub fn csv(n: &NoteTable, prefix: &str) -> String {
    let t = &n.table;
    let mut w = csv::Writer::from_writer(Vec::new());
    let header =
        ["id", "quantity", "unit"].into_iter().map(str::to_string).chain(t.columns.iter().map(|c| c.key.clone()));
    w.write_record(header).expect("writing to memory");
    for (k, r) in t.rows.iter().enumerate() {
        let id = format!("{prefix}.{}.{}", t.id, r.key);
        let cells =
            [id, n.quantity(k), r.unit.si().to_string()].into_iter().chain(r.values.iter().map(|&v| csv_number(v)));
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
/// four significant figures, as on the sheet. The table and each row carry their
/// identifiers as empty anchors, which a renderer does not show.
pub fn markdown(n: &NoteTable, prefix: &str) -> String {
    let t = &n.table;
    let [quantity, unit] = &n.headings;
    let mut s = format!(
        "<a id=\"{prefix}.{}\"></a>\n\n### {}\n\n| {} | {} |",
        t.id,
        md_escape(&n.title),
        md_escape(quantity),
        md_escape(unit)
    );
    for c in &n.column_titles {
        let _ = write!(s, " {} |", md_escape(c));
    }
    s.push_str("\n|---|---|");
    s.push_str(&"---:|".repeat(t.columns.len()));
    s.push('\n');
    for ((k, r), unit) in t.rows.iter().enumerate().zip(&n.units) {
        let (symbol, sub) = &n.printed[k];
        let sub = if sub.is_empty() { String::new() } else { format!("<sub>{}</sub>", md_escape(sub)) };
        let anchor = format!("<a id=\"{prefix}.{}.{}\"></a>", t.id, r.key);
        let _ = write!(s, "| {anchor}{}{sub} | {} |", md_escape(symbol), md_escape(unit));
        for v in n.printed_values(r) {
            let v = v.replace('-', "−");
            let _ = write!(s, " {} |", if n.decimal_comma { v.replace('.', ",") } else { v });
        }
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn note(column: &str, sub: &str, title: &str) -> NoteTable {
        let table = NumTable {
            id: "t",
            columns: vec![Column::new("c", column)],
            rows: vec![
                Row::new("v", Sub::name(sub), Unit::MPerS, vec![1.0]),
                Row::new("x", Sub::None, Unit::None, vec![-1e-12]),
            ],
        };
        NoteTable {
            printed: vec![("v".into(), sub.into()), ("x".into(), String::new())],
            units: vec!["m/s".into(), String::new()],
            column_titles: vec![column.into()],
            title: title.into(),
            table,
            headings: ["q".into(), "u".into()],
            decimal_comma: true,
            whole_numbers: false,
        }
    }

    #[test]
    fn csv_quotes_fields_with_separators_and_quotes_and_names_every_row() {
        let s = csv(&note("a,\"b\"", "B,A", "T"), "sheet9");
        assert_eq!(s, "id,quantity,unit,c\nsheet9.t.v_B_A,\"v_B,A\",m/s,1.000000000\nsheet9.t.x,x,,0.000000000\n");
    }

    #[test]
    fn markdown_cells_cannot_break_the_table() {
        let s = markdown(&note("x|y", "<b>*", "T | 1"), "sheet9");
        assert!(s.starts_with("<a id=\"sheet9.t\"></a>\n\n### T \\| 1\n"), "{s}");
        assert!(s.contains("| x\\|y |") && s.contains("<sub>&lt;b&gt;\\*</sub>") && s.contains("| 1,000 |"), "{s}");
        for line in s.lines().skip(4) {
            let unescaped = line.replace("\\|", "");
            assert_eq!(unescaped.matches('|').count(), 4, "{line}");
        }
    }
}
