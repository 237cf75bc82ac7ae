//! A region's heading on sheet 1: its title and its line of scales and formula, clear of
//! box 26 in the frame's top-left corner.

use crate::drawing::frame;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::text::LabelText;
use kurbo::{Point, Rect};

/// A region's title (5 mm) and its line of scale and formula (3.5 mm).
/// Each starts clear of box 26 where the region is in the frame's top-left corner.
pub(in crate::sheets::lever) fn region_header(g: &mut Group, r: Rect, title: &str, lines: &[LabelText]) {
    let clear = frame::clear_of_designation_box;
    g.text(Text::new(clear(Point::new(r.x0 + 2.0, r.y0 + 6.0), 5.0), title, 5.0, Anchor::Start));
    let mut x = clear(Point::new(r.x0 + 2.0, r.y0 + 12.5), 3.5).x;
    for line in lines {
        let bb = line.draw(g, Point::new(x, r.y0 + 12.5), 3.5, Anchor::Start);
        x = bb.x1 + 8.0;
    }
}
