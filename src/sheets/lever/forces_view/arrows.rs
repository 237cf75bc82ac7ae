//! Force arrows on a drawing at a round μ_F, between a least and a greatest length, kept
//! apart from the links and from each other.

use super::{ARROW_MAX, ARROW_MIN};
use crate::drawing::obstacles::segments_cross;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Group, THIN, VECTOR};
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
        let (start, tip) = match way(&self.drawn, push, at, d, (len, into_link.is_some())) {
            Way::Push => {
                self.drawn.push((at, -d, len));
                (at - d * len, at)
            }
            Way::Pull(slide) => {
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
        labels.add_at_any(&spots, label, self.h);
        natural < ARROW_MIN
    }
}

impl Arrows {
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
        let clearance = |s: Vec2| {
            let (a, b) = (at + s * BESIDE, at + s * BESIDE + d * len);
            let from_link = |&(p, q): &(Point, Point)| {
                let ends = [a, a.midpoint(b), b].map(|x| point_segment_distance(x, (p, q)));
                if segments_cross(a, b, p, q) { 0.0 } else { ends.into_iter().fold(f64::INFINITY, f64::min) }
            };
            self.links.iter().map(from_link).fold(f64::INFINITY, f64::min)
        };
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
mod tests {
    use super::*;
    use crate::drawing::path::Seg;
    use crate::drawing::scene::Item;
    use kurbo::Rect;

    /// An arrow 11° off the link through its point (3.7 mm of its shaft in the link's
    /// line) is set beside the link on the side it leaves it toward, whichever way it
    /// points along the link; 25° off, or leaving a block's outline 4 mm out at 11°, it is
    /// seen and stays; along the link's line on past its end it is seen too, and stays on
    /// its line of action through the joint.
    #[test]
    fn an_arrow_nearly_along_its_link_is_set_beside_it_on_the_side_it_leaves_toward() {
        let link = [(Point::new(-20.0, 0.0), Point::new(20.0, 0.0))];
        let dir =
            |deg: f64| Vec2::new(crate::num::math::cos(deg.to_radians()), crate::num::math::sin(deg.to_radians()));
        for deg in [11.0, -11.0, 169.0, -169.0] {
            let d = dir(deg);
            let side = beside_link(&link, Point::ZERO, d, (0.0, 15.0)).expect("set beside");
            assert!(side.dot(d).abs() < 1e-12, "{deg}°: across the arrow");
            assert!(side.y * d.y > 0.0, "{deg}°: toward the side the arrow leaves to, {side:?}");
        }
        assert_eq!(beside_link(&link, Point::ZERO, dir(25.0), (0.0, 15.0)), None);
        assert_eq!(beside_link(&link, Point::ZERO, dir(11.0), (4.0, 15.0)), None);
        let end = [(Point::new(-20.0, 0.0), Point::ZERO)];
        assert!(beside_link(&end, Point::ZERO, dir(177.0), (0.0, 15.0)).is_some(), "into the link from its end");
        assert_eq!(beside_link(&end, Point::ZERO, dir(3.0), (0.0, 15.0)), None, "on past the link's end");
        assert_eq!(beside_link(&end, Point::ZERO, dir(12.0), (0.0, 15.0)), None, "leaving the link's end");
    }

    /// Three forces at one point, two along one line and one a few degrees off it (as a
    /// weight, an inertia force and a gas force at a piston): each arrow and its leader stay
    /// on its own line of action through the point, where its moment about any point is
    /// the force's, and no arrow lies on another.
    #[test]
    fn twin_forces_slide_along_their_lines_and_keep_their_arms() {
        let at = Point::new(50.0, 50.0);
        let forces = [Vec2::new(0.0, -300.0), Vec2::new(0.0, -120.0), Vec2::new(20.0, -200.0)];
        let view = View::new(Point::new(20.0, 80.0), 0.01);
        let spans = spans_drawn(view, at, &forces, None);
        // The second (same direction as the first) starts past the first's tip.
        assert!(spans[1].1 > spans[0].2, "{spans:?}");
    }

    /// Each arrow's unit direction on paper and the least and greatest distance along it
    /// from the point of its shaft's ends, every end checked to lie on the force's line
    /// through the point; and whether the room [`twin_rows`] gives them is the farthest
    /// drawn.
    fn spans_drawn(view: View, at: Point, forces: &[Vec2], push: Option<Push>) -> Vec<(Vec2, f64, f64)> {
        let kept = push.clone();
        let mut arrows =
            Arrows { view, links: Vec::new(), push, blocks: Vec::new(), drawn: Vec::new(), mu_f: 20.0, h: 2.5 };
        let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
        let mut labels = Labels::new();
        let mut spans = Vec::new();
        for &f in forces {
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
        // The room a drawing sizes for them is where each arrow's far end is drawn.
        let rows = twin_rows(forces.iter().map(|&f| (at, view.dir(f))), kept.as_ref(), 20.0);
        assert_eq!(rows.len(), arrows.drawn.len());
        for (row, drawn) in rows.iter().zip(&arrows.drawn) {
            assert!((row.1 - drawn.1).norm() < 1e-9 && (row.2 - drawn.2).abs() < 1e-9, "{row:?} {drawn:?}");
        }
        spans
    }

    /// On the lever the smaller of two twins is drawn pushing, its tip at the point and its
    /// shaft on the other side, where nothing lies there; a third along the first slides past
    /// the first's tip. The second slides too where a line of the lever leaves the point on
    /// the other side, where a force drawn later points that way, or where its shaft would
    /// reach beyond the arrows slid.
    #[test]
    fn twins_push_from_the_free_side_and_slide_where_it_is_taken() {
        let at = Point::new(50.0, 50.0);
        let view = View::new(Point::new(20.0, 80.0), 0.01);
        let forces = [Vec2::new(0.0, -300.0), Vec2::new(0.0, -120.0), Vec2::new(20.0, -200.0)];
        let on_paper: Vec<(Point, Vec2)> = forces.iter().map(|&f| (at, view.dir(f) / f.norm())).collect();
        let push = |lines: Vec<(Point, Point)>, later: Option<Vec2>, within: Rect| Push {
            lines,
            points: vec![at],
            forces: on_paper.iter().copied().chain(later.map(|e| (at, e))).collect(),
            within,
            keep_lines: true,
        };
        let page = Rect::new(0.0, 0.0, 100.0, 100.0);
        let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), None, page)));
        assert!(spans[1].2.abs() < 1e-9 && spans[1].1 < -5.0, "the second pushes: {spans:?}");
        assert!(spans[2].1 > spans[0].2, "the third slides past the first: {spans:?}");
        // On paper y runs down: the forces point down the page and the pushing side is
        // above the point. A line from the point there, 6° off the second's line:
        let above = vec![(at, at + Vec2::new(3.0, -30.0))];
        let spans = spans_drawn(view, at, &forces, Some(push(above, None, page)));
        assert!(spans[1].1 > spans[0].2, "a line: the second slides: {spans:?}");
        // A force up the page at the point, drawn after them:
        let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), Some(Vec2::new(0.0, -1.0)), page)));
        assert!(spans[1].1 > spans[0].2, "a later force: the second slides: {spans:?}");
        // The arrows slid reach no higher than the point:
        let below = Rect::new(0.0, at.y, 100.0, 100.0);
        let spans = spans_drawn(view, at, &forces, Some(push(Vec::new(), None, below)));
        assert!(spans[1].1 > spans[0].2, "beyond the slid arrows' box: the second slides: {spans:?}");
    }

    /// The ends of the vector-pen shafts drawn since item `from`.
    fn shafts(g: &Group, from: usize) -> Vec<(Point, Point)> {
        (g.items[from..].iter())
            .filter_map(|item| match item {
                Item::Path { path, pen } if *pen == VECTOR => match path.segs.last() {
                    Some(Seg::Line(p)) => Some((path.start, *p)),
                    _ => None,
                },
                _ => None,
            })
            .collect()
    }

    /// On a group's drawing a force at a link's end pointing into the link is drawn pushing,
    /// its tip at the joint and its shaft on the link's line past the end; at a point inside
    /// the link, where the link goes on past the point, it is set beside the link as before.
    #[test]
    fn an_arrow_into_its_link_at_the_links_end_pushes_from_outside() {
        let (a, b) = (Point::new(30.0, 50.0), Point::new(70.0, 50.0));
        let view = View::new(Point::new(0.0, 100.0), 1.0);
        let push = Push {
            lines: vec![(a, b)],
            points: vec![a, b],
            forces: vec![(a, Vec2::new(1.0, 0.0))],
            within: Rect::new(0.0, 0.0, 100.0, 100.0),
            keep_lines: false,
        };
        let mut arrows = Arrows {
            view,
            links: vec![(a, b)],
            push: Some(push),
            blocks: Vec::new(),
            drawn: Vec::new(),
            mu_f: 1.0,
            h: 3.5,
        };
        let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
        let mut labels = Labels::new();
        arrows.arrow(&mut g, &mut labels, a, Vec2::new(12.0, 0.0), LabelText::new("R", "n"));
        let [(start, tip)] = shafts(&g, 0)[..] else { panic!("one shaft") };
        assert!((start.y - a.y).abs() < 1e-9 && (tip.y - a.y).abs() < 1e-9, "on the link's line");
        assert!(start.x < a.x - 5.0 && tip.x <= a.x, "pushing from outside: {start:?} {tip:?}");
        // Inside the link (its middle), the link goes on past the point: beside it.
        let from = g.items.len();
        arrows.arrow(&mut g, &mut labels, a.midpoint(b), Vec2::new(12.0, 0.0), LabelText::new("P", ""));
        let [(start, tip)] = shafts(&g, from)[..] else { panic!("one shaft") };
        assert!(((start.y - a.y).abs() - BESIDE).abs() < 1e-9 && tip.x > start.x, "beside: {start:?} {tip:?}");
    }

    /// A second force at a point pointing opposite to the first is set beside it, off the
    /// first's line (a thin line joins it to its point): drawn from the point both, they read
    /// as one arrow with a head at each end.
    #[test]
    fn an_arrow_opposite_to_an_earlier_one_at_its_point_is_set_beside_it() {
        let at = Point::new(50.0, 50.0);
        let view = View::new(Point::new(0.0, 100.0), 1.0);
        let mut arrows =
            Arrows { view, links: Vec::new(), push: None, blocks: Vec::new(), drawn: Vec::new(), mu_f: 1.0, h: 3.5 };
        let mut g = Group::new("test", Rect::new(0.0, 0.0, 100.0, 100.0));
        let mut labels = Labels::new();
        arrows.arrow(&mut g, &mut labels, at, Vec2::new(0.0, -10.0), LabelText::new("G", ""));
        let from = g.items.len();
        arrows.arrow(&mut g, &mut labels, at, Vec2::new(0.0, 10.0), LabelText::new("P", ""));
        let [(start, tip)] = shafts(&g, from)[..] else { panic!("one shaft") };
        assert!(((start.x - at.x).abs() - BESIDE).abs() < 1e-9 && start.x == tip.x, "beside: {start:?} {tip:?}");
        assert!(
            g.items[from..].iter().any(|i| matches!(i, Item::Path { pen, .. } if *pen == THIN)),
            "joined to its point"
        );
    }
}
