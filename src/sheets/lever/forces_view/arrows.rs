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
/// one from the same point in (nearly) the same direction as an earlier one beside that.
pub(super) struct Arrows {
    /// The drawing's world-to-paper map.
    pub(super) view: View,
    /// The drawing's link lines, paper mm.
    pub(super) links: Vec<(Point, Point)>,
    /// Slider blocks: centre, unit direction along the block, half length and half width.
    pub(super) blocks: Vec<(Point, Vec2, f64, f64)>,
    pub(super) drawn: Vec<(Point, Vec2)>,
    pub(super) mu_f: f64,
    pub(super) h: f64,
}

/// How far an arrow along a link or another arrow is set beside it, mm.
const BESIDE: f64 = 2.5;
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
        let len = natural.clamp(ARROW_MIN, ARROW_MAX);
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
        let twins = self.drawn.iter().filter(|(p, e)| (*p - at).norm() < 1.0 && e.dot(d) > 1.0 - ALONG).count();
        start += n * (BESIDE * twins as f64);
        self.drawn.push((at, d));
        let tip = start + d * len;
        if (start - (at + d * exit)).norm() > 0.0 {
            g.line(at + d * exit, start, THIN);
        }
        vector(g, start, tip, VECTOR);
        labels.add(start + d * (len * 0.55), n, label, self.h);
        natural < ARROW_MIN
    }
}
