//! What is already drawn, as straight segments and text boxes in a grid ([`super::grid`]): the
//! label placer asks it which candidate boxes are free, the layout measurement which texts a
//! line crosses. Curves are flattened to segments within [`FLATTEN`] mm; a filled shape
//! (an arrowhead, a dot) is its outline, which also catches a box that swallows it whole.

use super::grid::{self, Grid};
use super::scene::Item;
use crate::num::math::Norm;
use flatten::{meets, pieces_of, reach, stroke_pieces};
use kurbo::{Point, Rect};
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

mod flatten;
mod geometry;
mod hints;
mod memo;
pub use flatten::segments;
use geometry::disc_meets_rect;
pub use geometry::{rect_segment_distance, segment_meets_rect, segment_span_in_rect, segments_cross};
use hints::Hints;
pub use hints::SLOTS;
pub use memo::new_build;

/// Flattening tolerance of curves, mm: far below a line's width.
pub const FLATTEN: f64 = 0.02;

/// What an indexed piece is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// A stroke or the outline of a filled shape.
    Segment(Point, Point),
    /// A text's core box (the letters themselves).
    TextBox(Rect),
    /// A disc no label may enter (a roller: a number inside another roller's circle reads
    /// as that roller's).
    Disc(Point, f64),
    /// The room beside a value's statement on its line, where a label would read as part
    /// of it ([`crate::drawing::phrases::level_band`]): no label's box may enter it, a
    /// leader may cross it (nothing is drawn there).
    Band(Rect),
    /// A value's statement's letters and their height, mm (its letters are a text box
    /// too): a label level with it keeps off its line beside it, as far as the smaller's
    /// height needs ([`Obstacles::statement_meets`]); nothing else sees it.
    Statement(Rect, f64),
    /// A number's letters and their height, mm, that read as the index of a taller letter
    /// beside it on its line («2 A»: A₂): a taller label keeps off its line beside it
    /// ([`Obstacles::index_meets`]); nothing else sees it.
    Index(Rect, f64),
}

/// The side of the text boxes' grid's cells, mm: they are few and a leader's walk through
/// their grid crosses a cell every this much (the segments' grid keeps the label-sized
/// cells). Measured on the worked example's sheet 1: 3 mm cells took 6 % longer.
const BOX_CELL: f64 = 12.0;

/// A segment as its grid lists it: its piece's id and its ends, read where the cell is
/// (most tests are of segments, and most of them miss).
#[derive(Debug, Clone, Copy)]
struct Stroke {
    id: u32,
    a: Point,
    b: Point,
}

impl grid::Listed for Stroke {
    fn id(self) -> u32 {
        self.id
    }
}

/// An index of drawn geometry.
#[derive(Default, Clone)]
pub struct Obstacles {
    pieces: Vec<(Piece, usize)>,
    /// The segment that last met a box and the one a segment last crossed, asked first.
    hints: Hints,
    /// The segments, and apart from them the text boxes and discs: a leader's questions
    /// are about one kind, and a sheet holds many more segments than texts.
    strokes: Grid<Stroke>,
    boxes: Grid,
    /// The pieces' bounds together.
    extent: Option<Rect>,
}

impl Obstacles {
    /// Every item's segments and text boxes, each tagged with its item's index.
    pub fn of_items<'a>(items: impl IntoIterator<Item = &'a Item>) -> Obstacles {
        let (mut pieces, mut segs) = (Vec::new(), Vec::new());
        for (k, item) in items.into_iter().enumerate() {
            pieces_of(item, k, &mut pieces, &mut segs);
        }
        Obstacles::of_pieces(pieces)
    }

    /// [`Obstacles::of_items`] of drawn items (no texts) whose [`segments`] are already
    /// found, each given with them; the segments' grid of cells `cell` mm wide.
    pub fn of_flattened<'a>(items: impl IntoIterator<Item = (&'a Item, &'a [(Point, Point)])>, cell: f64) -> Obstacles {
        let mut pieces = Vec::new();
        for (k, (item, segs)) in items.into_iter().enumerate() {
            stroke_pieces(item, segs, k, &mut pieces);
        }
        Obstacles::of_pieces_in(pieces, cell)
    }

    /// As [`Obstacles::of_items`], without the pieces whose bounds miss `within`: for
    /// questions about `within` alone (a cell's labels among every cell drawn before it),
    /// whose answers those pieces cannot change. An item that cannot reach `within` is not
    /// even flattened.
    pub fn of_items_within<'a>(items: impl IntoIterator<Item = &'a Item>, within: Rect) -> Obstacles {
        let (mut pieces, mut segs) = (Vec::new(), Vec::new());
        for (k, item) in items.into_iter().enumerate() {
            if reach(item).is_none_or(|r| meets(r, within)) {
                let from = pieces.len();
                pieces_of(item, k, &mut pieces, &mut segs);
                let mut kept = from;
                for i in from..pieces.len() {
                    if meets(bounds(&pieces[i].0), within) {
                        pieces.swap(kept, i);
                        kept += 1;
                    }
                }
                pieces.truncate(kept);
            }
        }
        Obstacles::of_pieces(pieces)
    }

    /// The same index without the pieces whose tags `drop` names (a drawing without its
    /// breakable lines): what [`Obstacles::of_items_within`] of the items kept gives, but
    /// for the tags, which count here only as telling items apart.
    pub fn without(&self, drop: impl Fn(usize) -> bool) -> Obstacles {
        Obstacles::of_pieces(self.pieces.iter().filter(|(_, k)| !drop(*k)).copied().collect())
    }

    /// Pieces with their tags, loaded at once.
    pub fn of_pieces(pieces: Vec<(Piece, usize)>) -> Obstacles {
        Obstacles::of_pieces_in(pieces, grid::CELL)
    }

    /// [`Obstacles::of_pieces`], the segments' grid of cells `cell` mm wide.
    fn of_pieces_in(pieces: Vec<(Piece, usize)>, cell: f64) -> Obstacles {
        let extent = pieces.iter().map(|(p, _)| bounds(p)).reduce(|a, b| a.union(b));
        let over = extent.unwrap_or(Rect::ZERO);
        let id = |k: usize| u32::try_from(k).expect("fewer than 2³² pieces on a sheet");
        // Sized at once: a drawing's pieces are mostly segments, and growing the list
        // copied it over and over.
        let segments = pieces.iter().filter(|(p, _)| matches!(p, Piece::Segment(..))).count();
        let (mut strokes, mut boxes) = (Vec::with_capacity(segments), Vec::with_capacity(pieces.len() - segments));
        for (k, (p, _)) in pieces.iter().enumerate() {
            match *p {
                Piece::Segment(a, b) => strokes.push((grid::Shape::Segment(a, b), Stroke { id: id(k), a, b })),
                Piece::TextBox(_) | Piece::Disc(..) | Piece::Band(_) | Piece::Statement(..) | Piece::Index(..) => {
                    boxes.push((grid::Shape::Box(bounds(p)), id(k)))
                }
            }
        }
        Obstacles {
            pieces,
            hints: Hints::default(),
            strokes: Grid::with_cells(over, cell, &strokes),
            boxes: Grid::with_cells(over, BOX_CELL, &boxes),
            extent,
        }
    }

    /// An empty index whose cells cover `extent` (pieces beyond it still count).
    pub fn empty_over(extent: Rect) -> Obstacles {
        Obstacles {
            pieces: Vec::new(),
            hints: Hints::default(),
            strokes: Grid::over(extent),
            boxes: Grid::over_cells(extent, BOX_CELL),
            extent: None,
        }
    }

    /// The drawn pieces' bounds together, if there are any.
    pub fn extent(&self) -> Option<Rect> {
        self.extent
    }

    /// Adds `items`' pieces, each tagged with its index counted from `first` (the items
    /// drawn since the index was built, as [`Obstacles::of_items`] of them all would tag them).
    pub fn add_items(&mut self, items: &[Item], first: usize) {
        let (mut pieces, mut segs) = (Vec::new(), Vec::new());
        for (k, item) in items.iter().enumerate() {
            pieces_of(item, first + k, &mut pieces, &mut segs);
        }
        for (piece, owner) in pieces {
            self.add(piece, owner);
        }
    }

    /// Adds a piece (a placed label, its leader) tagged `owner`.
    pub fn add(&mut self, piece: Piece, owner: usize) {
        let id = u32::try_from(self.pieces.len()).expect("fewer than 2³² pieces on a sheet");
        self.pieces.push((piece, owner));
        let b = bounds(&piece);
        self.extent = Some(self.extent.map_or(b, |e| e.union(b)));
        match piece {
            Piece::Segment(a, b) => self.strokes.insert_segment(a, b, Stroke { id, a, b }),
            Piece::TextBox(_) | Piece::Disc(..) | Piece::Band(_) | Piece::Statement(..) | Piece::Index(..) => {
                self.boxes.insert_box(b, id)
            }
        }
    }

    /// The pieces that may touch `r` (a superset: callers test them), with their owners, each
    /// once, in the order they were added.
    pub fn near(&self, r: Rect) -> impl Iterator<Item = &(Piece, usize)> {
        let (mut ids, boxes) = (self.strokes.in_box(r), self.boxes.in_box(r));
        // Two sorted lists of different pieces.
        if !boxes.is_empty() {
            ids.extend(boxes);
            ids.sort_unstable();
        }
        ids.into_iter().map(|id| &self.pieces[id as usize])
    }

    /// Whether a segment meets the box `r`: what [`Obstacles::near`] would find, asked cell
    /// by cell without listing, sorting and deduplicating them (the layout measure's
    /// question for each text's letters).
    pub fn segment_meets(&self, r: Rect) -> bool {
        self.strokes.any_in_box(r, |s| segment_meets_rect(s.a, s.b, r))
    }

    /// How many segments cross the box `r`, and the area of text boxes it overlaps.
    pub fn hits(&self, r: Rect) -> (usize, f64) {
        let (mut strokes, mut area) = (0, 0.0);
        for (p, _) in self.near(r) {
            match *p {
                Piece::Segment(a, b) => strokes += usize::from(segment_meets_rect(a, b, r)),
                Piece::TextBox(t) | Piece::Band(t) => area += t.intersect(r).area().max(0.0),
                Piece::Statement(..) | Piece::Index(..) => {}
                Piece::Disc(c, rad) => strokes += usize::from(disc_meets_rect(c, rad, r)),
            }
        }
        (strokes, area)
    }

    /// How many drawn items (by their tags) have a segment meeting the box `r`: a curve
    /// flattened into many segments counts once.
    pub fn items_meeting(&self, r: Rect) -> usize {
        let mut owners: Vec<usize> = self
            .near(r)
            .filter_map(|&(p, owner)| matches!(p, Piece::Segment(a, b) if segment_meets_rect(a, b, r)).then_some(owner))
            .collect();
        owners.sort_unstable();
        owners.dedup();
        owners.len()
    }

    /// How many stroke segments the polyline `pts` crosses, segment by segment (an arc
    /// tried for a dimension, sampled).
    pub fn hits_polyline(&self, pts: &[Point]) -> usize {
        pts.windows(2).map(|w| self.hits_segment(w[0], w[1])).sum()
    }

    /// How many stroke segments the segment `a`–`b` crosses.
    pub fn hits_segment(&self, a: Point, b: Point) -> usize {
        // The few that cross, each once (a piece is listed in every cell it passes).
        let mut crossing = Vec::new();
        self.strokes.any_on_segment(a, b, |s| {
            if segments_cross(a, b, s.a, s.b) {
                crossing.push(s.id);
            }
            false
        });
        crossing.sort_unstable();
        crossing.dedup();
        crossing.len()
    }

    /// Whether nothing (no segment, no text box) meets the box `r`: [`Obstacles::hits`]
    /// stopping at the first piece.
    pub fn is_clear(&self, r: Rect) -> bool {
        self.clear_after(r, None)
    }

    /// [`Obstacles::is_clear`], first testing the segment that last met a box asked with the
    /// same `slot` (below [`SLOTS`]; a label's spots in one direction from its anchor, whose
    /// boxes one line mostly meets at distance after distance, while the spots asked in
    /// between, in other directions, meet other lines). The answer is the same.
    pub fn is_clear_in(&self, r: Rect, slot: usize) -> bool {
        self.clear_after(r, self.hints.slots.get(slot))
    }

    fn clear_after(&self, r: Rect, slot: Option<&AtomicU32>) -> bool {
        let meets = |p: &Piece| match *p {
            Piece::Segment(a, b) => segment_meets_rect(a, b, r),
            Piece::TextBox(t) | Piece::Band(t) => t.intersect(r).area() > 0.0,
            Piece::Statement(..) | Piece::Index(..) => false,
            Piece::Disc(c, rad) => disc_meets_rect(c, rad, r),
        };
        if slot.is_some_and(|s| self.hinted(s, |p, q| segment_meets_rect(p, q, r))) {
            return false;
        }
        if self.hinted(&self.hints.met, |p, q| segment_meets_rect(p, q, r)) {
            if let Some(s) = slot {
                s.store(self.hints.met.load(Relaxed), Relaxed);
            }
            return false;
        }
        let met = |s: Stroke| {
            segment_meets_rect(s.a, s.b, r)
                && slot.is_none_or(|h| self.hints.remember(h, s.id))
                && self.hints.remember(&self.hints.met, s.id)
        };
        !(self.strokes.any_in_box(r, met) || self.boxes.any_in_box(r, |id| meets(&self.pieces[id as usize].0)))
    }

    /// Whether the segment `a`–`b` crosses a stroke segment of an item that `of` picks (by
    /// its owner's index; pieces added with no item are never picked).
    pub fn segment_crosses_stroke_of(&self, a: Point, b: Point, of: impl Fn(usize) -> bool) -> bool {
        self.strokes.any_on_segment(a, b, |s| segments_cross(a, b, s.a, s.b) && of(self.pieces[s.id as usize].1))
    }

    /// Whether the segment `a`–`b` crosses any stroke segment.
    pub fn segment_crosses_stroke(&self, a: Point, b: Point) -> bool {
        self.crosses_after(a, b, None)
    }

    /// [`Obstacles::segment_crosses_stroke`], first testing the segment that last crossed
    /// one asked with the same `slot` (a label's leaders in one direction run along one
    /// ray, and the line one crosses the next mostly crosses too). The answer is the same.
    pub fn segment_crosses_stroke_in(&self, a: Point, b: Point, slot: usize) -> bool {
        self.crosses_after(a, b, self.hints.crossed_slots.get(slot))
    }

    fn crosses_after(&self, a: Point, b: Point, slot: Option<&AtomicU32>) -> bool {
        slot.is_some_and(|s| self.hinted(s, |p, q| segments_cross(a, b, p, q)))
            || self.hinted(&self.hints.crossed, |p, q| segments_cross(a, b, p, q))
                && slot.is_none_or(|s| self.hints.remember(s, self.hints.crossed.load(Relaxed)))
            || self.strokes.any_on_segment(a, b, |s| {
                segments_cross(a, b, s.a, s.b)
                    && slot.is_none_or(|h| self.hints.remember(h, s.id))
                    && self.hints.remember(&self.hints.crossed, s.id)
            })
    }

    /// Whether the segment `hint` names, if it names one, passes `test`.
    fn hinted(&self, hint: &AtomicU32, test: impl Fn(Point, Point) -> bool) -> bool {
        matches!(self.pieces.get(hint.load(Relaxed) as usize), Some(&(Piece::Segment(p, q), _)) if test(p, q))
    }

    /// Whether a stroke runs along the segment `a`–`b` over a stretch: nearly parallel to it
    /// (within about 6°) and within 0.6 mm of two of five points spread along it. A leader so
    /// drawn is lost in the line it follows.
    pub fn segment_runs_along_stroke(&self, a: Point, b: Point) -> bool {
        let u = b - a;
        let l = u.norm();
        if l <= 0.0 {
            return false;
        }
        let near = |s: Stroke| {
            let v = s.b - s.a;
            let lv = v.norm();
            let parallel = lv > 0.0 && (u.cross(v) / (l * lv)).abs() < ALONG_SIN;
            let close = |t: &&f64| {
                let p = a + u * **t;
                let k = ((p - s.a).dot(v) / (lv * lv)).clamp(0.0, 1.0);
                (p - (s.a + v * k)).norm() < ALONG_NEAR
            };
            parallel && [0.1, 0.3, 0.5, 0.7, 0.9].iter().filter(close).count() >= 2
        };
        self.strokes.any_on_segment(a, b, near)
    }

    /// Whether a level stroke runs along the box `r` (a label's letters) over or under it,
    /// within `gap` mm: within about 10° of the level and beside the box over
    /// 2 mm of its width or more (a third of a narrower one). Such a line reads as the label's over- or
    /// underline (a polygon's stub 0.7 mm over "G₃ = 4,415 N").
    /// A line through `own` (within 0.4 mm: the label's own line, a dimension line its
    /// value stands on) does not count.
    pub fn level_stroke_along(&self, r: Rect, gap: f64, own: Point) -> bool {
        let band = r.inflate(0.0, gap);
        let least = ALONG_TEXT_OVERLAP.min(r.width() / 3.0);
        let mine = Rect::from_center_size(own, (2.0 * OWN_LINE, 2.0 * OWN_LINE));
        self.strokes.any_in_box(band, |s| {
            let d = s.b - s.a;
            let level = d.y.abs() <= LEVEL_SLOPE * d.x.abs();
            let beside = s.a.x.max(s.b.x).min(r.x1) - s.a.x.min(s.b.x).max(r.x0);
            level && beside >= least && segment_meets_rect(s.a, s.b, band) && !segment_meets_rect(s.a, s.b, mine)
        })
    }

    /// Whether a text box (not a line) meeting the box `r` is one `blocks` accepts.
    pub fn text_box_meets(&self, r: Rect, blocks: impl Fn(Rect) -> bool) -> bool {
        self.boxes.any_in_box(
            r,
            |id| matches!(self.pieces[id as usize].0, Piece::TextBox(t) if t.intersect(r).area() > 0.0 && blocks(t)),
        )
    }

    /// Whether a statement's letters (with their height) meeting the box `r` are ones
    /// `blocks` accepts.
    pub fn statement_meets(&self, r: Rect, blocks: impl Fn(Rect, f64) -> bool) -> bool {
        self.boxes.any_in_box(
            r,
            |id| matches!(self.pieces[id as usize].0, Piece::Statement(s, h) if s.intersect(r).area() > 0.0 && blocks(s, h)),
        )
    }

    /// Whether the segment `a`–`b` crosses any text box.
    pub fn segment_crosses_text(&self, a: Point, b: Point) -> bool {
        let clear = |t: Rect| t.inflate(LEADER_CLEAR, LEADER_CLEAR);
        let meets =
            |id: u32| matches!(self.pieces[id as usize].0, Piece::TextBox(t) if segment_meets_rect(a, b, clear(t)));
        self.boxes.any_on_segment(a, b, meets)
    }

    /// Whether a number that reads as a taller letter's index ([`Piece::Index`]) meets `r`
    /// and `blocks` says it blocks (given its letters and their height).
    pub fn index_meets(&self, r: Rect, blocks: impl Fn(Rect, f64) -> bool) -> bool {
        self.boxes.any_in_box(
            r,
            |id| matches!(self.pieces[id as usize].0, Piece::Index(s, h) if s.intersect(r).area() > 0.0 && blocks(s, h)),
        )
    }
}

/// A stroke this near a leader's points, mm, and this near its direction (the sine of the
/// angle, about 6°), runs along it (`Obstacles::segment_runs_along_stroke`): the two
/// pens' half widths and a gap under 0.3 mm.
const ALONG_NEAR: f64 = 0.6;
const ALONG_SIN: f64 = 0.1;

/// A level line beside a label's box over this much of its width (or a third of it, when
/// narrower) runs along it, mm; level within this slope (about 10°).
const ALONG_TEXT_OVERLAP: f64 = 2.0;
const LEVEL_SLOPE: f64 = 0.18;
/// A line this near a label's anchor is its own, mm.
const OWN_LINE: f64 = 0.4;

/// A leader passes a text's letters' box at least this far off, mm: one grazing the letters
/// reads as a line through the label.
const LEADER_CLEAR: f64 = 0.4;

/// A piece's box in the index: a text's with the room a leader keeps from it, so that the
/// cells a leader passes through list every text it comes near.
fn bounds(p: &Piece) -> Rect {
    match *p {
        Piece::Segment(a, b) => Rect::from_points(a, b),
        Piece::TextBox(r) => r.inflate(LEADER_CLEAR, LEADER_CLEAR),
        Piece::Band(r) | Piece::Statement(r, _) | Piece::Index(r, _) => r,
        Piece::Disc(c, r) => Rect::from_center_size(c, (2.0 * r, 2.0 * r)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_meets_a_box_it_crosses_or_lies_in_and_misses_one_beside_it() {
        let r = Rect::new(0.0, 0.0, 2.0, 1.0);
        assert!(segment_meets_rect(Point::new(-1.0, 0.5), Point::new(3.0, 0.5), r), "through");
        assert!(segment_meets_rect(Point::new(0.5, 0.5), Point::new(1.0, 0.6), r), "inside");
        assert!(!segment_meets_rect(Point::new(-1.0, 2.0), Point::new(3.0, 1.5), r), "below");
        assert!(!segment_meets_rect(Point::new(-1.0, -0.5), Point::new(0.5, -2.0), r), "past the corner");
        assert!(segment_meets_rect(Point::new(-1.0, 1.5), Point::new(1.5, -1.0), r), "across the corner");
    }

    #[test]
    fn the_index_counts_crossing_strokes_and_overlapping_text() {
        use crate::drawing::scene::{Anchor, Item, Path, THIN, Text};
        let items = vec![
            Item::Path { path: Path::polyline(&[Point::new(0.0, 5.0), Point::new(50.0, 5.0)], false), pen: THIN },
            Item::Text(Text::new(Point::new(20.0, 20.0), "AB", 5.0, Anchor::Start)),
        ];
        let o = Obstacles::of_items(&items);
        assert_eq!(o.hits(Rect::new(10.0, 4.0, 12.0, 6.0)).0, 1);
        assert_eq!(o.hits(Rect::new(10.0, 6.0, 12.0, 8.0)), (0, 0.0));
        assert!(o.hits(Rect::new(20.0, 16.0, 21.0, 19.0)).1 > 0.0);
        assert!(o.segment_crosses_text(Point::new(19.0, 17.0), Point::new(30.0, 17.0)));
    }
}
