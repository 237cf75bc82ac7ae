//! Bottom-left packing of the force cells under a skyline: each cell goes where its top is
//! highest (then leftmost), so a short cell beside a tall one leaves no row-high hole under
//! it — the rows it replaced left a band empty under the tables beside a tall lever.

use crate::num::tol;
use kurbo::{Point, Rect};

/// A body's skyline: the x where each step starts and the y its cells reach down to (the
/// next cell's top), left to right, the last step running to the body's right edge.
struct Skyline {
    steps: Vec<(f64, f64)>,
    body: Rect,
}

impl Skyline {
    fn new(body: Rect) -> Skyline {
        Skyline { steps: vec![(body.x0, body.y0)], body }
    }

    /// The highest top, then leftmost, of a `w` × `h` cell set on a step's left end, if
    /// any fits the body.
    fn spot(&self, w: f64, h: f64) -> Option<Point> {
        let mut best: Option<Point> = None;
        for (i, &(x, _)) in self.steps.iter().enumerate() {
            if x + w > self.body.x1 + tol::PAPER {
                break;
            }
            // The lowest reach of the steps the cell spans.
            let y =
                self.steps[i..].iter().take_while(|s| s.0 < x + w - tol::PAPER).map(|s| s.1).fold(f64::MIN, f64::max);
            let fits = y + h <= self.body.y1 + tol::PAPER;
            if fits && best.is_none_or(|b| y < b.y - tol::PAPER) {
                best = Some(Point::new(x, y));
            }
        }
        best
    }

    /// Raises the skyline over `[x, x + w + gap)` to `bottom`.
    fn cover(&mut self, x: f64, w: f64, bottom: f64) {
        let x1 = (x + w).min(self.body.x1);
        // The reach just right of the covered span continues past it.
        let after = self.steps.iter().rev().find(|s| s.0 <= x1 + tol::PAPER).map_or(self.body.y0, |s| s.1);
        let mut steps: Vec<(f64, f64)> = self.steps.iter().copied().filter(|s| s.0 < x - tol::PAPER).collect();
        steps.push((x, bottom));
        if x1 < self.body.x1 - tol::PAPER {
            steps.push((x1, after));
            steps.extend(self.steps.iter().copied().filter(|s| s.0 > x1 + tol::PAPER));
        }
        self.steps = steps;
    }
}

/// Places cells (`w`, `h`) bottom-left into the bodies, each into the first body it fits
/// (the last cell into body `last_first` first, if any), `gap` apart. Returns each cell's body and corner, and whether all fit (a cell that fits
/// nowhere overflows the first body, under its lowest step).
pub(super) fn pack(
    cells: &[(f64, f64)],
    bodies: &[Rect],
    gap: f64,
    last_first: Option<usize>,
) -> (Vec<(usize, Point)>, bool) {
    let mut skylines: Vec<Skyline> = bodies.iter().map(|&b| Skyline::new(b)).collect();
    let mut out = Vec::new();
    let mut all = true;
    for (k, &(w, h)) in cells.iter().enumerate() {
        let first = last_first.filter(|_| k + 1 == cells.len());
        let order = first.into_iter().chain((0..skylines.len()).filter(|&i| Some(i) != first));
        let found = order.into_iter().find_map(|i| skylines[i].spot(w, h).map(|p| (i, p)));
        let (i, at) = found.unwrap_or_else(|| {
            all = false;
            let s = &skylines[0];
            (0, Point::new(s.body.x0, s.steps.iter().map(|s| s.1).fold(s.body.y0, f64::max)))
        });
        skylines[i].cover(at.x, w + gap, at.y + h + gap);
        out.push((i, at));
    }
    (out, all)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_cell_goes_under_its_short_neighbour_not_below_the_tall_one() {
        let body = Rect::new(0.0, 0.0, 100.0, 100.0);
        // A tall cell on the left, a short one on the right, then one as wide as the short.
        let (at, all) = pack(&[(50.0, 90.0), (40.0, 20.0), (40.0, 30.0)], &[body], 5.0, None);
        assert!(all);
        assert_eq!(at[0].1, Point::new(0.0, 0.0));
        assert_eq!(at[1].1, Point::new(55.0, 0.0));
        assert_eq!(at[2].1, Point::new(55.0, 25.0));
    }

    #[test]
    fn a_cell_spanning_steps_sits_below_the_lowest() {
        let body = Rect::new(0.0, 0.0, 100.0, 100.0);
        let (at, all) = pack(&[(30.0, 40.0), (30.0, 10.0), (80.0, 20.0)], &[body], 0.0, None);
        assert!(all);
        assert_eq!(at[2].1, Point::new(0.0, 40.0));
    }

    #[test]
    fn what_fits_nowhere_overflows_the_first_body_and_says_so() {
        let bodies = [Rect::new(0.0, 0.0, 50.0, 50.0), Rect::new(60.0, 0.0, 90.0, 30.0)];
        let (at, all) = pack(&[(40.0, 40.0), (20.0, 20.0), (45.0, 45.0)], &bodies, 2.0, None);
        assert!(!all);
        assert_eq!(at[1].0, 1);
        assert_eq!(at[2], (0, Point::new(0.0, 42.0)));
    }

    #[test]
    fn the_last_cell_tries_the_body_it_prefers_first() {
        let bodies = [Rect::new(0.0, 0.0, 100.0, 100.0), Rect::new(200.0, 0.0, 260.0, 100.0)];
        let (at, all) = pack(&[(40.0, 40.0), (50.0, 30.0)], &bodies, 2.0, Some(1));
        assert!(all);
        assert_eq!(at[0].0, 0, "the first cell keeps the bodies' order");
        assert_eq!(at[1], (1, Point::new(200.0, 0.0)));
        // Where it does not fit there, the bodies' order.
        let (at, _) = pack(&[(40.0, 40.0), (70.0, 30.0)], &bodies, 2.0, Some(1));
        assert_eq!(at[1].0, 0);
    }
}
