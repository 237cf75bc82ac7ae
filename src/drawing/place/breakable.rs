//! A label far off on a long leader stands beside its point instead where only breakable
//! thin lines (the other positions of a position plan) cross the spot: they are
//! interrupted for it.

use super::candidate::Candidate;
use super::request::Request;
use super::spots::Spots;
use super::{CLEAR, NEAR_SPOTS};
use crate::drawing::obstacles::Obstacles;
use crate::drawing::scene::MOST_BROKEN;
use crate::num::math::Norm;

/// A label whose first free spot is on a leader this long or longer, mm, stands beside its
/// point on breakable lines if it can ([`on_breakable`]): a pivot's "O" hung 20–35 mm off
/// the fan of its crank's twelve positions.
pub(super) const LONG_LEADER: f64 = 8.0;

/// A label's cheapest spot near its own anchor (beside it, or on a leader shorter than
/// [`LONG_LEADER`] that crosses no text) that only breakable lines of the drawing cross, at
/// most [`MOST_BROKEN`] of them, clear of everything else (`hard`) and of the labels
/// `placed`; it is marked to interrupt them.
pub(super) fn on_breakable(
    s: &mut Spots,
    req: &Request,
    (drawn, hard): (&Obstacles, &Obstacles),
    placed: &Obstacles,
) -> Option<Candidate> {
    (0..).map_while(|k| s.near(k, NEAR_SPOTS).map(|(c, _)| c.clone())).find_map(|mut c| {
        let r = c.r.inflate(CLEAR, CLEAR);
        let short = c.leader.is_none_or(|(a, b)| (b - a).norm() < LONG_LEADER && !hard.segment_crosses_text(a, b));
        let fits = short
            && c.anchor == req.anchor
            && hard.is_clear(r)
            && c.stands_apart(hard)
            && c.box_is_free(placed)
            && drawn.items_meeting(r) <= MOST_BROKEN;
        c.breaks = true;
        fits.then_some(c)
    })
}
