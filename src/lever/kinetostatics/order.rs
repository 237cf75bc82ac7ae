//! The crank's polygon in an order that does not cross itself. Its vector equation may
//! list the known forces in any order (their sum is the same), but the order draws the
//! polygon: G₁ + R₂₁ + P_m + R₀₁ = 0 of the offset crank-slider crossed R₂₁ with R₀₁, both
//! labelled at the crossing. The first order, from the course's, whose closed chain has no
//! two sides crossing is kept; where every order crosses, the course's. A group's polygon
//! reorders each link's known forces likewise ([`unfolded`]).

use super::{Applied, Kind};
use crate::num::math::{self, Norm, segments_cross_strictly};
use kurbo::Vec2;

/// `known` reordered so that the chain `known`, then `closing` (the balancing force and the
/// frame's reaction), draws a polygon without crossing sides, where one exists.
pub(super) fn uncrossed(known: Vec<Applied>, closing: &[Applied]) -> Vec<Applied> {
    let mut order: Vec<usize> = (0..known.len()).collect();
    loop {
        let forces = order.iter().map(|&i| known[i].force).chain(closing.iter().map(|a| a.force));
        if !crosses(&chain(forces)) {
            return order.iter().map(|&i| known[i]).collect();
        }
        if !next_permutation(&mut order) {
            return known;
        }
    }
}

/// A group's polygon `terms` with each link's own loads (G and P_i; `blocks`: where each
/// link's known forces start in `terms`, and how many) reordered among their places, so that
/// no side runs back over the side before it and no two sides cross, where some order does
/// that: the course's order where it has no such fault, else the first order with the
/// fewest. The worked example's II(2,3) drew P_i3 and then R^t03 back along it, their two
/// arrows one over the other; its equation may list G₃ and P_i3 either way. A reordering
/// within a link keeps the vertex where the links' forces meet, so the inner reaction and
/// the reactions at the ends are drawn as before.
pub(super) fn unfolded(terms: Vec<Applied>, blocks: [(usize, usize); 2]) -> Vec<Applied> {
    // Each link's own loads' places in `terms`, in the course's order, and the orders of
    // those places to try (the course's first).
    let places = blocks.map(|(start, len)| -> Vec<usize> {
        (start..start + len).filter(|&k| matches!(terms[k].kind, Kind::Weight | Kind::Inertia)).collect()
    });
    let orders = |places: &[usize]| -> Vec<Vec<usize>> {
        let mut p = places.to_vec();
        let mut all = vec![p.clone()];
        while places.len() <= PERMUTED_MOST && next_permutation(&mut p) {
            all.push(p.clone());
        }
        all
    };
    let (first, second) = (orders(&places[0]), orders(&places[1]));
    let arranged = |a: &[usize], b: &[usize]| -> Vec<Applied> {
        let mut out = terms.clone();
        for (&slot, &from) in places[0].iter().zip(a).chain(places[1].iter().zip(b)) {
            out[slot] = terms[from];
        }
        out
    };
    let mut best: Option<(usize, Vec<Applied>)> = None;
    for a in &first {
        for b in &second {
            let candidate = arranged(a, b);
            let count = faults(&chain(candidate.iter().map(|t| t.force)));
            if best.as_ref().is_none_or(|(least, _)| count < *least) {
                best = Some((count, candidate));
            }
            if count == 0 {
                return best.map(|(_, t)| t).expect("just set");
            }
        }
    }
    best.map_or(terms, |(_, t)| t)
}

/// A link's own loads are reordered when there are at most this many (120 orders).
const PERMUTED_MOST: usize = 5;

/// A side runs back over the one before it when it turns back within this angle of it:
/// the two arrows' lines less than a line's width apart along the shorter one.
const FOLD_DEG: f64 = 12.0;

/// The closed chain `pts`'s faults: sides running back over the (non-vanishing) side before
/// them, and pairs of sides that cross.
fn faults(pts: &[Vec2]) -> usize {
    let n = pts.len() - 1;
    let sides: Vec<Vec2> = (0..n).map(|k| pts[k + 1] - pts[k]).filter(|v| v.hypot2() > 0.0).collect();
    let cos_fold = math::cos(FOLD_DEG.to_radians());
    let folds = (0..sides.len())
        .filter(|&k| {
            let (a, b) = (sides[k], sides[(k + 1) % sides.len()]);
            sides.len() > 1 && -a.dot(b) > cos_fold * a.norm() * b.norm()
        })
        .count();
    folds + usize::from(crosses(pts))
}

/// The vertices of the chain of `forces` laid head to tail from the origin.
fn chain(forces: impl Iterator<Item = Vec2>) -> Vec<Vec2> {
    let mut at = Vec2::ZERO;
    let mut pts = vec![at];
    for f in forces {
        at += f;
        pts.push(at);
    }
    pts
}

/// Whether two sides of the closed chain `pts` that share no vertex cross each other
/// (strictly: sides meeting end to end, or lying along one line, do not count).
fn crosses(pts: &[Vec2]) -> bool {
    let n = pts.len() - 1;
    let side = |k: usize| (pts[k], pts[k + 1]);
    (0..n).any(|i| {
        (i + 2..n).filter(|&j| !(i == 0 && j == n - 1)).any(|j| {
            let ((a, b), (c, d)) = (side(i), side(j));
            segments_cross_strictly(a, b, c, d)
        })
    })
}

/// The next permutation of `p` in lexicographic order; false after the last.
fn next_permutation(p: &mut [usize]) -> bool {
    let Some(i) = (1..p.len()).rev().find(|&i| p[i - 1] < p[i]) else {
        return false;
    };
    let j = (i..p.len()).rev().find(|&j| p[j] > p[i - 1]).expect("p[i] is larger");
    p.swap(i - 1, j);
    p[i..].reverse();
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lever::kinetostatics::Kind;

    fn force(x: f64, y: f64) -> Applied {
        Applied { on: 1, kind: Kind::Weight, at: Vec2::ZERO, point: None, force: Vec2::new(x, y) }
    }

    #[test]
    fn a_crossed_chain_is_reordered_and_an_uncrossed_one_kept() {
        // (0,0) → (0,−1) → (−4,3) → (−4,−2) → back: the second side crosses the last.
        let known = vec![force(0.0, -1.0), force(-4.0, 4.0)];
        let closing = [force(0.0, -5.0), force(4.0, 2.0)];
        let pts = chain(known.iter().chain(&closing).map(|a| a.force));
        assert!(crosses(&pts));
        let out = uncrossed(known.clone(), &closing);
        assert_eq!(out[0].force, known[1].force);
        assert!(!crosses(&chain(out.iter().chain(&closing).map(|a| a.force))));
        // A square stays as it is.
        let square = vec![force(1.0, 0.0), force(0.0, 1.0)];
        let rest = [force(-1.0, 0.0), force(0.0, -1.0)];
        assert_eq!(uncrossed(square.clone(), &rest), square);
    }

    #[test]
    fn permutations_run_through_every_order_once() {
        let mut p = vec![0, 1, 2];
        let mut seen = vec![p.clone()];
        while next_permutation(&mut p) {
            seen.push(p.clone());
        }
        assert_eq!(seen.len(), 6);
        assert_eq!(seen.last(), Some(&vec![2, 1, 0]));
    }
}
