//! Tables drawn on the sheet: a header row, a label column, ruled cells.

use super::scene::{Anchor, Group, MAIN, Pen, THIN, Text};
use super::text::LabelText;
use kurbo::{Point, Rect};

pub const ROW_H: f64 = 5.0;
pub const CELL_TEXT: f64 = 2.5;

pub struct Table {
    pub title: String,
    pub header: Vec<String>,
    /// First cell of each row is its label (may carry a subscript).
    pub rows: Vec<(LabelText, Vec<String>)>,
    pub label_w: f64,
    pub cell_w: f64,
}

impl Table {
    fn grid_width(&self) -> f64 {
        self.label_w + self.cell_w * self.header.len() as f64
    }

    /// Width and height including the title line.
    pub fn size(&self) -> (f64, f64) {
        let title = Text::new(Point::ZERO, self.title.clone(), 3.5, Anchor::Start).bbox().width();
        (self.grid_width().max(title), ROW_H * (self.rows.len() + 1) as f64 + 7.0)
    }

    /// Draws the table with its top-left corner (title included) at `at`.
    pub fn draw(&self, g: &mut Group, at: Point) -> Rect {
        let (outer_w, h) = self.size();
        let w = self.grid_width();
        g.text(Text::new(Point::new(at.x, at.y + 4.0), self.title.clone(), 3.5, Anchor::Start));
        let top = at.y + 7.0;
        let n_rows = self.rows.len() + 1;
        let bottom = top + ROW_H * n_rows as f64;
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
            let y = top + ROW_H * r as f64;
            g.line(Point::new(at.x, y), Point::new(at.x + w, y), if r == 1 { MAIN } else { THIN });
        }
        let mut x = at.x + self.label_w;
        for _ in 0..self.header.len() {
            g.line(Point::new(x, top), Point::new(x, bottom), THIN);
            x += self.cell_w;
        }
        let base = |r: usize| top + ROW_H * r as f64 + ROW_H / 2.0 + CELL_TEXT / 2.0;
        let col = |c: usize| at.x + self.label_w + self.cell_w * (c as f64 + 0.5);
        for (c, hd) in self.header.iter().enumerate() {
            g.text(Text::new(Point::new(col(c), base(0)), hd.clone(), CELL_TEXT, Anchor::Middle));
        }
        for (r, (label, cells)) in self.rows.iter().enumerate() {
            label.draw(g, Point::new(at.x + self.label_w / 2.0, base(r + 1)), CELL_TEXT, Anchor::Middle);
            for (c, v) in cells.iter().enumerate() {
                g.text(Text::new(Point::new(col(c), base(r + 1)), v.clone(), CELL_TEXT, Anchor::Middle));
            }
        }
        Rect::new(at.x, at.y, at.x + outer_w, at.y + h)
    }
}
