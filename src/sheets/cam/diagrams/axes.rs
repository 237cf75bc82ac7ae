//! The diagrams' axes: the ticks in the tables' units, the analogs' values set clear of the
//! poles' rays, and the integrated curves' ordinates.

use crate::drawing::fmt;
use crate::drawing::labels::Language;
use crate::drawing::obstacles::Obstacles;
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
/// ([`axis_values`] writes them where they are clear, once the rays are drawn).
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

/// The y axis' values of a graph with a pole: each beside its tick, right of the axis (the
/// pole's rays fill the left) where the curves leave room, with the tick carried across the
/// axis to it, else left of it where no ray crosses the place, else left out (the graph's
/// scale is written above the pole). The values of one side of the x axis stand on one side
/// of the y axis where all of them can (0.4 and 0.8 left of it with 1.2 and 1.6 right read
/// as two scales). `start` marks the graph's first item: only its own lines are asked.
pub(super) fn axis_values(g: &mut Group, plot: &Plot, ticks: &[(f64, String)], start: usize) {
    let drawn = Obstacles::of_items(&g.items[start..]);
    let x0 = plot.at(plot.x.lo, 0.0).x;
    let clear = |r: Rect| drawn.is_clear(r.inflate(0.3, 0.3));
    let places: Vec<Place> = ticks
        .iter()
        .map(|(v, value)| {
            let y_tick = plot.at(0.0, *v).y;
            let y = y_tick + VALUE_H / 2.0;
            let w = LabelText::new(value.as_str(), "").width(VALUE_H);
            let xr = x0 + VALUE_TICK + 0.8;
            let right = clear(Rect::new(x0 + 0.6, y - VALUE_H, xr + w, y));
            let left = clear(Rect::new(x0 - 2.3 - w, y - VALUE_H, x0 - 2.3, y));
            Place { above: *v > 0.0, y_tick, right, left }
        })
        .collect();
    // Per side of the x axis: right of the y axis if all its values fit there, else left if
    // they all fit there, else each its own (`None`).
    let half = |above: bool| {
        let mut side = places.iter().filter(|p| p.above == above);
        if side.clone().all(|p| p.right) {
            Some(true)
        } else if side.all(|p| p.left) {
            Some(false)
        } else {
            None
        }
    };
    let sides = [half(false), half(true)];
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
            g.text(Text::new(Point::new(x0 - VALUE_TICK - 0.8, y), value.clone(), VALUE_H, Anchor::End));
        }
    }
}

/// Where a tick's value may stand: its tick's height and whether the x axis' upper side
/// holds it, and whether its place right and left of the y axis is clear.
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

/// The axis values' lettering height, mm (the plots' own).
const VALUE_H: f64 = 2.5;
