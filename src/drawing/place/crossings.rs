//! A label whose first clean spot hangs on a long leader (one running 100 mm down a channel
//! between two lines of a force polygon, crossing none): a spot much nearer whose leader
//! crosses a line or two reads better, and is taken where its distance and its crossings
//! weigh less than the long leader's distance.

use super::{Candidate, Spots, Verdict};
use crate::drawing::obstacles::Obstacles;
use crate::num::math::lines_cross;
use kurbo::Point;

/// A leader this long or longer, mm, is weighed against nearer spots across lines.
pub(super) const LONG: f64 = 20.0;
/// What each line a leader crosses costs, in distance steps (the steps of
/// [`super::DISTANCES`], each about a quarter further than the last): three steps, so a
/// leader crossing one line must be about half as long as a clean one to be taken.
pub(super) const PER_CROSSING: f64 = 3.0;

/// Of a label's spots cheaper than `bound` that `fits` (a free box; the leader may cross
/// lines) and whose leader is seen (runs along no line of `drawn`), the one whose cost plus
/// [`PER_CROSSING`] for each line of `drawn` and leader of `placed` it crosses, and once
/// more where it crosses a `bold` line, is least, if that is under `bound`.
pub(super) fn nearer_across(
    s: &mut Spots,
    fits: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    (drawn, placed): (&Obstacles, &Obstacles),
    bold: &dyn Fn(&Candidate) -> bool,
    bound: f64,
) -> Option<Candidate> {
    let mut best: Option<(f64, Candidate)> = None;
    for k in 0.. {
        let Some((c, v)) = s.get(k) else { break };
        // Spots come cheapest first, and crossings only add.
        if c.cost >= best.as_ref().map_or(bound, |b| b.0) {
            break;
        }
        if !fits(c, v) || !v.leader_seen(c, drawn) {
            continue;
        }
        let crossed = v.crossings(c, drawn) + c.crossings(placed);
        let score = c.cost + PER_CROSSING * crossed as f64;
        // The bold test is dearer than the count: asked only of a spot that could still win.
        let score = if score < best.as_ref().map_or(bound, |b| b.0) && bold(c) { score + PER_CROSSING } else { score };
        if score < best.as_ref().map_or(bound, |b| b.0) {
            best = Some((score, c.clone()));
        }
    }
    best.map(|b| b.1)
}

/// `c`, or where its leader crosses a leader of `placed` (or `crosses_wall`: a wall, a
/// bold line), the cheapest spot that `fits` whose leader crosses neither and is seen (runs
/// along no line of `drawn`), if it costs at most `steps` more ([`PER_CROSSING`] for a
/// leader or a wall) and its leader is at most `near` long ([`NEAR`]).
pub(super) fn off_leaders(
    s: &mut Spots,
    fits: &dyn Fn(&Candidate, &mut Verdict) -> bool,
    (drawn, placed): (&Obstacles, &Obstacles),
    Detour { crosses_wall, steps, near }: Detour,
    c: Candidate,
) -> Candidate {
    let crosses = |c: &Candidate| crosses_wall(c) || c.leader.is_some_and(|(a, b)| placed.segment_crosses_stroke(a, b));
    if !crosses(&c) {
        return c;
    }
    let bound = c.cost + steps;
    for k in 0.. {
        let Some((o, v)) = s.get(k) else { break };
        if o.cost > bound {
            break;
        }
        if o.leader_length() <= near && fits(o, v) && v.leader_seen(o, drawn) && !crosses(o) {
            return o.clone();
        }
    }
    c
}

/// How far [`off_leaders`] may move a label: what its leader must not cross besides other
/// leaders, how many distance steps further and how long a leader at most, mm.
pub(super) struct Detour<'a> {
    pub(super) crosses_wall: &'a dyn Fn(&Candidate) -> bool,
    pub(super) steps: f64,
    pub(super) near: f64,
}

/// How much further a spot off a bold line may be than one across it, in distance steps,
/// and how long its leader, mm: a leader across a plan's vector reads as cutting it, worse
/// than one across another label's leader.
pub(super) const OFF_BOLD: (f64, f64) = (2.0 * PER_CROSSING, 2.0 * NEAR);

/// The longest leader a label moved off another's leader may hang on, mm: moved further, it
/// took spots the labels after it needed (a crank's number went 58 mm off, a slider's «11»
/// 100 mm up its guide).
pub(super) const NEAR: f64 = 8.0;

/// Whether `c`'s leader, if any, crosses one of `walls` ([`super::Labels::keep_leaders_off`]).
pub(super) fn crosses_walls(walls: &[(Point, Point)], c: &Candidate) -> bool {
    c.leader.is_some_and(|l| walls.iter().any(|&w| lines_cross(l, w)))
}
