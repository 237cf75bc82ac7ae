//! The A1 sheet's frame (GOST 2.301: 20 mm margin on the left, 5 mm elsewhere) and the
//! title block, form 1 of GOST 2.104 (185 × 55 mm, bottom right).

use super::labels::Labels;
use super::text::{paragraph, wrap};
use super::scene::{Anchor, Group, Text, MAIN, THIN};
use kurbo::{Point, Rect};

pub const A1_W: f64 = 841.0;
pub const A1_H: f64 = 594.0;

/// The inside of the frame.
pub fn inner() -> Rect {
    Rect::new(20.0, 5.0, A1_W - 5.0, A1_H - 5.0)
}

/// The title block's rectangle.
pub fn title_block_rect() -> Rect {
    let f = inner();
    Rect::new(f.x1 - 185.0, f.y1 - 55.0, f.x1, f.y1)
}

/// What the title block says.
pub struct TitleBlock<'a> {
    pub designation: &'a str,
    pub sheet_name: &'a str,
    pub project_title: &'a str,
    pub student: &'a str,
    pub supervisor: &'a str,
    pub organisation: &'a str,
    pub scale: &'a str,
    pub sheet_no: u32,
}

pub fn frame(g: &mut Group) {
    let f = inner();
    g.path(vec![f.origin(), Point::new(f.x1, f.y0), Point::new(f.x1, f.y1), Point::new(f.x0, f.y1)], true, MAIN);
}

fn cell_text(g: &mut Group, x: f64, y: f64, s: &str, h: f64) {
    if !s.is_empty() {
        g.text(Text::new(Point::new(x, y), s, h, Anchor::Middle));
    }
}

/// Draws the title block with GOST column widths: 7, 10, 23, 15, 10 | 70 | 50.
pub fn title_block(g: &mut Group, l: &Labels, tb: &TitleBlock) {
    let r = title_block_rect();
    let (x0, y0) = (r.x0, r.y0);
    let row = |i: f64| y0 + 5.0 * i;
    g.path(vec![r.origin(), Point::new(r.x1, r.y0), Point::new(r.x1, r.y1), Point::new(r.x0, r.y1)], true, MAIN);
    let cols = [7.0, 10.0, 23.0, 15.0, 10.0];
    let mut x = x0;
    for w in cols {
        x += w;
        g.line(Point::new(x, y0), Point::new(x, r.y1), if x == x0 + 65.0 { MAIN } else { THIN });
    }
    for i in 1..11 {
        let pen = if i == 5 || i == 6 { MAIN } else { THIN };
        g.line(Point::new(x0, row(i as f64)), Point::new(x0 + 65.0, row(i as f64)), pen);
    }
    // Designation field, name field and the right-hand block.
    let (xd, xr) = (x0 + 65.0, x0 + 135.0);
    g.line(Point::new(xd, row(3.0)), Point::new(r.x1, row(3.0)), MAIN);
    g.line(Point::new(xr, row(3.0)), Point::new(xr, r.y1), MAIN);
    g.line(Point::new(xr, row(4.0)), Point::new(r.x1, row(4.0)), MAIN);
    g.line(Point::new(xr, row(7.0)), Point::new(r.x1, row(7.0)), MAIN);
    g.line(Point::new(xr, row(8.0)), Point::new(r.x1, row(8.0)), MAIN);
    for dx in [5.0, 10.0] {
        g.line(Point::new(xr + dx, row(4.0)), Point::new(xr + dx, row(7.0)), THIN);
    }
    g.line(Point::new(xr + 15.0, row(3.0)), Point::new(xr + 15.0, row(7.0)), MAIN);
    g.line(Point::new(xr + 32.0, row(3.0)), Point::new(xr + 32.0, row(7.0)), MAIN);
    g.line(Point::new(xr + 25.0, row(7.0)), Point::new(xr + 25.0, row(8.0)), THIN);
    // Header of the revisions table (row 6) and the signature rows (7–11).
    let hdr = [(l.get("tb_change"), 3.5), (l.get("tb_sheet_no"), 12.0), (l.get("tb_doc"), 28.5), (l.get("tb_sign"), 47.5), (l.get("tb_date"), 60.0)];
    for (s, cx) in hdr {
        cell_text(g, x0 + cx, row(6.0) - 1.2, s, 1.8);
    }
    let people = [(l.get("tb_drawn"), tb.student), (l.get("tb_checked"), tb.supervisor), ("", ""), ("", ""), (l.get("tb_approved"), "")];
    for (i, (role, name)) in people.iter().enumerate() {
        let y = row(7.0 + i as f64) - 1.2;
        if !role.is_empty() {
            g.text(Text::new(Point::new(x0 + 1.0, y), *role, 2.5, Anchor::Start));
        }
        if !name.is_empty() {
            g.text(Text::new(Point::new(x0 + 18.5, y), *name, 2.5, Anchor::Start));
        }
    }
    cell_text(g, xd + 60.0, row(2.0) + 0.5, tb.designation, 7.0);
    name_field(g, Rect::new(xd, row(3.0), xr, r.y1), tb, l);
    cell_text(g, xr + 7.5, row(4.0) - 1.2, l.get("tb_lit"), 2.5);
    cell_text(g, xr + 23.5, row(4.0) - 1.2, l.get("tb_mass"), 2.5);
    cell_text(g, xr + 41.0, row(4.0) - 1.2, l.get("tb_scale"), 2.5);
    cell_text(g, xr + 41.0, row(6.0), tb.scale, 3.5);
    cell_text(g, xr + 12.5, row(8.0) - 1.2, &format!("{} {}", l.get("tb_sheet_no"), tb.sheet_no), 2.5);
    cell_text(g, xr + 37.5, row(8.0) - 1.2, l.get("tb_sheets"), 2.5);
    cell_text(g, xr + 25.0, row(10.0), tb.organisation, 3.5);
}

/// The GOST-style box around `r` is not drawn for regions; this only helps tests.
pub fn is_inside(outer: Rect, r: Rect) -> bool {
    r.x0 >= outer.x0 - 1e-9 && r.y0 >= outer.y0 - 1e-9 && r.x1 <= outer.x1 + 1e-9 && r.y1 <= outer.y1 + 1e-9
}

/// The 70 × 40 mm name field: sheet name and project title, wrapped and centred.
fn name_field(g: &mut Group, r: Rect, tb: &TitleBlock, l: &Labels) {
    let w = r.width() - 3.0;
    let blocks = [(wrap(tb.sheet_name, 3.5, w), 3.5), (wrap(tb.project_title, 3.5, w), 3.5), (wrap(l.get("tb_course"), 2.5, w), 2.5)];
    let height: f64 = blocks.iter().map(|(ls, h)| ls.len() as f64 * 1.6 * h).sum::<f64>() + 2.0 * 2.0;
    let mut y = r.center().y - height / 2.0 + 4.0;
    for (lines, h) in &blocks {
        y = paragraph(g, Point::new(r.center().x, y), lines, *h, Anchor::Middle) + 2.0;
    }
}
