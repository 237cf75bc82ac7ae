//! A view's heading on sheet 3: its title at the region's top left and its scale under it,
//! and the width the two need.

use super::labels::CamWords;
use crate::drawing::fmt;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::text::LabelText;
use kurbo::{Point, Rect};

/// A view's title, set at the region's top left in [`TITLE_H`] lettering.
fn view_title(region: Rect, title: &str) -> Text {
    Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, TITLE_H, Anchor::Start)
}

/// The lettering of the sheet's section titles, mm: sheet 1's and sheet 2's (in 3.5 mm the
/// four views' titles were smaller than their tables' titles, a teacher's review).
pub(super) const TITLE_H: f64 = 5.0;

/// The width a view's region needs for its title (and the scale under it, which is
/// shorter): the title's box from the region's left edge, and as much again on the right.
pub(super) fn heading_w(title: &str) -> f64 {
    let bb = view_title(Rect::ZERO, title).bbox();
    bb.x1 + bb.x0
}

/// A view's group with its title at the region's top left.
pub(super) fn view_group(id: &str, region: Rect, title: &str) -> Group {
    let mut g = Group::new(id, region);
    let mut t = view_title(region, title);
    // Clear of box 26 in the frame's top-left corner (no view stands there yet).
    t.at = crate::drawing::frame::clear_of_designation_box(t.at, t.h);
    g.text(t);
    g
}

/// "μ_l = … m/mm" (and the GOST ratio) under a view's title: below the view it read as the
/// scale of the view under it.
pub(super) fn scale_note(g: &mut Group, mu: f64, ratio: Option<String>, words: &CamWords) {
    let lang = words.lang;
    let mut tail = format!(" = {} {}", fmt::trimmed(mu, lang), words.common.unit_m_per_mm());
    if let Some(r) = ratio {
        tail.push_str(&format!(" ({})", fmt::localise(&r, lang)));
    }
    let r = g.region;
    LabelText::new("μ", "l").with_tail(tail).draw(g, Point::new(r.x0 + 2.0, r.y0 + 11.5), 2.5, Anchor::Start);
}
