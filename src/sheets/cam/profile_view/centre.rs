//! What is drawn at the cam's centre O: r_min's radius into the near dwell, O's support and
//! the sense of rotation, ω's arrow. The radius and the arrow are chosen together: in the
//! middle of the near dwell the radius halves the widest gap between the construction's
//! lines, and ω's arrow crossed it on 12 of the catalogue's sheets; where the middle leaves
//! the arrow no clear start, the radius goes further round the dwell.

use crate::cams::Design;
use crate::drawing::along::{along_line, mirrored_room};
use crate::drawing::fmt;
use crate::drawing::obstacles::{Obstacles, Piece};
use crate::drawing::place::Labels;
use crate::drawing::scene::{Group, THIN};
use crate::drawing::symbols::{RoomAt, TurnChoice, best_turn, frame_pivot, turn_arrow, turn_arrow_into, vector};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::num::math::{Norm, sin_cos};
use crate::num::units::mm;
use crate::sheets::cam::labels::CamWords;
use crate::sheets::cam::nomogram::Placement;
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::TAU;

/// What [`draw`] drew of r_min, for [`write_r_min`] once every line of the view is drawn.
pub struct RMin {
    /// The radius, from O to the base circle, paper mm.
    radius: (Point, Point),
    value: LabelText,
}

/// Draws r_min's radius with the base circle's name, O with its support, and ω's arrow with
/// ω; returns the arrow's radius, mm, and r_min for [`write_r_min`].
pub fn draw(
    g: &mut Group,
    labels: &mut Labels,
    at: &Placement,
    view: View,
    d: &Design,
    words: &CamWords,
) -> (f64, RMin) {
    let value = r_min_value(d, words);
    let (share, omega) = r_min_and_omega(g, (view, at.area), d, &value);
    // r_min's radius before ω's arrow, which turns clear of it (it crossed the radius
    // beside its head on the worked example).
    let end = draw_r_min(g, labels, view, d, words, share);
    (draw_rotation(g, labels, view, omega), RMin { radius: (view.origin, end), value })
}

/// r_min's value along its radius where it finds room there, over it where it can (GOST
/// 2.307, as on the nomogram), else level beside it on a leader if need be; after every
/// line of the view is drawn, before the labels are placed.
pub fn write_r_min(g: &mut Group, labels: &mut Labels, area: Rect, r_min: RMin) {
    let RMin { radius: (o, end), value } = r_min;
    let drawn = Obstacles::of_items(&g.items);
    match along_line((&drawn, area), (clear_of_o(o, end), end), (&value, VALUE_H), None) {
        Some(t) => {
            labels.keep_clear(mirrored_room(&t, (o, end)));
            g.text(t)
        }
        None => labels.add_ranked(o + (end - o) * R_MIN_VALUE_AT, Vec2::ZERO, value, VALUE_H, 1),
    }
}

/// Where along the near dwell r_min's radius is tried, as shares of the dwell, best first.
const R_MIN_AT: [f64; 5] = [0.5, 0.35, 0.65, 0.2, 0.8];

/// Where along r_min's radius its value stands when set level, as a share of it from O.
const R_MIN_VALUE_AT: f64 = 0.55;

/// The share of the near dwell r_min's radius is drawn at and ω's arrow: the first share
/// whose radius leaves the arrow a start crossing nothing with all its room and its value
/// room along it, else the best of those whose value has that room, else the middle.
fn r_min_and_omega(g: &Group, (view, area): (View, Rect), d: &Design, value: &LabelText) -> (f64, Omega) {
    let below = Obstacles::of_items(&g.items);
    let mut best: Option<(f64, Omega, bool)> = None;
    for share in R_MIN_AT {
        // What draw_r_min and draw_rotation draw before the arrow.
        let mut centre = Group::new("centre", Rect::ZERO);
        let end = view.p(r_min_end(d, share));
        vector(&mut centre, view.origin, end, THIN);
        frame_pivot(&mut centre, view.origin, PIVOT_R);
        let mut drawn = below.clone();
        drawn.add_items(&centre.items, g.items.len());
        let omega = best_omega(&drawn, view, d);
        if best.as_ref().is_some_and(|b| omega.turn.crossings > b.1.turn.crossings) {
            // Cannot win, whether its value fits or not: not asked.
            continue;
        }
        let arrow = &mut Group::new("arrow", Rect::ZERO);
        turn_arrow_into(arrow, &mut drawn, view.origin, omega.r, omega.turn.start, omega.sweep, view.mirror, THIN);
        // ω's own letter, outside its arrow's middle, is in the way too.
        let (out, _) = omega_middle(view, &omega);
        drawn.add(Piece::TextBox(Rect::from_center_size(view.origin + out * (omega.r + 2.5), (4.0, 4.0))), usize::MAX);
        let radius = (clear_of_o(view.origin, end), end);
        let fits = along_line((&drawn, area), radius, (value, VALUE_H), None).is_some();
        // The radius leaves the middle only for a share where its value is written along
        // it, and ω's arrow crosses no more lines: where the value is set level it needs the
        // room the middle gives it (moved off it to clear ω, it went on 19–26 mm leaders on
        // task 3 variant 7 and task 14 variant 29).
        let better = |b: &(f64, Omega, bool)| {
            let (now, was) = (omega.turn, b.1.turn);
            fits && (now.crossings < was.crossings || (now.crossings == was.crossings && (!b.2 || now.room > was.room)))
        };
        if best.as_ref().is_none_or(better) {
            best = Some((share, omega, fits));
        }
        if omega.is_clear() && fits {
            break;
        }
    }
    best.map(|(share, omega, _)| (share, omega)).expect("the middle of the near dwell is always tried")
}

/// Where along r_min's radius from `o` to `end` its value may begin: clear of O's joint and
/// of the letter O beside it (set against the joint, the value read on into "O").
fn clear_of_o(o: Point, end: Point) -> Point {
    o + (end - o).unit() * (PIVOT_R + O_ROOM)
}

/// Kept between O's joint and r_min's value written along its radius, mm.
const O_ROOM: f64 = 3.5;

/// The lettering of r_min's value, mm.
const VALUE_H: f64 = 2.5;

/// The end of r_min's radius on the base circle at `share` of the near dwell, cam frame.
fn r_min_end(d: &Design, share: f64) -> Vec2 {
    let near = d.spec.program.rise + d.spec.program.far_dwell + d.spec.program.ret;
    d.profile.pitch(near + (TAU - near) * share).p.unit() * d.centre.r_min
}

/// Where along the near dwell the base circle's name may stand, best first, unless within
/// [`BASE_NAME_APART`] of r_min's radius.
const BASE_NAME_AT: [f64; 6] = [0.7, 0.85, 0.3, 0.15, 0.6, 0.4];
/// The least share of the near dwell between the base circle's name and r_min's radius
/// (clear of the radius' arrowhead).
const BASE_NAME_APART: f64 = 0.099;

/// r_min: a radius into the near dwell (at `share` of it), where the profile is the base
/// circle, with the base circle's name on a leader of its own a little further round.
fn draw_r_min(g: &mut Group, labels: &mut Labels, view: View, d: &Design, words: &CamWords, share: f64) -> Point {
    let end = view.p(r_min_end(d, share));
    vector(g, view.origin, end, THIN);
    // Several points of the near dwell, the first a little round from the radius: the
    // first alone hung the name 59 mm down a leader where the profile's region ends close
    // beside that point (task 13 variant 41).
    let spots: Vec<(Point, Vec2)> = BASE_NAME_AT
        .iter()
        .filter(|&&f| (f - share).abs() >= BASE_NAME_APART)
        .map(|&f| {
            let aside = view.p(r_min_end(d, f));
            (aside, aside - view.origin)
        })
        .collect();
    labels.add_line_name_at_any(&spots, &[], LabelText::new(words.sheet.base_circle(), ""), 2.5, 3);
    end
}

/// r_min = … (mm, without the unit as GOST 2.307 writes a dimension).
fn r_min_value(d: &Design, words: &CamWords) -> LabelText {
    LabelText::new("r", words.sheet.sub_min()).with_tail(format!(" = {}", fmt::trimmed(mm(d.centre.r_min), words.lang)))
}

/// The radius of O's joint circle, mm.
const PIVOT_R: f64 = 1.5;

/// The radii ω's arrow is tried at, as shares of its nominal radius (a quarter of r_min), in
/// the order preferred: the phases' arcs take the band beyond it.
const OMEGA_RADII: [f64; 3] = [1.0, 0.75, 1.3];

/// The sweeps ω's arrow is tried with, degrees, the usual first; a shorter one only where
/// its arc is still [`OMEGA_LEAST_ARC`] long.
const OMEGA_SWEEPS: [f64; 3] = [60.0, 45.0, 35.0];

/// The shortest arc of a shortened ω arrow, mm (its head is 3).
const OMEGA_LEAST_ARC: f64 = 12.0;

/// The step between the starts tried for ω's arrow, degrees: in 10° steps a gap of 70°
/// between r_min's radius and an axis had only starts on either line (task 1 variant 1).
const OMEGA_STEP: f64 = 5.0;

/// The smallest radius of ω's arrow, mm.
const OMEGA_LEAST_R: f64 = 6.0;

/// The room wanted round ω's arrow, mm.
const OMEGA_ROOM: f64 = 1.5;

/// ω's arrow: its radius, mm, its sweep, degrees, and its start.
#[derive(Clone, Copy)]
struct Omega {
    r: f64,
    sweep: f64,
    turn: TurnChoice,
}

impl Omega {
    /// Crossing nothing, with all the room asked: no other arrow can beat it.
    fn is_clear(&self) -> bool {
        self.turn.crossings == 0 && self.turn.room >= OMEGA_ROOM
    }
}

/// ω's arrow turned from the upper left to where it crosses fewest lines of `drawn`: the
/// usual arrow, else a smaller, a larger or a shorter one where it crosses fewer lines or
/// leaves more room (inside a translating follower's fan of axes, every start of the usual
/// one met a line: task 14 variant 37 crossed two; several began or ended under 1 mm from
/// one).
fn best_omega(drawn: &Obstacles, view: View, d: &Design) -> Omega {
    let nominal = 0.25 * d.centre.r_min / view.mu;
    let tries = OMEGA_SWEEPS
        .iter()
        .flat_map(|&sweep| OMEGA_RADII.iter().map(move |&f| ((nominal * f).max(OMEGA_LEAST_R), sweep)));
    let tries = tries.filter(|&(r, sweep)| sweep == OMEGA_SWEEPS[0] || r * sweep.to_radians() >= OMEGA_LEAST_ARC);
    let turned = |(r, sweep): (f64, f64)| {
        let choice = (THIN, OMEGA_ROOM, RoomAt::Whole);
        let turn = best_turn(drawn, view.origin, r, (200.0, OMEGA_STEP), sweep, view.mirror, choice);
        Omega { r, sweep, turn }
    };
    // The first that is clear cannot be beaten: the rest are not tried (most cams stop at
    // the usual arrow).
    let mut best: Option<Omega> = None;
    for next in tries.map(turned) {
        if best.is_none_or(|b| next.turn.beats(&b.turn)) {
            best = Some(next);
        }
        if next.is_clear() {
            break;
        }
    }
    best.expect("the usual arrow is always tried")
}

/// O, and the sense of rotation with ω beside its arrow (`omega`); the arrow's radius, mm.
fn draw_rotation(g: &mut Group, labels: &mut Labels, view: View, omega: Omega) -> f64 {
    frame_pivot(g, view.origin, PIVOT_R);
    labels.add_text(view.origin, Vec2::new(-1.0, 1.0), "O", 3.5);
    let Omega { r, sweep, turn } = omega;
    let start = turn.start;
    turn_arrow(g, view.origin, r, start, sweep, view.mirror, THIN);
    // ω at the arc's middle, outward.
    let (out, _) = omega_middle(view, &omega);
    labels.add_text_ranked(view.origin + out * r, out, "ω", 3.5, 0);
    r
}

/// The outward direction at the middle of ω's arrow, and that middle's paper angle, degrees.
fn omega_middle(view: View, omega: &Omega) -> (Vec2, f64) {
    let (start, sweep) = (omega.turn.start, omega.sweep);
    let middle = if view.mirror { start - sweep / 2.0 } else { start + sweep / 2.0 };
    let (s, c) = sin_cos(middle.to_radians());
    (Vec2::new(c, s), middle)
}
