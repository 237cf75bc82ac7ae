//! The scene: what a sheet is made of, in paper millimetres (x right, y down).
//!
//! **Architecture invariant:** every coordinate here is final paper geometry. Backends
//! only serialise a scene; they never compute geometry or choose scales.

pub use super::path::{Path, Seg};
use crate::num::math;
use kurbo::{Point, Rect, Vec2};

/// GOST 2.303 line types.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineType {
    Solid,
    /// Strokes 4 mm, gaps 1.5 mm.
    Dashed,
    /// Strokes 10 mm, gaps 3.5 mm with a dot: axes and trajectories.
    DashDot,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pen {
    pub width: f64,
    pub line: LineType,
}

/// Main (thick) line, S = 0.7 mm.
pub const MAIN: Pen = Pen { width: 0.7, line: LineType::Solid };
/// Thin line, S/3.
pub const THIN: Pen = Pen { width: 0.25, line: LineType::Solid };
/// Plan vectors of absolute motion.
pub const VECTOR: Pen = Pen { width: 0.45, line: LineType::Solid };
pub const DASHED: Pen = Pen { width: 0.25, line: LineType::Dashed };
pub const AXIS: Pen = Pen { width: 0.25, line: LineType::DashDot };

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    Start,
    Middle,
    End,
}

/// A line of text. `h` is the GOST lettering height (capital height, mm); `at` is the
/// anchor point on the baseline.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    pub at: Point,
    pub text: String,
    pub h: f64,
    pub anchor: Anchor,
    /// Rotation in degrees, counter-clockwise on paper.
    pub rotate: f64,
    /// GOST type B sloped lettering (75°).
    pub sloped: bool,
}

impl Text {
    pub fn new(at: Point, text: impl Into<String>, h: f64, anchor: Anchor) -> Text {
        Text { at, text: text.into(), h, anchor, rotate: 0.0, sloped: true }
    }

    /// Advance width of the text, mm.
    fn advance(&self) -> f64 {
        crate::font::metrics().width(&self.text, crate::font::size_for_cap(self.h))
    }

    /// Left edge of a box of width `w` placed by the anchor.
    fn left(&self, w: f64) -> f64 {
        match self.anchor {
            Anchor::Start => self.at.x,
            Anchor::Middle => self.at.x - w / 2.0,
            Anchor::End => self.at.x - w,
        }
    }

    /// The box of the letters themselves (advance width × capital height), for overlap
    /// tests: neighbouring texts such as a symbol and its subscript may touch it, not cross it.
    pub fn core_box(&self) -> Rect {
        let w = self.advance();
        let x0 = self.left(w);
        let r = Rect::new(x0, self.at.y - self.h, x0 + w, self.at.y);
        if self.rotate == 0.0 { r } else { rotated_bbox(r, self.at, self.rotate) }
    }

    /// Bounding box of unrotated text: from the descender to the capital height.
    pub fn bbox(&self) -> Rect {
        let w = self.advance() + self.h * 0.27; // slant overhang
        let x0 = self.left(w);
        let r = Rect::new(x0, self.at.y - self.h * 1.05, x0 + w, self.at.y + self.h * 0.3);
        if self.rotate == 0.0 {
            return r;
        }
        rotated_bbox(r, self.at, self.rotate)
    }
}

fn rotated_bbox(r: Rect, about: Point, deg: f64) -> Rect {
    let (s, c) = math::sin_cos(-deg.to_radians());
    let rot = |p: Point| {
        let d = p - about;
        about + Vec2::new(c * d.x - s * d.y, s * d.x + c * d.y)
    };
    let pts = [r.origin(), Point::new(r.x1, r.y0), Point::new(r.x1, r.y1), Point::new(r.x0, r.y1)].map(rot);
    pts.iter().skip(1).fold(Rect::from_points(pts[0], pts[0]), |acc, &p| acc.union_pt(p))
}

#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// A stroked path of lines, cubic Béziers and arcs.
    Path {
        path: Path,
        pen: Pen,
    },
    Circle {
        c: Point,
        r: f64,
        pen: Pen,
        filled: bool,
    },
    /// A filled outline with no stroke (arrowheads).
    Fill {
        path: Path,
    },
    Text(Text),
}

impl Item {
    pub fn bbox(&self) -> Rect {
        match self {
            Item::Path { path, pen } => path.bbox().inflate(pen.width / 2.0, pen.width / 2.0),
            Item::Fill { path } => path.bbox(),
            Item::Circle { c, r, pen, .. } => Rect::from_center_size(*c, (2.0 * r + pen.width, 2.0 * r + pen.width)),
            Item::Text(t) => t.bbox(),
        }
    }
}

pub fn points_bbox(pts: &[Point]) -> Rect {
    let first = pts.first().copied().unwrap_or_default();
    pts.iter().fold(Rect::from_points(first, first), |acc, &p| acc.union_pt(p))
}

/// A named part of the sheet with the region it must stay inside.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Stable id, written into the SVG.
    pub id: String,
    pub region: Rect,
    pub items: Vec<Item>,
}

impl Group {
    pub fn new(id: impl Into<String>, region: Rect) -> Group {
        Group { id: id.into(), region, items: Vec::new() }
    }

    pub fn line(&mut self, a: Point, b: Point, pen: Pen) {
        self.items.push(Item::Path { path: Path::polyline(&[a, b], false), pen });
    }

    /// A polyline through `pts` (nothing for fewer than two points).
    pub fn path(&mut self, pts: Vec<Point>, closed: bool, pen: Pen) {
        if pts.len() >= 2 {
            self.items.push(Item::Path { path: Path::polyline(&pts, closed), pen });
        }
    }

    /// A path of lines, curves and arcs.
    pub fn curve(&mut self, path: Path, pen: Pen) {
        self.items.push(Item::Path { path, pen });
    }

    /// A filled outline (an arrowhead).
    pub fn fill(&mut self, pts: &[Point]) {
        self.items.push(Item::Fill { path: Path::polyline(pts, true) });
    }

    pub fn circle(&mut self, c: Point, r: f64, pen: Pen) {
        self.items.push(Item::Circle { c, r, pen, filled: false });
    }

    pub fn dot(&mut self, c: Point, r: f64) {
        self.items.push(Item::Circle { c, r, pen: THIN, filled: true });
    }

    pub fn text(&mut self, t: Text) {
        self.items.push(Item::Text(t));
    }

    /// Bounding box of everything drawn in the group.
    /// The group's texts, in drawing order.
    pub fn texts(&self) -> impl Iterator<Item = &Text> {
        self.items.iter().filter_map(|i| match i {
            Item::Text(t) => Some(t),
            _ => None,
        })
    }

    pub fn content_bbox(&self) -> Option<Rect> {
        self.items.iter().map(Item::bbox).reduce(|a, b| a.union(b))
    }
}

/// A whole sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub width: f64,
    pub height: f64,
    pub title: String,
    pub groups: Vec<Group>,
}

impl Scene {
    pub fn texts(&self) -> impl Iterator<Item = &Text> {
        self.groups.iter().flat_map(Group::texts)
    }
}
