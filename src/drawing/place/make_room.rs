//! The repairs after the rounds ([`Labels::repair`]), the last of them here: a label the
//! rounds left without a clean spot (or on a leader across a vector, or across another
//! label's leader) takes a
//! spot near its anchor that only other labels block, and those labels move to clean spots
//! of their own. Putting the failed label first (the rounds) cannot do this
//! where the labels placed after it then fail in turn: a flat acceleration plan's n_BA,
//! boxed in by "d=s5", "b=n_DB", s2 and s4, hung on a leader through "d=s5" in every round.

use super::candidate::Candidate;
use super::crossings::crosses_walls;
use super::spots::Spots;
use super::{LABEL_GAP, Labels, Layers, NEAR_SPOTS, NUMBERS_RANK, crossings};
use crate::drawing::obstacles::{Obstacles, Piece};
use kurbo::Rect;

/// The most placed labels one failed label may move.
const MOST_MOVED: usize = 2;
/// How many of its spots a moved label looks through for a clean one: three times as many
/// as a failed label (the flat plan's "d=s5" found none among as many, one on an 8 mm
/// leader among these).
const MOVED_SPOTS: usize = 3 * NEAR_SPOTS;

impl Labels {
    /// The repairs after the rounds, on `best` (each label's bounds `own`): a label left
    /// without a clean spot, then one on a leader across a vector or a link, takes a spot
    /// near its point where the labels in its way can move ([`Labels::make_room`]); two
    /// labels whose leaders cross swap or turn a leader ([`Labels::untangle`]), and where
    /// they still cross one moves as well.
    pub(super) fn repair(&self, layers: Layers, spots: &mut [Spots], best: &mut [(Candidate, bool)], own: &[Rect]) {
        if best.iter().any(|p| !p.1) {
            let failed = |_: usize, (_, clean): &(Candidate, bool)| (!clean).then_some(0);
            self.make_room(layers, spots, best, failed, f64::INFINITY);
        }
        // A leader across a vector where the spots clear of it near its point were taken by
        // other labels (s₂ of a flat velocity plan, boxed in by «a» and «b=s₄»): those
        // labels moved, each to a spot near its own point. In a knot of thin lines (a
        // slider's positions on their guide) the new leader may cross as many thin lines.
        let thin_crossed = |c: &Candidate| c.crossings(layers.drawn);
        let across =
            |_: usize, (c, clean): &(Candidate, bool)| (*clean && layers.crosses_bold(c)).then(|| thin_crossed(c));
        self.make_room(layers, spots, best, across, crossings::NEAR);
        self.untangle(layers, own, best);
        // Two leaders still crossing, neither swapped nor turned to another corner: one
        // moves to a spot near its point, the labels in its way to spots of their own (over
        // the catalogue's Russian sheets 1, pairs of leaders crossing 249 → 193).
        let crossed: Vec<bool> =
            (0..best.len()).map(|i| (0..best.len()).any(|j| j != i && self.leaders_cross(best, i, j))).collect();
        if crossed.contains(&true) {
            let crossing = |i: usize, (c, clean): &(Candidate, bool)| (*clean && crossed[i]).then(|| thin_crossed(c));
            self.make_room(layers, spots, best, crossing, crossings::NEAR);
        }
    }

    /// What label `i` standing at `c` keeps the labels placed after it out of: its box
    /// (a position number's widened by [`LABEL_GAP`]: two numbers 0.5 mm apart read as
    /// one) and its leader.
    pub(super) fn pieces(&self, i: usize, c: &Candidate) -> impl Iterator<Item = Piece> {
        let gap = if self.requests[i].rank >= NUMBERS_RANK { LABEL_GAP } else { 0.0 };
        let leader = self.requests[i].drawn_leader(c).map(|(a, b)| Piece::Segment(a, b));
        // A statement keeps the labels placed after it off its line beside it.
        let statement = c.states_value.then_some(Piece::Statement(c.r, c.h));
        // A number kept off taller letters keeps a taller label placed after it off too.
        let index = c.apart_from_taller.then_some(Piece::Index(c.r, c.h));
        std::iter::once(Piece::TextBox(c.r.inflate(gap, 0.0))).chain(statement).chain(index).chain(leader)
    }

    /// The labels of `placed` that `keep` accepts, as obstacles.
    pub(super) fn obstacles_of(&self, placed: &[(Candidate, bool)], keep: impl Fn(usize) -> bool) -> Obstacles {
        let pieces = placed
            .iter()
            .enumerate()
            .filter(|&(j, _)| keep(j))
            .flat_map(|(j, (c, _))| self.pieces(j, c).map(move |p| (p, j)))
            .collect();
        Obstacles::of_pieces(pieces)
    }

    /// Gives each label of `placed` that `needs` a better spot (one without a clean spot,
    /// one on a leader across a vector) one near its anchor, its box free against the
    /// drawing and its leader across no vector and at most as many lines as `needs` says, where
    /// the labels blocking it (at most [`MOST_MOVED`], each clean) can move to clean spots of
    /// their own ([`MOVED_SPOTS`]) on leaders at most `reach` long (or no longer than they
    /// were); a label with no such spot stays where it is.
    pub(super) fn make_room(
        &self,
        layers: Layers,
        spots: &mut [Spots],
        placed: &mut [(Candidate, bool)],
        needs: impl Fn(usize, &(Candidate, bool)) -> Option<usize>,
        reach: f64,
    ) {
        // Each placed label as obstacles of its own, asked of every spot tried and made
        // again only when a move changes where labels stand.
        let each = |placed: &[(Candidate, bool)]| -> Vec<Obstacles> {
            (0..placed.len()).map(|j| self.obstacles_of(placed, |k| k == j)).collect()
        };
        let mut alone = each(placed);
        for i in 0..placed.len() {
            let Some(most_crossed) = needs(i, &placed[i]) else { continue };
            for k in 0.. {
                let Some((c, v)) = spots[i].near(k, NEAR_SPOTS) else { break };
                let clear = if most_crossed == 0 {
                    v.is_free(c, layers.drawn)
                } else {
                    v.box_is_free(c, layers.drawn)
                        && v.crossings(c, layers.drawn) <= most_crossed
                        && !layers.crosses_bold(c)
                };
                if !clear || !self.reads_as_own(i, c) || crosses_walls(&self.walls, c) {
                    continue;
                }
                let c = c.clone();
                let thin = most_crossed > 0;
                if let Some(moved) = self.moved_for(i, c, (layers, reach, thin), spots, (placed, &alone)) {
                    placed.clone_from_slice(&moved);
                    alone = each(placed);
                    break;
                }
            }
        }
    }

    /// `placed` (`alone`: each of its labels as obstacles) with label `i` at `c` (free
    /// against the drawing) and the clean labels blocking it moved to clean spots of their own; none where more than
    /// [`MOST_MOVED`] block it, a failed one does, or one finds no spot.
    fn moved_for(
        &self,
        i: usize,
        c: Candidate,
        (layers, reach, thin): (Layers, f64, bool),
        spots: &mut [Spots],
        (placed, alone): (&[(Candidate, bool)], &[Obstacles]),
    ) -> Option<Vec<(Candidate, bool)>> {
        let blocks = |j: usize| j != i && !c.is_free(&alone[j]);
        let blockers: Vec<usize> = (0..placed.len()).filter(|&j| blocks(j)).collect();
        if blockers.len() > MOST_MOVED || blockers.iter().any(|&j| !placed[j].1) {
            return None;
        }
        let mut trial = placed.to_vec();
        trial[i] = (c, true);
        for (n, &j) in blockers.iter().enumerate() {
            // Against every label but this blocker and those not yet moved.
            let others = self.obstacles_of(&trial, |k| k != j && !blockers[n..].contains(&k));
            let s = &mut spots[j];
            let reach = reach.max(placed[j].0.leader_length());
            let crossed = placed[j].0.crossings(layers.drawn);
            let spot = (0..)
                .map_while(|k| {
                    let (cand, v) = s.near(k, MOVED_SPOTS)?;
                    let clear = if thin {
                        v.box_is_free(cand, layers.drawn)
                            && v.crossings(cand, layers.drawn) <= crossed
                            && !layers.crosses_bold(cand)
                    } else {
                        v.is_free(cand, layers.drawn)
                    };
                    let fits = cand.leader_length() <= reach
                        && !crosses_walls(&self.walls, cand)
                        && clear
                        && cand.is_free(&others)
                        && self.reads_as_own(j, cand);
                    Some(fits.then(|| cand.clone()))
                })
                .flatten()
                .next()?;
            trial[j] = (spot, true);
        }
        Some(trial)
    }
}
