//! The largest free room of a region: a rectangle on a grid of cells that nothing drawn
//! meets (each cell grown by 1 mm), nor the title block, found row by row by the histogram
//! method and scored by what the caller will draw in it. The specific sliding's diagram
//! takes the mesh's largest room, the rack generation the sheet's largest left after it.

use crate::drawing::frame;
use crate::drawing::obstacles::Obstacles;
use kurbo::Rect;

/// The best-scoring rectangle of `area` at least `min` (width, height) on the grid of
/// `cell` whose cells `obstacles` leave clear; `score` takes its width and height and never
/// falls as either grows (a run from one cell rightwards stops once no wider run at its
/// height, nor a lower one, could beat the best: the same rectangle as scanning them all,
/// found in a fraction of the time).
pub(super) fn largest(
    obstacles: &Obstacles,
    area: Rect,
    cell: f64,
    min: (f64, f64),
    score: impl Fn(f64, f64) -> f64,
) -> Option<Rect> {
    let (nx, ny) = ((area.width() / cell).floor() as usize, (area.height() / cell).floor() as usize);
    let clear = clear_cells(obstacles, (area, cell), (nx, ny));
    let mut heights = vec![0usize; nx];
    let mut best: Option<(f64, Rect)> = None;
    for j in 0..ny {
        for (i, h) in heights.iter_mut().enumerate() {
            *h = if clear[j * nx + i] { *h + 1 } else { 0 };
        }
        for i0 in 0..nx {
            let mut h = usize::MAX;
            let widest = (nx - i0) as f64 * cell;
            for (i1, &column) in heights.iter().enumerate().skip(i0) {
                if column < h {
                    h = column;
                    // Lower from here on, never wider than the row: past beating the best.
                    let hh = h as f64 * cell;
                    if h == 0 || hh < min.1 || best.is_some_and(|(b, _)| score(widest, hh) <= b) {
                        break;
                    }
                }
                let (w, hh) = ((i1 + 1 - i0) as f64 * cell, h as f64 * cell);
                if w < min.0 {
                    continue;
                }
                let s = score(w, hh);
                if best.is_none_or(|(b, _)| s > b) {
                    let y1 = area.y0 + (j + 1) as f64 * cell;
                    best =
                        Some((s, Rect::new(area.x0 + i0 as f64 * cell, y1 - hh, area.x0 + (i1 + 1) as f64 * cell, y1)));
                }
            }
        }
    }
    best.map(|(_, r)| r)
}

/// Cells a block of this many a side are asked about together first.
const BLOCK: usize = 8;

/// Whether `obstacles` leave each cell of the `nx` × `ny` grid of `cell` over `area` clear
/// (grown by 1 mm) and off the title block, row by row. A block of cells clear as a whole has every cell clear (a
/// box inside a clear box is clear), so the empty paper is asked a block at a time and
/// only the blocks something meets cell by cell.
fn clear_cells(obstacles: &Obstacles, (area, cell): (Rect, f64), (nx, ny): (usize, usize)) -> Vec<bool> {
    let col = |i: usize| area.x0 + i as f64 * cell;
    let row = |j: usize| area.y0 + j as f64 * cell;
    // A region may reach over the title block's column (the mesh of a pair alone does).
    let block = frame::title_block_rect().inflate(2.0, 2.0);
    let mut clear = vec![false; nx * ny];
    for bj in (0..ny).step_by(BLOCK) {
        for bi in (0..nx).step_by(BLOCK) {
            let (i1, j1) = ((bi + BLOCK).min(nx), (bj + BLOCK).min(ny));
            let whole = Rect::new(col(bi), row(bj), col(i1), row(j1)).inflate(1.0, 1.0);
            let all = obstacles.is_clear(whole);
            for j in bj..j1 {
                for i in bi..i1 {
                    let c = Rect::new(col(i), row(j), col(i) + cell, row(j) + cell).inflate(1.0, 1.0);
                    clear[j * nx + i] = c.intersect(block).area() <= 0.0 && (all || obstacles.is_clear(c));
                }
            }
        }
    }
    clear
}
