//! Greedy placement of short labels next to the points they name, avoiding other labels
//! and staying inside a region.

use super::scene::{Anchor, Text};
use crate::num::math::{self, Norm};
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// Gap between a point and its label, mm.
const GAP: f64 = 1.0;

pub struct Placer {
    bounds: Rect,
    taken: Vec<Rect>,
}

impl Placer {
    pub fn new(bounds: Rect) -> Placer {
        Placer { bounds, taken: Vec::new() }
    }

    /// Marks an area as occupied (another label, a title).
    pub fn block(&mut self, r: Rect) {
        self.taken.push(r);
    }

    fn free(&self, r: &Rect) -> bool {
        let inside =
            r.x0 >= self.bounds.x0 && r.y0 >= self.bounds.y0 && r.x1 <= self.bounds.x1 && r.y1 <= self.bounds.y1;
        inside && self.taken.iter().all(|t| t.intersect(*r).area() <= tol::PAPER_AREA)
    }

    /// A label of height `h` beside `anchor`, preferably in the direction `pref`
    /// (paper coordinates). Tries eight directions at growing distances; if none is free
    /// it keeps the preferred spot (the overlap test then reports it).
    pub fn place(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64) -> Text {
        let probe = Text::new(Point::ZERO, text, h, Anchor::Middle);
        let bb = probe.bbox();
        let r = self.place_box(anchor, pref, bb.width(), bb.height());
        // The text's baseline sits where its box (descender to cap height) puts it.
        Text::new(Point::new(r.center().x, r.y1 - (bb.y1 - probe.at.y)), text, h, Anchor::Middle)
    }

    /// A free box of `w` × `ht` beside `anchor` (see [`Placer::place`]), now taken.
    pub fn place_box(&mut self, anchor: Point, pref: Vec2, w: f64, ht: f64) -> Rect {
        let base = if pref.norm() > tol::PAPER { pref.unit() } else { Vec2::new(1.0, -1.0).unit() };
        let mut first = None;
        for dist in [GAP, GAP + 1.5, GAP + 3.5, GAP + 6.0, GAP + 9.0, GAP + 13.0, GAP + 18.0, GAP + 24.0] {
            for ang in [0.0, 45.0, -45.0, 90.0, -90.0, 135.0, -135.0, 180.0] {
                let d = rotate(base, ang);
                let centre = anchor + Vec2::new(d.x * (w / 2.0 + dist), d.y * (ht / 2.0 + dist));
                let r = Rect::new(centre.x - w / 2.0, centre.y - ht / 2.0, centre.x + w / 2.0, centre.y + ht / 2.0);
                first.get_or_insert(r);
                if self.free(&r) {
                    self.taken.push(r);
                    return r;
                }
            }
        }
        let r = first.expect("at least one candidate");
        self.taken.push(r);
        r
    }
}

fn rotate(v: Vec2, deg: f64) -> Vec2 {
    let (s, c) = math::sin_cos(deg.to_radians());
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}
