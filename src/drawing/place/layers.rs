//! The drawing as a label sees it: all of it, its lines a label may not break, and its
//! bold lines a leader crosses only where it must.

use super::Candidate;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::scene::{Item, VECTOR};
use crate::num::math::Norm;
use kurbo::{Point, Shape};

/// The drawing as the labels see it: everything, and without its breakable lines (none
/// when it has none); and which of its items are bold, by index.
#[derive(Clone, Copy)]
pub(super) struct Layers<'a> {
    pub(super) drawn: &'a Obstacles,
    pub(super) hard: Option<&'a Obstacles>,
    pub(super) bold: &'a [bool],
    pub(super) items: &'a [Item],
}

impl Layers<'_> {
    /// Whether `c`'s leader crosses a bold item of the drawing ([`is_bold`]) other than one
    /// enclosing its anchor (a slider's block round its point: every leader crosses that).
    pub(super) fn crosses_bold(&self, c: &Candidate) -> bool {
        let bold = |k: usize| self.bold.get(k) == Some(&true) && !encloses(&self.items[k], c.anchor);
        c.leader.is_some_and(|(a, b)| self.drawn.segment_crosses_stroke_of(a, b, bold))
    }
}

/// Whether the closed outline `item` draws (a slider's block, a joint's circle) holds `p`.
fn encloses(item: &Item, p: Point) -> bool {
    match item {
        Item::Path { path, .. } if path.closed => path.bbox().contains(p) && path.to_bez().winding(p) != 0,
        Item::Circle { c, r, .. } => (p - *c).norm() < *r,
        _ => false,
    }
}

/// Whether a leader may cross `item` only where no label spot can be reached otherwise: a
/// line as heavy as a plan's vector or heavier, an arrowhead, a dot. Thin lines (a fan of
/// links, a construction) a leader crosses more readily.
pub(super) fn is_bold(item: &Item) -> bool {
    match item {
        Item::Path { pen, .. } => pen.width >= VECTOR.width,
        Item::Circle { pen, filled, .. } => *filled || pen.width >= VECTOR.width,
        Item::Fill { .. } => true,
        Item::Text(_) => false,
    }
}
