//! The layout measure's overlapping texts: which pairs of the sheet's text runs overlap,
//! found by a sweep along x.

use crate::num::tol;
use kurbo::Rect;

/// The pairs of runs `(i, j)`, `i < j`, of different texts whose boxes overlap (by more
/// than [`tol::TEXT_OVERLAP_AREA`]), in order: each run's with the later runs, those by
/// index. The runs come text by text, so `i`'s text is the earlier. Swept along x (a sheet's
/// few hundred runs overlap in x with a few each), not indexed.
pub(super) fn overlapping_runs(runs: &[(Rect, usize)]) -> Vec<(usize, usize)> {
    let mut by_x: Vec<usize> = (0..runs.len()).collect();
    by_x.sort_by(|&a, &b| runs[a].0.x0.total_cmp(&runs[b].0.x0));
    let mut pairs = Vec::new();
    for (n, &a) in by_x.iter().enumerate() {
        let ra = runs[a].0;
        // Every later run in x starting before `a` ends; one starting at its end or after
        // shares at most an edge with it.
        for &b in by_x[n + 1..].iter().take_while(|&&b| runs[b].0.x0 < ra.x1) {
            let (i, j) = (a.min(b), a.max(b));
            if runs[i].1 != runs[j].1 && runs[j].0.intersect(runs[i].0).area() > tol::TEXT_OVERLAP_AREA {
                pairs.push((i, j));
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The sweep finds what testing every pair of runs finds, in the same order: boxes
        /// on a coarse grid, so that many share edges or are equal.
        #[test]
        fn overlapping_runs_are_every_pair_that_overlaps(
            cells in proptest::collection::vec((0u8..12, 0u8..12, 1u8..5, 1u8..3, 0usize..6), 0..40)
        ) {
            let runs: Vec<(Rect, usize)> = cells
                .iter()
                .map(|&(x, y, w, h, k)| (Rect::new(f64::from(x), f64::from(y), f64::from(x + w), f64::from(y + h)), k))
                .collect();
            let mut every = Vec::new();
            for i in 0..runs.len() {
                for j in i + 1..runs.len() {
                    if runs[i].1 != runs[j].1 && runs[j].0.intersect(runs[i].0).area() > tol::TEXT_OVERLAP_AREA {
                        every.push((i, j));
                    }
                }
            }
            proptest::prop_assert_eq!(overlapping_runs(&runs), every);
        }
    }
}
