//! Sheet 2's tables: the wheels and the pair, the planetary stage and its conditions, as the
//! note writes them and as the sheet draws them.

use super::labels::GearWords;
use crate::drawing::fmt;
use crate::drawing::scene::Group;
use crate::drawing::table::{self, CELL_TEXT, Table};
use crate::drawing::text::LabelText;
use crate::gears::planetary::{ConditionKind, Relation};
use crate::project::GearsProject;
use crate::report::{self, NoteTable, Quantity};
use crate::sheets::scaffold;
use kurbo::Rect;

/// The note's tables in the sheet's language, numbered from `first` (the wheels and the
/// pair are one table, in two parts: the pair's part is headed as GOST 2.105 heads a
/// table's continued part, "Продолжение таблицы 6", in the note as on the sheet);
/// `eps_drawn` is the contact ratio measured on the drawing.
pub fn notes(p: &GearsProject, eps_drawn: f64, words: &GearWords, first: u32) -> Vec<NoteTable> {
    let (l, c, lang) = (words.sheet, words.common, words.lang);
    let n = |k: u32| (first + k).to_string();
    let (wheels, pair) = (l.pair_table(&n(0)), l.pair_table_continued(&n(0)));
    let mut out = vec![
        scaffold::note(lang, report::gears::wheels(&p.pair), &wheels, vec![l.wheel("1"), l.wheel("2")], true),
        scaffold::note(lang, report::gears::pair(&p.pair, eps_drawn), &pair, vec![c.value().into()], true),
    ];
    if let Some(pl) = &p.planetary {
        let stage = report::gears::stage(&pl.stage, pl.module);
        out.push(scaffold::note(lang, stage, &l.planetary_table(&n(1)), vec![c.value().into()], true));
        let columns = vec![l.value_col().into(), l.limit_col().into(), l.ok_col().into()];
        let conditions = report::gears::conditions(&pl.stage);
        out.push(scaffold::note(lang, conditions, &l.conditions_table(&n(2)), columns, true));
    }
    out
}

/// How many tables the note gets from sheet 2 (see [`notes`]).
pub fn table_count(p: &GearsProject) -> u32 {
    if p.planetary.is_some() { 3 } else { 1 }
}

/// Draws the tables in `region` in the largest of GOST 2.304's 5 and 3.5 mm letterings they
/// fit in, in columns spread over its width, else in rows (a wide table under the others); else in
/// 2.5 mm columns. The room the planetary views leave below them is the tables': a right
/// half left empty is what a teacher marks down.
pub fn group(notes: &[NoteTable], region: Rect, tolerance: Option<f64>, words: &GearWords) -> Group {
    let drawn = [LARGEST_TEXT, LARGE_TEXT].map(|h| lettered(notes, tolerance, words, h));
    let sizes = drawn.each_ref().map(|d| d.iter().map(Table::size).collect::<Vec<_>>());
    let [largest, large] = drawn;
    let lettering = |i: usize| if i == 0 { largest } else { large };
    match arrangement(&sizes, region) {
        Arrangement::Columns(i) => table::flow_spread("tables", lettering(i), region, GAP),
        Arrangement::Rows(i) => table::flow_rows("tables", lettering(i), region, GAP),
        Arrangement::Small => table::flow("tables", lettered(notes, tolerance, words, CELL_TEXT), region, GAP),
    }
}

/// How [`group`] sets the tables in a region: in columns or in rows in the lettering of the
/// index (0: 5 mm, 1: 3.5 mm), or in 2.5 mm columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arrangement {
    Columns(usize),
    Rows(usize),
    Small,
}

impl Arrangement {
    /// The cells' lettering, mm.
    pub fn lettering(self) -> f64 {
        match self {
            Arrangement::Columns(i) | Arrangement::Rows(i) => [LARGEST_TEXT, LARGE_TEXT][i],
            Arrangement::Small => CELL_TEXT,
        }
    }
}

/// How [`group`] sets tables of `sizes` (in 5 and in 3.5 mm lettering, [`largest_sizes`]
/// and [`large_sizes`]) in `region`: the first of 5 mm columns, 5 mm rows, 3.5 mm columns,
/// 3.5 mm rows that fits it, else 2.5 mm columns.
pub fn arrangement(sizes: &[Vec<(f64, f64)>; 2], region: Rect) -> Arrangement {
    for (i, s) in sizes.iter().enumerate() {
        if fit(s, region) {
            return Arrangement::Columns(i);
        }
        if table::rows_fit(s, region, GAP) {
            return Arrangement::Rows(i);
        }
    }
    Arrangement::Small
}

/// The tables' sizes in 3.5 mm lettering, for [`fit`] (the planetary views grow while they
/// fit): measured once, tried against every room.
pub fn large_sizes(notes: &[NoteTable], tolerance: Option<f64>, words: &GearWords) -> Vec<(f64, f64)> {
    lettered(notes, tolerance, words, LARGE_TEXT).iter().map(Table::size).collect()
}

/// The tables' sizes in 5 mm lettering: a pair without a stage has the right column to
/// itself, and takes it as wide as these need where they stand in one column.
pub fn largest_sizes(notes: &[NoteTable], tolerance: Option<f64>, words: &GearWords) -> Vec<(f64, f64)> {
    lettered(notes, tolerance, words, LARGEST_TEXT).iter().map(Table::size).collect()
}

/// Whether tables of `sizes` fit `region` as [`group`] flows them.
pub fn fit(sizes: &[(f64, f64)], region: Rect) -> bool {
    table::flow_fits(sizes, region, GAP)
}

/// A condition's limit as the sheet prints it, with its relation: "= 86", "> 0,630", "≥ 17",
/// and for the assembly "a whole number" (its limit cell, the nearest whole
/// number, would read as the value required, "81 / 8" as a fraction).
fn limit_cell(relation: Relation, limit: &str, words: &GearWords) -> String {
    match relation {
        Relation::Equal => format!("= {limit}"),
        Relation::Greater => format!("> {limit}"),
        Relation::AtLeast => format!("≥ {limit}"),
        Relation::Integer => words.sheet.integer().to_string(),
        // The ratio's row is written as its deviation where the tolerance is known (see
        // `sheet_table`).
        Relation::Within => limit.to_string(),
    }
}

fn lettered(notes: &[NoteTable], tolerance: Option<f64>, words: &GearWords, text_h: f64) -> Vec<Table> {
    notes.iter().map(|n| Table { text_h, ..sheet_table(n, tolerance, words) }).collect()
}

/// The tables' larger letterings, mm (GOST 2.304's next sizes), and the gap between them.
const LARGE_TEXT: f64 = 3.5;
const LARGEST_TEXT: f64 = 5.0;
pub const GAP: f64 = 4.0;

/// A table as sheet 2 draws it: units after the symbols, the conditions' verdicts in words,
/// the ratio's condition with its tolerance.
fn sheet_table(n: &NoteTable, tolerance: Option<f64>, words: &GearWords) -> Table {
    let (l, c, lang) = (words.sheet, words.common, words.lang);
    let conditions = n.table.id == "conditions";
    let mut rows = scaffold::drawn_rows(n, lang, !conditions);
    for ((label, cells), r) in rows.iter_mut().zip(&n.table.rows) {
        let Quantity::Condition(kind) = r.quantity else { continue };
        cells[2] = (if r.values[2] > 0.5 { l.yes() } else { l.no() }).to_string();
        if let (ConditionKind::Ratio, Some(t)) = (kind, tolerance) {
            // The ratio's condition as the course states it: u_1H off u_req by at most ±3 %
            // (both are in the stage's table above); the note's table keeps the two ratios.
            let off = 100.0 * (r.values[0] - r.values[1]) / r.values[1];
            let off = if off.abs() < 0.005 { 0.0 } else { off };
            // u with its subscript 1H where the words put it.
            let words = l.cond_ratio_deviation("\u{0}");
            let (before, after) = words.split_once('\u{0}').unwrap_or((&words, ""));
            *label = LabelText::new(format!("{before}u"), "1H").with_tail(after.to_string());
            cells[0] = format!("{} %", fmt::localise(&format!("{off:.2}"), lang));
            cells[1] = format!("±{} %", fmt::trimmed(t * 100.0, lang));
        } else {
            cells[1] = limit_cell(kind.relation(), &cells[1], words);
        }
    }
    let label_w = rows.iter().map(|(x, _)| x.width(CELL_TEXT) + 4.0).fold(14.0, f64::max);
    Table {
        id: format!("{}{}", crate::drawing::table::PART, n.table.id),
        title: n.title.clone(),
        header: n.column_titles.clone(),
        rows,
        label_w,
        cell_w: 14.0,
        corner: if conditions { l.condition_col().into() } else { c.quantity().into() },
        text_h: crate::drawing::table::CELL_TEXT,
        least_columns: Vec::new(),
    }
}
