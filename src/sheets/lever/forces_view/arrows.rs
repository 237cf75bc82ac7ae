//! Force arrows on a drawing at a round μ_F, between a least and a greatest length, kept
//! apart from the links and from each other.

use super::{ARROW_MAX, ARROW_MIN};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Group, THIN, VECTOR};
use crate::drawing::symbols::vector;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Point, Vec2};

/// The round scale (N/mm) that draws the largest of `forces` no longer than [`ARROW_MAX`].
pub(super) fn arrow_scale(largest: f64) -> f64 {
    scale::round_up(largest.max(f64::MIN_POSITIVE) / ARROW_MAX)
}

/// Force arrows of one drawing, kept apart: an arrow along a link is drawn beside it, and
/// one from the same point in (nearly) the same direction as an earlier one slid along its
/// own line of action past that one's tip. Sliding keeps the force's moment about every
/// point (set beside, it would change its arm, which the lever and the groups' moment
/// equations are read by).
pub(super) struct Arrows {
    /// The drawing's world-to-paper map.
    pub(super) view: View,
    /// The drawing's link lines, paper mm.
    pub(super) links: Vec<(Point, Point)>,
    /// Slider blocks: centre, unit direction along the block, half length and half width.
    pub(super) blocks: Vec<(Point, Vec2, f64, f64)>,
    /// Each arrow drawn: its point, its unit direction on paper and how far from the point
    /// its tip is, mm.
    pub(super) drawn: Vec<(Point, Vec2, f64)>,
    pub(super) mu_f: f64,
    pub(super) h: f64,
}

/// How far an arrow along a link or another arrow is set beside it, mm.
const BESIDE: f64 = 2.5;
/// How far past an earlier twin's tip an arrow slid along its line starts, mm.
const TWIN_GAP: f64 = 1.5;
/// Directions closer than this (sine of the angle) count as along.
const ALONG: f64 = 0.17;

impl Arrows {
    /// Draws a force arrow from `at` (nothing for a zero force) and asks for its label
    /// beside its shaft; returns whether it was drawn at the minimum length.
    pub(super) fn arrow(
        &mut self,
        g: &mut Group,
        labels: &mut Labels,
        at: Point,
        force: Vec2,
        label: LabelText,
    ) -> bool {
        let f = force.norm();
        if f <= 0.0 {
            return false;
        }
        let natural = f / self.mu_f;
        let len = length(f, self.mu_f);
        let d = self.view.dir(force) / f;
        let n = d.turn_90();
        // A force on a slider starts at the block's outline, not under it.
        let exit = self.blocks.iter().find(|b| (b.0 - at).norm() < 0.5).map_or(0.0, |&(_, u, hl, hw)| {
            let (along, across) = (d.dot(u).abs(), d.dot(u.turn_90()).abs());
            (hl / along.max(tol::PARALLEL_SIN)).min(hw / across.max(tol::PARALLEL_SIN))
        });
        let mut start = at + d * exit;
        let along_link = self.links.iter().any(|&(a, b)| {
            let u = b - a;
            let on_line = (at - a).cross(u).abs() / u.norm().max(tol::PAPER) < 0.5;
            on_line && (d.cross(u) / u.norm().max(tol::PAPER)).abs() < ALONG
        });
        if along_link {
            start += n * BESIDE;
        }
        start += d * (past_twins(&self.drawn, at, d) - exit).max(0.0);
        let tip = start + d * len;
        self.drawn.push((at, d, (tip - at).norm()));
        if (start - (at + d * exit)).norm() > 0.0 {
            g.line(at + d * exit, start, THIN);
        }
        vector(g, start, tip, VECTOR);
        // Beside the arrow's middle, else nearer its tip or its tail on either side.
        let along = |k: f64| start + d * (len * k);
        let spots = [(along(0.55), n), (along(0.55), -n), (along(0.85), n), (along(0.85), -n), (along(0.25), n)];
        labels.add_at_any(&spots, label, self.h);
        natural < ARROW_MIN
    }
}

/// An arrow's length on paper for a force of `f` at `mu_f`, mm.
fn length(f: f64, mu_f: f64) -> f64 {
    (f / mu_f).clamp(ARROW_MIN, ARROW_MAX)
}

/// How far from `at` along `d` an arrow starts past the tips of the arrows `drawn` earlier
/// from the same point in nearly its direction, mm (0 for none).
fn past_twins(drawn: &[(Point, Vec2, f64)], at: Point, d: Vec2) -> f64 {
    drawn
        .iter()
        .filter(|(p, e, _)| (*p - at).norm() < 1.0 && e.dot(d) > 1.0 - ALONG)
        .map(|&(_, _, reach)| reach + TWIN_GAP)
        .fold(0.0, f64::max)
}

/// Each of `forces` (at its point on paper) as drawn at `mu_f`, twins slid along their
/// lines: its point, its unit direction and how far from the point its tip is, mm.
pub(super) fn twin_rows(forces: impl IntoIterator<Item = (Point, Vec2)>, mu_f: f64) -> Vec<(Point, Vec2, f64)> {
    let mut drawn: Vec<(Point, Vec2, f64)> = Vec::new();
    for (at, force) in forces {
        let f = force.norm();
        if f > 0.0 {
            let d = force / f;
            drawn.push((at, d, past_twins(&drawn, at, d) + length(f, mu_f)));
        }
    }
    drawn
}

/// The farthest an arrow's tip reaches from its point (see [`twin_rows`]), mm: the room a
/// drawing needs round its points.
pub(super) fn twins_reach(forces: impl IntoIterator<Item = (Point, Vec2)>, mu_f: f64) -> f64 {
    twin_rows(forces, mu_f).iter().map(|x| x.2).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::path::Seg;
    use crate::drawing::scene::Item;
    use kurbo::Rect;

    /// Three forces at one point, two along one line and one a few degrees off it (as a
    /// weight, an inertia force and a gas force at a piston): each arrow and its leader stay
    /// on its own line of action through the point, where its moment about any point is
    /// the force's, and no arrow lies on another.
    #[test]
    fn twin_forces_slide_along_their_lines_and_keep_their_arms() {
        let at = Point::new(50.0, 50.0);
        let forces = [Vec2::new(0.0, -300.0), Vec2::new(0.0, -120.0), Vec2::new(20.0, -200.0)];
        let view = View::new(Point::new(20.0, 80.0), 0.01);
        let mut arrows = Arrows { view, links: Vec::new(), blocks: Vec::new(), drawn: Vec::new(), mu_f: 20.0, h: 2.5 };
        let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
        let mut labels = Labels::new();
        let mut spans = Vec::new();
        for f in forces {
            let from = g.items.len();
            arrows.arrow(&mut g, &mut labels, at, f, LabelText::new("F", ""));
            let d = view.dir(f) / f.norm();
            // The shaft's ends (the leader along the line from the point is thin).
            let mut along: Vec<f64> = Vec::new();
            for item in &g.items[from..] {
                let Item::Path { path, pen } = item else { continue };
                let ends = std::iter::once(path.start).chain(path.segs.iter().filter_map(|s| match s {
                    Seg::Line(p) => Some(*p),
                    _ => None,
                }));
                for p in ends {
                    assert!((p - at).cross(d).abs() < 1e-9, "{f:?}: {p:?} is off the line through the point");
                    if *pen == VECTOR {
                        along.push((p - at).dot(d));
                    }
                }
            }
            spans.push((
                d,
                along.iter().copied().fold(f64::INFINITY, f64::min),
                along.iter().copied().fold(0.0, f64::max),
            ));
        }
        // The second (same direction as the first) starts past the first's tip.
        assert!(spans[1].1 > spans[0].2, "{spans:?}");
        // The room a drawing sizes for them is the farthest tip drawn.
        let tips = arrows.drawn.iter().map(|x| x.2).fold(0.0, f64::max);
        assert!((twins_reach(forces.map(|f| (at, view.dir(f))), 20.0) - tips).abs() < 1e-9);
    }
}
