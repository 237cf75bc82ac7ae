//! A diagram's pole: its rays to the ordinates of the curve it integrates (or differentiates),
//! its name H and distance, and the scale text kept clear of its rays.

use super::CamWords;
use crate::drawing::fmt;
use crate::drawing::plot::Plot;
use crate::drawing::scene::{Anchor, Group};
use crate::drawing::text::LabelText;
use kurbo::Point;

/// Between a diagram's scale text and its axis's values, and the text's height, mm.
pub(super) const SCALE_GAP: f64 = 4.0;
pub(super) const SCALE_TEXT: f64 = 2.5;

/// The baseline of the `k`-th line of scale text set from `at` down: the first 3 mm under
/// `at`, the next 4.5 mm apart.
pub(super) fn scale_line(at: Point, k: usize) -> Point {
    Point::new(at.x, at.y + 3.0 + 4.5 * k as f64)
}

/// Lines of scale text at the graph's top left (above the pole's rays), from `at` down.
pub(super) fn scale_text(g: &mut Group, at: Point, lines: &[LabelText]) {
    for (k, t) in lines.iter().enumerate() {
        t.draw(g, scale_line(at, k), SCALE_TEXT, Anchor::Start);
    }
}

/// The highest of a pole's rays (at H left of the plot's origin, to the ordinates `ys` at
/// `mu` a mm): the one the scale texts above the axis may reach.
pub(super) fn top_ray(plot: &Plot, h: f64, ys: &[f64], mu: f64) -> (Point, Point) {
    let high = ys.iter().copied().fold(0.0, f64::max);
    (Point::new(plot.origin.x - h, plot.origin.y), Point::new(plot.origin.x, plot.origin.y - high / mu))
}

/// The scale `lines` at their place ([`above_pole`] from `(x, top, axis)`) with each line
/// whose end would cross the pole's highest ray `ray` broken after its "=": a long μ (a
/// short H, "μ_d²s/dφ² = 0.0005968 m/mm") reached into the fan.
pub(super) fn clear_of_rays(
    lines: &[LabelText],
    (x, top, axis): (f64, f64, f64),
    ray: (Point, Point),
) -> (Point, Vec<LabelText>) {
    let at = above_pole(x, top, axis, lines);
    let crosses = |t: &LabelText, k: usize| {
        let b = t.text(scale_line(at, k), SCALE_TEXT, Anchor::Start).bbox();
        crate::drawing::obstacles::segment_meets_rect(ray.0, ray.1, b.inflate(0.5, 0.5))
    };
    let broken: Vec<LabelText> = lines
        .iter()
        .enumerate()
        .flat_map(|(k, t)| match t.tail.strip_prefix(" = ") {
            Some(value) if crosses(t, k) => {
                vec![LabelText { tail: " =".into(), ..t.clone() }, LabelText::new(value, "")]
            }
            _ => vec![t.clone()],
        })
        .collect();
    (above_pole(x, top, axis, &broken), broken)
}

/// Where a graph's scale `lines` start: at its top `top`, or higher where a low graph would
/// bring their last line down to the pole's name on the axis at `axis` (the letters' boxes
/// 2 mm apart: a line's depth under its baseline 0.6 mm, the name's height over its own
/// baseline, 1 mm under the axis, 1.8 mm).
pub(super) fn above_pole(x: f64, top: f64, axis: f64, lines: &[LabelText]) -> Point {
    let last = scale_line(Point::ZERO, lines.len().max(1) - 1).y;
    Point::new(x, top.min(axis + 1.0 - 1.8 - 2.0 - 0.6 - last))
}

/// A pole: its distance H from the origin, mm, and its index.
pub(super) struct Pole<'a> {
    pub(super) h: f64,
    pub(super) index: &'a str,
}

/// The pole at H left of the origin on the x axis, and its rays to the ordinates `ys` (at
/// `mu` a mm) carried to the y axis, returned to be drawn once the axis' values are set
/// ([`axis_values`] breaks them for a value): each chord of the integral is drawn parallel
/// to its ray.
pub(super) fn pole(
    g: &mut Group,
    plot: &Plot,
    pole: Pole,
    ys: &[f64],
    mu: f64,
    words: &CamWords,
) -> Vec<(Point, Point)> {
    let h = pole.h;
    let p = Point::new(plot.origin.x - h, plot.origin.y);
    g.dot(p, 0.6);
    // H with its index as the sheet's other subscripts, clear of the pole's dot.
    let text = LabelText::new("H", pole.index).with_tail(format!(
        " = {} {}",
        fmt::trimmed(h, words.lang),
        words.common.unit_mm()
    ));
    text.draw(g, Point::new(p.x - 2.5, p.y + 1.0), 2.5, Anchor::End);
    // One ray for equal ordinates (a symmetric law's chords): a line drawn twice over is
    // darker in one renderer than in another.
    let mut rays: Vec<(Point, Point)> = Vec::with_capacity(ys.len());
    for &y in ys {
        let ray = (p, Point::new(plot.origin.x, plot.origin.y - y / mu));
        if !rays.iter().any(|r| (r.1 - ray.1).hypot2() < 1e-18) {
            rays.push(ray);
        }
    }
    rays
}
