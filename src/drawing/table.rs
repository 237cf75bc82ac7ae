//! Tables drawn on the sheet: a header row, a label column, ruled cells.

use super::scene::{Anchor, Group, MAIN, Pen, THIN, Text};
use super::text::{LINE_PITCH, LabelText, SLANT, caption_head, paragraph, wrap};
use crate::num::digits::JUMP;
use kurbo::{Point, Rect};

/// A row's height and the cells' lettering at the usual size, mm; a table of larger
/// lettering ([`Table::text_h`]) scales both and its padding alike.
pub const ROW_H: f64 = 5.0;
pub const CELL_TEXT: f64 = 2.5;
/// The larger lettering tables take where a sheet has room, mm.
pub const LARGE_TEXT: f64 = 3.5;
/// The title's lettering: one GOST size above the cells'.
const TITLE_TEXT: f64 = 3.5;
const TITLE_TEXT_LARGE: f64 = 5.0;

/// How every table's part id begins: "table.velocities".
pub const PART: &str = "table.";

#[derive(Clone)]
pub struct Table {
    /// Its id on the sheet ([`PART`] and its name: "table.velocities"), its SVG group's;
    /// empty for none.
    pub id: String,
    pub title: String,
    pub header: Vec<String>,
    /// First cell of each row is its label (may carry a subscript).
    pub rows: Vec<(LabelText, Vec<String>)>,
    pub label_w: f64,
    /// The least width of a value cell; wider values widen their table's cells.
    pub cell_w: f64,
    /// What the header names, written in the header row above the labels ("Link",
    /// "Position"); may be empty.
    pub corner: String,
    /// The cells' lettering, mm: [`CELL_TEXT`], or 3.5 where the sheet has room; `label_w`
    /// and `cell_w` are given for [`CELL_TEXT`] and scale with it.
    pub text_h: f64,
    /// The least width of each value column at [`CELL_TEXT`], mm: its twin's, where it has
    /// one to line up with (see [`Table::line_up`]); empty for none.
    pub least_columns: Vec<f64>,
}

/// Room either side of a cell's text, mm.
const CELL_PAD: f64 = 1.2;

impl Table {
    /// The lettering's scale against [`CELL_TEXT`].
    fn k(&self) -> f64 {
        self.text_h / CELL_TEXT
    }

    fn row_h(&self) -> f64 {
        ROW_H * self.k()
    }

    fn title_text(&self) -> f64 {
        if self.text_h > CELL_TEXT { TITLE_TEXT_LARGE } else { TITLE_TEXT }
    }

    /// The widths of the value columns: every column as wide as the table's least width or
    /// its widest single value or heading, and a column holding a jump's two values
    /// ("1,169→−1,169", see [`JUMP`]) as wide as those need,
    /// so one jump does not widen the whole table.
    fn column_widths(&self) -> Vec<f64> {
        self.widths(true)
    }

    /// [`Table::column_widths`], widened for the jumps' pairs of values or not.
    fn widths(&self, jumps: bool) -> Vec<f64> {
        let h = self.text_h;
        let width = |t: &str| {
            Text::new(Point::ZERO, t, h, Anchor::Middle).core_box().width() + 2.0 * CELL_PAD * self.k() + h * SLANT
        };
        let pair = |v: &&String| v.contains(JUMP);
        let cells = || self.rows.iter().flat_map(|(_, cells)| cells.iter());
        let single = cells().filter(|v| !pair(v)).chain(&self.header).map(|v| width(v));
        let usual = single.fold(self.cell_w * self.k(), f64::max);
        let mut widths = vec![usual; self.header.len()];
        for (w, least) in widths.iter_mut().zip(&self.least_columns) {
            *w = w.max(least * self.k());
        }
        for (_, cells) in self.rows.iter().filter(|_| jumps) {
            for (w, v) in widths.iter_mut().zip(cells).filter(|(_, v)| pair(v)) {
                *w = w.max(width(v));
            }
        }
        widths
    }

    /// The label column's width: as given, or the corner caption's.
    fn label_width(&self) -> f64 {
        let h = self.text_h;
        let corner = Text::new(Point::ZERO, self.corner.as_str(), h, Anchor::Middle).core_box().width();
        (self.label_w * self.k()).max(corner + 2.0 * CELL_PAD * self.k() + h * super::text::SLANT)
    }

    /// Gives twin tables (a phase's and the next one's, one above the other) the same label
    /// column and the same value columns, each the widest of theirs: their grids line up.
    /// Tables of another count of columns are left as they are.
    pub fn line_up(twins: &mut [Table]) {
        let Some(n) = twins.first().map(|t| t.header.len()) else { return };
        if twins.iter().any(|t| t.header.len() != n) {
            return;
        }
        let mut least = vec![0.0f64; n];
        let mut label = 0.0f64;
        for t in twins.iter() {
            for (l, w) in least.iter_mut().zip(t.widths(false)) {
                *l = l.max(w / t.k());
            }
            label = label.max(t.label_width() / t.k());
        }
        for t in twins.iter_mut() {
            t.least_columns = least.clone();
            t.label_w = label;
        }
    }

    fn grid_width(&self) -> f64 {
        self.label_width() + self.column_widths().iter().sum::<f64>()
    }

    /// The title's lines: wrapped to the grid's width `grid_w` when it is wider (at least
    /// 60 mm at 2.5 mm lettering, more at larger).
    fn title_lines(&self, grid_w: f64) -> Vec<String> {
        // A narrow table's title may reach past its grid, to hold the caption's head on one
        // line.
        let h = self.title_text();
        let head =
            caption_head(&self.title).map_or(0.0, |head| Text::new(Point::ZERO, head, h, Anchor::Start).bbox().width());
        wrap(&self.title, h, grid_w.max(60.0 * self.k()).max(head))
    }

    /// Height of the title of `lines` above the grid, mm.
    fn title_height(&self, lines: &[String]) -> f64 {
        let h = self.title_text();
        7.0 + (h - TITLE_TEXT) + (lines.len().max(1) - 1) as f64 * h * LINE_PITCH
    }

    /// Width and height including the title.
    pub fn size(&self) -> (f64, f64) {
        // The grid's width measures every cell: measured once here, not again for the
        // title's lines and their height (a sheet sizes its tables for every layout it tries).
        let grid_w = self.grid_width();
        self.size_with(grid_w, &self.title_lines(grid_w))
    }

    /// [`Table::size`] of the grid's width `grid_w` and the title's `lines`.
    fn size_with(&self, grid_w: f64, lines: &[String]) -> (f64, f64) {
        let title =
            lines.iter().map(|l| Text::new(Point::ZERO, l.as_str(), self.title_text(), Anchor::Start).bbox().width());
        let title = title.fold(0.0, f64::max);
        (grid_w.max(title), self.row_h() * (self.rows.len() + 1) as f64 + self.title_height(lines))
    }

    /// Draws the table with its top-left corner (title included) at `at`.
    pub fn draw(&self, g: &mut Group, at: Point) -> Rect {
        let start = g.mark();
        let drawn = self.draw_grid(g, at);
        g.part_from(self.id.as_str(), start);
        drawn
    }

    /// The title, the rules and the cells; returns the box taken.
    fn draw_grid(&self, g: &mut Group, at: Point) -> Rect {
        let w = self.grid_width();
        let lines = self.title_lines(w);
        let (outer_w, h) = self.size_with(w, &lines);
        let title_h = self.title_text();
        paragraph(g, Point::new(at.x, at.y + 4.0 + (title_h - TITLE_TEXT)), &lines, title_h, Anchor::Start);
        let top = at.y + self.title_height(&lines);
        let n_rows = self.rows.len() + 1;
        let (row_h, text_h) = (self.row_h(), self.text_h);
        let bottom = top + row_h * n_rows as f64;
        let outline = |g: &mut Group, pen: Pen| {
            g.path(
                vec![
                    Point::new(at.x, top),
                    Point::new(at.x + w, top),
                    Point::new(at.x + w, bottom),
                    Point::new(at.x, bottom),
                ],
                true,
                pen,
            )
        };
        outline(g, MAIN);
        for r in 1..n_rows {
            let y = top + row_h * r as f64;
            g.line(Point::new(at.x, y), Point::new(at.x + w, y), if r == 1 { MAIN } else { THIN });
        }
        let (label_w, widths) = (self.label_width(), self.column_widths());
        // Each column's left edge, from the label column's right.
        let lefts: Vec<f64> = widths.iter().scan(at.x + label_w, |x, w| Some(std::mem::replace(x, *x + w))).collect();
        for &x in &lefts {
            g.line(Point::new(x, top), Point::new(x, bottom), THIN);
        }
        let base = |r: usize| top + row_h * r as f64 + row_h / 2.0 + text_h / 2.0;
        let col = |c: usize| lefts[c] + widths[c] / 2.0;
        if !self.corner.is_empty() {
            g.text(Text::new(Point::new(at.x + label_w / 2.0, base(0)), self.corner.clone(), text_h, Anchor::Middle));
        }
        for (c, hd) in self.header.iter().enumerate() {
            g.text(Text::new(Point::new(col(c), base(0)), hd.clone(), text_h, Anchor::Middle));
        }
        for (r, (label, cells)) in self.rows.iter().enumerate() {
            label.draw(g, Point::new(at.x + label_w / 2.0, base(r + 1)), text_h, Anchor::Middle);
            for (c, v) in cells.iter().enumerate() {
                g.text(Text::new(Point::new(col(c), base(r + 1)), v.clone(), text_h, Anchor::Middle));
            }
        }
        Rect::new(at.x, at.y, at.x + outer_w, at.y + h)
    }
}

/// Between columns of tables, mm, and the most [`flow_spread`] widens a gap by.
const COLUMN_GAP: f64 = 6.0;
pub const SPREAD_MAX: f64 = 40.0;

/// Tables drawn in `region` top to bottom, a new column to the right when the next one would
/// leave the region's bottom; `gap` mm between tables and 6 mm between columns.
pub fn flow(id: &str, tables: impl IntoIterator<Item = Table>, region: Rect, gap: f64) -> Group {
    let tables: Vec<Table> = tables.into_iter().collect();
    let sizes: Vec<(f64, f64)> = tables.iter().map(Table::size).collect();
    drawn_at(id, &tables, region, &packed(&sizes, region.height(), gap).0)
}

/// As [`flow`], the columns spread over the region's width: the room left over shared
/// between the gaps, each growing by at most [`SPREAD_MAX`], the block centred in what is
/// still left (tables under a drawing as wide as the region, balanced under it rather than
/// crowded to its left, and never two columns alone at its far edges).
pub fn flow_spread(id: &str, tables: impl IntoIterator<Item = Table>, region: Rect, gap: f64) -> Group {
    let tables: Vec<Table> = tables.into_iter().collect();
    let sizes: Vec<(f64, f64)> = tables.iter().map(Table::size).collect();
    let (mut corners, right) = packed(&sizes, region.height(), gap);
    // Each column starts at a new x; the k-th of n moves right by k/(n − 1) of the spare width.
    let mut starts: Vec<f64> = Vec::new();
    for c in &corners {
        if starts.last().is_none_or(|&x| c.x > x) {
            starts.push(c.x);
        }
    }
    let spare = (region.width() - right).max(0.0);
    let gaps = starts.len().saturating_sub(1) as f64;
    let share = if gaps > 0.0 { (spare / gaps).min(SPREAD_MAX) } else { 0.0 };
    let margin = (spare - share * gaps) / 2.0;
    for c in &mut corners {
        let k = starts.iter().position(|&x| x == c.x).unwrap_or(0);
        c.x += margin + share * k as f64;
    }
    drawn_at(id, &tables, region, &corners)
}

/// Tables drawn in `region` left to right, a new row under the row's tallest when the next
/// one would leave the region's right edge; `gap` mm between rows and 6 mm between tables.
/// Where [`flow`]'s columns leave a table too wide for the region's remaining width, rows
/// keep the wide one under the others.
pub fn flow_rows(id: &str, tables: impl IntoIterator<Item = Table>, region: Rect, gap: f64) -> Group {
    let tables: Vec<Table> = tables.into_iter().collect();
    let sizes: Vec<(f64, f64)> = tables.iter().map(Table::size).collect();
    drawn_at(id, &tables, region, &packed_rows(&sizes, region.width(), gap).0)
}

/// The tables drawn with their top left corners at `corners` from the region's.
fn drawn_at(id: &str, tables: &[Table], region: Rect, corners: &[Point]) -> Group {
    let mut g = Group::new(id, region);
    for (table, at) in tables.iter().zip(corners) {
        table.draw(&mut g, Point::new(region.x0 + at.x, region.y0 + at.y));
    }
    g
}

/// How [`flow_rows`] packs tables of `sizes` into a region `width` mm wide: each one's top
/// left from the region's, and the height taken.
fn packed_rows(sizes: &[(f64, f64)], width: f64, gap: f64) -> (Vec<Point>, f64) {
    let (at, taken) = shelves(sizes.iter().copied(), width, COLUMN_GAP, gap);
    (at.into_iter().map(|(x, y)| Point::new(x, y)).collect(), taken)
}

/// Whether [`flow_rows`] fits tables of `sizes` inside `region`: none wider than it, the
/// rows no taller.
pub fn rows_fit(sizes: &[(f64, f64)], region: Rect, gap: f64) -> bool {
    sizes.iter().all(|s| s.0 <= region.width()) && packed_rows(sizes, region.width(), gap).1 <= region.height()
}

/// How [`flow`] packs tables of `sizes` into a column `height` mm tall: each one's top left
/// from the region's, and the width taken.
fn packed(sizes: &[(f64, f64)], height: f64, gap: f64) -> (Vec<Point>, f64) {
    let (at, taken) = shelves(sizes.iter().map(|&(w, h)| (h, w)), height, gap, COLUMN_GAP);
    (at.into_iter().map(|(y, x)| Point::new(x, y)).collect(), taken)
}

/// Boxes of `(along, across)` sizes laid along shelves at most `limit` long, `along_gap`
/// apart on a shelf, a new shelf `across_gap` past the deepest box of the last when the next
/// box would pass the limit (a box alone on a shelf may): each box's `(along, across)` offset
/// and the depth all the shelves take. Columns of tables are shelves down the region, rows
/// shelves across it.
fn shelves(
    sizes: impl Iterator<Item = (f64, f64)>,
    limit: f64,
    along_gap: f64,
    across_gap: f64,
) -> (Vec<(f64, f64)>, f64) {
    let (mut along, mut across, mut depth) = (0.0, 0.0, 0.0f64);
    let mut at = Vec::new();
    for (l, d) in sizes {
        if along + l > limit && along > 0.0 {
            across += depth + across_gap;
            along = 0.0;
            depth = 0.0;
        }
        at.push((along, across));
        along += l + along_gap;
        depth = depth.max(d);
    }
    (at, across + depth)
}

/// Whether [`flow`] fits tables of `sizes` inside `region`: no column taller than it, all
/// of them within its width.
pub fn flow_fits(sizes: &[(f64, f64)], region: Rect, gap: f64) -> bool {
    sizes.iter().all(|s| s.1 <= region.height()) && flow_width(sizes, region.height(), gap) <= region.width()
}

/// The width [`flow`] takes for tables of `sizes` in a region `height` mm tall.
pub fn flow_width(sizes: &[(f64, f64)], height: f64, gap: f64) -> f64 {
    packed(sizes, height, gap).1
}

/// The least height (whole mm) in which [`flow`] fits tables of `sizes` into `width`, or
/// `None` when one column is wider.
pub fn flow_height(sizes: &[(f64, f64)], width: f64, gap: f64) -> Option<f64> {
    let tallest = sizes.iter().map(|s| s.1).fold(0.0, f64::max).ceil();
    let total: f64 = sizes.iter().map(|s| s.1 + gap).sum();
    let mut h = tallest;
    while h <= total.ceil() + 1.0 {
        if flow_width(sizes, h, gap) <= width {
            return Some(h);
        }
        h += 1.0;
    }
    None
}
