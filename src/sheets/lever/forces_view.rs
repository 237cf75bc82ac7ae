//! The force analysis on sheet 1: each Assur group and the crank drawn apart at one length
//! scale with their forces, each force polygon at its own round μ_P with its vector
//! equation, the Zhukovsky lever, the load diagrams and tables 3–5. The cells are packed
//! in rows; when they do not fit, the drawings get smaller scales, never smaller text.

use super::labels::LeverLabels;
use super::mechanism_view::split_name;
use super::plans_view::{MARGIN, PlanCell, TITLE, draw_plan, plan_bbox};
use crate::drawing::fmt;
use crate::drawing::labels::{Common, Language};
use crate::drawing::obstacles::Obstacles;
use crate::drawing::place::Labels;
use crate::drawing::plot::{Axis, Plot, round_ticks};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN, Text, VECTOR};
use crate::drawing::symbols::{clear_turn_arrow, frame_pivot, slider, vector};
use crate::drawing::table::Table;
use crate::drawing::text::{LabelText, wrap};
use crate::lever::analysis::ForceAnalysis;
use crate::lever::kinetostatics::{FRAME, Kind, Part, Polygon};
use crate::lever::linkage::{LinkKind, Mechanism, State};
use crate::lever::load::{Load, Stroke};
use crate::lever::plans::{Plan, velocity_plan};
use crate::num::math::Norm;
use crate::num::tol;
use crate::report::ForceKind;
use crate::report::lever::load_kind;
use kurbo::{Point, Rect, Vec2};

/// Longest and shortest force arrow on a group drawing or the lever, mm. A force whose
/// arrow would be shorter is drawn at the minimum with its value written.
const ARROW_MAX: f64 = 20.0;
const ARROW_MIN: f64 = 7.0;
/// Room around a group drawing for its arrows and labels, mm.
const PAD: f64 = ARROW_MAX + 6.0;
/// Room around a force polygon for its labels, mm.
const POLY_PAD: f64 = 9.0;
const CELL_TITLE: f64 = 8.0;
const LINE: f64 = 5.5;
const GAP: f64 = 6.0;
const LOAD_W: f64 = 96.0;
const LOAD_H: f64 = 78.0;

pub struct ForcesInput<'a> {
    pub m: &'a Mechanism,
    pub fa: &'a ForceAnalysis,
    /// The state at φ1.
    pub state: &'a State,
    pub phi_deg: f64,
    pub l: &'a LeverLabels,
    pub c: &'a Common,
    pub lang: Language,
    /// Tables 3–5 as drawn.
    pub tables: Vec<Table>,
}

/// The scales the force drawings got.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ForceScales {
    /// Length scale of each group drawing (groups from the last, then the crank), m/mm.
    pub mu_l: Vec<f64>,
    /// μ_P of each polygon (groups from the last, then the crank), N/mm.
    pub mu_p: Vec<f64>,
    /// The scale of the force arrows on each group drawing, N/mm.
    pub mu_f: Vec<f64>,
    /// Velocity scale of the Zhukovsky lever, (m/s)/mm.
    pub mu_lever: f64,
    /// The scale of the force arrows on the lever, N/mm.
    pub mu_f_lever: f64,
}

enum Content {
    /// Index into the polygons, and the layout computed for the cell's size.
    Polygon(usize, GroupLayout),
    /// The turned velocity plan, its scale and the scale of its force arrows.
    Lever(Plan, f64, f64),
    Load(usize),
    Table(usize),
}

/// What sizes a group cell and then draws it: computed once per layout attempt.
struct GroupLayout {
    /// The group's points in the world, m.
    world: Rect,
    mu_l: f64,
    /// Width of the group drawing with its room for arrows, mm.
    drawing_w: f64,
    mu_p: f64,
    /// Scale of the force arrows on the group drawing, N/mm.
    mu_f: f64,
    /// The polygon's vertices in newtons, from its start, and their box.
    chain: Vec<Vec2>,
    chain_box: Rect,
    equation: Vec<Vec<LabelText>>,
    /// Each force's symbol and value, wrapped into lines.
    legend: Vec<Vec<LabelText>>,
}

struct Cell {
    w: f64,
    h: f64,
    content: Content,
}

/// Sizes that one layout attempt uses, mm: the largest group drawing's longest side (at a
/// GOST scale no larger), each force polygon's and the lever's.
#[derive(Clone, Copy)]
struct Sizes {
    group_box: f64,
    poly_box: f64,
    lever_box: f64,
    /// Longest side of the largest group (or crank) in the world, m.
    widest: f64,
}

impl Sizes {
    /// A drawing's length scale: the common GOST scale that fits the largest group into its
    /// box, unless that leaves this drawing shorter than half the box (a crank beside a
    /// long rod); then its own GOST scale for that half.
    fn mu_l(&self, wb: Rect) -> f64 {
        let common = scale::length_scale(self.widest / self.group_box);
        let side = wb.width().max(wb.height());
        let least = self.group_box / 2.0;
        if side / common >= least { common } else { scale::length_scale(side / least) }
    }

    fn shrunk(self) -> Sizes {
        const STEP: f64 = 0.9;
        // The groups are what overflow; the polygons and the lever keep a readable floor.
        Sizes {
            group_box: self.group_box * STEP,
            poly_box: (self.poly_box * STEP).max(60.0),
            lever_box: (self.lever_box * STEP).max(80.0),
            ..self
        }
    }
}

/// Draws the force analysis into `main` (the region below the mechanism, titled) and, when
/// the mechanism leaves room beside it, `side`; returns the scales the drawings got.
pub fn draw_forces(main: &mut Group, mut side: Option<&mut Group>, inp: &ForcesInput) -> ForceScales {
    let region = main.region;
    let title = inp.l.forces_title(&fmt::localise(&format!("{:.1}", inp.phi_deg), inp.lang));
    main.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, 5.0, Anchor::Start));
    let bodies = bodies(region, side.as_ref().map(|g| g.region));
    let (cells, at, _) = arrange(inp, &bodies, DRAWN, SHRINK_TRIES);
    let mut scales = ForceScales { mu_l: vec![], mu_p: vec![], mu_f: vec![], mu_lever: 0.0, mu_f_lever: 0.0 };
    for (cell, &(body, origin)) in cells.iter().zip(&at) {
        let g: &mut Group = match (body, side.as_deref_mut()) {
            (1, Some(sg)) => sg,
            _ => &mut *main,
        };
        let r = Rect::new(origin.x, origin.y, origin.x + cell.w, origin.y + cell.h);
        // Each cell places its own labels inside itself, so cells never collide.
        let mut labels = Labels::new();
        match cell.content {
            Content::Polygon(i, ref layout) => {
                draw_group_cell(g, &mut labels, r, inp, &inp.fa.forces.polygons[i], layout);
                scales.mu_l.push(layout.mu_l);
                scales.mu_p.push(layout.mu_p);
                scales.mu_f.push(layout.mu_f);
            }
            Content::Lever(ref plan, mu, mu_f) => {
                draw_lever(g, &mut labels, r, inp, plan, (mu, mu_f));
                scales.mu_lever = mu;
                scales.mu_f_lever = mu_f;
            }
            Content::Load(i) => draw_load(g, &mut labels, r, inp, i),
            Content::Table(i) => {
                inp.tables[i].draw(g, origin);
            }
        }
        labels.place(g, r.inflate(-0.5, -0.5));
    }
    scales
}

/// The areas the cells may use: the main region below its title, then the side region.
fn bodies(main: Rect, side: Option<Rect>) -> Vec<Rect> {
    let mut out = vec![Rect::new(main.x0, main.y0 + 10.0, main.x1, main.y1)];
    out.extend(side);
    out
}

/// How many times the drawings may shrink by 10 % to fit; a region that needs more than
/// [`COMFORTABLE`] shrinks is cramped.
const SHRINK_TRIES: usize = 12;
const COMFORTABLE: usize = 3;
/// The sizes a comfortable layout starts from (the mechanism above gets the rest), and the
/// larger ones the drawings start from, shrinking until they fit what they got.
const COMFORTABLE_START: Sizes = Sizes { group_box: 130.0, poly_box: 90.0, lever_box: 110.0, widest: 0.0 };
const DRAWN: Sizes = Sizes { group_box: 170.0, poly_box: 120.0, lever_box: 150.0, widest: 0.0 };

/// Cells packed into the bodies, shrinking the drawings up to `tries − 1` times until they
/// fit; the last attempt is returned even if it does not (the layout measurement then
/// reports it), with whether it fits.
fn arrange(inp: &ForcesInput, bodies: &[Rect], start: Sizes, tries: usize) -> (Vec<Cell>, Vec<(usize, Point)>, bool) {
    let widest =
        inp.fa.forces.polygons.iter().map(|p| world_box(inp, p)).map(|b| b.width().max(b.height())).fold(0.0, f64::max);
    let mut attempt = Sizes { widest, ..start };
    let mut k = 0;
    loop {
        let cells = cells(inp, attempt);
        let (at, ok) = pack(&cells, bodies);
        k += 1;
        if ok || k >= tries {
            return (cells, at, ok);
        }
        attempt = attempt.shrunk();
    }
}

/// Whether the force drawings fit the main region (and the side region, if any) without
/// being cramped.
pub fn fit_comfortably(inp: &ForcesInput, main: Rect, side: Option<Rect>) -> bool {
    arrange(inp, &bodies(main, side), COMFORTABLE_START, COMFORTABLE + 1).2
}

/// The world box of a polygon's group (or the crank): its links' points.
fn world_box(inp: &ForcesInput, poly: &Polygon) -> Rect {
    let pts = drawn_points(inp, poly);
    let first = pts.first().map_or(Point::ZERO, |p| p.to_point());
    pts.iter().fold(Rect::from_points(first, first), |r, p| r.union_pt(p.to_point()))
}

fn links_of(inp: &ForcesInput, poly: &Polygon) -> Vec<usize> {
    match poly.group {
        Some(gi) => inp.m.groups[gi].links.to_vec(),
        None => vec![inp.m.crank().link],
    }
}

fn drawn_points(inp: &ForcesInput, poly: &Polygon) -> Vec<Vec2> {
    links_of(inp, poly).iter().flat_map(|&l| inp.m.links[l].points.iter().map(|&p| inp.state.points[p].p)).collect()
}

/// Extent of a polygon's chain of vectors, in newtons, from its start.
fn chain(poly: &Polygon) -> Vec<Vec2> {
    let mut pts = vec![Vec2::ZERO];
    for t in &poly.terms {
        pts.push(*pts.last().expect("starts with the origin") + t.force);
    }
    pts
}

fn bbox_of(pts: &[Vec2]) -> Rect {
    pts.iter().fold(Rect::from_points(Point::ZERO, Point::ZERO), |r, p| r.union_pt(p.to_point()))
}

/// Items in rows no wider than `width`, each followed by `sep` and the last by `last`.
fn wrap_items(items: Vec<LabelText>, width: f64, sep: &str, last: &str) -> Vec<Vec<LabelText>> {
    let mut lines: Vec<Vec<LabelText>> = vec![vec![]];
    let mut w = 0.0;
    let n = items.len();
    for (i, t) in items.into_iter().enumerate() {
        let end = if i + 1 == n { last } else { sep };
        let item = LabelText { tail: format!("{}{end}", t.tail), ..t };
        let iw = measure(&item, 3.5).width() + 2.5;
        if w + iw > width && w > 0.0 {
            lines.push(vec![]);
            w = 0.0;
        }
        w += iw;
        lines.last_mut().expect("one line at least").push(item);
    }
    lines.retain(|l| !l.is_empty());
    lines
}

fn equation_lines(inp: &ForcesInput, poly: &Polygon, width: f64) -> Vec<Vec<LabelText>> {
    let terms: Vec<LabelText> = poly
        .terms
        .iter()
        .filter(|t| t.force.norm() > 0.0)
        .enumerate()
        .map(|(k, t)| {
            let l = force_label(inp, t.kind, t.on);
            if k == 0 { l } else { LabelText { main: format!("+ {}", l.main), ..l } }
        })
        .collect();
    wrap_items(terms, width, "", " = 0")
}

/// The round scale (N/mm) that draws the largest of `forces` no longer than [`ARROW_MAX`].
fn arrow_scale(largest: f64) -> f64 {
    scale::round_up(largest.max(f64::MIN_POSITIVE) / ARROW_MAX)
}

/// "G₂ = 19,6 N", with a star when the arrow is drawn longer than its scale gives.
fn value_item(inp: &ForcesInput, label: LabelText, value: f64, unit: &str, short: bool) -> LabelText {
    let star = if short { "*" } else { "" };
    label.with_tail(format!("{star} = {} {unit}", fmt::value(value, inp.lang)))
}

/// The legend of a group drawing: every force on it and the inner reaction with their
/// values, the inertia moments, and the note on short arrows when one is.
fn group_legend(inp: &ForcesInput, poly: &Polygon, mu_f: f64, width: f64) -> Vec<Vec<LabelText>> {
    let mut items = Vec::new();
    let mut short = false;
    for t in poly.terms.iter().filter(|t| t.force.norm() > 0.0) {
        let f = t.force.norm();
        let s = f / mu_f < ARROW_MIN;
        short |= s;
        items.push(value_item(inp, force_label(inp, t.kind, t.on), f, inp.c.unit_n(), s));
    }
    if let Some(inner) = &poly.inner {
        items.push(value_item(inp, force_label(inp, inner.kind, inner.on), inner.force.norm(), inp.c.unit_n(), false));
    }
    for il in inp.fa.forces.inertia.iter().filter(|il| links_of(inp, poly).contains(&il.link) && il.moment != 0.0) {
        let label = LabelText::new("M", inp.l.force(ForceKind::Inertia, &inp.m.links[il.link].number.to_string()));
        items.push(value_item(inp, label, il.moment.abs(), inp.c.unit_n_m(), false));
    }
    with_short_note(inp, wrap_items(items, width, ";", ""), short, width)
}

fn with_short_note(inp: &ForcesInput, mut lines: Vec<Vec<LabelText>>, short: bool, width: f64) -> Vec<Vec<LabelText>> {
    if short {
        let note = inp.l.short_arrow(&format!("{ARROW_MIN}"));
        lines.extend(wrap(&note, 3.5, width).into_iter().map(|l| vec![LabelText::new(l, "")]));
    }
    lines
}

/// The box a label draws (symbol, subscript and tail) when centred on the origin.
fn measure(l: &LabelText, h: f64) -> Rect {
    l.draw(&mut Group::new("probe", Rect::ZERO), Point::ZERO, h, Anchor::Middle)
}

fn group_layout(inp: &ForcesInput, poly: &Polygon, s: Sizes) -> (GroupLayout, f64, f64) {
    let world = world_box(inp, poly);
    let mu_l = s.mu_l(world);
    let (drawing_w, drawing_h) = (world.width() / mu_l + 2.0 * PAD, world.height() / mu_l + 2.0 * PAD);
    let chain = chain(poly);
    let chain_box = bbox_of(&chain);
    let mu_p = scale::round_up(chain_box.width().max(chain_box.height()) / s.poly_box);
    let mu_f = arrow_scale(poly.terms.iter().map(|t| t.force.norm()).fold(0.0, f64::max));
    let (poly_w, poly_h) = (chain_box.width() / mu_p + 2.0 * POLY_PAD, chain_box.height() / mu_p + 2.0 * POLY_PAD);
    let w = (drawing_w + poly_w).max(120.0);
    let equation = equation_lines(inp, poly, w - 4.0);
    let legend = group_legend(inp, poly, mu_f, w - 4.0);
    let text_lines = equation.len() + legend.len() + SCALE_LINES;
    let h = CELL_TITLE + drawing_h.max(poly_h) + LINE * text_lines as f64 + 2.0;
    (GroupLayout { world, mu_l, drawing_w, mu_p, mu_f, chain, chain_box, equation, legend }, w, h)
}

/// Lines of scales under a group drawing: μ_l, μ_F and μ_P.
const SCALE_LINES: usize = 2;

fn cells(inp: &ForcesInput, s: Sizes) -> Vec<Cell> {
    let mut out = Vec::new();
    for (i, poly) in inp.fa.forces.polygons.iter().enumerate() {
        let (layout, w, h) = group_layout(inp, poly, s);
        out.push(Cell { w, h, content: Content::Polygon(i, layout) });
    }
    let lever = velocity_plan(inp.m, inp.state).turned(inp.m.omega1.signum());
    let bb = plan_bbox(&lever);
    let mu = scale::round_up(bb.width().max(bb.height()) / s.lever_box);
    let mu_f = lever_arrow_scale(inp);
    let pad = MARGIN + ARROW_MAX + 4.0;
    let w = (bb.width() / mu + 2.0 * pad).max(110.0);
    let text_lines = LEVER_LINES + lever_legend(inp, mu_f, w - 4.0).len();
    let h = TITLE + bb.height() / mu + 2.0 * pad + text_lines as f64 * LINE;
    out.push(Cell { w, h, content: Content::Lever(lever, mu, mu_f) });
    for i in 0..inp.fa.model.loads.len() {
        out.push(Cell { w: LOAD_W, h: LOAD_H, content: Content::Load(i) });
    }
    for (i, t) in inp.tables.iter().enumerate() {
        let (w, h) = t.size();
        out.push(Cell { w: w + 2.0, h: h + 2.0, content: Content::Table(i) });
    }
    out
}

/// Places cells in rows, first fit: each cell goes into the first body where it fits, in
/// that body's current row or a new one. Returns each cell's body and corner, and whether
/// all fit (a cell that fits nowhere overflows the first body).
fn pack(cells: &[Cell], bodies: &[Rect]) -> (Vec<(usize, Point)>, bool) {
    // Per body: the next cell's x, its row's top and the row's height so far.
    let mut rows: Vec<(f64, f64, f64)> = bodies.iter().map(|b| (b.x0, b.y0, 0.0)).collect();
    let mut out = Vec::new();
    let mut all = true;
    for c in cells {
        let mut spot = None;
        for (i, b) in bodies.iter().enumerate() {
            let (x, y, row_h) = rows[i];
            let fits = |x: f64, y: f64| x + c.w <= b.x1 + tol::PAPER && y + c.h <= b.y1 + tol::PAPER;
            if fits(x, y) {
                spot = Some((i, Point::new(x, y), (x + c.w + GAP, y, row_h.max(c.h))));
            } else if row_h > 0.0 && fits(b.x0, y + row_h + GAP) {
                let y = y + row_h + GAP;
                spot = Some((i, Point::new(b.x0, y), (b.x0 + c.w + GAP, y, c.h)));
            }
            if spot.is_some() {
                break;
            }
        }
        let (i, at, next) = spot.unwrap_or_else(|| {
            all = false;
            let (_, y, row_h) = rows[0];
            let y = y + row_h + GAP;
            (0, Point::new(bodies[0].x0, y), (bodies[0].x0 + c.w + GAP, y, c.h))
        });
        rows[i] = next;
        out.push((i, at));
    }
    (out, all)
}

/// The label of a force: G₂, Pᵢ₂, P_c5, Rⁿ₁₂, Pₘ.
fn force_label(inp: &ForcesInput, kind: Kind, on: usize) -> LabelText {
    let n = |l: usize| if l == FRAME { 0 } else { inp.m.links[l].number };
    match kind {
        Kind::Weight => LabelText::new("G", n(on).to_string()),
        Kind::Inertia => LabelText::new("P", inp.l.force(ForceKind::Inertia, &n(on).to_string())),
        Kind::Load(i) => LabelText::new("P", inp.l.force(load_kind(inp.fa.model.loads[i].kind), &n(on).to_string())),
        Kind::Reaction { from, part } => {
            let main = match part {
                Part::Whole => "R",
                Part::Normal => "Rⁿ",
                Part::Tangential => "Rᵗ",
            };
            LabelText::new(main, format!("{}{}", n(from), n(on)))
        }
        Kind::Balancing => LabelText::new("P", inp.l.sub_balancing()),
    }
}

/// The label of the forces of the couple that replaces link `on`'s inertia moment on the
/// lever.
fn couple_label(inp: &ForcesInput, on: usize) -> LabelText {
    LabelText::new("P", format!("M{}", inp.m.links[on].number))
}

/// World to paper for a drawing of world box `wb` centred in `r` at scale `mu`.
fn view(wb: Rect, r: Rect, mu: f64) -> impl Fn(Vec2) -> Point {
    let c = r.center();
    let wc = wb.center();
    move |v: Vec2| Point::new(c.x + (v.x - wc.x) / mu, c.y - (v.y - wc.y) / mu)
}

fn paper_dir(v: Vec2) -> Vec2 {
    Vec2::new(v.x, -v.y)
}

/// Force arrows of one drawing, kept apart: an arrow along a link is drawn beside it, and
/// one from the same point in (nearly) the same direction as an earlier one beside that.
struct Arrows {
    /// The drawing's link lines, paper mm.
    links: Vec<(Point, Point)>,
    /// Slider blocks: centre, unit direction along the block, half length and half width.
    blocks: Vec<(Point, Vec2, f64, f64)>,
    drawn: Vec<(Point, Vec2)>,
    mu_f: f64,
    h: f64,
}

/// How far an arrow along a link or another arrow is set beside it, mm.
const BESIDE: f64 = 2.5;
/// Directions closer than this (sine of the angle) count as along.
const ALONG: f64 = 0.17;

impl Arrows {
    /// Draws a force arrow from `at` (nothing for a zero force) and asks for its label
    /// beside its shaft; returns whether it was drawn at the minimum length.
    fn arrow(&mut self, g: &mut Group, labels: &mut Labels, at: Point, force: Vec2, label: LabelText) -> bool {
        let f = force.norm();
        if f <= 0.0 {
            return false;
        }
        let natural = f / self.mu_f;
        let len = natural.clamp(ARROW_MIN, ARROW_MAX);
        let d = paper_dir(force) / f;
        let n = d.turn_90();
        // A force on a slider starts at the block's outline, not under it.
        let exit = self.blocks.iter().find(|b| (b.0 - at).norm() < 0.5).map_or(0.0, |&(_, u, hl, hw)| {
            let (along, across) = (d.dot(u).abs(), d.dot(u.turn_90()).abs());
            (hl / along.max(1e-9)).min(hw / across.max(1e-9))
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

fn cell_title(g: &mut Group, r: Rect, text: &str) {
    g.text(Text::new(Point::new(r.x0 + 2.0, r.y0 + 5.0), text, 3.5, Anchor::Start));
}

fn group_title(inp: &ForcesInput, poly: &Polygon) -> String {
    match poly.group {
        Some(gi) => {
            let links = inp.m.groups[gi].links.map(|l| inp.m.links[l].number);
            inp.l.group(&format!("II({},{})", links[0], links[1]))
        }
        None => inp.l.driving_link().to_string(),
    }
}

/// Rows of items from `y` down, one row per line; returns the next line's baseline.
fn text_rows(g: &mut Group, x0: f64, mut y: f64, rows: &[Vec<LabelText>]) -> f64 {
    for line in rows {
        let mut x = x0;
        for item in line {
            let bb = item.draw(g, Point::new(x, y), 3.5, Anchor::Start);
            x = bb.x1 + 2.5;
        }
        y += LINE;
    }
    y
}

fn scale_item(inp: &ForcesInput, sub: &str, mu: f64, unit: &str) -> LabelText {
    LabelText::new("μ", sub).with_tail(format!(" = {} {unit}", fmt::localise(&scale::format(mu), inp.lang)))
}

fn with_semicolon(mut l: LabelText) -> LabelText {
    l.tail.push(';');
    l
}

fn draw_group_cell(
    g: &mut Group,
    labels: &mut Labels,
    r: Rect,
    inp: &ForcesInput,
    poly: &Polygon,
    layout: &GroupLayout,
) {
    cell_title(g, r, &group_title(inp, poly));
    let top = r.y0 + CELL_TITLE;
    let lines = layout.equation.len() + layout.legend.len() + SCALE_LINES;
    let bottom = r.y1 - LINE * lines as f64 - 2.0;
    let geo = Rect::new(r.x0, top, r.x0 + layout.drawing_w, bottom);
    draw_group_geometry(g, labels, inp, poly, geo, layout);
    let pr = Rect::new(r.x0 + layout.drawing_w, top, r.x1, bottom);
    draw_polygon(g, labels, inp, poly, layout, pr);
    let scales = vec![
        vec![
            with_semicolon(scale_item(inp, "l", layout.mu_l, inp.c.unit_m_per_mm())),
            scale_item(inp, "F", layout.mu_f, inp.c.unit_n_per_mm()),
        ],
        vec![scale_item(inp, "P", layout.mu_p, inp.c.unit_n_per_mm())],
    ];
    let y = text_rows(g, r.x0 + 2.0, bottom + LINE, &layout.equation);
    let y = text_rows(g, r.x0 + 2.0, y, &layout.legend);
    text_rows(g, r.x0 + 2.0, y, &scales);
}

fn draw_group_geometry(
    g: &mut Group,
    labels: &mut Labels,
    inp: &ForcesInput,
    poly: &Polygon,
    r: Rect,
    layout: &GroupLayout,
) {
    let p = view(layout.world, r, layout.mu_l);
    let m = inp.m;
    let mut link_lines = Vec::new();
    let mut blocks = Vec::new();
    for &l in &links_of(inp, poly) {
        let link = &m.links[l];
        let joints: Vec<usize> = link.points.iter().copied().filter(|&q| !m.is_mass_centre(q)).collect();
        let Some(&first) = joints.first() else { continue };
        match link.kind {
            LinkKind::Slider => {
                let dir = inp.state.links[l].dir;
                slider(g, p(inp.state.points[first].p), paper_dir(dir), 10.0, 5.0, MAIN);
                let c = p(inp.state.points[first].p);
                let u = paper_dir(dir);
                blocks.push((c, u.unit(), 5.0, 2.5));
                g.line(c - u * 14.0 + u.turn_90() * 2.5, c + u * 14.0 + u.turn_90() * 2.5, THIN);
            }
            LinkKind::Block => {
                let (c, u) = (p(inp.state.points[first].p), paper_dir(inp.state.links[l].dir));
                slider(g, c, u, 8.0, 4.0, MAIN);
                blocks.push((c, u.unit(), 4.0, 2.0));
            }
            _ => {
                for &q in &joints[1..] {
                    let (a, b) = (p(inp.state.points[first].p), p(inp.state.points[q].p));
                    g.line(a, b, MAIN);
                    link_lines.push((a, b));
                }
            }
        }
    }
    // A joint shared by the group's two links is drawn and named once.
    let mut points: Vec<usize> = Vec::new();
    for &l in &links_of(inp, poly) {
        points.extend(m.links[l].points.iter().filter(|q| !points.contains(q)).collect::<Vec<_>>());
    }
    for &q in &points {
        let at = p(inp.state.points[q].p);
        if m.is_frame(q) {
            frame_pivot(g, at, 1.2);
        } else if m.is_mass_centre(q) {
            g.dot(at, 0.6);
        } else {
            g.circle(at, 1.0, THIN);
        }
    }
    let mut drawn = Obstacles::of_items(&g.items);
    for il in inp.fa.forces.inertia.iter().filter(|il| links_of(inp, poly).contains(&il.link) && il.moment != 0.0) {
        let centre = m.mass_centres.iter().find(|c| c.0 == il.link).map_or(m.links[il.link].points[0], |c| c.1);
        let at = p(inp.state.points[centre].p);
        let start = clear_turn_arrow(g, &mut drawn, at, MOMENT_R, 200.0, MOMENT_SWEEP, il.moment > 0.0, THIN);
        let sign = if il.moment > 0.0 { -1.0 } else { 1.0 };
        let mid = at + crate::num::math::from_angle((start + sign * MOMENT_SWEEP / 2.0).to_radians()) * MOMENT_R;
        labels.add(
            mid,
            mid - at,
            LabelText::new("M", inp.l.force(ForceKind::Inertia, &m.links[il.link].number.to_string())),
            3.5,
        );
    }
    let mut arrows = Arrows { links: link_lines, blocks, drawn: Vec::new(), mu_f: layout.mu_f, h: 3.5 };
    for t in &poly.terms {
        arrows.arrow(g, labels, p(t.at), t.force, force_label(inp, t.kind, t.on));
    }
    // The letters last: they keep clear of the arrows.
    for &q in &points {
        let at = p(inp.state.points[q].p);
        let (main, sub) = split_name(m.name(q));
        labels.add(at, Vec2::new(-1.0, -1.0), LabelText::new(main, sub), 3.5);
    }
}

/// Radius and sweep of an inertia moment's arc, mm and degrees.
const MOMENT_R: f64 = 6.0;
const MOMENT_SWEEP: f64 = 120.0;

fn draw_polygon(g: &mut Group, labels: &mut Labels, inp: &ForcesInput, poly: &Polygon, layout: &GroupLayout, r: Rect) {
    let p = view(layout.chain_box, r, layout.mu_p);
    let pts = &layout.chain;
    // Labels stand outside the polygon: beside each side, away from the vertices' centre.
    let centre = {
        let n = pts.len().max(1) as f64;
        let c = pts.iter().fold(Vec2::ZERO, |acc, &v| acc + v) / n;
        p(c)
    };
    let outward = |a: Point, b: Point| {
        let n = (b - a).turn_90();
        if n.dot(a.midpoint(b) - centre) < 0.0 { -n } else { n }
    };
    for (k, t) in poly.terms.iter().enumerate() {
        let (a, b) = (p(pts[k]), p(pts[k + 1]));
        if (b - a).norm() < tol::PAPER_INVISIBLE {
            continue;
        }
        vector(g, a, b, VECTOR);
        labels.add(a.midpoint(b), outward(a, b), force_label(inp, t.kind, t.on), 3.5);
    }
    if let Some(inner) = &poly.inner {
        let (a, b) = (p(pts[poly.split]), p(pts[0]));
        if (b - a).norm() >= tol::PAPER_INVISIBLE {
            vector(g, a, b, DASHED);
            // The inner reaction runs inside the polygon: its label beside it, either side.
            labels.add(a.midpoint(b), (b - a).turn_90(), force_label(inp, inner.kind, inner.on), 3.5);
        }
    }
    g.dot(p(pts[0]), 0.5);
}

/// Lines under the lever besides its legend: μ_v and μ_F, P′ₘ, Δ.
const LEVER_LINES: usize = 3;

fn lever_arrow_scale(inp: &ForcesInput) -> f64 {
    let f = &inp.fa.forces;
    arrow_scale(f.lever.iter().map(|l| l.force.norm()).fold(f.p_m_lever.abs(), f64::max))
}

/// The lever's legend: each force once, with its value.
fn lever_legend(inp: &ForcesInput, mu_f: f64, width: f64) -> Vec<Vec<LabelText>> {
    let mut items: Vec<LabelText> = Vec::new();
    let mut short = false;
    for l in &inp.fa.forces.lever {
        let f = l.force.norm();
        if f <= 0.0 {
            continue;
        }
        let label = if l.couple { couple_label(inp, l.on) } else { force_label(inp, l.kind, l.on) };
        if items.iter().any(|i| i.main == label.main && i.sub == label.sub) {
            continue;
        }
        let s = f / mu_f < ARROW_MIN;
        short |= s;
        items.push(value_item(inp, label, f, inp.c.unit_n(), s));
    }
    with_short_note(inp, wrap_items(items, width, ";", ""), short, width)
}

fn draw_lever(g: &mut Group, labels: &mut Labels, r: Rect, inp: &ForcesInput, plan: &Plan, (mu, mu_f): (f64, f64)) {
    let f = &inp.fa.forces;
    let legend = lever_legend(inp, mu_f, r.width() - 4.0);
    let text_h = (LEVER_LINES + legend.len()) as f64 * LINE;
    let plan_cell = Rect::new(r.x0, r.y0, r.x1, r.y1 - text_h);
    let cell = PlanCell { cell: plan_cell, title: inp.l.lever_title(), plan, mu, pole: "p", scale_line: None };
    let pole = draw_plan(g, &cell, labels);
    let at = |v: Vec2| Point::new(pole.x + v.x / mu, pole.y - v.y / mu);
    let mut arrows = Arrows { links: Vec::new(), blocks: Vec::new(), drawn: Vec::new(), mu_f, h: 2.5 };
    for l in &f.lever {
        let label = if l.couple { couple_label(inp, l.on) } else { force_label(inp, l.kind, l.on) };
        arrows.arrow(g, labels, at(l.image), l.force, label);
    }
    let crank = inp.m.crank();
    let a_img = inp.state.points[crank.pin].v.turn_90() * inp.m.omega1.signum();
    arrows.arrow(g, labels, at(a_img), f.dir_m * f.p_m_lever, LabelText::new("P′", inp.l.sub_balancing()));
    let lang = inp.lang;
    let lines = [
        vec![
            with_semicolon(scale_item(inp, "v", mu, inp.c.unit_v_per_mm())),
            scale_item(inp, "F", mu_f, inp.c.unit_n_per_mm()),
        ],
        vec![LabelText::new("P′", inp.l.sub_balancing()).with_tail(format!(
            " = {} {}",
            fmt::value(f.p_m_lever, lang),
            inp.c.unit_n()
        ))],
        vec![LabelText::new("Δ", "").with_tail(format!(" = {} %", fmt::value(f.difference_percent(), lang)))],
    ];
    let y = text_rows(g, r.x0 + 2.0, r.y1 - text_h + LINE, &legend);
    text_rows(g, r.x0 + 2.0, y, &lines);
}

/// A load diagram: force against S/H for both strokes, the analysed position marked.
fn draw_load(g: &mut Group, labels: &mut Labels, r: Rect, inp: &ForcesInput, i: usize) {
    let load: &Load = &inp.fa.model.loads[i];
    let value = inp.fa.forces.loads[i];
    let n = inp.m.links[load.link].number;
    let lang = inp.lang;
    cell_title(g, r, &inp.l.load_title(&n.to_string()));
    let area = Rect::new(r.x0 + 20.0, r.y0 + 20.0, r.x1 - 14.0, r.y1 - 22.0);
    let signed = |b: usize, y: f64| y * load.branches[b].scale;
    let values =
        || load.branches.iter().enumerate().flat_map(|(b, br)| br.curve.points.iter().map(move |p| signed(b, p.1)));
    let (least, most) = values().fold((f64::MAX, f64::MIN), |(lo, hi), y| (lo.min(y), hi.max(y)));
    // The drawing spans zero, where the S/H axis runs.
    let (lo, hi) = (least.min(0.0), most.max(0.0));
    let mu = scale::round_up((hi - lo) / area.height());
    let x = Axis {
        lo: 0.0,
        hi: 1.0,
        mu: 1.0 / area.width(),
        name: "S/H".into(),
        ticks: [0.0, 0.5, 1.0].map(|v| (v, fmt::localise(&format!("{v}"), lang))).to_vec(),
    };
    let y = Axis { lo, hi, mu, name: format!("P, {}", inp.c.unit_n()), ticks: round_ticks(lo, hi, mu, lang) };
    let plot = Plot::in_area(Rect::new(area.x0, area.y1 - (hi - lo) / mu, area.x1, area.y1), x, y);
    plot.draw_axes(g);
    let mut names = Vec::new();
    for (b, br) in load.branches.iter().enumerate() {
        let data: Vec<(f64, f64)> = br.curve.points.iter().map(|&(s, y)| (s, signed(b, y))).collect();
        plot.line(g, &data, if b == 0 { MAIN } else { DASHED });
        let name = match br.name {
            Stroke::Working => inp.l.stroke_working(),
            Stroke::Idle => inp.l.stroke_idle(),
            Stroke::TowardHead => inp.l.stroke_toward_head(),
            Stroke::AwayFromHead => inp.l.stroke_away_from_head(),
            Stroke::Expansion => inp.l.stroke_expansion(),
            Stroke::Exhaust => inp.l.stroke_exhaust(),
            Stroke::Intake => inp.l.stroke_intake(),
            Stroke::Compression => inp.l.stroke_compression(),
        };
        // Named at a third of the stroke, on the side away from the other branch.
        let (s, y) = data[data.len() / 3];
        names.push((plot.at(s, y), Vec2::new(0.3, if b == 0 { -1.0 } else { 1.0 }), name));
    }
    let along = value.force.dot(load.axis);
    let mark = plot.at(value.s, along);
    g.line(plot.at(value.s, 0.0), mark, THIN);
    g.circle(mark, 1.0, MAIN);
    for (at, pref, name) in names {
        labels.add_text(at, pref, name, 2.5);
    }
    let phi = fmt::localise(&format!("{:.1}", inp.phi_deg), lang);
    labels.add(mark, Vec2::new(1.0, -1.0), LabelText::new("φ", "1").with_tail(format!(" = {phi}°")), 2.5);
    let lines = [
        vec![LabelText::new("φ", "1").with_tail(format!(
            ": S/H = {}, P = {} {}",
            fmt::value(value.s, lang),
            fmt::value(along, lang),
            inp.c.unit_n()
        ))],
        vec![scale_item(inp, "P", mu, inp.c.unit_n_per_mm())],
    ];
    text_rows(g, r.x0 + 2.0, r.y1 - 2.0 - LINE, &lines);
}
