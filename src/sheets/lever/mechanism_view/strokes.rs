//! Each slider's stroke H dimensioned between its extreme positions, its value along the
//! dimension line where it has room.

use super::slider_numbers::SliderNumbers;
use super::{MechanismView, SLIDER};
use crate::drawing::along::along_line;
use crate::drawing::fmt;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::place::{Labels, label_size};
use crate::drawing::scene::{Group, Item, MAIN};
use crate::drawing::symbols::{dimension, value_along};
use crate::drawing::text::LabelText;
use crate::lever::linkage::{PointId, Step};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Point, Vec2};

/// A slider's stroke shorter than this on paper is not dimensioned: its arrows would hide it, mm.
const STROKE_MIN_MM: f64 = 3.0;
/// A slider's stroke to dimension: the rod's joint, the slider's point, the guide (a point and
/// its direction), the extreme positions on paper and H, m.
struct Stroke {
    joint: PointId,
    slider: PointId,
    through: Vec2,
    dir: Vec2,
    ea: Point,
    eb: Point,
    length: f64,
}

/// The room between a slider's block and its numbers, and between them and the stroke's
/// dimension line beyond them, mm.
const NUMBERS_GAP: f64 = 1.5;

/// How far a slider's numbers reach off its guide on their side, their boxes' extent along
/// the guide's normal (2.5 mm lettering), mm.
fn numbers_depth(plan: &SliderNumbers) -> f64 {
    let depth = |text: &String| {
        let (w, up, down) = label_size(&LabelText::new(text.as_str(), ""), 2.5);
        w * plan.up.x.abs() + (up + down) * plan.up.y.abs()
    };
    plan.numbers.iter().map(|(_, text)| depth(text)).fold(0.0, f64::max)
}

/// How much further out a stroke's dimension line goes to have its value over it, mm: the
/// value's 3.5 mm lettering and its gaps.
const VALUE_ROOM: f64 = 5.0;

/// Two strokes whose ends are this close on paper are one (mm).
const STROKE_SAME_MM: f64 = 0.5;

impl MechanismView<'_> {
    /// Each slider's stroke H, dimensioned between its point's extreme positions: beyond the
    /// guide's hatching, or on the rod's side, at the offset whose lines cross the fewest
    /// drawn lines — a contour line (the thick position's rod) counting as ten — and stay in
    /// the drawing's region. Drawn after the positions, so that it sees them.
    ///
    /// With two sliders each H is named by its slider's point (H_B, H_E); two strokes between
    /// the same extreme points (two pistons on one line, cranks 180° apart) are one dimension.
    ///
    /// Returns the dimension lines drawn.
    pub(super) fn strokes(&self, g: &mut Group, labels: &mut Labels, numbers: &[SliderNumbers]) -> Vec<(Point, Point)> {
        let mut strokes: Vec<Stroke> = Vec::new();
        for st in &self.m.steps {
            let Step::Rrp { p: joint, d: slider, through, dir, .. } = *st else { continue };
            let (lo, hi) = self.travel(slider, through, dir);
            let (ea, eb) = (self.view.p(through + dir * lo), self.view.p(through + dir * hi));
            let near = |a: Point, b: Point| (a - b).norm() < STROKE_SAME_MM;
            let repeated =
                strokes.iter().any(|s| (near(s.ea, ea) && near(s.eb, eb)) || (near(s.ea, eb) && near(s.eb, ea)));
            if (eb - ea).norm() >= STROKE_MIN_MM && !repeated {
                strokes.push(Stroke { joint, slider, through, dir, ea, eb, length: hi - lo });
            }
        }
        let named = strokes.len() > 1;
        let mut drawn_lines = Vec::new();
        for Stroke { joint, slider, through, dir, ea, eb, length } in strokes {
            let n_world = dir.turn_90();
            let hatch_side = self.view.dir(n_world * self.hatch_side(joint, through, n_world));
            // On the numbers' side, the dimension line beyond them: between the guide and
            // it, their leaders cross it no more (the offset crank-slider's «8» and «4»
            // hung across its H).
            let beyond = numbers.iter().find(|n| n.slider == slider).map_or(0.0, numbers_depth);
            let all = Obstacles::of_items(&g.items);
            let contours =
                Obstacles::of_items(g.items.iter().filter(|i| matches!(i, Item::Path { pen, .. } if *pen == MAIN)));
            let inside = g.region.inflate(-5.0, -5.0);
            // The dimension line and its extension lines, run `past` mm beyond it (as drawn,
            // 2 mm: `dimension`; the cost and the fit count them to the dimension line).
            let lines_past = |off: Vec2, past: f64| {
                let ext = off + off / off.norm().max(tol::PAPER) * past;
                [(ea + off, eb + off), (ea, ea + ext), (eb, eb + ext)]
            };
            let lines = |off: Vec2| lines_past(off, 0.0);
            let cost = |off: Vec2| -> usize {
                lines(off).iter().map(|&(a, b)| 10 * contours.hits_segment(a, b) + all.hits_segment(a, b)).sum()
            };
            let hatch_off = SLIDER.1 / 2.0
                + 2.5
                + if self.numbers_beyond_hatching && beyond > 0.0 { NUMBERS_GAP + beyond + NUMBERS_GAP } else { 4.0 };
            let rod_off = if beyond > 0.0 { SLIDER.1 / 2.0 + NUMBERS_GAP + beyond + NUMBERS_GAP } else { 6.0 };
            let candidates = [
                hatch_side * hatch_off,
                hatch_side * (hatch_off + 4.0),
                -hatch_side * rod_off,
                -hatch_side * (rod_off + 4.0),
            ];
            let fits = |off: &Vec2| lines(*off).iter().all(|&(a, b)| inside.contains(a) && inside.contains(b));
            // A line across a text (the trajectories' legend under a long stroke) only where
            // every offset that fits crosses one: the cost counts lines alone.
            let crosses_text = |off: &Vec2| lines_past(*off, 2.0).iter().any(|&(a, b)| all.segment_crosses_text(a, b));
            let fitting = candidates.into_iter().filter(fits);
            let Some(off) = fitting.min_by_key(|&off| (crosses_text(&off), cost(off))) else { continue };
            // Without its unit, as GOST 2.307 writes a drawing's millimetres.
            let value = format!(" = {}", fmt::trimmed(1e3 * length, self.words.lang));
            let sub = if named { self.m.name(slider) } else { "" };
            let label = LabelText::new("H", sub).with_tail(value);
            // Its value over the line (GOST 2.307): where the slider's numbers leave no room
            // there, the line a value's height further out (the worked example's H stood
            // under its line, the numbers 1, 2 and 6 over it).
            let further = off + off / off.norm().max(tol::PAPER) * VALUE_ROOM;
            let over = [off, further].into_iter().filter(|o| *o == off || (fits(o) && !crosses_text(o))).find(|&o| {
                let since = g.items.len();
                dimension(g, ea, eb, o);
                let written = value_along(g, (&all, since), &label, (ea + o, eb + o), 3.5, inside, true);
                if !written {
                    g.items.truncate(since);
                }
                written
            });
            if let Some(o) = over {
                labels.keep_leaders_off((ea + o, eb + o));
                drawn_lines.push((ea + o, eb + o));
                continue;
            }
            let since = g.items.len();
            let mid = dimension(g, ea, eb, off);
            let line = (ea + off, eb + off);
            labels.keep_leaders_off(line);
            drawn_lines.push(line);
            if value_along(g, (&all, since), &label, line, 3.5, inside, false) {
                continue;
            }
            // An oblique stroke's value along its line too, as GOST 2.307 writes it (a
            // V-compressor's «H_B = 100 mm» stood level 4 mm off its slanted line).
            let oblique = (line.1 - line.0).x.abs() > tol::PAPER && (line.1 - line.0).y.abs() > tol::PAPER;
            let drawn = || Obstacles::of_items(&g.items);
            match oblique.then(|| along_line((&drawn(), inside), line, (&label, 3.5), Some(off))).flatten() {
                Some(text) => g.text(text),
                None => labels.add(mid, off, label, 3.5),
            }
        }
        drawn_lines
    }
}
