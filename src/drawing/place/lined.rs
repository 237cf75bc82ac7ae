//! A label just over or under a level line reads as over- or underlined: a spot clear of
//! such a line, a little further off, where one is free.

use super::NEAR_SPOTS;
use super::candidate::{Candidate, Verdict};
use super::spots::Spots;
use crate::drawing::obstacles::Obstacles;

/// `chosen`, or where a level line runs along it ([`Candidate::is_lined`]) the cheapest of
/// the label's first [`NEAR_SPOTS`] spots that `fits` with no such line, on a leader at most
/// [`LINED_DETOUR`] longer.
pub(super) fn unlined(
    s: &mut Spots,
    chosen: Candidate,
    fits: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    drawn: &Obstacles,
) -> Candidate {
    if !chosen.is_lined(drawn) {
        return chosen;
    }
    let longest = chosen.leader_length() + LINED_DETOUR;
    (0..)
        .map_while(|k| {
            s.near(k, NEAR_SPOTS).map(|(c, v)| (c.leader_length() <= longest && fits(c, v)).then(|| c.clone()))
        })
        .flatten()
        .find(|c| !c.is_lined(drawn))
        .unwrap_or(chosen)
}

/// How much longer a leader may grow to take its label off a level line, mm.
const LINED_DETOUR: f64 = 4.0;
