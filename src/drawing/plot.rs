//! Diagrams as the course draws them: data against two axes, each at a stated scale, the x
//! axis through y = 0 and the y axis at the start of x, arrows at the positive ends, ticks
//! with their values and the axes' names. The load diagram of sheet 1 uses it; the cam
//! diagrams of sheet 3 will.

use super::labels::Language;
use super::scene::{Anchor, Group, Pen, THIN, Text};
use super::symbols::{ARROW_HALF, vector};
use super::{fmt, scale};
use kurbo::{Point, Rect};

/// Length of a tick mark, mm, and how far an axis runs past its data for the arrow. The x
/// axis' name stands after its arrow: a plot needs `OVERRUN` + 1 mm + the name's width of room
/// on its right.
const TICK: f64 = 1.5;
const OVERRUN: f64 = 6.0;
/// Lettering of tick values and axis names, mm.
const TEXT: f64 = 2.5;

/// One axis: the data range it shows, its scale (data units per mm), its name and ticks.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub lo: f64,
    pub hi: f64,
    /// Data units per paper millimetre.
    pub mu: f64,
    /// Written at the arrow, e.g. "S/H" or "P, N".
    pub name: String,
    /// Values to mark, with their labels as the sheet prints them.
    pub ticks: Vec<(f64, String)>,
}

/// A diagram placed on the sheet: where data (0, 0) falls on paper, and its two axes.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    pub origin: Point,
    pub x: Axis,
    pub y: Axis,
    /// Whether the x values stand above the x axis; `None`: on the side with less of the
    /// data range.
    pub x_above: Option<bool>,
}

impl Plot {
    /// A plot whose data ranges fill `area` (x from its left, y from its bottom); the ranges
    /// must include 0 on y, where the x axis runs.
    pub fn in_area(area: Rect, x: Axis, y: Axis) -> Plot {
        let origin = Point::new(area.x0 - x.lo / x.mu, area.y1 + y.lo / y.mu);
        Plot { origin, x, y, x_above: None }
    }

    /// The paper point of data (x, y).
    pub fn at(&self, x: f64, y: f64) -> Point {
        Point::new(self.origin.x + x / self.x.mu, self.origin.y - y / self.y.mu)
    }

    /// The paper box of the data ranges.
    pub fn area(&self) -> Rect {
        Rect::from_points(self.at(self.x.lo, self.y.lo), self.at(self.x.hi, self.y.hi))
    }

    /// Straight lines through data points.
    pub fn line(&self, g: &mut Group, data: &[(f64, f64)], pen: Pen) {
        g.path(data.iter().map(|&(x, y)| self.at(x, y)).collect(), false, pen);
    }

    /// The left end of the y axis's values and name as [`Plot::draw_axes`] writes them, mm:
    /// what a text set left of the axis keeps clear of.
    pub fn y_labels_left(&self) -> f64 {
        let x0 = self.at(self.x.lo, 0.0).x;
        let m = crate::font::metrics();
        let values = self.y.ticks.iter().map(|(v, l)| self.y_value(*v, l));
        // Every one anchored at its end: its left is its end less its width.
        values.chain([self.y_name()]).map(|t| t.at.x - m.width(&t.text, t.h)).fold(x0 - TICK, f64::min)
    }

    /// The baselines of the y axis's values as [`Plot::draw_axes`] writes them, mm: what a
    /// text set level beside them keeps off (on one baseline, they read as one phrase).
    pub fn y_value_baselines(&self) -> impl Iterator<Item = f64> + '_ {
        self.y.ticks.iter().map(|(v, l)| self.y_value(*v, l).at.y)
    }

    /// A y tick's value, left of its tick mark.
    fn y_value(&self, v: f64, label: &str) -> Text {
        let p = Point::new(self.at(self.x.lo, 0.0).x, self.at(0.0, v).y);
        Text::new(Point::new(p.x - TICK - 0.8, p.y + TEXT / 2.0), label.to_string(), TEXT, Anchor::End)
    }

    /// The y axis's name, left of its arrow, a millimetre clear of the arrowhead's side (the
    /// slanted letters' tops lean towards it).
    fn y_name(&self) -> Text {
        let (x0, a) = (self.at(self.x.lo, 0.0).x, self.area());
        let x = x0 - ARROW_HALF - 1.0;
        Text::new(Point::new(x, a.y0 - OVERRUN + TEXT), self.y.name.clone(), TEXT, Anchor::End)
    }

    /// The axes with arrows, tick marks, tick values and names (labels placed afterwards
    /// keep clear of them).
    pub fn draw_axes(&self, g: &mut Group) {
        let a = self.area();
        let x0 = self.at(self.x.lo, 0.0).x;
        let y_of_x_axis = self.at(0.0, 0.0).y;
        vector(g, Point::new(x0, y_of_x_axis), Point::new(a.x1 + OVERRUN, y_of_x_axis), THIN);
        vector(g, Point::new(x0, a.y1 + TICK), Point::new(x0, a.y0 - OVERRUN), THIN);
        let text = |g: &mut Group, t: Text| g.text(t);
        let above = self.x_values_above();
        for (v, label) in &self.x.ticks {
            let p = self.at(*v, 0.0);
            g.line(p, Point::new(p.x, p.y + if above { -TICK } else { TICK }), THIN);
            if !label.is_empty() {
                text(g, self.x_value(*v, label));
            }
        }
        for (v, label) in &self.y.ticks {
            let p = Point::new(x0, self.at(0.0, *v).y);
            g.line(p, Point::new(p.x - TICK, p.y), THIN);
            if !label.is_empty() {
                text(g, self.y_value(*v, label));
            }
        }
        text(
            g,
            Text::new(
                Point::new(a.x1 + OVERRUN + 1.0, y_of_x_axis + TEXT / 2.0),
                self.x.name.clone(),
                TEXT,
                Anchor::Start,
            ),
        );
        text(g, self.y_name());
    }
}

impl Plot {
    /// Whether the x values stand above the x axis: as set, else on the side with less of
    /// the data range, where the curves are least likely to run through them (above it when
    /// the data lies mostly below zero, as a resistance does).
    pub fn x_values_above(&self) -> bool {
        self.x_above.unwrap_or(-self.y.lo > self.y.hi)
    }

    /// The x axis' value `label` at `v` as [`Plot::draw_axes`] sets it: under its tick, or
    /// over it (on the side with less of the data range); the value at the y axis beside it
    /// rather than across it.
    pub fn x_value(&self, v: f64, label: &str) -> Text {
        let p = self.at(v, 0.0);
        let above = self.x_values_above();
        let baseline = if above { -(TICK + 0.8) } else { TICK + TEXT + 0.8 };
        // Beside the y axis where its line runs past the value, farther off: over the x axis
        // the y axis always reaches up to its arrow, under it where its range goes below
        // zero (0.8 mm left a slanted «0» within 0.4 mm of a load diagram's P axis, its
        // range all below zero).
        let axis_beside = above || self.y.lo < 0.0;
        let off = if axis_beside { 1.4 } else { 0.8 };
        let (x, anchor) = if v == self.x.lo { (p.x + off, Anchor::Start) } else { (p.x, Anchor::Middle) };
        Text::new(Point::new(x, p.y + baseline), label, TEXT, anchor)
    }
}

/// Ticks of an axis at a round step (the round value at or above a sixth of the range, and
/// at least 4 mm on paper), without zero, where the other axis crosses: the values as the
/// sheet in `lang` prints them.
pub fn round_ticks(lo: f64, hi: f64, mu: f64, lang: Language) -> Vec<(f64, String)> {
    let step = scale::round_up((hi - lo) / 6.0);
    // Ticks closer than 4 mm would print their values on each other.
    let step = if step / mu < 4.0 { scale::round_up(4.0 * mu) } else { step };
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last)
        .filter(|&k| k != 0)
        .map(|k| {
            let v = k as f64 * step;
            (v, fmt::localise(&scale::format(v), lang))
        })
        .collect()
}

/// Ticks at the diagram's own force levels (each printed with its value left of the P
/// axis, however near the S/H axis, from a millimetre off it; closer ones than 4 mm
/// merged), then the round ticks of [`round_ticks`] that keep 7 mm clear of them and do not
/// stand between two of them closer than 8 mm: a reader finds P_max, the idle level and
/// every corner's level on the axis, and the round numbers apart from them (6 mm apart, a
/// teacher read the worked example's «−4000» over «−4600» as crowded).
pub fn level_ticks(levels: &[f64], lo: f64, hi: f64, mu: f64, lang: Language) -> Vec<(f64, String)> {
    const CLEAR: f64 = 4.0;
    const ROUND_CLEAR: f64 = 7.0;
    let mut marked: Vec<f64> = Vec::new();
    // A level nearer the axis than a millimetre is drawn on it.
    let mut sorted: Vec<f64> = levels.iter().copied().filter(|v| v.abs() / mu >= 1.0).collect();
    sorted.sort_by(|a, b| b.abs().total_cmp(&a.abs()));
    for v in sorted {
        if marked.iter().all(|m| (m - v).abs() / mu >= CLEAR) {
            marked.push(v);
        }
    }
    // Written alike, at the largest's decimals: «203.6» under «1357» read as two precisions.
    let mut ticks: Vec<(f64, String)> = marked.iter().copied().zip(fmt::values_alike(&marked, lang)).collect();
    // A round value between two levels both within twice that reads as one more corner's
    // level ("9121, 8000, 7069" up an indicator diagram's axis): it goes too.
    let within = |v: f64, above: bool| marked.iter().any(|&m| (m > v) == above && (m - v).abs() / mu < 2.0 * CLEAR);
    let round = round_ticks(lo, hi, mu, lang);
    ticks.extend(round.into_iter().filter(|&(v, _)| {
        marked.iter().all(|m| (m - v).abs() / mu >= ROUND_CLEAR) && !(within(v, true) && within(v, false))
    }));
    ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
    ticks
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(lo: f64, hi: f64, mu: f64) -> Axis {
        Axis { lo, hi, mu, name: "x".into(), ticks: vec![] }
    }

    #[test]
    fn data_maps_onto_its_area_at_its_scales() {
        let area = Rect::new(10.0, 20.0, 110.0, 70.0);
        let p = Plot::in_area(area, axis(0.0, 1.0, 0.01), axis(-100.0, 400.0, 10.0));
        assert_eq!(p.at(0.0, -100.0), Point::new(10.0, 70.0));
        assert_eq!(p.at(1.0, 400.0), Point::new(110.0, 20.0));
        assert_eq!(p.area(), area);
        assert_eq!(p.at(0.5, 0.0), Point::new(60.0, 60.0), "the x axis runs through y = 0");
    }

    #[test]
    fn round_ticks_cover_the_range_at_a_round_step_without_zero() {
        let t = round_ticks(-4600.0, 1650.0, 100.0, Language::Ru);
        let values: Vec<f64> = t.iter().map(|x| x.0).collect();
        // The step is the round value at or above a sixth of the 6250 N range: 2000 N.
        assert_eq!(values, [-4000.0, -2000.0]);
        assert_eq!(t[0].1, "−4000");
        // At 100 N/mm a 200 N step would be 2 mm apart: it grows to 400 N, 4 mm on paper.
        let dense: Vec<f64> = round_ticks(0.0, 1200.0, 100.0, Language::En).iter().map(|x| x.0).collect();
        assert_eq!(dense, [400.0, 800.0, 1200.0]);
    }

    #[test]
    fn level_ticks_mark_every_level_and_keep_round_ones_clear_of_them() {
        // A working stroke at −1299 N and an idle one at −130 N, at 20 N/mm.
        let t = level_ticks(&[-1299.0, -130.0, -1299.0, 0.0], -1299.0, 0.0, 20.0, Language::Ru);
        let values: Vec<f64> = t.iter().map(|x| x.0).collect();
        // Round step 250 N (a sixth of 1299 N, rounded up): −1250 is 2.45 mm from −1299 and
        // −250 6 mm from −130: both go; −500 is 18.5 mm from −130 and stays.
        assert_eq!(values, [-1299.0, -1000.0, -750.0, -500.0, -130.0]);
        assert_eq!(t[0].1, "−1299");
        // A small idle level 1.5 mm from the axis is marked (its value left of the P axis,
        // where the S/H axis does not run); one 0.5 mm from it is drawn on the axis.
        let idle = level_ticks(&[30.0, -1000.0], -1000.0, 30.0, 20.0, Language::En);
        assert!(idle.iter().any(|x| x.0 == 30.0 && x.1 == "30"), "{idle:?}");
        assert!(level_ticks(&[10.0], 0.0, 1000.0, 20.0, Language::En).iter().all(|x| x.0 != 10.0));
        // One precision up the axis: the offset crank-slider's levels read «203.6» under
        // «1357»; at the largest's four digits, 6786 N, every level is whole.
        let alike = level_ticks(&[203.6, 1357.2, 6786.0], 0.0, 6786.0, 50.0, Language::En);
        let written: Vec<&str> = alike.iter().filter(|x| x.0 % 1000.0 != 0.0).map(|x| x.1.as_str()).collect();
        assert_eq!(written, ["204", "1357", "6786"]);
        // Round step 2000 N at 250 N/mm. Between levels at 9900 and 6100 N, both 7.6 mm off
        // it, 8000 goes; with the lower level at 5000 N, 12 mm off, it stays.
        let sandwiched = level_ticks(&[9900.0, 6100.0, 0.0], 0.0, 9900.0, 250.0, Language::En);
        assert!(sandwiched.iter().all(|x| x.0 != 8000.0), "{sandwiched:?}");
        let open = level_ticks(&[9900.0, 5000.0, 0.0], 0.0, 9900.0, 250.0, Language::En);
        assert!(open.iter().any(|x| x.0 == 8000.0), "{open:?}");
        // The worked example's −4000 N, 6 mm from its working level −4600 N at 100 N/mm.
        let worked = level_ticks(&[1650.0, -4600.0, 0.0], -4600.0, 1650.0, 100.0, Language::Ru);
        assert!(worked.iter().all(|x| x.0 != -4000.0) && worked.iter().any(|x| x.0 == -2000.0), "{worked:?}");
    }
}
