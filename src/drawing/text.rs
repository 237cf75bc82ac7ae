//! Symbols with subscripts (v_BA, ω₂, aⁿ_BA): the subscript is set as its own smaller
//! text item so that every backend shows it the same way.

use super::scene::{Anchor, Group, Text};
use crate::font;
use kurbo::{Point, Rect};

/// A symbol and an optional subscript, e.g. ("v", "BA").
#[derive(Debug, Clone, PartialEq)]
pub struct LabelText {
    pub main: String,
    pub sub: String,
    /// Text after the subscript, at the symbol's size (" = 0,005 m/mm").
    pub tail: String,
}

impl LabelText {
    pub fn new(main: impl Into<String>, sub: impl Into<String>) -> LabelText {
        LabelText { main: main.into(), sub: sub.into(), tail: String::new() }
    }

    pub fn with_tail(mut self, tail: impl Into<String>) -> LabelText {
        self.tail = tail.into();
        self
    }

    fn widths(&self, h: f64) -> (f64, f64, f64) {
        let m = font::metrics();
        let (size, sub) = (font::size_for_cap(h), font::size_for_cap(h * SUB));
        (m.width(&self.main, size), m.width(&self.sub, sub), m.width(&self.tail, size))
    }

    /// Draws the symbol with its baseline at `at.y`, anchored horizontally by `anchor`;
    /// returns the bounding box of what it drew.
    pub fn draw(&self, g: &mut Group, at: Point, h: f64, anchor: Anchor) -> Rect {
        let (wm, ws, wt) = self.widths(h);
        let total = wm + ws + wt;
        let x0 = match anchor {
            Anchor::Start => at.x,
            Anchor::Middle => at.x - total / 2.0,
            Anchor::End => at.x - total,
        };
        g.text(Text::new(Point::new(x0, at.y), self.main.clone(), h, Anchor::Start));
        let mut bb = g.items.last().map(|i| i.bbox()).unwrap_or_default();
        if !self.sub.is_empty() {
            g.text(Text::new(Point::new(x0 + wm, at.y + h * 0.3), self.sub.clone(), h * SUB, Anchor::Start));
            bb = bb.union(g.items.last().map(|i| i.bbox()).unwrap_or_default());
        }
        if !self.tail.is_empty() {
            // SVG drops a text's leading white space, so the gap is made by position instead.
            let trimmed = self.tail.trim_start();
            let lead = wt - font::metrics().width(trimmed, font::size_for_cap(h));
            g.text(Text::new(Point::new(x0 + wm + ws + lead, at.y), trimmed, h, Anchor::Start));
            bb = bb.union(g.items.last().map(|i| i.bbox()).unwrap_or_default());
        }
        bb
    }
}

/// Subscript height relative to the symbol (GOST 2.304: indices one size smaller).
const SUB: f64 = 0.7;

/// Breaks `text` into lines no wider than `width` mm at lettering height `h`.
pub fn wrap(text: &str, h: f64, width: f64) -> Vec<String> {
    let m = font::metrics();
    let size = font::size_for_cap(h);
    let fits = |s: &str| m.width(s, size) + 0.27 * h <= width;
    let mut lines = Vec::new();
    let mut cur = String::new();
    for word in text.split_whitespace() {
        let candidate = if cur.is_empty() { word.to_string() } else { format!("{cur} {word}") };
        if fits(&candidate) || cur.is_empty() {
            cur = candidate;
        } else {
            lines.push(std::mem::take(&mut cur));
            cur = word.to_string();
        }
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

/// Draws wrapped lines starting with the first baseline at `at`, line pitch 1.6·h;
/// returns the y of the next free line.
pub fn paragraph(g: &mut Group, at: Point, lines: &[String], h: f64, anchor: Anchor) -> f64 {
    let mut y = at.y;
    for line in lines {
        g.text(Text::new(Point::new(at.x, y), line.clone(), h, anchor));
        y += 1.6 * h;
    }
    y
}
