//! One label waiting to be placed: its anchors, its lines, its rank and what it names.

use super::candidate::Candidate;
use super::candidate::TOUCH;
use super::{LEADER_GAP, LINE_PITCH, label_size};
use crate::drawing::phrases;
use crate::drawing::text::LabelText;
use kurbo::{Point, Vec2};

/// Where a label went: whether its spot is clean, its leader's length (0: none), mm, and
/// its rank.
#[derive(Debug, Clone, Copy)]
pub struct Placed {
    pub clean: bool,
    pub leader: f64,
    pub rank: u8,
}

/// One label to place.
#[derive(Debug, Clone)]
pub(super) struct Request {
    pub(super) anchor: Point,
    pub(super) pref: Vec2,
    /// Further anchors on the same line with their preferred directions, tried after the
    /// first one's near spots (a profile's name where its first point is crowded).
    pub(super) others: Vec<(Point, Vec2)>,
    /// More points of a line it names, looked at only where those before leave the name
    /// far off (see [`super::spots::Spots::along`]).
    pub(super) along: Vec<(Point, Vec2)>,
    pub(super) label: LabelText,
    /// Further lines set under the first, centred on it (one label in a stack).
    pub(super) more: Vec<LabelText>,
    pub(super) h: f64,
    /// Lower goes first: a class of labels (a mechanism's joint letters) may claim the
    /// best spots before another (its position numbers).
    pub(super) rank: u8,
    /// A label naming a line (a curve's name): always on a leader that touches the line.
    pub(super) names_line: bool,
    /// Its anchors lie on a drawn line (an angle's arc), not at a joint's circle: a leader
    /// starts on the line (with a gap off it, 2–3 mm of leader read as a dash in the text,
    /// «−φ_fd = 20°», «φ_ut = 30°|»).
    pub(super) on_line: bool,
    /// The segment the label names (a polygon's side): a spot nearer another named segment
    /// than this one reads as that one's name, and is taken only when no other is free.
    pub(super) side: Option<(Point, Point)>,
    /// It states a value ("φ₁ = 150,0°"): a name or a number beside it on its line reads
    /// as part of it ([`phrases::run_together`]).
    pub(super) states_value: bool,
    /// It keeps a statement's distance from taller texts on its line: a slider's number a
    /// word's space before a point's letter reads as one designation with it («0 D»: the
    /// guide's D₀).
    pub(super) apart_from_taller: bool,
}

impl Request {
    /// A one-line label of rank 0 at one anchor.
    pub(super) fn new(anchor: Point, pref: Vec2, label: LabelText, h: f64) -> Request {
        let states_value = phrases::states_value(&label.chars_in_order());
        Request {
            anchor,
            pref,
            others: Vec::new(),
            along: Vec::new(),
            label,
            more: Vec::new(),
            h,
            rank: 0,
            names_line: false,
            on_line: false,
            side: None,
            states_value,
            apart_from_taller: false,
        }
    }

    /// The label's box: width, height above the first baseline, depth below it (the further
    /// lines included).
    pub(super) fn size(&self) -> (f64, f64, f64) {
        let (w, up, down) = label_size(&self.label, self.h);
        self.more.iter().fold((w, up, down), |(w, up, _), line| {
            let (lw, _, ld) = label_size(line, self.h);
            (w.max(lw), up, ld + self.more.len() as f64 * LINE_PITCH * self.h)
        })
    }

    /// A candidate's leader as drawn: one from a line reaches the line.
    pub(super) fn drawn_leader(&self, c: &Candidate) -> Option<(Point, Point)> {
        c.leader.map(|(a, b)| (if self.leader_from_line() { c.anchor } else { a }, b))
    }

    /// Whether its leader starts on its anchor's line (checked from [`TOUCH`] off it).
    fn leader_from_line(&self) -> bool {
        self.names_line || self.on_line
    }

    /// How far off the anchor its leader is checked from, mm: a joint's leader keeps clear
    /// of the joint's circle.
    pub(super) fn leader_gap(&self) -> f64 {
        if self.leader_from_line() { TOUCH } else { LEADER_GAP }
    }
}
