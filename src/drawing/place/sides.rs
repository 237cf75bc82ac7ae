//! A force polygon's side names: a spot reads as naming its own side when it is nearer to
//! it than to any other side named in the same batch.

use super::{Candidate, DIRECTIONS, Labels, Spots, Verdict, first_preferred};
use kurbo::Point;

impl Labels {
    /// Whether spot `c` of label `i` reads as its own: any spot of a label that names no
    /// side, a side's name's spot where it reads as that side's (see [`unambiguous`]).
    pub(super) fn reads_as_own(&self, i: usize, c: &Candidate) -> bool {
        self.requests[i].side.is_none_or(|own| unambiguous(c, own, self.other_sides(i)))
    }

    /// The sides named by the labels other than `i`.
    fn other_sides(&self, i: usize) -> impl Iterator<Item = (Point, Point)> + '_ {
        self.requests.iter().enumerate().filter(move |&(j, _)| j != i).filter_map(|(_, r)| r.side)
    }

    /// For a side's name, its first free spot that reads as naming that side (see
    /// [`unambiguous`]), looked for up to [`AMBIGUITY_LOOKAHEAD`] spots past its first free
    /// one; none for other labels, or when there is none.
    pub(super) fn unambiguous_spot(
        &self,
        i: usize,
        s: &mut Spots,
        free: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    ) -> Option<Candidate> {
        let own = self.requests[i].side?;
        self.other_sides(i).next()?;
        first_preferred(s, free, |c, _| unambiguous(c, own, self.other_sides(i)), AMBIGUITY_LOOKAHEAD)
    }
}

/// How many spots past its first free one a side's name looks for one that is not nearer
/// another side: two rings of directions.
const AMBIGUITY_LOOKAHEAD: usize = 2 * DIRECTIONS;

/// A side's name reads as that side's when its box is nearer to it than to any other named
/// side by [`NEARER_BY`] (a name on a leader is read along the leader).
fn unambiguous(c: &Candidate, own: (Point, Point), mut others: impl Iterator<Item = (Point, Point)>) -> bool {
    if c.leader.is_some() {
        return true;
    }
    let d_own = crate::drawing::obstacles::rect_segment_distance(c.r, own);
    others.all(|o| crate::drawing::obstacles::rect_segment_distance(c.r, o) >= d_own + NEARER_BY)
}

/// How much nearer its own side than any other a side's name stands, mm.
pub(super) const NEARER_BY: f64 = 0.5;
