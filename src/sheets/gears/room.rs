//! The largest free room of a region: a rectangle on a grid of cells that nothing drawn
//! meets (each cell grown by 1 mm), nor the title block, found row by row by the histogram
//! method and scored by what the caller will draw in it. The specific sliding's diagram
//! takes the mesh's largest room, the rack generation the sheet's largest left after it.

use crate::drawing::frame;
use crate::drawing::obstacles::Obstacles;
use kurbo::Rect;

/// The best-scoring rectangle of `area` at least `min` (width, height) on the grid of
/// `cell` whose cells `obstacles` leave clear; `score` takes its width and height.
pub(super) fn largest(
    obstacles: &Obstacles,
    area: Rect,
    cell: f64,
    min: (f64, f64),
    score: impl Fn(f64, f64) -> f64,
) -> Option<Rect> {
    // A region may reach over the title block's column (the mesh of a pair alone does).
    let block = frame::title_block_rect().inflate(2.0, 2.0);
    let (nx, ny) = ((area.width() / cell).floor() as usize, (area.height() / cell).floor() as usize);
    let at = |i: usize, j: usize| {
        let (x, y) = (area.x0 + i as f64 * cell, area.y0 + j as f64 * cell);
        Rect::new(x, y, x + cell, y + cell)
    };
    let mut heights = vec![0usize; nx];
    let mut best: Option<(f64, Rect)> = None;
    for j in 0..ny {
        for (i, h) in heights.iter_mut().enumerate() {
            let c = at(i, j).inflate(1.0, 1.0);
            *h = if c.intersect(block).area() <= 0.0 && obstacles.is_clear(c) { *h + 1 } else { 0 };
        }
        for i0 in 0..nx {
            let mut h = usize::MAX;
            for (i1, &column) in heights.iter().enumerate().skip(i0) {
                h = h.min(column);
                if h == 0 {
                    break;
                }
                let (w, hh) = ((i1 + 1 - i0) as f64 * cell, h as f64 * cell);
                if w < min.0 || hh < min.1 {
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
