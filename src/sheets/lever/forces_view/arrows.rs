//! Force arrows on a drawing at a round μ_F, between a least and a greatest length, kept
//! apart from the links and from each other.

use super::{ARROW_MAX, ARROW_MIN};
use crate::drawing::obstacles::{self, segments_cross};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Group, Item, THIN, VECTOR};
use crate::drawing::symbols::vector;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// The round scale (N/mm) that draws the largest of `forces` no longer than [`ARROW_MAX`].
pub(super) fn arrow_scale(largest: f64) -> f64 {
    scale::round_up(largest.max(f64::MIN_POSITIVE) / ARROW_MAX)
}

/// Force arrows of one drawing, kept apart: an arrow along a link is drawn beside it (or
/// pushing, at the link's end), one opposite to an earlier one at its point beside that (on
/// a group drawing), and
/// one from the same point in (nearly) the same direction as an earlier one drawn pushing
/// (its tip at the point, from the other side) where that side is free, else slid along its
/// own line of action past the earlier one's tip. Either keeps the force's moment about
/// every point (set beside, it would change its arm, which the lever and the groups' moment
/// equations are read by); pushing keeps the two arrows on either side of the point, where
/// slid end to end the first one's head read as a second head on the other's shaft.
pub(super) struct Arrows {
    /// The drawing's world-to-paper map.
    pub(super) view: View,
    /// The drawing's link lines, paper mm: an arrow along one is set beside it.
    pub(super) links: Vec<(Point, Point)>,
    /// Where arrows may be drawn pushing, what a pushing arrow keeps clear of: twins on
    /// the lever; on the group drawings (whose twins stand at blocks and centres of mass on
    /// their links and slide) an arrow into its link at the link's end. `None`: none pushes.
    pub(super) push: Option<Push>,
    /// Slider blocks: centre, unit direction along the block, half length and half width.
    pub(super) blocks: Vec<(Point, Vec2, f64, f64)>,
    /// Each arrow drawn: its point, the unit direction from the point along which it lies
    /// on paper (its force's, or the opposite for one drawn pushing) and how far from the
    /// point its farther end is, mm.
    pub(super) drawn: Vec<(Point, Vec2, f64)>,
    pub(super) mu_f: f64,
    pub(super) h: f64,
}

/// What a twin drawn pushing keeps clear of, paper mm: its shaft lies on the side of its
/// point that no other arrow or line takes, crosses no line, passes no other point near and
/// stays where the arrows slid would reach (so that pushing never makes the drawing
/// larger, and its scale coarser).
#[derive(Debug, Clone, Default)]
pub(super) struct Push {
    /// The drawing's lines.
    pub(super) lines: Vec<(Point, Point)>,
    /// The drawing's named points.
    pub(super) points: Vec<Point>,
    /// Every force's point and unit direction, those drawn later included.
    pub(super) forces: Vec<(Point, Vec2)>,
    /// The box the arrows reach with every twin slid.
    pub(super) within: Rect,
    /// Whether every arrow keeps its line of action through its point (the lever, whose
    /// arms are read on paper): twins push, and none is set beside another. Else (a group
    /// drawing) only an arrow that would run into its link from the link's end pushes, its
    /// shaft on the link's line past the end (the jaw crusher's Rn03 ran up link 3 into
    /// G3's head at S3, a teacher's review).
    pub(super) keep_lines: bool,
}

/// Forces on paper (point, force) as [`Push::forces`] holds them: point and unit direction.
pub(super) fn unit_directions(forces: impl IntoIterator<Item = (Point, Vec2)>) -> Vec<(Point, Vec2)> {
    forces.into_iter().map(|(at, d)| (at, d / d.norm().max(f64::MIN_POSITIVE))).collect()
}

/// A pushing arrow's shaft passes no other point nearer than this, mm.
const PUSH_POINT_CLEAR: f64 = 5.0;

/// The least a twin leaving a block is set beside the first, mm: closer, their heads touch.
const BLOCK_BESIDE_MIN: f64 = 1.8;

/// How far an arrow along a link or another arrow is set beside it, mm.
const BESIDE: f64 = 2.5;
/// How far past an earlier twin's tip an arrow slid along its line starts, mm.
const TWIN_GAP: f64 = 1.5;
/// Directions closer than this (sine of the angle) count as along.
const ALONG: f64 = 0.17;
/// A shaft this near a link's centre line is lost in it, mm: the two pens' half widths
/// (0.225 and 0.35) and a hair.
const MERGED: f64 = 0.7;
/// The most of a shaft that may run lost in a link, mm: crossing it at a joint, a shaft
/// runs into its link for a millimetre or two, and 12° off it (3.4 mm) it still reads as
/// leaving its point (set beside, it took a kink and met the moment's arc: the four-bar's
/// P_i2, a teacher's review).
const MERGED_MOST: f64 = 3.5;
/// A pushing arrow keeps at least this far from every line at its point (sine of the
/// angle): nearer, it and the line close a wedge its label and the line's crowd.
const PUSH_CLEAR: f64 = 0.34;

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
        let push = self.push.as_ref().filter(|_| exit == 0.0);
        let into_link = beside_link(&self.links, at, d, (exit, len));
        // At a block a twin pushes into the outline from the other side, else leaves it
        // beside the first (slid past the first one's tip, P_i5 and P_c5 read as one arrow
        // with two heads, a teacher's review).
        let block_twin = if exit > 0.0 { self.block_twin(g, at, d, (exit, len)) } else { None };
        let (start, tip) = match (block_twin, way(&self.drawn, push, at, d, (len, into_link.is_some()))) {
            (Some(BlockTwin::Push), _) => {
                self.drawn.push((at, -d, exit + len));
                (at - d * (exit + len), at - d * exit)
            }
            (Some(BlockTwin::Beside(offset)), _) => {
                self.drawn.push((at, d, exit + len));
                (at + d * exit + offset, at + d * (exit + len) + offset)
            }
            (None, Way::Push) => {
                self.drawn.push((at, -d, len));
                (at - d * len, at)
            }
            (None, Way::Pull(slide)) => {
                let mut start = at + d * exit;
                // At a block the forces leave its outline apart already; one slid past a
                // twin starts away from the point (and a twin drawn pushing ends at it).
                let opposite = || self.beside_opposite(at, d, len).filter(|_| exit == 0.0 && slide == 0.0);
                if let Some(side) = into_link.or_else(opposite) {
                    start += side * BESIDE;
                }
                start += d * (slide - exit).max(0.0);
                let tip = start + d * len;
                self.drawn.push((at, d, (tip - at).norm()));
                if (start - (at + d * exit)).norm() > 0.0 {
                    g.line(at + d * exit, start, THIN);
                }
                (start, tip)
            }
        };
        vector(g, start, tip, VECTOR);
        // Beside the arrow's middle, else nearer its tip or its tail on either side.
        let along = |k: f64| start + d * (len * k);
        let spots = [(along(0.55), n), (along(0.55), -n), (along(0.85), n), (along(0.85), -n), (along(0.25), n)];
        labels.add_side_at_any(&spots, (start, tip), label, self.h);
        natural < ARROW_MIN
    }
}

impl Arrows {
    /// How a twin (`d` the way of the one earlier arrow from the block at `at`, `len` long,
    /// leaving the outline `exit` from the point) stands: pushing into the outline from the
    /// block's other side, else leaving it beside the first — [`BESIDE`] across `d`, or less
    /// so that it starts on the block's outline, at least [`BLOCK_BESIDE_MIN`] — on the side
    /// whose shaft keeps farther from the drawing's lines; each only where its shaft keeps
    /// 1 mm clear of every line and arrow drawn. `None` (it slides past the first) else, or
    /// for a third twin.
    fn block_twin(&self, g: &Group, at: Point, d: Vec2, (exit, len): (f64, f64)) -> Option<BlockTwin> {
        let n = d.turn_90();
        let across = |&(_, u, hl, hw): &(Point, Vec2, f64, f64)| n.dot(u).abs() * hl + n.dot(u.turn_90()).abs() * hw;
        let block = self.blocks.iter().find(|b| (b.0 - at).norm() < 0.5)?;
        if twins_from(&self.drawn, at, d) != 1 || twins_from(&self.drawn, at, -d) != 0 {
            return None;
        }
        let lines = drawn_segments(g);
        // From 1.2 mm off the outline (where the shaft meets it: the outline is 1 mm clear
        // there) to its far end.
        let clearance = |a: Point, b: Point| shaft_clearance(&lines, (a, b));
        // Not into the side a force still to be drawn leaves by: it would slide past the
        // pushed twin's tail, beyond the room the drawing keeps for its arrows (a slider 8°
        // off the vertical: G3 down, P_i3 pushed in from above, the load P_c3 slid past
        // P_i3's tail into the group's title; the sweep, stop 71).
        let later_that_way = self
            .push
            .as_ref()
            .is_some_and(|p| p.forces.iter().any(|&(q, e)| (q - at).norm() < 1.0 && e.dot(-d) > 1.0 - ALONG));
        if !later_that_way && clearance(at - d * (exit + 1.2), at - d * (exit + len)) >= 1.0 {
            return Some(BlockTwin::Push);
        }
        let off = BESIDE.min(0.75 * across(block));
        let beside = |s: Vec2| clearance(at + d * (exit + 1.2) + s * off, at + d * (exit + len) + s * off);
        let side = if beside(-n) > beside(n) { -n } else { n };
        (off >= BLOCK_BESIDE_MIN && beside(side) >= 1.0).then_some(BlockTwin::Beside(side * off))
    }

    /// The side (unit, across `d`) an arrow `len` long from `at` along `d` is set to where
    /// an earlier arrow from the same point lies the opposite way: drawn from the point both,
    /// they read as one arrow with a head at each end (the v-compressor's P_i4 up and G4 down,
    /// a teacher's review). The side whose shaft keeps farther from the links (crossing one
    /// counts as touching it); level, the arrow's left. Never on the lever (see
    /// [`Push::keep_lines`]).
    fn beside_opposite(&self, at: Point, d: Vec2, len: f64) -> Option<Vec2> {
        let keep_lines = self.push.as_ref().is_some_and(|p| p.keep_lines);
        let opposite =
            !keep_lines && self.drawn.iter().any(|(p, e, _)| (*p - at).norm() < 1.0 && e.dot(d) < ALONG - 1.0);
        let n = d.turn_90();
        let clearance = |s: Vec2| shaft_clearance(&self.links, (at + s * BESIDE, at + s * BESIDE + d * len));
        opposite.then(|| if clearance(-n) > clearance(n) { -n } else { n })
    }
}

/// The side an arrow `len` long from `at` along `d`, starting `exit` from it (a block's
/// outline), is set to beside a link it would run into (unit, across the arrow), if one: a
/// link through `at` within [`ALONG`] of `d` (its line, ends included), or one its shaft
/// runs into for more than [`MERGED_MOST`] (within about 11°; from a block's outline it
/// has left the link: the two-cylinder compressor's G3 ran 8 mm inside its rod). Set to the side the arrow leaves the link toward, so that its shaft
/// never crosses back over the link (parallel, the arrow's left).
fn beside_link(links: &[(Point, Point)], at: Point, d: Vec2, (exit, len): (f64, f64)) -> Option<Vec2> {
    let n = d.turn_90();
    links.iter().find_map(|&(a, b)| {
        let u = b - a;
        let l = u.norm().max(tol::PAPER);
        let on_line = (at - a).cross(u).abs() / l < 0.5;
        let sin = d.cross(u) / l;
        // How far along the arrow the link reaches from `at`, mm.
        let over = ((a - at).dot(d)).max((b - at).dot(d)).min(exit + len);
        let merged = (MERGED / sin.abs().max(tol::PARALLEL_SIN)).min(over) - exit;
        // Along the link's line but leaving its end, the arrow runs on past the joint, seen:
        // set beside, its line of action missed the joint (the frame's R01 at O, a
        // teacher's review).
        let along = (sin.abs() < ALONG && over > MERGED) || merged > MERGED_MOST;
        // The arrow leaves the link toward where its part across the link points.
        let across = d - u * (d.dot(u) / (l * l));
        let side = if across.norm() < tol::PARALLEL_SIN || across.dot(n) >= 0.0 { n } else { -n };
        (on_line && along).then_some(side)
    })
}

/// An arrow's length on paper for a force of `f` at `mu_f`, mm.
fn length(f: f64, mu_f: f64) -> f64 {
    (f / mu_f).clamp(ARROW_MIN, ARROW_MAX)
}

/// The segments of the lines drawn in `g` so far: links, guides, outlines, arrows' shafts.
fn drawn_segments(g: &Group) -> Vec<(Point, Point)> {
    g.items.iter().filter(|item| matches!(item, Item::Path { .. })).flat_map(obstacles::segments).collect()
}

/// How near a shaft from `a` to `b` comes to `lines`, mm: its ends' and middle's least
/// distance to them, 0 where it crosses one.
fn shaft_clearance(lines: &[(Point, Point)], (a, b): (Point, Point)) -> f64 {
    let from_line = |&(p, q): &(Point, Point)| {
        let ends = [a, a.midpoint(b), b].map(|x| point_segment_distance(x, (p, q)));
        if segments_cross(a, b, p, q) { 0.0 } else { ends.into_iter().fold(f64::INFINITY, f64::min) }
    };
    lines.iter().map(from_line).fold(f64::INFINITY, f64::min)
}

/// How a twin at a block stands ([`Arrows::block_twin`]).
enum BlockTwin {
    /// Into the outline from the block's other side.
    Push,
    /// Leaving the outline beside the first, this far across.
    Beside(Vec2),
}

/// How many of the arrows `drawn` earlier leave `at` along `d`.
fn twins_from(drawn: &[(Point, Vec2, f64)], at: Point, d: Vec2) -> usize {
    drawn.iter().filter(|(p, e, _)| (*p - at).norm() < 1.0 && e.dot(d) > 1.0 - ALONG).count()
}

/// How far from `at` along `d` an arrow starts past the far ends of the arrows `drawn`
/// earlier from the same point along `d`, mm (0 for none).
fn past_twins(drawn: &[(Point, Vec2, f64)], at: Point, d: Vec2) -> f64 {
    drawn
        .iter()
        .filter(|(p, e, _)| (*p - at).norm() < 1.0 && e.dot(d) > 1.0 - ALONG)
        .map(|&(_, _, reach)| reach + TWIN_GAP)
        .fold(0.0, f64::max)
}

/// How an arrow stands at its point.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Way {
    /// From the point, this far along its direction past earlier twins (0 for none), mm.
    Pull(f64),
    /// Its tip at the point, from the other side.
    Push,
}

/// How an arrow `len` long from `at` along `d` stands: where pushing is allowed (`push`),
/// pushing where an earlier arrow lies along `d` and its shaft keeps clear of all `push`
/// names; else slid past the earlier ones.
fn way(drawn: &[(Point, Vec2, f64)], push: Option<&Push>, at: Point, d: Vec2, (len, into_link): (f64, bool)) -> Way {
    let slide = past_twins(drawn, at, d);
    let tail = at - d * len;
    let near = |q: Point| (q - at).norm() < 1.0;
    let clear = |p: &Push| {
        past_twins(drawn, at, -d) == 0.0
            && !p.forces.iter().any(|&(q, e)| near(q) && e.dot(-d) > 1.0 - ALONG)
            && !p.lines.iter().any(|&l| line_along(l, at, -d, PUSH_CLEAR))
            && !p.lines.iter().any(|&(a, b)| !near(a) && !near(b) && segments_cross(tail, at, a, b))
            && !p.points.iter().any(|&q| !near(q) && point_segment_distance(q, (tail, at)) < PUSH_POINT_CLEAR)
            && p.within.inflate(tol::PAPER, tol::PAPER).contains(tail)
    };
    let wanted = |p: &Push| (slide > 0.0 && p.keep_lines) || into_link;
    if push.is_some_and(|p| wanted(p) && clear(p)) { Way::Push } else { Way::Pull(slide) }
}

/// The distance from `q` to the segment `a`–`b`, mm.
fn point_segment_distance(q: Point, (a, b): (Point, Point)) -> f64 {
    use kurbo::ParamCurveNearest;
    kurbo::Line::new(a, b).nearest(q, 0.0).distance_sq.sqrt()
}

/// Whether line `(a, b)` runs from `at` within the angle whose sine is `within` of the ray
/// `e` (a unit vector), for more than half a millimetre.
fn line_along((a, b): (Point, Point), at: Point, e: Vec2, within: f64) -> bool {
    let u = b - a;
    let l = u.norm();
    let through = l > tol::PAPER && (at - a).cross(u).abs() / l < 0.5;
    let on_line = through && (e.cross(u) / l).abs() < within;
    on_line && [a, b].iter().any(|&p| (p - at).dot(e) > 0.5)
}

/// Each of `forces` (at its point on paper, its direction on paper) as drawn at `mu_f`,
/// twins pushing where `push` lets them (as [`Arrows::push`]) or slid along their lines: its
/// point, the unit direction from the point along which it lies and how far from the point
/// its farther end is, mm.
pub(super) fn twin_rows(
    forces: impl IntoIterator<Item = (Point, Vec2)>,
    push: Option<&Push>,
    mu_f: f64,
) -> Vec<(Point, Vec2, f64)> {
    let mut drawn: Vec<(Point, Vec2, f64)> = Vec::new();
    for (at, force) in forces {
        let f = force.norm();
        if f > 0.0 {
            let d = force / f;
            let row = match way(&drawn, push, at, d, (length(f, mu_f), false)) {
                Way::Push => (at, -d, length(f, mu_f)),
                Way::Pull(slide) => (at, d, slide + length(f, mu_f)),
            };
            drawn.push(row);
        }
    }
    drawn
}

/// The farthest a group drawing's arrow reaches from its point, twins slid (see
/// [`twin_rows`]), mm: the room the drawing needs round its points.
pub(super) fn twins_reach(forces: impl IntoIterator<Item = (Point, Vec2)>, mu_f: f64) -> f64 {
    twin_rows(forces, None, mu_f).iter().map(|x| x.2).fold(0.0, f64::max)
}

#[cfg(test)]
#[path = "arrows_tests.rs"]
mod tests;
