//! A uniform grid of square cells over paper mm, each cell listing the pieces that may meet
//! it: the obstacle index of [`super::obstacles`]. Why not an R-tree: the queries are
//! label-sized boxes and leaders on a bounded sheet, the pieces short flattened segments;
//! a grid answers them by visiting a few cells, without a tree walk or a bulk load
//! (measured: ARCHITECTURE.md, "Dependencies").
//!
//! A piece is listed in every cell it may touch (conservatively: a point of the piece lies
//! in the closed cell), so a query visiting every cell its own shape may touch sees every
//! piece that meets it. Beyond the grid's extent the border cells stand for the outside.

use kurbo::{Point, Rect};

/// Side of a cell, mm: about a label's height.
const CELL: f64 = 3.0;
/// At most this many cells; a larger extent gets larger cells.
const MAX_CELLS: f64 = 65_536.0;

/// The cells as singly linked lists in one array: no allocation per cell (a sheet's grid
/// has tens of thousands of cells, most of them empty).
#[derive(Debug, Clone)]
pub struct Grid {
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// Each cell's first entry in `entries`, or [`END`].
    heads: Vec<u32>,
    /// (piece, next entry of the same cell or [`END`]).
    entries: Vec<(u32, u32)>,
}

const END: u32 = u32::MAX;

impl Default for Grid {
    fn default() -> Grid {
        Grid::over(Rect::ZERO)
    }
}

impl Grid {
    /// An empty grid over `extent` (pieces outside it still go in, to the border cells).
    pub fn over(extent: Rect) -> Grid {
        let (w, h) = (extent.width().max(0.0), extent.height().max(0.0));
        let cell = if w.is_finite() && h.is_finite() { CELL.max((w * h / MAX_CELLS).sqrt()) } else { CELL };
        let count = |len: f64| ((len / cell).ceil() as usize).clamp(1, MAX_CELLS as usize);
        let (nx, ny) = (count(w), count(h));
        let origin = if extent.x0.is_finite() && extent.y0.is_finite() { extent.origin() } else { Point::ZERO };
        Grid { origin, cell, nx, ny, heads: vec![END; nx * ny], entries: Vec::new() }
    }

    /// The pieces listed in cell `c`.
    fn cell(&self, c: usize) -> impl Iterator<Item = u32> + '_ {
        let mut at = self.heads[c];
        std::iter::from_fn(move || {
            let (id, next) = *self.entries.get(at as usize)?;
            at = next;
            Some(id)
        })
    }

    /// Lists piece `id` in cell `c`.
    fn push(heads: &mut [u32], entries: &mut Vec<(u32, u32)>, c: usize, id: u32) {
        // An entry index past u32's range would be END: unreachable on a sheet (2³² entries).
        let at = entries.len() as u32;
        entries.push((id, heads[c]));
        heads[c] = at;
    }

    /// The column or row of grid coordinate `t` (cells from the origin), clamped to the grid.
    fn index(t: f64, n: usize) -> usize {
        // `as` saturates (and maps NaN to 0): never out of the grid.
        (t.floor().max(0.0) as usize).min(n - 1)
    }

    fn gx(&self, x: f64) -> f64 {
        (x - self.origin.x) / self.cell
    }

    fn gy(&self, y: f64) -> f64 {
        (y - self.origin.y) / self.cell
    }

    /// Calls `f` with every cell the box `r` may touch.
    fn box_cells(&self, r: Rect, mut f: impl FnMut(usize) -> bool) -> bool {
        let (i0, i1) = (Grid::index(self.gx(r.x0), self.nx), Grid::index(self.gx(r.x1), self.nx));
        let (j0, j1) = (Grid::index(self.gy(r.y0), self.ny), Grid::index(self.gy(r.y1), self.ny));
        for j in j0..=j1 {
            for i in i0..=i1 {
                if f(j * self.nx + i) {
                    return true;
                }
            }
        }
        false
    }

    /// Calls `f` with every cell the segment `a`–`b` may pass through, row by row: in each
    /// row, the columns between the segment's x where it enters and leaves the row's band.
    fn segment_cells(&self, a: Point, b: Point, mut f: impl FnMut(usize) -> bool) -> bool {
        let (ax, ay, bx, by) = (self.gx(a.x), self.gy(a.y), self.gx(b.x), self.gy(b.y));
        let (ylo, yhi) = (ay.min(by), ay.max(by));
        let (j0, j1) = (Grid::index(ylo, self.ny), Grid::index(yhi, self.ny));
        let x_at = |y: f64| if by == ay { ax } else { ax + (bx - ax) * ((y - ay) / (by - ay)) };
        for j in j0..=j1 {
            // The border rows stand for everything beyond them.
            let lo = if j == 0 { ylo } else { ylo.max(j as f64) };
            let hi = if j == self.ny - 1 { yhi } else { yhi.min(j as f64 + 1.0) };
            let (xa, xb) = if by == ay { (ax, bx) } else { (x_at(lo), x_at(hi)) };
            // A hair wider than the exact span: rounding must not drop the cell a point is in.
            let (i0, i1) = (Grid::index(xa.min(xb) - 1e-9, self.nx), Grid::index(xa.max(xb) + 1e-9, self.nx));
            for i in i0..=i1 {
                if f(j * self.nx + i) {
                    return true;
                }
            }
        }
        false
    }

    /// Lists piece `id` with the cells of the box `r`.
    pub fn insert_box(&mut self, r: Rect, id: u32) {
        let (mut heads, mut entries) = (std::mem::take(&mut self.heads), std::mem::take(&mut self.entries));
        self.box_cells(r, |c| {
            Grid::push(&mut heads, &mut entries, c, id);
            false
        });
        (self.heads, self.entries) = (heads, entries);
    }

    /// Lists piece `id` with the cells of the segment `a`–`b`.
    pub fn insert_segment(&mut self, a: Point, b: Point, id: u32) {
        let (mut heads, mut entries) = (std::mem::take(&mut self.heads), std::mem::take(&mut self.entries));
        self.segment_cells(a, b, |c| {
            Grid::push(&mut heads, &mut entries, c, id);
            false
        });
        (self.heads, self.entries) = (heads, entries);
    }

    /// Whether `test` holds for a piece listed in a cell of the box `r` (a piece may be
    /// tested more than once).
    pub fn any_in_box(&self, r: Rect, mut test: impl FnMut(u32) -> bool) -> bool {
        self.box_cells(r, |c| self.cell(c).any(&mut test))
    }

    /// Whether `test` holds for a piece listed in a cell of the segment `a`–`b`.
    pub fn any_on_segment(&self, a: Point, b: Point, mut test: impl FnMut(u32) -> bool) -> bool {
        self.segment_cells(a, b, |c| self.cell(c).any(&mut test))
    }

    /// Every piece listed in a cell of the box `r`, each once, in ascending order.
    pub fn in_box(&self, r: Rect) -> Vec<u32> {
        let mut out = Vec::new();
        self.box_cells(r, |c| {
            out.extend(self.cell(c));
            false
        });
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Every piece listed in a cell of the segment `a`–`b`, each once, in ascending order.
    pub fn on_segment(&self, a: Point, b: Point) -> Vec<u32> {
        let mut out = Vec::new();
        self.segment_cells(a, b, |c| {
            out.extend(self.cell(c));
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
