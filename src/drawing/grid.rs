//! A uniform grid of square cells over paper mm, each cell listing the pieces that may meet
//! it: the obstacle index of [`super::obstacles`]. Why not an R-tree: the queries are
//! label-sized boxes and leaders on a bounded sheet, the pieces short flattened segments;
//! a grid answers them by visiting a few cells, without a tree walk or a bulk load
//! (measured: ARCHITECTURE.md, "Dependencies").
//!
//! A piece is listed in every cell it may touch (conservatively: a point of the piece lies
//! in the closed cell), so a query visiting every cell its own shape may touch sees every
//! piece that meets it. Beyond the grid's extent the border cells stand for the outside.
//!
//! The pieces known at once ([`Grid::with`]: a drawing, for its labels) are listed cell
//! after cell in one array, a row's cells side by side: a query reads the cells it crosses
//! in a row as one slice, most of them empty (a leader crosses dozens of cells, a label's
//! box a dozen, to meet a few segments). Pieces added later (the labels placed, an arrow
//! turned clear) go to linked lists.

use kurbo::{Point, Rect};

/// Side of a cell, mm: about a label's height.
pub const CELL: f64 = 3.0;
/// At most this many cells; a larger extent gets larger cells.
const MAX_CELLS: f64 = 65_536.0;

/// The cells: the pieces loaded at once in one array, those inserted later as singly
/// linked lists in another; no allocation per cell (a sheet's grid has tens of thousands
/// of cells, most of them empty). Each listing is a `T`: a piece's id, or its id with what
/// its queries test (a segment's ends), read where the cell is.
#[derive(Debug, Clone)]
pub struct Grid<T = u32> {
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// Cell c's pieces loaded at once are `loaded[starts[c]..starts[c + 1]]` (no starts:
    /// none loaded).
    starts: Vec<u32>,
    loaded: Vec<T>,
    /// Each cell's first entry in `entries`, or [`END`] (empty until a piece is inserted).
    heads: Vec<u32>,
    /// (piece, next entry of the same cell or [`END`]).
    entries: Vec<(T, u32)>,
}

/// What a grid lists: a piece, known by its id.
pub trait Listed: Copy {
    fn id(self) -> u32;
}

impl Listed for u32 {
    fn id(self) -> u32 {
        self
    }
}

/// A piece's shape, for loading a grid at once.
#[derive(Debug, Clone, Copy)]
pub enum Shape {
    Segment(Point, Point),
    Box(Rect),
}

const END: u32 = u32::MAX;

impl<T: Listed> Default for Grid<T> {
    fn default() -> Grid<T> {
        Grid::over(Rect::ZERO)
    }
}

impl<T: Listed> Grid<T> {
    /// An empty grid over `extent` (pieces outside it still go in, to the border cells).
    pub fn over(extent: Rect) -> Grid<T> {
        Grid::over_cells(extent, CELL)
    }

    /// An empty grid over `extent` of cells `side` mm wide (or wider, for a large extent).
    pub fn over_cells(extent: Rect, side: f64) -> Grid<T> {
        let (w, h) = (extent.width().max(0.0), extent.height().max(0.0));
        let cell = if w.is_finite() && h.is_finite() { side.max((w * h / MAX_CELLS).sqrt()) } else { side };
        let count = |len: f64| ((len / cell).ceil() as usize).clamp(1, MAX_CELLS as usize);
        let (nx, ny) = (count(w), count(h));
        let origin = if extent.x0.is_finite() && extent.y0.is_finite() { extent.origin() } else { Point::ZERO };
        Grid { origin, cell, nx, ny, starts: Vec::new(), loaded: Vec::new(), heads: Vec::new(), entries: Vec::new() }
    }

    /// A grid over `extent` listing `shapes`, each with its piece's id: counted cell by
    /// cell, then laid out in one array.
    pub fn with(extent: Rect, shapes: &[(Shape, T)]) -> Grid<T> {
        Grid::with_cells(extent, CELL, shapes)
    }

    /// [`Grid::with`] of cells `side` mm wide (see [`Grid::over_cells`]): each shape's cells
    /// found once, then counted and laid out cell by cell.
    pub fn with_cells(extent: Rect, side: f64, shapes: &[(Shape, T)]) -> Grid<T> {
        let mut g = Grid::over_cells(extent, side);
        // Nothing to list (the text boxes' index has no segments): no cells to count, and a
        // query reads no loaded cell (`loaded_in`), as in a grid made empty.
        if shapes.is_empty() {
            return g;
        }
        // (cell, listing): a grid has at most MAX_CELLS cells.
        let mut listed: Vec<(u32, T)> = Vec::with_capacity(2 * shapes.len());
        for &(shape, item) in shapes {
            g.shape_cells(shape, |c| listed.push((c as u32, item)));
        }
        // Each cell's end, then (filled from it backwards) its start.
        let mut starts = vec![0u32; g.nx * g.ny + 1];
        for &(c, _) in &listed {
            starts[c as usize] += 1;
        }
        for c in 1..starts.len() {
            starts[c] += starts[c - 1];
        }
        let mut loaded: Vec<T> = listed.iter().map(|&(_, item)| item).collect();
        for &(c, item) in listed.iter().rev() {
            starts[c as usize] -= 1;
            loaded[starts[c as usize] as usize] = item;
        }
        (g.starts, g.loaded) = (starts, loaded);
        g
    }

    /// Calls `f` with every cell `shape` may touch.
    fn shape_cells(&self, shape: Shape, mut f: impl FnMut(usize)) {
        let mut row = |j: usize, i0: usize, i1: usize| {
            (i0..=i1).for_each(|i| f(j * self.nx + i));
            false
        };
        match shape {
            // Most segments (flattened curves) lie in one row or one column of cells: their
            // box's cells, a hair wider than the walk's spans, are listed without walking
            // the rows. Listing a piece in a cell more is safe: queries test what they read.
            Shape::Segment(a, b) => {
                const WIDER: f64 = 1e-6;
                let (xa, xb) = (self.gx(a.x), self.gx(b.x));
                let (i0, i1) = (Self::index(xa.min(xb) - WIDER, self.nx), Self::index(xa.max(xb) + WIDER, self.nx));
                let (ya, yb) = (self.gy(a.y), self.gy(b.y));
                let (j0, j1) = (Self::index(ya.min(yb), self.ny), Self::index(ya.max(yb), self.ny));
                if i0 == i1 || j0 == j1 {
                    (j0..=j1).for_each(|j| {
                        row(j, i0, i1);
                    });
                } else {
                    self.segment_rows(a, b, &mut row);
                }
            }
            Shape::Box(r) => {
                self.box_rows(r, &mut row);
            }
        }
    }

    /// The pieces loaded at once in the cells `i0..=i1` of row `j`, in cell order.
    fn loaded_in(&self, j: usize, i0: usize, i1: usize) -> &[T] {
        match (self.starts.get(j * self.nx + i0), self.starts.get(j * self.nx + i1 + 1)) {
            (Some(&from), Some(&to)) => &self.loaded[from as usize..to as usize],
            _ => &[],
        }
    }

    /// The pieces inserted later in cell `c`.
    fn inserted(&self, c: usize) -> impl Iterator<Item = T> + '_ {
        let mut at = self.heads.get(c).copied().unwrap_or(END);
        std::iter::from_fn(move || {
            let (id, next) = *self.entries.get(at as usize)?;
            at = next;
            Some(id)
        })
    }

    /// Every piece listed in the cells `i0..=i1` of row `j`.
    fn in_row(&self, j: usize, i0: usize, i1: usize) -> impl Iterator<Item = T> + '_ {
        let inserted = (!self.heads.is_empty()).then(|| (i0..=i1).flat_map(move |i| self.inserted(j * self.nx + i)));
        self.loaded_in(j, i0, i1).iter().copied().chain(inserted.into_iter().flatten())
    }

    /// Lists piece `id` in cell `c`.
    fn push(&mut self, c: usize, item: T) {
        if self.heads.is_empty() {
            self.heads = vec![END; self.nx * self.ny];
        }
        // An entry index past u32's range would be END: unreachable on a sheet (2³² entries).
        let at = self.entries.len() as u32;
        self.entries.push((item, self.heads[c]));
        self.heads[c] = at;
    }

    /// The column or row of grid coordinate `t` (cells from the origin), clamped to the grid.
    fn index(t: f64, n: usize) -> usize {
        // `as` truncates toward zero and saturates (NaN to 0): `t.floor().max(0.0) as usize`
        // without the call to `floor`, never out of the grid. Through i64, whose conversion
        // is one instruction and a fix-up where usize's takes a dozen (the grid's hottest
        // line): the same cell for every `t`, a negative one's clamped to 0.
        (t as i64).clamp(0, n as i64 - 1) as usize
    }

    fn gx(&self, x: f64) -> f64 {
        (x - self.origin.x) / self.cell
    }

    fn gy(&self, y: f64) -> f64 {
        (y - self.origin.y) / self.cell
    }

    /// Calls `f` with every row the box `r` may touch and the span of its columns there,
    /// until `f` says stop; returns whether it did.
    fn box_rows(&self, r: Rect, mut f: impl FnMut(usize, usize, usize) -> bool) -> bool {
        let (i0, i1) = (Self::index(self.gx(r.x0), self.nx), Self::index(self.gx(r.x1), self.nx));
        let (j0, j1) = (Self::index(self.gy(r.y0), self.ny), Self::index(self.gy(r.y1), self.ny));
        (j0..=j1).any(|j| f(j, i0, i1))
    }

    /// Calls `f` with every row the segment `a`–`b` may pass through, from `a`'s row, and the
    /// span of columns between the segment's x where it enters and leaves the row's band,
    /// until `f` says stop; returns whether it did.
    fn segment_rows(&self, a: Point, b: Point, mut f: impl FnMut(usize, usize, usize) -> bool) -> bool {
        let (ax, ay, bx, by) = (self.gx(a.x), self.gy(a.y), self.gx(b.x), self.gy(b.y));
        let (ylo, yhi) = (ay.min(by), ay.max(by));
        let (j0, j1) = (Self::index(ylo, self.ny), Self::index(yhi, self.ny));
        let x_at = |y: f64| if by == ay { ax } else { ax + (bx - ax) * ((y - ay) / (by - ay)) };
        (0..=j1 - j0).map(|step| if ay <= by { j0 + step } else { j1 - step }).any(|j| {
            // The border rows stand for everything beyond them.
            let lo = if j == 0 { ylo } else { ylo.max(j as f64) };
            let hi = if j == self.ny - 1 { yhi } else { yhi.min(j as f64 + 1.0) };
            let (xa, xb) = if by == ay { (ax, bx) } else { (x_at(lo), x_at(hi)) };
            // A hair wider than the exact span: rounding must not drop the cell a point is in.
            f(j, Self::index(xa.min(xb) - 1e-9, self.nx), Self::index(xa.max(xb) + 1e-9, self.nx))
        })
    }

    /// Lists piece `id` with the cells of the box `r`.
    pub fn insert_box(&mut self, r: Rect, item: T) {
        self.insert(Shape::Box(r), item);
    }

    /// Lists piece `id` with the cells of the segment `a`–`b`.
    pub fn insert_segment(&mut self, a: Point, b: Point, item: T) {
        self.insert(Shape::Segment(a, b), item);
    }

    fn insert(&mut self, shape: Shape, item: T) {
        let mut cells = Vec::new();
        self.shape_cells(shape, |c| cells.push(c));
        for c in cells {
            self.push(c, item);
        }
    }

    /// Whether `test` holds for a piece listed in a cell of the box `r` (a piece may be
    /// tested more than once).
    pub fn any_in_box(&self, r: Rect, mut test: impl FnMut(T) -> bool) -> bool {
        // The loaded slice on its own, then the inserted lists only where there are any: a
        // chain of both, asked for each of the label placer's boxes, cost more than the
        // tests it made.
        self.box_rows(r, |j, i0, i1| {
            self.loaded_in(j, i0, i1).iter().any(|&item| test(item))
                || (!self.heads.is_empty() && (i0..=i1).any(|i| self.inserted(j * self.nx + i).any(&mut test)))
        })
    }

    /// Whether `test` holds for a piece listed in a cell of the segment `a`–`b`, asked from
    /// `a`'s end (a leader's crossings are mostly near its anchor).
    pub fn any_on_segment(&self, a: Point, b: Point, mut test: impl FnMut(T) -> bool) -> bool {
        let backwards = a.x > b.x;
        self.segment_rows(a, b, |j, i0, i1| {
            let loaded = self.loaded_in(j, i0, i1);
            let found = if backwards {
                loaded.iter().rev().any(|&item| test(item))
            } else {
                loaded.iter().any(|&item| test(item))
            };
            found || (!self.heads.is_empty() && (i0..=i1).any(|i| self.inserted(j * self.nx + i).any(&mut test)))
        })
    }

    /// Every piece listed in a cell of the box `r`, each once, in ascending order.
    pub fn in_box(&self, r: Rect) -> Vec<u32> {
        let mut out = Vec::new();
        self.box_rows(r, |j, i0, i1| {
            out.extend(self.in_row(j, i0, i1).map(T::id));
            false
        });
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Every piece listed in a cell of the segment `a`–`b`, each once, in ascending order.
    pub fn on_segment(&self, a: Point, b: Point) -> Vec<u32> {
        let mut out = Vec::new();
        self.segment_rows(a, b, |j, i0, i1| {
            out.extend(self.in_row(j, i0, i1).map(T::id));
            false
        });
        out.sort_unstable();
        out.dedup();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::obstacles::{segment_meets_rect, segments_cross};
    use proptest::prelude::*;

    fn point() -> impl Strategy<Value = Point> {
        // Beyond the grid's extent too: the border cells must stand for the outside.
        (-30.0..130.0f64, -30.0..130.0f64).prop_map(|(x, y)| Point::new(x, y))
    }

    proptest! {
        /// The grid misses nothing: a brute-force search over every segment finds the same
        /// segments meeting a box, and crossing a segment, as the cells do.
        #[test]
        fn the_cells_find_every_segment_a_box_or_a_segment_meets(
            segs in prop::collection::vec((point(), point()), 1..40),
            corner in point(), size in (0.1..20.0f64, 0.1..20.0f64),
            (qa, qb) in (point(), point()),
        ) {
            let mut grid = Grid::over(Rect::new(0.0, 0.0, 100.0, 100.0));
            for (k, &(a, b)) in segs.iter().enumerate() {
                grid.insert_segment(a, b, k as u32);
            }
            let r = Rect::from_origin_size(corner, size);
            let brute: Vec<u32> =
                (0..segs.len() as u32).filter(|&k| segment_meets_rect(segs[k as usize].0, segs[k as usize].1, r)).collect();
            let found: Vec<u32> =
                grid.in_box(r).into_iter().filter(|&k| segment_meets_rect(segs[k as usize].0, segs[k as usize].1, r)).collect();
            prop_assert_eq!(found, brute);
            let brute: Vec<u32> = (0..segs.len() as u32)
                .filter(|&k| segments_cross(qa, qb, segs[k as usize].0, segs[k as usize].1))
                .collect();
            let found: Vec<u32> = grid
                .on_segment(qa, qb)
                .into_iter()
                .filter(|&k| segments_cross(qa, qb, segs[k as usize].0, segs[k as usize].1))
                .collect();
            prop_assert_eq!(found, brute);
        }

        /// A grid loaded at once, then added to, lists every piece in the cells a grid
        /// inserted piece by piece does, and its queries answer alike.
        #[test]
        fn a_grid_loaded_at_once_answers_as_one_inserted_piece_by_piece(
            segs in prop::collection::vec((point(), point()), 1..40),
            boxes in prop::collection::vec((point(), (0.1..20.0f64, 0.1..20.0f64)), 0..10),
            split in 0usize..50,
            corner in point(), size in (0.1..20.0f64, 0.1..20.0f64),
            (qa, qb) in (point(), point()),
        ) {
            let extent = Rect::new(0.0, 0.0, 100.0, 100.0);
            let shapes: Vec<(Shape, u32)> = segs
                .iter()
                .map(|&(a, b)| Shape::Segment(a, b))
                .chain(boxes.iter().map(|&(c, s)| Shape::Box(Rect::from_origin_size(c, s))))
                .zip(0..)
                .collect();
            let split = split.min(shapes.len());
            let mut one_by_one = Grid::over(extent);
            let mut at_once = Grid::with(extent, &shapes[..split]);
            for &(shape, id) in &shapes {
                one_by_one.insert(shape, id);
            }
            for &(shape, id) in &shapes[split..] {
                at_once.insert(shape, id);
            }
            let r = Rect::from_origin_size(corner, size);
            prop_assert_eq!(at_once.in_box(r), one_by_one.in_box(r));
            prop_assert_eq!(at_once.on_segment(qa, qb), one_by_one.on_segment(qa, qb));
            for k in 0..shapes.len() as u32 {
                prop_assert_eq!(at_once.any_in_box(r, |id| id == k), one_by_one.in_box(r).contains(&k));
                prop_assert_eq!(at_once.any_on_segment(qa, qb, |id| id == k), one_by_one.on_segment(qa, qb).contains(&k));
            }
        }
    }

    /// Axis-parallel segments on a cell's edge and a point-sized segment are found.
    #[test]
    fn segments_on_cell_edges_and_points_are_found() {
        let mut grid = Grid::over(Rect::new(0.0, 0.0, 30.0, 30.0));
        grid.insert_segment(Point::new(3.0, 3.0), Point::new(3.0, 12.0), 0);
        grid.insert_segment(Point::new(6.0, 9.0), Point::new(15.0, 9.0), 1);
        grid.insert_segment(Point::new(20.0, 20.0), Point::new(20.0, 20.0), 2);
        assert!(grid.in_box(Rect::new(2.0, 10.0, 3.0, 11.0)).contains(&0));
        assert!(grid.in_box(Rect::new(10.0, 9.0, 11.0, 9.5)).contains(&1));
        assert!(grid.in_box(Rect::new(20.0, 20.0, 20.0, 20.0)).contains(&2));
    }
}
