//! The diagrams' axes: the ticks in the tables' units, the analogs' values set clear of the
//! poles' rays, and the integrated curves' ordinates.

use crate::drawing::fmt;
use crate::drawing::labels::Language;
use crate::drawing::obstacles::{Obstacles, segment_meets_rect};
use crate::drawing::path::Path;
use crate::drawing::phrases;
use crate::drawing::plot::{Plot, round_ticks};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, THIN, Text};
use crate::drawing::text::LabelText;
use crate::num::units;
use kurbo::{Point, Rect};
use std::f64::consts::PI;

/// The displacement's ticks in the tables' units, round there: mm for a translating
/// follower, degrees for a rocker (the values stay in SI for the plot).
pub(super) fn lift_ticks(lift: f64, mu_s: f64, rocker: bool, lang: Language) -> Vec<(f64, String)> {
    let k = if rocker { 180.0 / PI } else { units::MM_PER_M };
    round_ticks(0.0, lift * k, mu_s * k, lang).into_iter().map(|(v, t)| (v / k, t)).collect()
}

/// Tick marks without their values: on a graph with a pole the rays cross the values' place
/// ([`axis_values`] writes them, and breaks the rays where they cross a value).
pub(super) fn unlabelled(ticks: Vec<(f64, String)>) -> Vec<(f64, String)> {
    ticks.into_iter().map(|(v, _)| (v, String::new())).collect()
}

/// The ordinates of the integrated curve at the division points, thin, from the axis: what the
/// course measures the table's values on. Those under half a millimetre are left out.
pub(super) fn ordinates(g: &mut Group, plot: &Plot, drawn: &[(f64, f64)]) {
    for &(x, y) in drawn {
        if (y / plot.y.mu).abs() >= 0.5 {
            g.line(plot.at(x, 0.0), plot.at(x, y), THIN);
        }
    }
}

/// The y axis' values of a graph with a pole, and the pole's `rays` (from the pole to the
/// axis): each value beside its tick, right of the axis (the rays fill the left) where the
/// curves leave room, with the tick carried across the axis to it, else left of it, where
/// the rays crossing its place are broken for it (GOST 2.307: the lines of a drawing are
/// interrupted where a number is written), else left out where a curve or a text holds
/// both places (the graph's scale is written above the pole). The values of one side of
/// the x axis stand on one side of the y axis where all of them can (0.4 and 0.8 left of
/// it with 1.2 and 1.6 right read as two scales).
/// `start` marks the graph's first item: only its own lines are asked.
pub(super) fn axis_values(g: &mut Group, plot: &Plot, ticks: &[(f64, String)], start: usize, rays: &[(Point, Point)]) {
    let drawn = Obstacles::of_items(&g.items[start..]);
    let x0 = plot.at(plot.x.lo, 0.0).x;
    let clear = |r: Rect| drawn.is_clear(r.inflate(0.3, 0.3));
    let off_rays = |r: Rect| !rays.iter().any(|&(a, b)| segment_meets_rect(a, b, r.inflate(0.3, 0.3)));
    let places: Vec<Place> = ticks
        .iter()
        .map(|(v, value)| {
            let y_tick = plot.at(0.0, *v).y;
            let y = y_tick + VALUE_H / 2.0;
            let w = LabelText::new(value.as_str(), "").width(VALUE_H);
            let xr = x0 + VALUE_TICK + 0.8;
            let right = Rect::new(x0 + 0.6, y - VALUE_H, xr + w, y);
            // Left of the axis the rays may cross it: they are broken for it.
            // Its letters' own box (the slant and a subscript's drop of the scale's text above
            // reach past a box of the value's width).
            let left_text = Text::new(Point::new(x0 - LEFT_OFF, y), value.clone(), VALUE_H, Anchor::End);
            // A text level with it (the scale's, above the pole) stays a phrase's gap away:
            // «μ_ds/dφ = 0,04 m/mm» 2.7 mm before «2000» read as one.
            let apart = phrases::APART * VALUE_H;
            let left = clear(left_box(x0, y, w))
                && drawn.is_clear(left_text.bbox().inflate(0.5, 0.5))
                && !drawn.text_box_meets(Rect::new(left_text.bbox().x0 - apart, y - 0.6 * VALUE_H, x0, y), |_| true);
            Place { above: *v > 0.0, y_tick, right: clear(right) && off_rays(right), left }
        })
        .collect();
    let sides = [side_of_half(&places, false), side_of_half(&places, true)];
    let mut gaps = Vec::new();
    for ((_, value), p) in ticks.iter().zip(&places) {
        let y = p.y_tick + VALUE_H / 2.0;
        let right = match sides[usize::from(p.above)] {
            Some(right) => right,
            None if p.right || p.left => p.right,
            None => continue,
        };
        if right {
            g.line(Point::new(x0, p.y_tick), Point::new(x0 + VALUE_TICK, p.y_tick), THIN);
            g.text(Text::new(Point::new(x0 + VALUE_TICK + 0.8, y), value.clone(), VALUE_H, Anchor::Start));
        } else {
            let text = Text::new(Point::new(x0 - LEFT_OFF, y), value.clone(), VALUE_H, Anchor::End);
            // The lettering's own box: its slant and the comma's tail reach past `left_box`.
            gaps.push(text.bbox().inflate(RAY_GAP, RAY_GAP));
            g.text(text);
        }
    }
    for &(a, b) in rays {
        let ray = Path::polyline(&[a, b], false);
        match ray.outside_rects(&gaps) {
            Some(pieces) => pieces.into_iter().for_each(|piece| g.curve(piece, THIN)),
            None => g.curve(ray, THIN),
        }
    }
}

/// Per side of the x axis (`above`): right of the y axis if all its values fit there, else
/// left if they all fit there (the rays broken for them), else each its own (`None`).
fn side_of_half(places: &[Place], above: bool) -> Option<bool> {
    let half = || places.iter().filter(move |p| p.above == above);
    if half().all(|p| p.right) {
        Some(true)
    } else if half().all(|p| p.left) {
        Some(false)
    } else {
        None
    }
}

/// A value's box left of the y axis at `x0`, its baseline `y`, its width `w`.
fn left_box(x0: f64, y: f64, w: f64) -> Rect {
    Rect::new(x0 - LEFT_OFF - w, y - VALUE_H, x0 - LEFT_OFF, y)
}

/// Where a tick's value may stand: its tick's height, whether the x axis' upper side holds
/// it, whether its place right of the y axis is clear, and whether its place left of it is
/// (the pole's rays aside).
struct Place {
    above: bool,
    y_tick: f64,
    right: bool,
    left: bool,
}

/// An analog's ticks each side of its axis (`peak` its largest value): at a round step
/// about a tenth of the range and at least [`VALUE_STEP_MM`] apart, the values in mm for a
/// translating follower (as its tables give them), without unit for a rocker.
pub(super) fn analog_ticks(peak: f64, mu: f64, rocker: bool, lang: Language) -> Vec<(f64, String)> {
    let k = if rocker { 1.0 } else { units::MM_PER_M };
    let step = scale::round_up(2.0 * peak * k / 10.0).max(scale::round_up(VALUE_STEP_MM * mu * k));
    let n = (peak * k / step * (1.0 + 1e-9)).floor() as i64;
    (-n..=n)
        .filter(|&i| i != 0)
        .map(|i| {
            let v = i as f64 * step;
            (v / k, fmt::localise(&scale::format(v), lang))
        })
        .collect()
}

/// The analogs' values at least this far apart, mm.
const VALUE_STEP_MM: f64 = 8.0;
/// The plots' tick length, mm: a value right of the axis gets its tick there too.
const VALUE_TICK: f64 = 1.5;

/// A value left of the y axis ends this far from it, mm: past its tick (the plot's, drawn
/// left of the axis) by 1.3 mm, so that its lettering's slant, with the clearance asked,
/// keeps off the tick (at 0.8 mm past it every value's place left of the axis met its own
/// tick, and where the curve held the right, as the worked example's 0,4 and 0,8 of
/// d²s/dφ², the value was left out).
const LEFT_OFF: f64 = VALUE_TICK + 1.3;

/// The axis values' lettering height, mm (the plots' own).
const VALUE_H: f64 = 2.5;
/// A ray's gap for a value is this much wider than the value's box each side, mm: a
/// break as wide as the letters' strokes are apart reads, printed, as the ray run through
/// them (0.5 mm: a teacher read the worked example's 0,8 of d²s/dφ² as struck out).
const RAY_GAP: f64 = 1.2;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::plot::Axis;
    use crate::drawing::scene::{Item, MAIN};
    use crate::num::math::Norm;

    /// A graph whose curve rises steeply along its y axis (no value fits right of it) and
    /// whose pole's rays cross every value's place left of it: every value is written left,
    /// none is left out, and no ray comes within 1 mm of a value's lettering (each is broken
    /// for it, wide enough to read as broken, and still reaches the axis). The plot's own
    /// tick marks, left of the axis, are drawn as on the sheet: the values' places left of
    /// the axis once all met them, and the worked example's 0,4 and 0,8 of d²s/dφ² were
    /// left out.
    #[test]
    fn values_crossed_by_the_rays_are_written_with_the_rays_broken_for_them() {
        let ticks: Vec<(f64, String)> = [-40.0, -20.0, 20.0, 40.0].iter().map(|&v| (v, format!("{v}"))).collect();
        let axis = |lo: f64, hi: f64, mu: f64| Axis { lo, hi, mu, name: String::new(), ticks: Vec::new() };
        let plot = Plot {
            origin: Point::new(100.0, 100.0),
            x: axis(0.0, 100.0, 1.0),
            y: Axis { ticks: unlabelled(ticks.clone()), ..axis(-50.0, 50.0, 1.0) },
            x_above: None,
        };
        let mut g = Group::new("test", Rect::new(0.0, 0.0, 200.0, 200.0));
        let start = g.mark();
        plot.draw_axes(&mut g);
        plot.line(&mut g, &[(0.0, -50.0), (2.0, 0.0), (0.0, 50.0)], MAIN);
        let pole = Point::new(80.0, 100.0);
        let rays: Vec<(Point, Point)> = (-10..=10).map(|k| (pole, plot.at(0.0, 5.0 * k as f64 + 1.0))).collect();
        axis_values(&mut g, &plot, &ticks, start, &rays);
        let texts: Vec<_> = g
            .items
            .iter()
            .filter_map(|i| if let Item::Text(t) = i { Some(t.clone()) } else { None })
            .filter(|t| !t.text.is_empty())
            .collect();
        assert_eq!(texts.len(), ticks.len(), "every value written");
        assert!(texts.iter().all(|t| t.at.x < 100.0), "left of the axis, the curve holding the right");
        let strokes: Vec<(Point, Point)> = g.items[1..]
            .iter()
            .filter_map(|i| match i {
                Item::Path { path, .. } => Some((path.start, path.end())),
                _ => None,
            })
            .collect();
        for t in &texts {
            assert!(strokes.iter().all(|&(a, c)| !segment_meets_rect(a, c, t.bbox())), "a ray through {:?}", t.text);
            // The rays' pieces: on a line through the pole (the axis' own ticks stand nearer).
            let on_a_ray = |&&(a, c): &&(Point, Point)| ((a - pole).cross(c - pole)).abs() < 1e-6 * (c - pole).norm();
            let near = t.bbox().inflate(1.0, 1.0);
            assert!(
                strokes.iter().filter(on_a_ray).all(|&(a, c)| !segment_meets_rect(a, c, near)),
                "a ray near {:?}",
                t.text
            );
        }
        for &(_, end) in &rays {
            assert!(strokes.iter().any(|&(_, c)| c == end), "a ray ends short of the axis at {end:?}");
        }
        assert!(strokes.len() > rays.len(), "some rays are broken");
    }
}
