//! Tables 1 and 2 and the notes above the title block on sheet 1, and the note's tables as
//! sheet 1 draws them (labels without units but where a table's rows carry their own).

use super::compose::Input;
use super::labels::LeverWords;
use crate::drawing::columns::{self, Para};
use crate::drawing::frame;
use crate::drawing::labels::Language;
use crate::drawing::scene::Group;
use crate::drawing::table::{CELL_TEXT, Table};
use crate::drawing::text::{LabelText, TooLong};
use crate::report::NoteTable;
use crate::sheets::notes::Room;
use crate::sheets::scaffold;
use kurbo::{Point, Rect};

/// Tables 1 and 2 and the notes under them, above the title block.
pub(super) struct NoteTables {
    t1: Table,
    t2: Table,
    side_by_side: bool,
    /// Where table 1 stands in the corner left of the title block, the notes under it: the
    /// notes' width. Else the tables and the notes under both end above the title block.
    corner: Option<f64>,
    assumptions: Vec<String>,
    /// The region they take: as wide as the column, from their top to the title block.
    pub(super) region: Rect,
}

/// What [`note_tables`] sets whatever the column: tables 1 and 2 as sheet 1 draws them with
/// their sizes, the assumptions, and the notes' height under table 1 in the corner. Made
/// once for the sheet: every layout tried (three column widths in each of the variants)
/// asks for the same, and lettering the tables' values was a twentieth of building sheet 1.
pub(super) struct NoteParts {
    t1: Table,
    t2: Table,
    size1: (f64, f64),
    size2: (f64, f64),
    assumptions: Vec<String>,
    corner_notes: f64,
}

impl NoteParts {
    pub(super) fn new(inp: &Input, words: &LeverWords) -> NoteParts {
        let (c, lang) = (words.common, words.lang);
        let t1 = Table { corner: c.position_col().into(), ..sheet_table(&inp.notes[0], lang) };
        let t2 = Table { corner: c.position_col().into(), ..sheet_table(&inp.notes[1], lang) };
        let (size1, size2) = (t1.size(), t2.size());
        let assumptions: Vec<String> = inp.project.assumptions.iter().map(|a| a.get(lang).to_string()).collect();
        let corner_notes = notes_height(words, &assumptions, size1.0 + 2.0);
        NoteParts { t1, t2, size1, size2, assumptions, corner_notes }
    }
}

/// Tables 1 and 2 side by side when the column (`across`: its left and right x) is wide enough,
/// else one above the other, and the notes under them; refuses assumptions too long for
/// the room above the title block. With `corner`, table 1 goes down into the corner left of
/// the title block where it fits there.
pub(super) fn note_tables(
    parts: &NoteParts,
    words: &LeverWords,
    across: (f64, f64),
    corner: bool,
) -> Result<NoteTables, TooLong> {
    let ((w1, h1), (w2, h2)) = (parts.size1, parts.size2);
    let right_w = across.1 - across.0;
    let side_by_side = 1.0 + w1 + 8.0 + w2 + 1.0 <= right_w;
    let tables_h = if side_by_side { h1.max(h2) } else { h1 + 6.0 + h2 };
    let (t1, t2, assumptions) = (parts.t1.clone(), parts.t2.clone(), parts.assumptions.clone());
    let title = frame::title_block_rect();
    // Table 1 beside the title block, down in its corner, where it fits there with the notes
    // under it (as wide as it: table 2 stands beside it): the band left of the title block
    // would be empty paper, and the plans above get its height.
    let corner_w = w1 + 2.0;
    let corner_notes = parts.corner_notes;
    let in_corner = corner && side_by_side && across.0 + corner_w + 4.0 <= title.x0 && corner_notes <= NOTES_MAX_H;
    if in_corner {
        let top = (title.y0 - 3.0 - h2).min(frame::inner().y1 - 3.0 - corner_notes - 4.0 - h1);
        let region = Rect::new(across.0, top, across.1, frame::inner().y1 - 3.0);
        return Ok(NoteTables { t1, t2, side_by_side, corner: Some(corner_w), assumptions, region });
    }
    let notes_lines = notes_height(words, &assumptions, right_w);
    let room =
        Room { field: "mechanism.assumptions", place: "notes above the title block", size: (right_w, NOTES_MAX_H) };
    room.check(&assumptions, notes_lines)?;
    let top = title.y0 - 3.0 - notes_lines - tables_h - 4.0;
    let region = Rect::new(across.0, top, across.1, title.y0 - 3.0);
    Ok(NoteTables { t1, t2, side_by_side, corner: None, assumptions, region })
}

/// Tables 1 and 2 and the notes, drawn: one group, or, with table 1 in the corner beside
/// the title block, table 1 with the notes under it and table 2 apart (`tables-2`), so that
/// no region covers the title block.
pub(super) fn tables_group(n: &NoteTables, words: &LeverWords) -> Vec<Group> {
    let r = n.region;
    if let Some(w) = n.corner {
        let split = r.x0 + w + 4.0;
        let mut first = Group::new("tables", Rect::new(r.x0, r.y0, split, r.y1));
        let r1 = n.t1.draw(&mut first, Point::new(r.x0 + 1.0, r.y0));
        notes(&mut first, words, &n.assumptions, Rect::new(r.x0, r1.y1 + 4.0, r.x0 + w, r.y1));
        let mut second = Group::new("tables-2", Rect::new(split, r.y0, r.x1, frame::title_block_rect().y0 - 3.0));
        n.t2.draw(&mut second, Point::new(r1.x1 + 8.0, r.y0));
        return vec![first, second];
    }
    let mut tables = Group::new("tables", r);
    let r1 = n.t1.draw(&mut tables, Point::new(r.x0 + 1.0, r.y0));
    let at2 = if n.side_by_side { Point::new(r1.x1 + 8.0, r.y0) } else { Point::new(r.x0 + 1.0, r1.y1 + 6.0) };
    let r2 = n.t2.draw(&mut tables, at2);
    let notes_top = r1.y1.max(r2.y1) + 4.0;
    notes(&mut tables, words, &n.assumptions, Rect::new(r.x0, notes_top, r.x1, r.y1));
    vec![tables]
}

/// The notes (the exactness note and the assumptions) may take this much height, mm.
const NOTES_MAX_H: f64 = 60.0;

/// A note table as sheet 1 draws it: labels without units (the title names them), cells
/// at least 11 mm wide.
pub(super) fn sheet_table(n: &NoteTable, lang: Language) -> Table {
    let rows = scaffold::drawn_rows(n, lang, false);
    Table {
        id: format!("{}{}", crate::drawing::table::PART, n.table.id),
        title: n.title.clone(),
        header: n.column_titles.clone(),
        label_w: label_column(&rows),
        rows,
        cell_w: 11.0,
        corner: String::new(),
        text_h: crate::drawing::table::CELL_TEXT,
        least_columns: Vec::new(),
    }
}

/// A table whose rows carry their own units (the title names none): "m, kg", "J_S, kg·m²".
pub(super) fn with_units(table: Table, n: &NoteTable, lang: Language) -> Table {
    let rows = scaffold::drawn_rows(n, lang, true);
    Table { label_w: label_column(&rows), rows, ..table }
}

/// The label column's width: the widest label and 1.5 mm either side, at least 14 mm.
fn label_column(rows: &[(LabelText, Vec<String>)]) -> f64 {
    rows.iter().map(|(l, _)| l.width(CELL_TEXT) + 3.0 + CELL_TEXT * crate::drawing::text::SLANT).fold(14.0, f64::max)
}

/// The notes (the exactness note, then the assumptions under their heading) as paragraphs.
fn note_paras(words: &LeverWords, assumptions: &[String]) -> Vec<Para> {
    let mut paras = vec![Para::new(words.sheet.exact_note(), 2.0)];
    if !assumptions.is_empty() {
        paras.push(Para::heading(format!("{}:", words.common.assumed()), 0.5));
        paras.extend(assumptions.iter().map(|a| Para::new(a.clone(), 1.0)));
    }
    paras
}

/// Height the notes need set `w` wide: their first baseline 3.5 mm under the top.
fn notes_height(words: &LeverWords, assumptions: &[String], w: f64) -> f64 {
    3.5 + columns::set(&note_paras(words, assumptions), 2.5, w - 2.0).height + 0.5
}

fn notes(g: &mut Group, words: &LeverWords, assumptions: &[String], r: Rect) {
    let set = columns::set(&note_paras(words, assumptions), 2.5, r.width() - 2.0);
    columns::draw(g, Point::new(r.x0, r.y0 + 3.5), &set, 2.5);
}
