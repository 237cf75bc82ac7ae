//! The scene: what a sheet is made of, in paper millimetres (x right, y down).
//!
//! **Architecture invariant:** every coordinate here is final paper geometry. Backends
//! only serialise a scene; they never compute geometry or choose scales.

pub use super::path::{Path, Seg};

mod text;
mod text_boxes;
use kurbo::{Point, Rect};
pub use text::{Run, SUB, SUB_DROP, Text};

/// GOST 2.303 line types.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineType {
    Solid,
    /// Strokes 4 mm, gaps 1.5 mm.
    Dashed,
    /// Strokes 10 mm, 3.5 mm between them with a dot: axes (GOST 2.303 asks strokes of
    /// 5–30 mm and 3–5 mm between strokes).
    DashDot,
}

impl LineType {
    /// The dash pattern (strokes and gaps, mm); `None`: solid.
    pub const fn dashes(self) -> Option<&'static [f64]> {
        match self {
            LineType::Solid => None,
            LineType::Dashed => Some(&[4.0, 1.5]),
            LineType::DashDot => Some(&[10.0, 1.5, 0.5, 1.5]),
        }
    }
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

/// One drawing or table inside a group (a velocity plan of one position, one force
/// polygon, one table): its stable id and the run of the group's items that draw it, so that
/// the SVG can wrap it in its own `<g id>` and a test can compare it alone.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Stable id within the sheet ("plan.v.3"), written into the SVG after the sheet's name.
    pub id: String,
    pub items: std::ops::Range<usize>,
}

/// A named part of the sheet with the region it must stay inside.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Stable id within the sheet, written into the SVG after the sheet's name.
    pub id: String,
    pub region: Rect,
    pub items: Vec<Item>,
    /// Its drawings, in item order, none overlapping another (items between them belong to
    /// the group only).
    pub parts: Vec<Part>,
    /// The lines that belong to its writing, not its constructions (a label's leader, a
    /// legend's sample line), by item index: the overlay leaves them out with the texts.
    pub writing: Vec<usize>,
    /// Of the writing, the leaders that join a label to its point, by item index: the layout
    /// measures how far a label stands from what it names.
    pub leaders: Vec<usize>,
    /// Thin lines a label may interrupt where no spot near its point is free (the position
    /// plan's other positions of the links, the trajectories: GOST 2.316 interrupts lines
    /// at an inscription), by item index, ascending.
    pub breakable: Vec<usize>,
    /// Where the breakable lines end as drawn, before any break: a piece of one ending
    /// elsewhere ends at a break.
    line_ends: Vec<Point>,
}

/// The shortest piece of a line kept between two breaks, mm: shorter, at 150 dpi it reads
/// as a stray tick between two labels («φ_ut = 30°|»), not as the line passing them.
pub const STUB: f64 = 3.0;

/// The most breakable lines (a link's position, a trajectory's dash) one text may
/// interrupt: a label's, or a stroke's value along its dimension line.
pub const MOST_BROKEN: usize = 6;

impl Group {
    pub fn new(id: impl Into<String>, region: Rect) -> Group {
        Group {
            id: id.into(),
            region,
            items: Vec::new(),
            parts: Vec::new(),
            writing: Vec::new(),
            leaders: Vec::new(),
            breakable: Vec::new(),
            line_ends: Vec::new(),
        }
    }

    /// Where the next item will go: the start of a part (see [`Group::part_from`]).
    pub fn mark(&self) -> usize {
        self.items.len()
    }

    /// Names the items drawn since `start` (a [`Group::mark`]) as the part `id`. Nothing is
    /// recorded for an empty run; a run reaching into the previous part is cut to follow it.
    pub fn part_from(&mut self, id: impl Into<String>, start: usize) {
        let (id, start) = (id.into(), start.max(self.parts.last().map_or(0, |p| p.items.end)));
        if !id.is_empty() && start < self.items.len() {
            self.parts.push(Part { id, items: start..self.items.len() });
        }
    }

    /// The items of the part `id`, if the group has it.
    pub fn part(&self, id: &str) -> Option<&[Item]> {
        self.parts.iter().find(|p| p.id == id).map(|p| &self.items[p.items.clone()])
    }

    pub fn line(&mut self, a: Point, b: Point, pen: Pen) {
        self.items.push(Item::Path { path: Path::polyline(&[a, b], false), pen });
    }

    /// Marks the items drawn since `start` (a [`Group::mark`]) that are paths of lines and
    /// cubics as breakable (see [`Group::breakable`]).
    pub fn breakable_from(&mut self, start: usize) {
        for k in start..self.items.len() {
            if let Item::Path { path, .. } = &self.items[k]
                && path.has_no_arc()
            {
                self.line_ends.extend([path.start, path.end()]);
                self.breakable.push(k);
            }
        }
    }

    /// Interrupts the breakable lines where they cross the boxes `gaps` (labels and values
    /// set on them). A piece left between two breaks shorter than [`STUB`] goes too.
    pub fn interrupt_breakable(&mut self, gaps: &[Rect]) {
        if gaps.is_empty() {
            return;
        }
        for k in self.breakable.clone().into_iter().rev() {
            let Item::Path { path, pen } = &self.items[k] else { continue };
            let Some(mut runs) = path.outside_rects(gaps) else { continue };
            let pen = *pen;
            runs.retain(|run| self.is_line_end(run.start) || self.is_line_end(run.end()) || run.length() >= STUB);
            self.split_item(k, runs.into_iter().map(|path| Item::Path { path, pen }).collect());
        }
    }

    /// Whether `p` is where a breakable line ends as drawn (not a break's end).
    pub fn is_line_end(&self, p: Point) -> bool {
        self.line_ends.iter().any(|e| (*e - p).hypot2() < 1e-18)
    }

    /// Replaces item `k` by `pieces` (none: removes it), keeping every index the group holds
    /// (its parts, its writing, its breakable lines) on the items they named.
    pub fn split_item(&mut self, k: usize, pieces: Vec<Item>) {
        let n = pieces.len();
        self.items.splice(k..=k, pieces);
        let moved = |i: usize| if i > k { i + n - 1 } else { i };
        for part in &mut self.parts {
            // A part ending at k + 1 holds the pieces; one starting after k moves with them.
            part.items =
                moved(part.items.start)..if part.items.end > k { part.items.end + n - 1 } else { part.items.end };
        }
        let remap = |v: &mut Vec<usize>| {
            *v = v.iter().flat_map(|&i| if i == k { (k..k + n).collect() } else { vec![moved(i)] }).collect();
        };
        remap(&mut self.writing);
        remap(&mut self.leaders);
        remap(&mut self.breakable);
    }

    /// A line that belongs to the writing (see [`Group::writing`]).
    pub fn writing_line(&mut self, a: Point, b: Point, pen: Pen) {
        self.writing.push(self.items.len());
        self.line(a, b, pen);
    }

    /// A label's leader: a line of the writing (see [`Group::leaders`]).
    pub fn leader_line(&mut self, a: Point, b: Point, pen: Pen) {
        self.leaders.push(self.items.len());
        self.writing_line(a, b, pen);
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

    /// A curve in `pen`'s line type, its strokes cut here as solid pieces: every renderer
    /// dashes a long Bézier curve by its own measure of its length, so the SVG, PDF and PNG
    /// put the gaps of a dashed trajectory in different places (straight lines they dash
    /// alike, and keep their line type).
    pub fn dashed_curve(&mut self, path: Path, pen: Pen) {
        let Some(pattern) = pen.line.dashes() else {
            return self.curve(path, pen);
        };
        let solid = Pen { line: LineType::Solid, ..pen };
        let mut piece: Option<Path> = None;
        for el in kurbo::dash(path.to_bez().into_iter(), 0.0, pattern) {
            match el {
                kurbo::PathEl::MoveTo(p) => {
                    self.items.extend(piece.replace(Path::new(p)).map(|path| Item::Path { path, pen: solid }));
                }
                kurbo::PathEl::LineTo(p) => piece.iter_mut().for_each(|q| q.segs.push(Seg::Line(p))),
                kurbo::PathEl::QuadTo(p1, p2) => {
                    // Raised to a cubic (dashing a cubic path never makes one; kept exact).
                    let p0 = piece.as_ref().map_or(p1, Path::end);
                    let (c1, c2) = (p0 + (p1 - p0) * (2.0 / 3.0), p2 + (p1 - p2) * (2.0 / 3.0));
                    piece.iter_mut().for_each(|q| q.segs.push(Seg::Cubic(c1, c2, p2)));
                }
                kurbo::PathEl::CurveTo(p1, p2, p3) => {
                    piece.iter_mut().for_each(|q| q.segs.push(Seg::Cubic(p1, p2, p3)))
                }
                kurbo::PathEl::ClosePath => {}
            }
        }
        self.items.extend(piece.map(|path| Item::Path { path, pen: solid }));
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

/// The colour a scene is drawn in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ink {
    /// Black on white: the sheet.
    #[default]
    Black,
    /// One contrasting colour on nothing (no page fill): an overlay to print on film and
    /// lay over a hand drawing, or to stack on a scan.
    Overlay,
}

impl Ink {
    /// Red, green, blue.
    pub fn rgb(self) -> [u8; 3] {
        match self {
            Ink::Black => [0, 0, 0],
            // A red that pencil grey and blue ink do not have.
            Ink::Overlay => [230, 0, 0],
        }
    }
}

/// A whole sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub ink: Ink,
    /// The sheet's name in ids ("sheet1"): every group's and part's SVG id begins with it.
    pub name: String,
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
