//! A turn arrow (ω, ε, a moment) turned round its centre to where it crosses the fewest lines
//! drawn, with the most room round it.

use super::turn_arrow;
use crate::drawing::obstacles::{Obstacles, Piece, rect_segment_distance, segments, segments_cross};
use crate::drawing::scene::{Group, Item, Pen};
use kurbo::{ParamCurveNearest, Point, Rect};

/// What a turn arrow crossing a text costs, in lines crossed: a stroke's value written along
/// its line before the arrows is worse to cross than a line.
const TEXT_CROSSED: usize = 20;

/// Room under this, mm, is a line touched.
const TOUCHING: f64 = 0.05;

/// Where the room round a turn arrow is measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RoomAt {
    /// Round its head's tip: an inertia moment's head on a weight's head (sheet 1).
    Tip,
    /// Round the whole arrow, a head or tail on a line counting as crossing it (sheet 3's
    /// ω, whose tail began on r_min's radius).
    Whole,
}

/// Where a turn arrow goes: its start, paper degrees, the lines it crosses and the room
/// left round it, mm (up to the room asked).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurnChoice {
    pub start: f64,
    pub crossings: usize,
    pub room: f64,
}

impl TurnChoice {
    /// Whether this choice beats `other`: fewer crossings, then more room.
    pub fn beats(&self, other: &TurnChoice) -> bool {
        self.crossings < other.crossings || (self.crossings == other.crossings && self.room > other.room)
    }
}

/// The start (every `step` degrees from `pref_deg`) for a [`turn_arrow`] round `c` that
/// crosses the fewest segments of `drawn`, with the most room round the whole arrow among
/// equals (up to `room` mm; 0 for none asked), then nearest `pref_deg`. Draws nothing.
#[allow(clippy::too_many_arguments)]
pub fn best_turn(
    drawn: &Obstacles,
    c: Point,
    r: f64,
    (pref_deg, step): (f64, f64),
    sweep_deg: f64,
    ccw: bool,
    (pen, room, at): (Pen, f64, RoomAt),
) -> TurnChoice {
    let probe = |start: f64| {
        let mut p = Group::new("probe", Rect::ZERO);
        turn_arrow(&mut p, c, r, start, sweep_deg, ccw, pen);
        let tail = match p.items.first() {
            Some(Item::Path { path, .. }) => path.start,
            _ => c,
        };
        let (arc, head) = match p.items.as_slice() {
            [arc, head @ ..] => (segments(arc), head.iter().flat_map(segments).collect()),
            [] => (Vec::new(), Vec::new()),
        };
        Probe { arc, head, tail }
    };
    // Its crossings, counted up to one past `most`: a start crossing more than the best so
    // far cannot win, and is left as soon as that is known.
    let crossings = |arrow: &Probe, most: usize| {
        let mut n = 0;
        for &(a, b) in arrow.all() {
            n += drawn.hits_segment(a, b) + if drawn.segment_crosses_text(a, b) { TEXT_CROSSED } else { 0 };
            if n > most {
                break;
            }
        }
        n
    };
    let turn = |a: f64| {
        let d = (a - pref_deg).rem_euclid(360.0);
        d.min(360.0 - d)
    };
    // Tried nearest the preferred start first: the first that crosses nothing with all the
    // room asked wins without drawing the rest.
    let count = (360.0 / step).round() as u32;
    let mut starts: Vec<(f64, f64)> =
        (0..count).map(|k| pref_deg + step * f64::from(k)).map(|a| (turn(a), a)).collect();
    starts.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut best: Option<TurnChoice> = None;
    for (_, start) in starts {
        let arrow = probe(start);
        let most = best.map_or(usize::MAX, |b| b.crossings);
        let crossed = crossings(&arrow, most);
        if crossed > most {
            // Beaten by the best on crossings alone: its room is not measured.
            continue;
        }
        let room_left = match at {
            RoomAt::Tip => room_round_tip(drawn, &arrow, room),
            RoomAt::Whole => room_round(drawn, &arrow, room),
        };
        // A head or tail on a line crosses it as far as the eye can tell (the crossings
        // counted are proper ones): with room asked all round it counts as one.
        let touches = at == RoomAt::Whole && room > 0.0 && room_left < TOUCHING;
        let choice = TurnChoice { start, crossings: crossed + usize::from(touches), room: room_left };
        if best.is_none_or(|b| choice.beats(&b)) {
            best = Some(choice);
        }
        if choice.crossings == 0 && choice.room >= room {
            break;
        }
    }
    best.unwrap_or(TurnChoice { start: pref_deg, crossings: 0, room })
}

/// The [`turn_arrow`] starting at `start`, drawn into `g` and joining `drawn`.
#[allow(clippy::too_many_arguments)]
pub fn turn_arrow_into(
    g: &mut Group,
    drawn: &mut Obstacles,
    c: Point,
    r: f64,
    start: f64,
    sweep_deg: f64,
    ccw: bool,
    pen: Pen,
) {
    let mut arrow = Group::new("arrow", Rect::ZERO);
    turn_arrow(&mut arrow, c, r, start, sweep_deg, ccw, pen);
    for (a, b) in arrow.items.iter().flat_map(segments) {
        drawn.add(Piece::Segment(a, b), usize::MAX);
    }
    g.items.extend(arrow.items);
}

/// A [`turn_arrow`] at the [`best_turn`] start, every 10° from `pref_deg`, with `room` mm
/// asked round its tip; it joins `drawn`. Returns its start.
#[allow(clippy::too_many_arguments)]
pub fn clear_turn_arrow(
    g: &mut Group,
    drawn: &mut Obstacles,
    c: Point,
    r: f64,
    pref_deg: f64,
    sweep_deg: f64,
    ccw: bool,
    (pen, room): (Pen, f64),
) -> f64 {
    let start = best_turn(drawn, c, r, (pref_deg, 10.0), sweep_deg, ccw, (pen, room, RoomAt::Tip)).start;
    turn_arrow_into(g, drawn, c, r, start, sweep_deg, ccw, pen);
    start
}

/// An arrow probed: its arc's and its head's segments, and its tail (the arc's start).
struct Probe {
    arc: Vec<(Point, Point)>,
    head: Vec<(Point, Point)>,
    tail: Point,
}

impl Probe {
    fn all(&self) -> impl Iterator<Item = &(Point, Point)> {
        self.arc.iter().chain(&self.head)
    }
}

/// The room round the arrow: the distance to the nearest piece of `drawn`, up to `room` (0
/// when none is asked). A line the arrow crosses counts by its distance from the head and
/// the tail alone: among starts crossing alike, one crossing mid-arc reads, one at the head
/// does not. (The head alone was measured once: a rocker cam's ω began on r_min's radius.)
fn room_round(drawn: &Obstacles, arrow: &Probe, room: f64) -> f64 {
    if room <= 0.0 {
        return 0.0;
    }
    let Some(bounds) = arrow.all().map(|&(a, b)| Rect::from_points(a, b)).reduce(|r, s| r.union(s)) else {
        return 0.0;
    };
    let to_ends = |piece: &Piece| {
        arrow.head.iter().map(|&s| distance(piece, s)).fold(distance(piece, (arrow.tail, arrow.tail)), f64::min)
    };
    drawn
        .near(bounds.inflate(room, room))
        .map(|(piece, _)| {
            let whole = arrow.all().map(|&s| distance(piece, s)).fold(f64::INFINITY, f64::min);
            if whole > 0.0 { whole } else { to_ends(piece) }
        })
        .fold(room, f64::min)
}

/// The room round the arrow's tip: the distance to the nearest piece of `drawn`, up to
/// `room` (0 when none is asked).
fn room_round_tip(drawn: &Obstacles, arrow: &Probe, room: f64) -> f64 {
    let Some(&(_, tip)) = arrow.arc.last() else { return 0.0 };
    if room <= 0.0 {
        return 0.0;
    }
    let near = drawn.near(Rect::from_center_size(tip, (2.0 * room, 2.0 * room)));
    near.map(|(piece, _)| distance(piece, (tip, tip))).fold(room, f64::min)
}

/// The distance from a piece to the segment `s` (0 where they meet).
fn distance(piece: &Piece, s: (Point, Point)) -> f64 {
    let to = |p: Point, (a, b): (Point, Point)| kurbo::Line::new(a, b).nearest(p, 0.0).distance_sq.sqrt();
    match *piece {
        Piece::Segment(a, b) if segments_cross(a, b, s.0, s.1) => 0.0,
        Piece::Segment(a, b) => to(a, s).min(to(b, s)).min(to(s.0, (a, b))).min(to(s.1, (a, b))),
        Piece::Disc(c, rad) => (to(c, s) - rad).max(0.0),
        Piece::TextBox(r) | Piece::Band(r) => rect_segment_distance(r, s),
        Piece::Statement(..) | Piece::Index(..) => f64::INFINITY,
    }
}
