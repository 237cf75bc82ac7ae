//! A label's candidate box (with its leader) and what the drawing says of it: free, its
//! verdict remembered, or the least bad when none is free.

use super::{CLEAR, Request};
use crate::drawing::obstacles::Obstacles;
use crate::drawing::phrases;
use crate::num::math::Norm;
use kurbo::{Point, Rect};

/// A candidate's two tests against the fixed drawing, each asked at most once.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Verdict {
    box_free: Option<bool>,
    leader_clear: Option<bool>,
    leader_seen: Option<bool>,
    crossings: Option<usize>,
}

impl Verdict {
    /// [`Candidate::box_is_free`] against `drawn`, remembered.
    pub(super) fn box_is_free(&mut self, c: &Candidate, drawn: &Obstacles) -> bool {
        *self.box_free.get_or_insert_with(|| c.box_is_free(drawn))
    }

    /// Whether its leader, if any, is short ([`SEEN_SHORT`]) or runs along no stroke of
    /// `drawn` (where it would be lost in the line), remembered.
    pub(super) fn leader_seen(&mut self, c: &Candidate, drawn: &Obstacles) -> bool {
        *self.leader_seen.get_or_insert_with(|| {
            c.leader.is_none_or(|(a, b)| (b - a).norm() < SEEN_SHORT || !drawn.segment_runs_along_stroke(a, b))
        })
    }

    /// How many stroke segments of `drawn` its leader, if any, crosses, remembered.
    pub(super) fn crossings(&mut self, c: &Candidate, drawn: &Obstacles) -> usize {
        *self.crossings.get_or_insert_with(|| c.crossings(drawn))
    }

    /// [`Candidate::is_free`] against `drawn`, remembered.
    /// The leader is asked first: with its direction's hint a crossing is mostly found at
    /// the first segment tested, where the box's test reads its cells.
    pub(super) fn is_free(&mut self, c: &Candidate, drawn: &Obstacles) -> bool {
        *self.leader_clear.get_or_insert_with(|| {
            c.leader.is_none_or(|(a, b)| !drawn.segment_crosses_stroke_in(a, b, usize::from(c.dir)))
        }) && self.box_is_free(c, drawn)
    }
}

#[derive(Debug, Clone, Default)]
pub(super) struct Candidate {
    pub(super) r: Rect,
    /// The anchor it labels (a request may have several).
    pub(super) anchor: Point,
    pub(super) leader: Option<(Point, Point)>,
    pub(super) cost: f64,
    /// It stands on breakable thin lines, to be interrupted for it (see
    /// [`crate::drawing::scene::Group::breakable`]).
    pub(super) breaks: bool,
    /// Its direction from its anchor (an index of the turns tried): the box's test asks
    /// first the line that last met a box in that direction.
    pub(super) dir: u8,
    /// Its label states a value ([`Request::states_value`]).
    pub(super) states_value: bool,
    /// It keeps off taller texts on its line ([`Request::apart_from_taller`]).
    pub(super) apart_from_taller: bool,
    /// Its lettering height, mm.
    pub(super) h: f64,
    /// It is the box of the candidate before it with another leader (see
    /// [`super::spots`]).
    pub(super) again: bool,
    /// How many boxes of its label's spots come before its own (a box's further leaders
    /// share it): a window of near spots counts boxes, not leaders.
    pub(super) nth: usize,
}

/// A leader shorter than this leaves its label beside its point, seen or lost in a line,
/// mm: a label further off in the open on a longer leader reads no better.
const SEEN_SHORT: f64 = 8.0;

/// A text box this many times as high as a label's is taller lettering (a point's 5 mm
/// letter beside a 2.5 or 3.5 mm number).
const TALLER: f64 = 1.3;

/// A level line keeps this far over or under a label, mm (GOST 2.307 sets a value about
/// 1 mm over its line): nearer, it reads as the label's over- or underline.
const ALONG_CLEAR: f64 = 1.0;

/// A line's name's leader is checked against the drawing from this far off its line, mm
/// (drawn from the line itself, [`Labels::add_line_name`]).
pub(super) const TOUCH: f64 = 0.4;

impl Candidate {
    /// Its leader's length, mm (0: none).
    pub(super) fn leader_length(&self) -> f64 {
        self.leader.map_or(0.0, |(a, b)| (b - a).norm())
    }

    /// Whether it hangs on a leader `mm` long or longer.
    pub(super) fn leader_at_least(&self, mm: f64) -> bool {
        self.leader.is_some_and(|(a, b)| (b - a).norm() >= mm)
    }

    /// How many stroke segments of `o` its leader, if any, crosses.
    pub(super) fn crossings(&self, o: &Obstacles) -> usize {
        self.leader.map_or(0, |(a, b)| o.hits_segment(a, b))
    }

    pub(super) fn is_free(&self, o: &Obstacles) -> bool {
        self.box_is_free(o)
            && self.leader.is_none_or(|(a, b)| !o.segment_crosses_stroke_in(a, b, usize::from(self.dir)))
    }

    /// Whether a level line of `o` other than one through its anchor runs just over or
    /// under its box ([`ALONG_CLEAR`]), where it reads as the label's over- or underline.
    pub(super) fn is_lined(&self, o: &Obstacles) -> bool {
        o.level_stroke_along(self.r, ALONG_CLEAR, self.anchor)
    }

    /// The box is clear, its leader crosses no text (it may cross lines), and it reads
    /// apart from the texts on its line ([`Candidate::stands_apart`]).
    pub(super) fn box_is_free(&self, o: &Obstacles) -> bool {
        o.is_clear_in(self.r.inflate(CLEAR, CLEAR), usize::from(self.dir))
            && self.leader.is_none_or(|(a, b)| !o.segment_crosses_text(a, b))
            && self.stands_apart(o)
    }

    /// Whether no text of `o` level with it runs into it: none beside it if it states a
    /// value ([`Request::states_value`]), no statement beside it if not, no taller text
    /// beside it if it keeps off those ([`Request::apart_from_taller`]), and no such
    /// shorter number beside it ([`crate::drawing::obstacles::Piece::Index`]). A text box's height
    /// stands for its lettering's (at most: a smaller name may stand nearer).
    pub(super) fn stands_apart(&self, o: &Obstacles) -> bool {
        let band = phrases::level_band(self.r, phrases::APART * self.h);
        let statement_beside = o.statement_meets(band, |s, h| self.runs_into(s, h));
        let text_beside = || o.text_box_meets(band, |t| self.runs_into(t, t.height()));
        let taller = |t: Rect| t.height() > TALLER * self.r.height() && self.runs_into(t, t.height());
        let taller_beside = || self.apart_from_taller && o.text_box_meets(band, taller);
        let shorter = |t: Rect, h: f64| self.r.height() > TALLER * t.height() && self.runs_into(t, h);
        let index_beside = || o.index_meets(band, shorter);
        !(statement_beside || self.states_value && text_beside() || taller_beside() || index_beside())
    }

    /// Whether letters `t`, `h` high, level with it stand nearer than [`phrases::APART`]
    /// of the smaller's height.
    fn runs_into(&self, t: Rect, h: f64) -> bool {
        let gap = (t.x0 - self.r.x1).max(self.r.x0 - t.x1);
        gap < phrases::APART * h.min(self.h)
    }
}

/// The candidate with the fewest crossings when none is free.
pub(super) fn least_bad(cands: &[Candidate], layers: [&Obstacles; 2], req: &Request, bounds: Rect) -> Candidate {
    // No candidate inside the bounds (a label wider than its cell): beside the anchor,
    // pushed inside the bounds as far as they allow.
    let fallback = || {
        let (w, up, down) = req.size();
        let x0 = req.anchor.x.min(bounds.x1 - w).max(bounds.x0);
        let y1 = req.anchor.y.max(bounds.y0 + up + down).min(bounds.y1);
        let r = Rect::new(x0, y1 - up - down, x0 + w, y1);
        Candidate { r, anchor: req.anchor, states_value: req.states_value, h: req.h, ..Candidate::default() }
    };
    cands
        .iter()
        .map(|c| {
            let (strokes, area) = layers.iter().map(|o| o.hits(c.r)).fold((0, 0.0), |s, h| (s.0 + h.0, s.1 + h.1));
            let leader_on_text = c.leader.is_some_and(|(a, b)| layers.iter().any(|o| o.segment_crosses_text(a, b)));
            (strokes as f64 * 10.0 + area * 100.0 + if leader_on_text { 10.0 } else { 0.0 } + c.cost, c)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map_or_else(fallback, |(_, c)| c.clone())
}
