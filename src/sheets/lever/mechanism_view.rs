//! The mechanism in all its positions at the length scale μ_l: thin links for every
//! position, the assigned position thick with its letters and the senses of ω and ε,
//! the centres of mass and their trajectories, frame pivots and guides.

use super::labels::LeverWords;
use crate::drawing::fmt;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::path::Path;
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, DASHED, Group, MAIN, Pen, THIN};
use crate::drawing::symbols::{clear_turn_arrow, frame_pivot, hatch, slider, turn_arrow_reach};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::analysis::{Kinematics, Position};
use crate::lever::linkage::{LinkKind, Mechanism, PointId, State, Step};
use crate::num::math::{self, Norm};
use crate::num::tol;
use kurbo::{CubicBez, Point, Rect, Vec2};

mod crank_detail;
mod slider_numbers;
use slider_numbers::SliderNumbers;
mod strokes;
mod swing;
pub(super) use crank_detail::{DETAIL_GAP, DetailAt, DetailPlace, detail_place};
pub(super) use slider_numbers::SLIDER_SAME_MM;

/// Paper sizes of the symbols, mm.
const SLIDER: (f64, f64) = (10.0, 5.0);
const BLOCK: (f64, f64) = (7.0, 4.0);
const JOINT_R: f64 = 1.0;
/// The centres of mass' paths, and the legend's sample of them: thin dashed (a dash-dot
/// line is an axis in GOST 2.303), the paths' dashes cut on the scene
/// ([`Group::dashed_curve`]) so that every renderer puts them in the same places.
pub const TRAJECTORY: Pen = DASHED;
/// Positions whose every point is nearer than this on paper are one drawn position, mm:
/// GOST 2.303's least distance between parallel lines (closer, two positions print as one
/// thick line with two numbers).
const SAME_POSITION_MM: f64 = 0.8;
/// The length of the crank pin's circle each position number needs in 3.5 mm lettering, mm.
const CROWDED_NUMBERS: f64 = 8.0;

/// Drawn length of a kulisa: given, or its longest reach to the block plus 15 %.
fn kulisa_len(k: &Kinematics, c: PointId, a3: PointId, given: Option<f64>) -> f64 {
    given.unwrap_or_else(|| {
        let reach = k.positions.iter().map(|p| (p.state.points[a3].p - p.state.points[c].p).norm()).fold(0.0, f64::max);
        reach * 1.15
    })
}

/// Everything the view draws, in world coordinates, for choosing the scale.
pub fn world_extent(m: &Mechanism, k: &Kinematics, kulisa: &[(usize, Option<f64>)]) -> Rect {
    let mut pts: Vec<Vec2> = Vec::new();
    for p in k.positions.iter().chain(std::iter::once(&k.assigned)) {
        pts.extend(p.state.points.iter().map(|q| q.p));
        for st in &m.steps {
            if let Step::Rpr { c, a3, links, .. } = *st {
                let given = kulisa.iter().find(|(l, _)| *l == links[1]).and_then(|x| x.1);
                let len = kulisa_len(k, c, a3, given);
                let d = (p.state.points[a3].p - p.state.points[c].p).unit();
                pts.push(p.state.points[c].p + d * len);
            }
        }
    }
    for t in &k.trajectories {
        pts.extend(t.samples.iter().copied());
    }
    let crank = m.crank();
    let c = m.frame.iter().find(|f| f.0 == crank.pivot).map(|f| f.1).unwrap_or_default();
    let r = Vec2::new(crank.length, crank.length);
    pts.extend([c + r, c - r]);
    let first = pts[0].to_point();
    pts.iter().fold(Rect::from_points(first, first), |r, p| r.union_pt(p.to_point()))
}

pub struct MechanismView<'a> {
    pub m: &'a Mechanism,
    pub k: &'a Kinematics,
    pub view: View,
    pub kulisa: &'a [(usize, Option<f64>)],
    pub words: &'a LeverWords,
    /// The crank's enlarged detail, when the crank is too small on paper for its numbers,
    /// and its box beside the drawing (none: a free spot in the drawing's region, if any).
    /// The mechanism then leaves the crank's numbers, letters and ω₁ to it.
    pub detail: Option<(DetailPlace, Option<Rect>)>,
    /// A slider's positions this near on paper share one number, mm (0: each its own).
    pub slider_same_mm: f64,
    /// Whether a stroke short of 5 mm for each position (its positions on one point counted
    /// once) is numbered: it is tried, and drawn again without where a number hangs far.
    pub number_short_strokes: bool,
    /// Whether a numbered slider's stroke dimensioned beyond its hatching leaves room for
    /// numbers between them: tried where a number crowded off its side crossed the line.
    pub numbers_beyond_hatching: bool,
}

/// What drawing the mechanism tells its caller.
pub struct ViewDrawn {
    /// The μ_l of the crank's detail, where one was drawn.
    pub detail_mu_l: Option<f64>,
    /// The labels (by their order in `labels`) of the short strokes' numbers.
    pub short_stroke_numbers: Vec<usize>,
    /// The strokes' dimension lines, paper mm.
    pub dimension_lines: Vec<(Point, Point)>,
}

impl MechanismView<'_> {
    /// Draws the mechanism, its labels into `labels`.
    pub fn draw(&self, g: &mut Group, labels: &mut Labels) -> ViewDrawn {
        self.crank_circle(g);
        for t in &self.k.trajectories {
            // World to paper is affine, so the pieces map exactly through their control points.
            let map = |c: &CubicBez| {
                let [p0, p1, p2, p3] = [c.p0, c.p1, c.p2, c.p3].map(|q| self.view.p(q.to_vec2()));
                CubicBez::new(p0, p1, p2, p3)
            };
            let path = Path::cubics(&t.fitted.cubics.iter().map(map).collect::<Vec<_>>());
            let bb = path.bbox();
            // A path that is a point or a line (a slider's centre) is not drawn: its guide shows it.
            if bb.width().max(bb.height()) > 1.0 && bb.width().min(bb.height()) > 0.3 {
                let start = g.mark();
                g.dashed_curve(path, TRAJECTORY);
                g.breakable_from(start);
            }
        }
        self.guides(g);
        // Positions that coincide on paper are drawn once (twice, their thin lines would
        // read as one thick line).
        let groups = self.coincident();
        // Planned once: the strokes' dimensions leave their numbers room, then they are placed.
        let slider_numbers = self.slider_number_plan(&groups);
        for group in &groups {
            self.position(g, &self.k.positions[group[0]], THIN, 0.7);
        }
        self.position(g, &self.k.assigned, MAIN, JOINT_R * 1.3);
        for &(id, p) in &self.m.frame {
            if self.is_pivot(id) {
                frame_pivot(g, self.view.p(p), JOINT_R * 1.5);
            }
        }
        let dimension_lines = self.strokes(g, labels, &slider_numbers);
        swing::swing(self, g, labels);
        // The other links' arrows before a free spot for the crank's detail is sought, so
        // that it keeps clear of them; ω₁ in the mechanism only if no detail has it.
        let not_crank = |kind: LinkKind| kind != LinkKind::Crank;
        let detail = match self.detail {
            None => {
                self.senses(g, labels, |_| true);
                None
            }
            Some((d, rect)) => {
                self.senses(g, labels, not_crank);
                let found = rect.map(|r| (d, r)).or_else(|| self.free_spot(g, &d));
                match &found {
                    Some((d, rect)) => self.crank_detail(g, labels, d, *rect),
                    None => self.senses(g, labels, |kind| !not_crank(kind)),
                }
                found
            }
        };
        let detailed = detail.is_some();
        let short_stroke_numbers = self.position_numbers(labels, detailed, &groups, slider_numbers);
        self.letters(labels, detailed);
        ViewDrawn { detail_mu_l: detail.map(|d| d.0.mu), short_stroke_numbers, dimension_lines }
    }

    /// A slider's point `d` over the positions: its least and largest distance along its
    /// guide (through `through`, along `dir`), m.
    fn travel(&self, d: PointId, through: Vec2, dir: Vec2) -> (f64, f64) {
        let s = self.k.positions.iter().map(|p| (p.state.points[d].p - through).dot(dir));
        s.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)))
    }

    /// The side of a guide (±1 along its normal `n_world`) away from where the rod's
    /// joint mostly is: the hatching's.
    fn hatch_side(&self, joint: PointId, through: Vec2, n_world: Vec2) -> f64 {
        let rod: f64 = self.k.positions.iter().map(|p| (p.state.points[joint].p - through).dot(n_world)).sum();
        if rod >= 0.0 { -1.0 } else { 1.0 }
    }

    fn is_pivot(&self, id: PointId) -> bool {
        self.m.links.iter().any(|l| l.points.contains(&id))
    }

    fn crank_circle(&self, g: &mut Group) {
        let crank = self.m.crank();
        let c = self.k.assigned.state.points[crank.pivot].p;
        g.circle(self.view.p(c), self.view.len(crank.length), THIN);
    }

    /// Each guide: its axis (dash-dot) over the slider's travel and a hatched frame line.
    fn guides(&self, g: &mut Group) {
        for st in &self.m.steps {
            let Step::Rrp { p: joint, d, through, dir, .. } = *st else { continue };
            let (lo, hi) = self.travel(d, through, dir);
            // Past the slider's extreme positions by its half length and 4 mm (within MECH_PAD).
            let ext = (SLIDER.0 / 2.0 + 4.0) * self.view.mu;
            let (a, b) = (through + dir * (lo - ext), through + dir * (hi + ext));
            g.line(self.view.p(a), self.view.p(b), AXIS);
            // Hatch on the side away from the rod, so it never crosses the links.
            let n_world = dir.turn_90();
            let side = self.hatch_side(joint, through, n_world);
            let off = self.view.dir(n_world * side) * (SLIDER.1 / 2.0);
            let (pa, pb) = (self.view.p(a) + off, self.view.p(b) + off);
            g.line(pa, pb, THIN);
            hatch(g, pa, pb, self.view.dir(n_world * side), 2.5);
        }
    }

    fn position(&self, g: &mut Group, pos: &Position, pen: Pen, joint_r: f64) {
        let st = &pos.state;
        let p = |id: PointId| self.view.p(st.points[id].p);
        for (li, link) in self.m.links.iter().enumerate() {
            let pts: Vec<PointId> = link.points.iter().copied().filter(|&id| !self.m.is_mass_centre(id)).collect();
            match link.kind {
                LinkKind::Slider => {
                    let u = self.slider_dir(li);
                    slider(g, p(pts[0]), u, SLIDER.0, SLIDER.1, pen);
                }
                LinkKind::Block => {
                    let u = self.view.dir(st.links[li].dir);
                    slider(g, p(pts[0]), u, BLOCK.0, BLOCK.1, pen);
                }
                _ => {
                    // The other positions' links are thin lines a label may interrupt.
                    let start = g.mark();
                    if let Some((c, a3, given)) = self.kulisa_of(li) {
                        let len = kulisa_len(self.k, c, a3, given);
                        let d = (st.points[a3].p - st.points[c].p).unit();
                        g.line(p(c), self.view.p(st.points[c].p + d * len), pen);
                    } else {
                        let ring: Vec<Point> = pts.iter().map(|&id| p(id)).collect();
                        g.path(ring.clone(), ring.len() > 2, pen);
                    }
                    if pen == THIN {
                        g.breakable_from(start);
                    }
                }
            }
        }
        for id in self.joints() {
            if !self.m.is_frame(id) {
                g.circle(p(id), joint_r, if pen == MAIN { THIN } else { pen });
            }
        }
        for &(_, id) in &self.m.mass_centres {
            g.dot(p(id), if pen == MAIN { 0.9 } else { 0.45 });
        }
    }

    fn kulisa_of(&self, link: usize) -> Option<(PointId, PointId, Option<f64>)> {
        self.m.steps.iter().find_map(|s| match *s {
            Step::Rpr { c, a3, links, .. } if links[1] == link => {
                let given = self.kulisa.iter().find(|(l, _)| *l == link).and_then(|x| x.1);
                Some((c, a3, given))
            }
            _ => None,
        })
    }

    fn slider_dir(&self, link: usize) -> Vec2 {
        self.m
            .steps
            .iter()
            .find_map(|s| match *s {
                Step::Rrp { dir, links, .. } if links[1] == link => Some(self.view.dir(dir)),
                _ => None,
            })
            .unwrap_or(Vec2::new(1.0, 0.0))
    }

    /// Revolute joints drawn as small circles: every link point that is not a centre of
    /// mass and not a kulisa image.
    fn joints(&self) -> Vec<PointId> {
        let mut out: Vec<PointId> = Vec::new();
        for l in &self.m.links {
            for &id in &l.points {
                if !self.m.is_mass_centre(id) && !self.m.is_kulisa_image(id) && !out.contains(&id) {
                    out.push(id);
                }
            }
        }
        out
    }

    /// The positions in runs that coincide on paper: each next one within
    /// [`SAME_POSITION_MM`] of the run's first at every point (an extreme position a fraction
    /// of a degree from a numbered one, "5′" at 179.76° beside "6" at 180°).
    fn coincident(&self) -> Vec<Vec<usize>> {
        self.coincident_in(&self.view)
    }

    /// As [`Self::coincident`], on paper at `view`'s scale.
    fn coincident_in(&self, view: &View) -> Vec<Vec<usize>> {
        let mut out: Vec<Vec<usize>> = Vec::new();
        for (i, pos) in self.k.positions.iter().enumerate() {
            let same = |first: usize| {
                let a = &self.k.positions[first].state.points;
                let b = &pos.state.points;
                a.iter().zip(b).all(|(p, q)| view.len((p.p - q.p).norm()) < SAME_POSITION_MM)
            };
            match out.last_mut() {
                Some(run) if same(run[0]) => run.push(i),
                _ => out.push(vec![i]),
            }
        }
        out
    }

    /// The number of a run of coincident positions: "5′ ≡ 6".
    fn joined_label(&self, run: &[usize]) -> String {
        run.iter().map(|&i| self.k.positions[i].label.as_str()).collect::<Vec<_>>().join(" ≡ ")
    }

    /// The lettering height of position numbers round a crank circle of radius `r` on
    /// paper: 3.5 mm where each has about 8 mm of the circle, else 2.5 mm (GOST 2.304's next
    /// size), lest they crowd onto the connecting rods' lines.
    fn numbers_height(&self, r: f64) -> f64 {
        let per_number = std::f64::consts::TAU * r / self.k.positions.len() as f64;
        if per_number >= CROWDED_NUMBERS { 3.5 } else { 2.5 }
    }

    /// Position numbers beside the crank pin of every position, outward from the pivot
    /// (in the crank's detail instead, when it has one), and each slider's as `sliders` plans;
    /// returns the short strokes' numbers' labels.
    fn position_numbers(
        &self,
        labels: &mut Labels,
        detailed: bool,
        groups: &[Vec<usize>],
        sliders: Vec<SliderNumbers>,
    ) -> Vec<usize> {
        let crank = self.m.crank();
        let ends = |st: &State| (self.view.p(st.points[crank.pivot].p), self.view.p(st.points[crank.pin].p));
        if !detailed {
            let r = self.k.positions.first().map_or(f64::INFINITY, |p| {
                let (o, a) = ends(&p.state);
                (a - o).norm()
            });
            let h = self.numbers_height(r);
            for group in groups {
                let (o, a) = ends(&self.k.positions[group[0]].state);
                labels.add_text_apart(a, a - o, &self.joined_label(group), h, 2);
            }
        }
        self.slider_numbers(labels, sliders)
    }

    /// Letters of the assigned position's points, away from the mechanism's centre.
    fn letters(&self, labels: &mut Labels, detailed: bool) {
        let st = &self.k.assigned.state;
        let centre = {
            let ps: Vec<Point> = st.points.iter().map(|q| self.view.p(q.p)).collect();
            crate::drawing::scene::points_bbox(&ps).center()
        };
        let crank = (self.m.crank().pivot, self.crank_points());
        let in_detail = |id: PointId| detailed && (id == crank.0 || crank.1.contains(&id));
        for (id, name) in self.m.point_names.iter().enumerate() {
            if self.m.is_kulisa_image(id) || in_detail(id) {
                continue;
            }
            let at = self.view.p(st.points[id].p);
            let (main, sub) = split_name(name);
            labels.add(at, at - centre + Vec2::new(0.0, -2.0), LabelText::new(main, sub), 5.0);
        }
    }

    /// Arc arrows of ω (radius 6 mm) and ε (9.5 mm) at every turning link of the thick
    /// position (of the kinds `drawn_here` takes), each turned to where it crosses the fewest
    /// lines already drawn.
    fn senses(&self, g: &mut Group, labels: &mut Labels, drawn_here: impl Fn(LinkKind) -> bool) {
        let st = &self.k.assigned.state;
        let turning: Vec<_> = self
            .m
            .links
            .iter()
            .enumerate()
            .filter(|(_, link)| !matches!(link.kind, LinkKind::Slider | LinkKind::Block) && drawn_here(link.kind))
            .map(|(li, link)| {
                let pts: Vec<Vec2> = link.points.iter().map(|&id| st.points[id].p).collect();
                let centre = match link.kind {
                    LinkKind::Crank | LinkKind::Rocker => self.view.p(pts[0]),
                    _ => self.view.p((pts[0] + pts[1]) * 0.5),
                };
                (li, link, centre)
            })
            .collect();
        // What the arrows may cross: the lines round their centres.
        let reach =
            turning.iter().map(|&(.., c)| turn_arrow_reach(c, SENSE_R.0.max(SENSE_R.1))).reduce(|a, b| a.union(b));
        let mut drawn = reach.map_or_else(Obstacles::default, |r| Obstacles::of_items_within(&g.items, r));
        for (li, link, centre) in turning {
            let lk = st.links[li];
            let along = self.view.dir(lk.dir).arg().to_degrees();
            // Relative to the crank's ω1 and ω1²: a link at rest turns neither way. The
            // crank turns uniformly, so it has no ε arrow.
            let w1 = self.m.omega1.abs();
            let turns = [
                (lk.omega, SENSE_R.0, "ω", tol::ZERO_SPEED * w1, true),
                (lk.eps, SENSE_R.1, "ε", tol::ZERO_SPEED * w1 * w1, link.kind != LinkKind::Crank),
            ];
            for (value, r, sym, zero, drawn_here) in turns {
                if !drawn_here || value.abs() <= zero {
                    continue;
                }
                let name = LabelText::new(sym, link.number.to_string());
                sense_arrow(g, (&mut drawn, labels), (centre, r), along, value > 0.0, name);
            }
        }
    }
}

/// Radii of the ω and ε arrows, mm, and their sweep, degrees.
const SENSE_R: (f64, f64) = (6.0, 9.5);
const SENSE_SWEEP: f64 = 110.0;

/// One arc arrow of a turn (counter-clockwise on paper if `ccw`) round `centre` at radius
/// `r`, started 40° past the link's direction `along` (degrees on paper) and turned to where
/// it crosses the fewest lines of `drawn`; its `name` beside its middle.
fn sense_arrow(
    g: &mut Group,
    (drawn, labels): (&mut Obstacles, &mut Labels),
    (centre, r): (Point, f64),
    along: f64,
    ccw: bool,
    name: LabelText,
) {
    let start = clear_turn_arrow(g, drawn, centre, r, along + 40.0, SENSE_SWEEP, ccw, (THIN, 0.0));
    let mid = (start + if ccw { -SENSE_SWEEP / 2.0 } else { SENSE_SWEEP / 2.0 }).to_radians();
    let at = centre + math::from_angle(mid) * r;
    labels.add_on_line_at_any(&[(at, at - centre)], name, 3.5, 1);
}

/// "μ_l = 0,005 m/mm": a length scale in the sheet's language (the mechanism's header, its
/// crank's detail).
pub fn mu_l_text(mu_l: f64, words: &LeverWords) -> LabelText {
    let scale = fmt::localise(&crate::drawing::scale::format(mu_l), words.lang);
    LabelText::new("μ", "l").with_tail(format!(" = {scale} {}", words.common.unit_m_per_mm()))
}

/// "S2" → ("S", "2"), "O1" → ("O", "1"), "A" → ("A", "").
pub fn split_name(name: &str) -> (String, String) {
    let mut chars = name.chars();
    let first: String = chars.next().map(String::from).unwrap_or_default();
    (first, chars.collect())
}
