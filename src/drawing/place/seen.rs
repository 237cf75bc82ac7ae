//! A label's spot whose leader is seen, or that another preference accepts, looked for a
//! few spots past the first that fits.

use super::{Candidate, DIRECTIONS, Spots, Verdict};
use crate::drawing::obstacles::Obstacles;

/// The first of a label's spots that `fits` and that `prefer` accepts, looked for up to
/// `lookahead` spots past the first that fits; none where there is none.
pub(super) fn first_preferred(
    s: &mut Spots,
    fits: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    mut prefer: impl FnMut(&Candidate, &mut Verdict) -> bool,
    lookahead: usize,
) -> Option<Candidate> {
    let mut last = usize::MAX;
    for k in 0.. {
        if k > last {
            return None;
        }
        let (c, v) = s.get(k)?;
        if !fits(c, v) {
            continue;
        }
        if prefer(c, v) {
            return Some(c.clone());
        }
        last = last.min(k + lookahead);
    }
    None
}

/// A label's first spot that `fits` (free, or free but for thin lines its leader crosses)
/// whose leader, if any, runs along no line of the drawing, looked for up to
/// [`SEEN_LOOKAHEAD`] spots past the first that fits: a leader along a line is lost in it
/// and its label seems to name nothing (the compressors' crank centre "O" hung 30 mm down
/// its own centre line, the one way out of the fan of position lines a leader crossed no
/// line by). None where there is none: a leader crossing thin lines, seen, is tried before
/// one lost in a line.
pub(super) fn seen_spot(
    s: &mut Spots,
    fits: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    drawn: &Obstacles,
) -> Option<Candidate> {
    first_preferred(s, fits, |c, v| v.leader_seen(c, drawn), SEEN_LOOKAHEAD)
}

/// How many spots past its first that fits a label looks for one whose leader is seen: two
/// rings of directions.
const SEEN_LOOKAHEAD: usize = 2 * DIRECTIONS;
