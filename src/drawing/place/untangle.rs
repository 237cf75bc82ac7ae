//! Two labels whose leaders cross read as each other's (a rocker's ω₃ and ε₃ over its
//! pivot, each hung across the other's leader): where the labels swap spots — each box
//! centred where the other's was — their leaders no longer cross (two crossing segments
//! with their ends exchanged never do), and they are swapped where both stand as clear as
//! before. First, though, a short leader that meets its label at a corner may go to the
//! side's other corner instead, where that one crosses nothing (a slider's «4» and «8»).

use super::candidate::{Candidate, Verdict};
use super::crossings::crosses_walls;
use super::spots::leader_ends;
use super::{LEADER_FROM, Labels, Layers};
use crate::num::math::{Norm, lines_cross, rect_inside};
use kurbo::{Point, Rect};

/// Passes over the placement: a swap may leave another pair crossing.
const ROUNDS: usize = 3;

impl Labels {
    /// Swaps the spots of two placed labels whose leaders cross, where both then stand
    /// clear (see [`Labels::swapped`]), each inside its bounds `own`.
    pub(super) fn untangle(&self, layers: Layers, own: &[Rect], placed: &mut [(Candidate, bool)]) {
        for _ in 0..ROUNDS {
            let mut swapped = false;
            for i in 0..placed.len() {
                for j in i + 1..placed.len() {
                    if !self.leaders_cross(placed, i, j) {
                        continue;
                    }
                    if let Some(c) = self.rerouted(layers, placed, i).or_else(|| self.rerouted(layers, placed, j)) {
                        let k = if c.anchor == placed[i].0.anchor && c.r == placed[i].0.r { i } else { j };
                        placed[k].0 = c;
                        swapped = true;
                        continue;
                    }
                    let inside = |k: usize, c: &Candidate| rect_inside(own[k], c.r);
                    let moved = self.swapped(layers, placed, i, j);
                    if let Some((a, b)) = moved.filter(|(a, b)| inside(i, a) && inside(j, b)) {
                        (placed[i].0, placed[j].0) = (a, b);
                        swapped = true;
                    }
                }
            }
            if !swapped {
                break;
            }
        }
    }

    pub(super) fn leaders_cross(&self, placed: &[(Candidate, bool)], i: usize, j: usize) -> bool {
        let drawn = |k: usize| self.requests[k].drawn_leader(&placed[k].0);
        match (drawn(i), drawn(j)) {
            (Some(l), Some(m)) => lines_cross(l, m),
            _ => false,
        }
    }

    /// Labels `i` and `j` at each other's spots, if both boxes are free of the drawing,
    /// of the other labels and of each other, their leaders seen, crossing no other label's
    /// leader, no wall and, together, no more lines than before; none where a label stands
    /// on lines broken for it or would read as naming another side.
    fn swapped(
        &self,
        layers: Layers,
        placed: &[(Candidate, bool)],
        i: usize,
        j: usize,
    ) -> Option<(Candidate, Candidate)> {
        let (ci, cj) = (&placed[i].0, &placed[j].0);
        if ci.breaks || cj.breaks {
            return None;
        }
        let (a, b) = (self.moved(i, ci, cj.r.center()), self.moved(j, cj, ci.r.center()));
        let drawn = layers.drawn;
        let crossings = |c: &Candidate| c.crossings(drawn);
        if crossings(&a) + crossings(&b) > crossings(ci) + crossings(cj) {
            return None;
        }
        let clear = |c: &Candidate| {
            let mut v = Verdict::default();
            v.box_is_free(c, drawn) && v.leader_seen(c, drawn) && !crosses_walls(&self.walls, c)
        };
        if !(clear(&a) && clear(&b) && self.reads_as_own(i, &a) && self.reads_as_own(j, &b)) {
            return None;
        }
        let mut others = self.obstacles_of(placed, |k| k != i && k != j);
        if !a.is_free(&others) {
            return None;
        }
        for piece in self.pieces(i, &a) {
            others.add(piece, i);
        }
        b.is_free(&others).then_some((a, b))
    }

    /// Label `k` where it stands with its leader to the other corner of its box's side
    /// ([`leader_ends`]), if that one crosses no other label's leader, is seen, crosses no
    /// wall, no vector or link it did not, and no more lines.
    fn rerouted(&self, layers: Layers, placed: &[(Candidate, bool)], k: usize) -> Option<Candidate> {
        let c = &placed[k].0;
        let (first, second) = leader_ends(c.anchor, c.r, self.requests[k].leader_gap());
        // Only a corner leader has another (most labels have none: nothing to index).
        let other = second.filter(|_| c.leader.is_some()).map(|o| if c.leader == Some(o) { first } else { o })?;
        let drawn = layers.drawn;
        let labels = self.obstacles_of(placed, |m| m != k);
        let a = Candidate { leader: Some(other), ..c.clone() };
        let fits = a.crossings(drawn) <= c.crossings(drawn)
            && Verdict::default().leader_seen(&a, drawn)
            && !crosses_walls(&self.walls, &a)
            && (layers.crosses_bold(c) || !layers.crosses_bold(&a))
            && a.is_free(&labels);
        fits.then_some(a)
    }

    /// Label `k`'s candidate `c` moved to have its box centred at `centre`, its leader
    /// drawn anew.
    fn moved(&self, k: usize, c: &Candidate, centre: Point) -> Candidate {
        let r = Rect::from_center_size(centre, c.r.size());
        let nearest = Point::new(c.anchor.x.clamp(r.x0, r.x1), c.anchor.y.clamp(r.y0, r.y1));
        let gap = self.requests[k].leader_gap();
        let leader = ((nearest - c.anchor).norm() >= LEADER_FROM).then(|| leader_ends(c.anchor, r, gap).0);
        Candidate { r, leader, ..c.clone() }
    }
}
