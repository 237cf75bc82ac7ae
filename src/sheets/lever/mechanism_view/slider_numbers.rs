//! Each slider's positions numbered on its guide, as the guide numbers D0 … D11.

use super::MechanismView;
use crate::drawing::place::Labels;
use crate::drawing::text::merged_labels;
use crate::lever::linkage::{PointId, Step};
use crate::num::math::Norm;
use kurbo::{Point, Vec2};

/// The length of a slider's stroke each of its position numbers needs (2.5 mm lettering), mm.
const SLIDER_NUMBER_MM: f64 = 5.0;
/// Where a slider's numbers leave a label no clean spot, its positions nearer than this on
/// paper are one point to the reader and share a number ("0 ≡ 1 ≡ 9"), as the cam's do:
/// round a dead centre the slider barely moves, and eight numbers within 5 mm left one no
/// spot off the guide's lines. Only then, or where three or more stand that near
/// ([`lingers`]): "1 ≡ 7" reads as positions that coincide.
pub(in crate::sheets::lever) const SLIDER_SAME_MM: f64 = 1.5;
/// Positions nearer than this on paper are one point to the eye (the guide's line is 0.5 mm
/// thick) and always share a number: a symmetric crank-slider's 1 and 11 stand on one point,
/// and two numbers side by side on leaders into it («9 3») read as two positions.
const SLIDER_ONE_POINT_MM: f64 = 0.5;

/// A slider's numbers as they will be written: at their points, on the guide's side `up`
/// (on paper, unit), and whether its stroke is short of room for every position.
pub(super) struct SliderNumbers {
    /// The slider's point.
    pub slider: PointId,
    pub up: Vec2,
    pub numbers: Vec<(Point, String)>,
    pub short: bool,
}

impl MechanismView<'_> {
    /// Each slider's positions numbered on the side of the guide away from its hatching
    /// (where the rod comes from), as [`Self::slider_number_plan`] plans them; returns the
    /// labels (by their order in `labels`) of the short strokes' numbers.
    pub(super) fn slider_numbers(&self, labels: &mut Labels, plans: Vec<SliderNumbers>) -> Vec<usize> {
        let mut short = Vec::new();
        for plan in plans {
            for (point, label) in plan.numbers {
                if plan.short {
                    short.push(labels.count());
                }
                labels.add_text_apart(point, plan.up, &label, 2.5, 2);
            }
        }
        short
    }

    /// The sliders whose positions are numbered: those whose stroke leaves each number room
    /// (those on one point share one); crowded, they would only hide the guide. `groups`
    /// are the runs of positions drawn as one. A slider travelling where one already
    /// numbered does (two pistons one behind the other, drawn on one axis) is left
    /// unnumbered: two numbers at every point would name neither.
    pub(super) fn slider_number_plan(&self, groups: &[Vec<usize>]) -> Vec<SliderNumbers> {
        let mut numbered: Vec<(Point, Point)> = Vec::new();
        let mut plans = Vec::new();
        for st in &self.m.steps {
            let Step::Rrp { p: joint, d, through, dir, .. } = *st else { continue };
            let (lo, hi) = self.travel(d, through, dir);
            let travel = (self.view.p(through + dir * lo), self.view.p(through + dir * hi));
            if numbered.iter().any(|&other| shares_travel(travel, other)) {
                continue;
            }
            let at = |group: &Vec<usize>| self.view.p(self.k.positions[group[0]].state.points[d].p);
            let numbers: Vec<(Point, String)> = groups.iter().map(|g| (at(g), self.joined_label(g))).collect();
            let same = if lingers(&numbers) { SLIDER_SAME_MM } else { self.slider_same_mm.max(SLIDER_ONE_POINT_MM) };
            // Positions on one point need one number's room; short of room for each
            // position, its numbers are tried (see `number_short_strokes`).
            let apart = merged(numbers.iter().cloned(), SLIDER_ONE_POINT_MM).len();
            let stroke = self.view.len(hi - lo);
            let short = stroke < SLIDER_NUMBER_MM * self.k.positions.len() as f64;
            if stroke < SLIDER_NUMBER_MM * apart as f64 || (short && !self.number_short_strokes) {
                continue;
            }
            let n_world = dir.turn_90();
            let up = self.view.dir(n_world * -self.hatch_side(joint, through, n_world));
            plans.push(SliderNumbers { slider: d, up, numbers: merged(numbers.into_iter(), same), short });
            numbered.push(travel);
        }
        plans
    }
}

/// Whether two travels on paper overlap on one line (within [`SLIDER_ONE_POINT_MM`]).
fn shares_travel((a, b): (Point, Point), (c, d): (Point, Point)) -> bool {
    let along = (b - a).unit();
    let off = |p: Point| along.cross(p - a).abs();
    let at = |p: Point| along.dot(p - a);
    let (c_at, d_at) = (at(c).min(at(d)), at(c).max(at(d)));
    off(c) < SLIDER_ONE_POINT_MM && off(d) < SLIDER_ONE_POINT_MM && c_at < (b - a).norm() && d_at > 0.0
}

/// Whether three or more of the numbers stand within [`SLIDER_SAME_MM`] of one: a slider
/// lingering at its dead centre, whose numbers share a label even where each would find a
/// spot (six numbers on leaders into one 1.5 mm cluster name no point a reader can tell).
fn lingers(numbers: &[(Point, String)]) -> bool {
    numbers.iter().any(|(p, _)| numbers.iter().filter(|(q, _)| (*q - *p).norm() < SLIDER_SAME_MM).count() >= 3)
}

/// The numbers at their points, each merged into the first earlier one nearer than `same`
/// mm ("10 ≡ 11") and dropped from its own point.
fn merged(numbers: impl Iterator<Item = (Point, String)>, same: f64) -> Vec<(Point, String)> {
    let (points, labels): (Vec<Point>, Vec<String>) = numbers.unzip();
    let near = |j: usize, k: usize| (points[j] - points[k]).norm() < same;
    points.iter().zip(merged_labels(labels, near, " ≡ ")).filter_map(|(&p, label)| Some((p, label?))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_within_a_point_share_the_first_ones_label() {
        let at = |x: f64| Point::new(x, 0.0);
        let numbers = [(at(0.0), "0"), (at(1.0), "1"), (at(9.0), "2"), (at(1.4), "3"), (at(1.6), "4")];
        let got = merged(numbers.iter().map(|(p, l)| (*p, l.to_string())), SLIDER_SAME_MM);
        let labels: Vec<&str> = got.iter().map(|(_, l)| l.as_str()).collect();
        // 1 and 3 are within 1.5 mm of 0; 4 is 1.6 mm from 0 and starts its own.
        assert_eq!(labels, ["0 ≡ 1 ≡ 3", "2", "4"]);
        assert_eq!(got[2].0, at(1.6));
        assert_eq!(merged(numbers.iter().map(|(p, l)| (*p, l.to_string())), 0.0).len(), 5);
    }
}
