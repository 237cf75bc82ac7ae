//! The scene: what a sheet is made of, in paper millimetres (x right, y down).
//!
//! **Architecture invariant:** every coordinate here is final paper geometry. Backends
//! only serialise a scene; they never compute geometry or choose scales.

pub use super::path::{Path, Seg};

mod text_boxes;
use kurbo::{Point, Rect};

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

/// Subscript height relative to its symbol (GOST 2.304: indices one size smaller; 2.5 mm
/// lettering takes 1.8 mm indices, the smallest size, not 1.75).
pub const SUB: f64 = 0.72;
/// How far a subscript's baseline lies below its symbol's, in the symbol's heights.
pub const SUB_DROP: f64 = 0.3;

/// A line of text: a symbol or words, an optional subscript and an optional tail after it at
/// the symbol's height (v_BA, "μ_l = 0,005 m/mm"). One item, so that every backend sets the
/// subscript after the main text with its own font. `h` is the GOST lettering height
/// (capital height, mm); `at` is the anchor point on the main text's baseline.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    pub at: Point,
    pub text: String,
    /// Set at [`SUB`] of `h`, its baseline [`SUB_DROP`]·h lower.
    pub sub: String,
    /// Set after the subscript at `h`, on the main baseline.
    pub tail: String,
    pub h: f64,
    pub anchor: Anchor,
    /// Rotation in degrees, counter-clockwise on paper.
    pub rotate: f64,
    /// GOST type B sloped lettering (75°).
    pub sloped: bool,
    /// Width factor of the letters (1: the font's own; below 1 condensed, as GOST 2.304's
    /// narrow type A, to fit a long name into its title-block cell).
    pub stretch: f64,
}

/// One run of a [`Text`]: its text, its lettering height and its baseline's drop below the
/// main baseline, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run<'a> {
    pub text: &'a str,
    pub h: f64,
    pub drop: f64,
}

impl Text {
    pub fn new(at: Point, text: impl Into<String>, h: f64, anchor: Anchor) -> Text {
        Text {
            at,
            text: text.into(),
            sub: String::new(),
            tail: String::new(),
            h,
            anchor,
            rotate: 0.0,
            sloped: true,
            stretch: 1.0,
        }
    }

    /// The same text condensed (or widened) by `stretch`.
    pub fn with_stretch(mut self, stretch: f64) -> Text {
        self.stretch = stretch;
        self
    }

    /// A run's advance width as set, mm (its stretch applied).
    fn width_of(&self, r: Run) -> f64 {
        run_width(r) * self.stretch
    }

    /// The same text with a subscript and a tail.
    pub fn with_sub(mut self, sub: impl Into<String>, tail: impl Into<String>) -> Text {
        self.sub = sub.into();
        self.tail = tail.into();
        self
    }

    /// The runs in order: the main text, the subscript, the tail (the empty ones left out).
    pub fn runs(&self) -> impl Iterator<Item = Run<'_>> {
        let h = self.h;
        [
            Run { text: self.text.as_str(), h, drop: 0.0 },
            Run { text: self.sub.as_str(), h: h * SUB, drop: h * SUB_DROP },
            Run { text: self.tail.as_str(), h, drop: 0.0 },
        ]
        .into_iter()
        .filter(|r| !r.text.is_empty())
    }

    /// The text as one string for messages: "v_BA = 1".
    pub fn plain(&self) -> String {
        if self.sub.is_empty() {
            format!("{}{}", self.text, self.tail)
        } else {
            format!("{}_{}{}", self.text, self.sub, self.tail)
        }
    }

    /// Advance width of every run together, mm.
    pub fn advance(&self) -> f64 {
        self.runs().map(|r| self.width_of(r)).sum()
    }

    /// Left edge of a box of width `w` placed by the anchor.
    fn left(&self, w: f64) -> f64 {
        match self.anchor {
            Anchor::Start => self.at.x,
            Anchor::Middle => self.at.x - w / 2.0,
            Anchor::End => self.at.x - w,
        }
    }

    /// Each run without its leading spaces, with the left end of its baseline, unrotated
    /// (the spaces before a tail are room, not letters), and the width of its letters.
    /// Each run is measured once (a text's boxes are asked for thousands of times while a
    /// sheet is composed, and measuring was 6 % of building sheet 1); the sums and
    /// differences are those of measuring it anew each time, so every box is the same.
    fn placed_runs(&self) -> impl Iterator<Item = (Run<'_>, Point, f64)> {
        let mut widths = [(Run { text: "", h: 0.0, drop: 0.0 }, 0.0, 0.0); 3];
        let mut n = 0;
        for r in self.runs() {
            let letters = Run { text: r.text.trim_start(), ..r };
            let w = self.width_of(r);
            // Without leading spaces the letters are the run: its width.
            let lw = if letters.text.len() == r.text.len() { w } else { self.width_of(letters) };
            widths[n] = (letters, w, lw);
            n += 1;
        }
        let mut x = self.left(widths[..n].iter().map(|&(_, w, _)| w).sum());
        widths.into_iter().take(n).map(move |(letters, w, lw)| {
            let at = Point::new(x + w - lw, self.at.y + letters.drop);
            x += w;
            (letters, at, lw)
        })
    }
}

/// A run's advance width, mm.
fn run_width(r: Run) -> f64 {
    crate::font::metrics().width(r.text, crate::font::size_for_cap(r.h))
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
