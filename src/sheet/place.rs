//! Greedy placement of short labels next to the points they name, avoiding other labels
//! and staying inside a region.

use super::scene::{Anchor, Text};
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
        let inside = r.x0 >= self.bounds.x0 && r.y0 >= self.bounds.y0 && r.x1 <= self.bounds.x1 && r.y1 <= self.bounds.y1;
        inside && self.taken.iter().all(|t| t.intersect(*r).area() <= 1e-9)
    }

    /// A label of height `h` beside `anchor`, preferably in the direction `pref`
    /// (paper coordinates). Tries eight directions at growing distances; if none is free
    /// it keeps the preferred spot (the overlap test then reports it).
    pub fn place(&mut self, anchor: Point, pref: Vec2, text: &str, h: f64) -> Text {
        let base = if pref.hypot() > 1e-9 { pref.normalize() } else { Vec2::new(1.0, -1.0).normalize() };
        let probe = Text::new(Point::ZERO, text, h, Anchor::Middle);
        let bb = probe.bbox();
        let (w, ht) = (bb.width(), bb.height());
        let mut first = None;
        for dist in [GAP, GAP + 1.5, GAP + 3.5, GAP + 6.0] {
            for i in 0..8 {
                let ang = [0.0, 45.0, -45.0, 90.0, -90.0, 135.0, -135.0, 180.0][i];
                let d = rotate(base, ang);
                let centre = anchor + Vec2::new(d.x * (w / 2.0 + dist), d.y * (ht / 2.0 + dist));
                let t = Text::new(Point::new(centre.x, centre.y + ht / 2.0 - h * 0.3), text, h, Anchor::Middle);
                let r = t.bbox();
                first.get_or_insert((t.clone(), r));
                if self.free(&r) {
                    self.taken.push(r);
                    return t;
                }
            }
        }
        let (t, r) = first.expect("at least one candidate");
        self.taken.push(r);
        t
    }
}

fn rotate(v: Vec2, deg: f64) -> Vec2 {
    let (s, c) = deg.to_radians().sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}
