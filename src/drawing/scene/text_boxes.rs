//! A text's boxes, for clearance and the layout measure: its letters' boxes, its full box
//! (slant and descenders), and a rotated text's in pieces that follow its letters.

use super::Text;
use crate::num::math;
use kurbo::{Point, Rect};

impl Text {
    /// The boxes of the letters themselves (advance width × capital height), one a run, for
    /// overlap tests: a symbol's box and its subscript's touch, a third text may cross
    /// neither. A run after the first is boxed from where the one before it ends, its
    /// leading space included: a leader ran through the space of "μP = 75 N/mm)" between
    /// the subscript and "=", and neither the placer nor the layout measure saw it cross the
    /// title. A rotated run is boxed in pieces half as long as its letters are high, so that
    /// a line running 1 mm beside a slanted text does not meet its boxes' corners.
    pub fn core_boxes(&self) -> impl Iterator<Item = Rect> + '_ {
        let mut end: Option<f64> = None;
        self.placed_runs().flat_map(move |(r, at, w)| {
            let x0 = end.map_or(at.x, |e| e.min(at.x));
            let x1 = at.x + w;
            end = Some(x1);
            self.turned_pieces(Rect::new(x0, at.y - r.h, x1, at.y), r.h / 2.0)
        })
    }

    /// As [`Text::bbox`], a rotated text's runs boxed in pieces half as long as its letters
    /// are high (a value set along a slanted dimension line, tested for room beside it).
    pub fn bbox_pieces(&self) -> impl Iterator<Item = Rect> + '_ {
        self.placed_runs().flat_map(|(r, at, w)| {
            let w = w + r.h * crate::drawing::text::SLANT;
            self.turned_pieces(Rect::new(at.x, at.y - r.h * 1.05, at.x + w, at.y + r.h * 0.3), r.h / 2.0)
        })
    }

    /// `r` turned with the text: whole where the text is level, else in pieces no longer
    /// than `piece` each turned and boxed.
    fn turned_pieces(&self, r: Rect, piece: f64) -> impl Iterator<Item = Rect> + '_ {
        let n = if self.rotate == 0.0 { 1 } else { (r.width() / piece).ceil().max(1.0) as usize };
        let step = r.width() / n as f64;
        (0..n).map(move |k| {
            if n == 1 {
                return self.turned(r);
            }
            let x0 = r.x0 + step * k as f64;
            self.turned(Rect::new(x0, r.y0, x0 + step, r.y1))
        })
    }

    /// The union of [`Text::core_boxes`].
    pub fn core_box(&self) -> Rect {
        self.core_boxes().reduce(|a, b| a.union(b)).unwrap_or_else(|| Rect::from_points(self.at, self.at))
    }

    /// Bounding box of every run: from its descender to its capital height, from where its
    /// advance starts to where its slant's overhang ends (type B leans right: the capitals'
    /// tops overhang the advance by tan 15° of their height, and a descender's lean left
    /// stays inside the letter's side bearing). The labeller boxes a label the same way, so
    /// a label it sets against a region's edge is measured inside it.
    pub fn bbox(&self) -> Rect {
        let boxes = self.placed_runs().map(|(r, at, w)| {
            let w = w + r.h * crate::drawing::text::SLANT;
            self.turned(Rect::new(at.x, at.y - r.h * 1.05, at.x + w, at.y + r.h * 0.3))
        });
        boxes.reduce(|a, b| a.union(b)).unwrap_or_else(|| Rect::from_points(self.at, self.at))
    }

    fn turned(&self, r: Rect) -> Rect {
        if self.rotate == 0.0 { r } else { rotated_bbox(r, self.at, self.rotate) }
    }
}

fn rotated_bbox(r: Rect, about: Point, deg: f64) -> Rect {
    let rot = |p: Point| about + math::rotate(p - about, -deg.to_radians());
    let pts = [r.origin(), Point::new(r.x1, r.y0), Point::new(r.x1, r.y1), Point::new(r.x0, r.y1)].map(rot);
    pts.iter().skip(1).fold(Rect::from_points(pts[0], pts[0]), |acc, &p| acc.union_pt(p))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::obstacles::segment_meets_rect;
    use crate::drawing::scene::Anchor;
    use kurbo::Vec2;

    /// A slanted text's letters are boxed in pieces that follow it: a line 1 mm beside its
    /// letters, parallel to it, meets none of them, though it crosses the one box that
    /// would hold the whole text; every letter stays inside the pieces.
    #[test]
    fn a_slanted_texts_boxes_follow_its_letters() {
        let mut t = Text::new(Point::new(50.0, 50.0), "s = 7,142", 3.5, Anchor::Middle);
        t.rotate = 35.0;
        let (s, c) = math::sin_cos(35f64.to_radians());
        // Along the baseline (up and right on paper) and the letters' up.
        let (along, up) = (Vec2::new(c, -s), Vec2::new(-s, -c));
        let w = t.advance();
        // 1 mm under the baseline, running the text's length and more.
        let (a, b) = (t.at - along * w - up * 1.0, t.at + along * w - up * 1.0);
        assert!(segment_meets_rect(a, b, t.core_box()), "the whole box is crossed");
        assert!(t.core_boxes().count() >= 10, "a piece half a letter or so");
        assert!(t.core_boxes().all(|r| !segment_meets_rect(a, b, r)), "a piece is crossed");
        // The letters' own frame, level, turned: its corners inside the pieces' union.
        let level = Text { rotate: 0.0, ..t.clone() };
        for r in level.core_boxes() {
            for q in [Point::new(r.x0 + 0.2, r.y0 + 0.2), Point::new(r.x1 - 0.2, r.y1 - 0.2)] {
                let turned = t.at + math::rotate(q - t.at, -t.rotate.to_radians());
                assert!(t.core_boxes().any(|p| p.contains(turned)), "{turned:?} outside the pieces");
            }
        }
    }
}
