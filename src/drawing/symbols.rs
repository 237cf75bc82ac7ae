//! Drafting symbols built from scene primitives: arrows, pivots, sliders, hatching.

mod turn;
pub use turn::{RoomAt, TurnChoice, best_turn, clear_turn_arrow, turn_arrow_into};

use super::obstacles::Obstacles;
use super::path::{Path, on_circle};
use super::scene::{Anchor, Group, MOST_BROKEN, Pen, THIN, Text};
use super::text::LabelText;
use crate::num::math::{self, Norm};
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// Arrowhead length and half width, mm (drafting practice for thin lines).
pub const ARROW_LEN: f64 = 3.0;
pub const ARROW_HALF: f64 = 0.55;

/// Adds a filled arrowhead with its tip at `tip`, pointing along `dir`.
pub fn arrowhead(g: &mut Group, tip: Point, dir: Vec2) {
    let len = dir.norm();
    if len < tol::PAPER {
        return;
    }
    let u = dir / len;
    let n = u.turn_90();
    let base = tip - u * ARROW_LEN;
    g.fill(&[tip, base + n * ARROW_HALF, base - n * ARROW_HALF]);
}

/// A vector from `a` to `b` with an arrowhead at `b`. Vectors shorter than the arrowhead
/// get a shorter head so the arrow never points backwards; zero vectors draw nothing.
pub fn vector(g: &mut Group, a: Point, b: Point, pen: Pen) {
    let d = b - a;
    let len = d.norm();
    if len < tol::PAPER_INVISIBLE {
        return;
    }
    if len <= ARROW_LEN * 1.2 {
        let u = d / len;
        let n = u.turn_90();
        let base = b - u * (len * 0.8);
        g.fill(&[b, base + n * ARROW_HALF * 0.8, base - n * ARROW_HALF * 0.8]);
        return;
    }
    g.line(a, b - d / len * (ARROW_LEN * 0.6), pen);
    arrowhead(g, b, d);
}

/// A fixed pivot: a joint circle on a short base with hatching below it.
pub fn frame_pivot(g: &mut Group, c: Point, r: f64) {
    g.circle(c, r, THIN);
    let y = c.y + r * 2.6;
    let half = r * 3.0;
    g.line(Point::new(c.x - r * 0.9, c.y + r * 0.5), Point::new(c.x - r * 1.6, y), THIN);
    g.line(Point::new(c.x + r * 0.9, c.y + r * 0.5), Point::new(c.x + r * 1.6, y), THIN);
    g.line(Point::new(c.x - half, y), Point::new(c.x + half, y), THIN);
    hatch(g, Point::new(c.x - half, y), Point::new(c.x + half, y), Vec2::new(0.0, 1.0), 1.6);
}

/// Short 45° strokes along `a → b` on the side `side` (a unit vector): the frame symbol.
pub fn hatch(g: &mut Group, a: Point, b: Point, side: Vec2, step: f64) {
    hatch_strokes(g, a, b, |_| side, 0.0, step);
}

/// The strokes of [`hatch`] on `a → b` from `first` mm on, every `step` mm, toward the side
/// `side(u)` gives for the segment's direction u. Returns where the next stroke falls past
/// `b` (for a polyline's next segment); a segment too short to have a direction adds none.
fn hatch_strokes(g: &mut Group, a: Point, b: Point, side: impl Fn(Vec2) -> Vec2, first: f64, step: f64) -> f64 {
    let len = (b - a).norm();
    if len < tol::PAPER {
        return first;
    }
    let u = (b - a) / len;
    let stroke = (side(u) - u) * (step * 0.9 / std::f64::consts::SQRT_2);
    let count = ((len - first) / step).floor().max(-1.0) as i64 + 1;
    for i in 0..count {
        let p = a + u * (first + i as f64 * step);
        g.line(p, p + stroke, THIN);
    }
    first + count as f64 * step - len
}

/// A slider block: a rectangle centred at `c` along the unit direction `u`.
pub fn slider(g: &mut Group, c: Point, u: Vec2, len: f64, wid: f64, pen: Pen) {
    let n = u.turn_90();
    let (hl, hw) = (u * (len / 2.0), n * (wid / 2.0));
    g.path(vec![c - hl - hw, c + hl - hw, c + hl + hw, c - hl + hw], true, pen);
}

/// An arc arrow of radius `r` around `c` showing a turning sense (ω, ε, an inertia moment):
/// a true circular arc from `start_deg` through `sweep_deg` (paper angles), turning
/// counter-clockwise on the sheet when `ccw`. The arrowhead follows the chord over its own
/// length, so it sits on the arc rather than on its tangent.
pub fn turn_arrow(g: &mut Group, c: Point, r: f64, start_deg: f64, sweep_deg: f64, ccw: bool, pen: Pen) {
    let sign = if ccw { -1.0 } else { 1.0 }; // paper y points down: ccw on the sheet is a falling angle
    let (a0, sweep) = (start_deg.to_radians(), sign * sweep_deg.to_radians());
    let arc = Path::arc(c, r, a0, sweep);
    let tip = arc.end();
    let back = on_circle(c, r, a0 + sweep - sign * (ARROW_LEN / r).min(sweep.abs()));
    g.curve(arc, pen);
    arrowhead(g, tip, tip - back);
}

/// The box a [`turn_arrow`] round `c` of radius `r` stays inside, whatever its start and
/// sweep: what [`clear_turn_arrow`] may cross lies in it.
pub fn turn_arrow_reach(c: Point, r: f64) -> Rect {
    let out = 2.0 * (r + ARROW_LEN);
    Rect::from_center_size(c, (out, out))
}

/// A linear dimension of the features at `a` and `b`: extension lines from them along
/// `offset` (past the dimension line by 2 mm, 1 mm clear of the features), the dimension line
/// at `offset` with arrowheads at its ends — inside when the two heads and a gap fit, else
/// outside, pointing in, on 5 mm lines. Returns the dimension line's middle (for its text).
pub fn dimension(g: &mut Group, a: Point, b: Point, offset: Vec2) -> Point {
    let (da, db) = (a + offset, b + offset);
    let len = (db - da).norm();
    let off = offset.norm();
    if off > tol::PAPER {
        let u = offset / off;
        for p in [a, b] {
            g.line(p + u * off.min(1.0), p + offset + u * 2.0, THIN);
        }
    }
    if len < tol::PAPER {
        return da;
    }
    let u = (db - da) / len;
    let tail = dimension_tail(da, db);
    if tail == 0.0 {
        g.line(da, db, THIN);
        arrowhead(g, da, -u);
        arrowhead(g, db, u);
    } else {
        g.line(da - u * tail, db + u * tail, THIN);
        arrowhead(g, da, u);
        arrowhead(g, db, -u);
    }
    da.midpoint(db)
}

/// How far a dimension line da–db runs past each end, mm: 5 where it is too short for its
/// arrows between its ends and they stand outside, pointing in; else none.
pub fn dimension_tail(da: Point, db: Point) -> f64 {
    if (db - da).norm() >= 2.0 * ARROW_LEN + 2.0 { 0.0 } else { 5.0 }
}

/// A dimension's value written along its horizontal or vertical dimension line `a`–`b` (GOST
/// 2.307: over a horizontal line, left of a vertical one reading upward; else on the other
/// side), where nothing drawn in `g` is within 0.5 mm of it (`drawn` indexes its items
/// before `since`, the caller's index reused; those after are indexed here) and it stays
/// inside `bounds`, under its line too unless `over_only`; returns whether it was written
/// (else nothing was, and the caller places it as a label: an oblique line, a value longer
/// than its line, or no room on either side).
pub fn value_along(
    g: &mut Group,
    (drawn, since): (&Obstacles, usize),
    value: &LabelText,
    (a, b): (Point, Point),
    h: f64,
    bounds: Rect,
    over_only: bool,
) -> bool {
    let d = b - a;
    let len = d.norm();
    let axis_aligned = d.x.abs() < tol::PAPER || d.y.abs() < tol::PAPER;
    if !axis_aligned || value.width(h) + 2.0 * ARROW_LEN > len {
        return false;
    }
    // Reading left to right, or upward: its "up" to the left of the reading direction.
    let t = if d.x.abs() >= tol::PAPER { d * d.x.signum() / len } else { Vec2::new(0.0, -1.0) };
    let up = Vec2::new(t.y, -t.x);
    let rotate = math::atan2(-t.y, t.x).to_degrees();
    // What `drawn` does not hold: the items drawn since it was indexed (the dimension).
    let added = Obstacles::of_items(&g.items[since..]);
    let mid = a.midpoint(b);
    // The value's box across the line when its baseline is on it: the lowest and highest
    // points "up" from the line.
    let on_line = Text { rotate, ..value.text(mid, h, Anchor::Middle) }.bbox();
    let corners = [
        on_line.origin(),
        Point::new(on_line.x1, on_line.y0),
        Point::new(on_line.x0, on_line.y1),
        Point::new(on_line.x1, on_line.y1),
    ];
    let across = corners.map(|c| (c - mid).dot(up));
    let (lo, hi) = (across.iter().copied().fold(f64::MAX, f64::min), across.iter().copied().fold(f64::MIN, f64::max));
    // Over the line (GOST 2.307), its box VALUE_GAP from the line, at its middle, then slid
    // toward either end while it stays between the arrows, with more room round it (from
    // the middle, with the guide on one side and the rods' lines on the other, a stroke's
    // value hung on a 76 mm leader; slid into a gap just its width, it took the room the
    // slider's numbers needed); only then under it, in the same order (tried side by side
    // at each slide, 166 of the Russian catalogue's 516 strokes stood under their lines).
    let half = corners.iter().map(|&c| (c - mid).dot(t).abs()).fold(0.0, f64::max);
    let room = (len / 2.0 - half - ARROW_LEN - VALUE_CLEAR).max(0.0);
    let spots = || {
        let under = (!over_only).then_some(-VALUE_GAP - hi);
        [Some(VALUE_GAP - lo), under].into_iter().flatten().flat_map(move |shift| {
            along_slides().map(move |slide| {
                let text = Text { rotate, ..value.text(mid + t * (slide * room) + up * shift, h, Anchor::Middle) };
                let clear = if slide == 0.0 { VALUE_CLEAR } else { SLID_CLEAR };
                (text.bbox(), clear, text)
            })
        })
    };
    // Inside, `clear` mm from what was drawn before, and from the dimension as near as its
    // middle's value stands.
    let free = |bb: Rect, clear: f64, hard: &Obstacles| {
        bounds.contains(bb.origin())
            && bounds.contains(Point::new(bb.x1, bb.y1))
            && hard.is_clear(bb.inflate(clear, clear))
            && added.is_clear(bb.inflate(VALUE_CLEAR, VALUE_CLEAR))
    };
    if let Some((_, _, text)) = spots().find(|&(bb, clear, _)| free(bb, clear, drawn)) {
        g.text(text);
        return true;
    }
    // Else across a few of the other positions' thin lines, interrupted for it (the
    // rocker's twelve positions fan across a stroke beside its guide: the value hung on a
    // 76 mm leader below the crank).
    let hard = drawn.without(|k| k < since && g.breakable.binary_search(&k).is_ok());
    let gap = |bb: Rect| bb.inflate(VALUE_CLEAR, VALUE_CLEAR);
    let breaks_few = |bb: Rect| drawn.items_meeting(gap(bb)) <= MOST_BROKEN;
    let Some((bb, _, text)) = spots().find(|&(bb, clear, _)| free(bb, clear, &hard) && breaks_few(bb)) else {
        return false;
    };
    g.text(text);
    g.interrupt_breakable(&[gap(bb)]);
    true
}

/// Where along its dimension line a value is tried: the middle, then in steps of a sixth
/// of the room each side of it, alternately toward either end.
const ALONG_STEPS: usize = 6;
fn along_slides() -> impl Iterator<Item = f64> {
    (0..=2 * ALONG_STEPS).map(|k| k.div_ceil(2) as f64 / ALONG_STEPS as f64 * if k % 2 == 1 { -1.0 } else { 1.0 })
}
/// Room kept between a value slid off its line's middle and anything drawn but its
/// dimension, mm.
const SLID_CLEAR: f64 = 2.0;

/// From a dimension line to its value's box, mm (GOST 2.307: about 1 mm to the letters;
/// more than [`VALUE_CLEAR`], so that the line itself leaves the box clear).
const VALUE_GAP: f64 = 0.7;
/// Room kept between a dimension's value and anything else drawn, mm (the label placer's).
const VALUE_CLEAR: f64 = 0.5;

/// An angle's mark at `apex` from the unit direction `from` to the unit direction `to`
/// (the smaller turn): an arc of radius `r`. Returns the arc's middle, where its value is
/// named ([`crate::drawing::place::Labels::add_on_line_at_any`]: a leader, where it needs
/// one, starts on the arc; one from 2 mm outside it read as a stray tick, «|α_k = 45°»).
pub fn angle_mark(g: &mut Group, apex: Point, from: Vec2, to: Vec2, r: f64) -> Point {
    let (a0, sweep) = turn(from, to);
    g.curve(Path::arc(apex, r, a0, sweep), THIN);
    on_circle(apex, r, a0 + sweep / 2.0)
}

/// The smaller turn from the unit direction `from` to `to`: its start angle and its signed
/// sweep, radians.
pub fn turn(from: Vec2, to: Vec2) -> (f64, f64) {
    (math::atan2(from.y, from.x), math::atan2(from.cross(to), from.dot(to)))
}

/// An angular dimension at `apex` from the unit direction `from` to `to` (the smaller turn):
/// an arc of radius `r` with its arrowheads on the two lines, pointing out along the arc where
/// it is at least `inside_min` mm long, else outside the lines pointing in, the arc run on
/// 5 mm past each (GOST 2.307, as a short linear dimension's).
pub fn angular_dimension(g: &mut Group, apex: Point, (from, to): (Vec2, Vec2), r: f64, inside_min: f64) {
    let (a0, sweep) = turn(from, to);
    arc_dimension(g, apex, (a0, sweep), r, inside_min);
}

/// As [`angular_dimension`], from the paper angle `a0` by the signed `sweep` (radians), which
/// may exceed half a turn (a cam's phase of 200°).
pub fn arc_dimension(g: &mut Group, apex: Point, (a0, sweep): (f64, f64), r: f64, inside_min: f64) {
    let tangent = |a: f64| Vec2::new(-math::sin(a), math::cos(a)) * sweep.signum();
    let out = if r * sweep.abs() < inside_min { -1.0 } else { 1.0 };
    let past = if out > 0.0 { 0.0 } else { 5.0 / r * sweep.signum() };
    g.curve(Path::arc(apex, r, a0 - past, sweep + 2.0 * past), THIN);
    arrowhead(g, on_circle(apex, r, a0), -tangent(a0) * out);
    arrowhead(g, on_circle(apex, r, a0 + sweep), tangent(a0 + sweep) * out);
}

/// Short 45° strokes every `step` mm of arc length along the polyline `pts`, on the side
/// where `inside` (a unit vector) points: a zone's boundary as a drawing hatches it.
pub fn hatch_along(g: &mut Group, pts: &[Point], inside: Vec2, step: f64) {
    let toward_inside = |u: Vec2| {
        let normal = Vec2::new(-u.y, u.x);
        if normal.dot(inside) >= 0.0 { normal } else { -normal }
    };
    let mut first = 0.0;
    for w in pts.windows(2) {
        first = hatch_strokes(g, w[0], w[1], toward_inside, first, step);
    }
}
