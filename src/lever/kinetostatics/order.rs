//! The crank's polygon in an order that does not cross itself. Its vector equation may
//! list the known forces in any order (their sum is the same), but the order draws the
//! polygon: G₁ + R₂₁ + P_m + R₀₁ = 0 of the offset crank-slider crossed R₂₁ with R₀₁, both
//! labelled at the crossing. The first order, from the course's, whose closed chain has no
//! two sides crossing is kept; where every order crosses, the course's.

use super::Applied;
use crate::num::math::segments_cross_strictly;
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
