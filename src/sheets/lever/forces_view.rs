//! The force analysis on sheet 1: each Assur group and the crank drawn apart at one length
//! scale with their forces, each force polygon at its own round μ_P with its vector
//! equation, the Zhukovsky lever, the load diagrams and tables 3–5. The cells are packed
//! in rows; when they do not fit, the drawings get smaller scales, never smaller text.

use super::labels::LeverLabels;
use super::mechanism_view::split_name;
use super::plans_view::{MARGIN, TITLE, draw_plan_with, plan_bbox};
use crate::drawing::fmt;
use crate::drawing::labels::{Common, Language};
use crate::drawing::place::Placer;
use crate::drawing::plot::{Axis, Plot};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN, Text, VECTOR};
use crate::drawing::symbols::{frame_pivot, slider, turn_arrow, vector};
use crate::drawing::table::Table;
use crate::drawing::text::LabelText;
use crate::lever::analysis::ForceAnalysis;
use crate::lever::kinetostatics::{FRAME, Kind, Part, Polygon};
use crate::lever::linkage::{LinkKind, Mechanism, State};
use crate::lever::load::{Load, Stroke};
use crate::lever::plans::{Plan, velocity_plan};
use crate::num::math::Norm;
use crate::num::tol;
use crate::report::lever::load_letter;
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
const LINE: f64 = 5.0;
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
    /// Velocity scale of the Zhukovsky lever, (m/s)/mm.
    pub mu_lever: f64,
}

enum Content {
    /// Index into the polygons, and the layout computed for the cell's size.
    Polygon(usize, GroupLayout),
    /// The turned velocity plan and its scale.
    Lever(Plan, f64),
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
    /// The polygon's vertices in newtons, from its start, and their box.
    chain: Vec<Vec2>,
    chain_box: Rect,
    equation: Vec<Vec<LabelText>>,
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

pub fn draw_forces(g: &mut Group, region: Rect, inp: &ForcesInput) -> ForceScales {
    let title = inp.l.forces_title(&fmt::localise(&format!("{:.1}", inp.phi_deg), inp.lang));
    g.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, 5.0, Anchor::Start));
    let body = Rect::new(region.x0, region.y0 + 10.0, region.x1, region.y1);
    let widest =
        inp.fa.forces.polygons.iter().map(|p| world_box(inp, p)).map(|b| b.width().max(b.height())).fold(0.0, f64::max);
    let mut attempt = Sizes { group_box: 130.0, poly_box: 90.0, lever_box: 110.0, widest };
    // Shrink until the cells fit; the last attempt is drawn even if it does not (the layout
    // test then reports it).
    let (cells, at) = {
        let mut tries = 0;
        loop {
            let cells = cells(inp, attempt);
            let at = pack(&cells, body);
            tries += 1;
            if fits(&cells, &at, body) || tries == 12 {
                break (cells, at);
            }
            attempt = attempt.shrunk();
        }
    };
    let mut scales = ForceScales { mu_l: vec![], mu_p: vec![], mu_lever: 0.0 };
    for (cell, origin) in cells.iter().zip(at) {
        let r = Rect::new(origin.x, origin.y, origin.x + cell.w, origin.y + cell.h);
        // Each cell places its own labels inside itself, so cells never collide.
        let mut placer = Placer::new(r);
        match cell.content {
            Content::Polygon(i, ref layout) => {
                draw_group_cell(g, &mut placer, r, inp, &inp.fa.forces.polygons[i], layout);
                scales.mu_l.push(layout.mu_l);
                scales.mu_p.push(layout.mu_p);
            }
            Content::Lever(ref plan, mu) => {
                draw_lever(g, &mut placer, r, inp, plan, mu);
                scales.mu_lever = mu;
            }
            Content::Load(i) => draw_load(g, &mut placer, r, inp, i),
            Content::Table(i) => {
                inp.tables[i].draw(g, origin);
            }
        }
    }
    scales
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

fn equation_lines(inp: &ForcesInput, poly: &Polygon, width: f64) -> Vec<Vec<LabelText>> {
    let terms: Vec<LabelText> =
        poly.terms.iter().filter(|t| t.force.norm() > 0.0).map(|t| force_label(inp, t.kind, t.on)).collect();
    let mut lines: Vec<Vec<LabelText>> = vec![vec![]];
    let mut w = 0.0;
    for (i, t) in terms.iter().enumerate() {
        let last = i + 1 == terms.len();
        let item = LabelText { tail: if last { " = 0".into() } else { " +".into() }, ..t.clone() };
        let iw = measure(&item, 3.5).width() + 2.0;
        if w + iw > width && w > 0.0 {
            lines.push(vec![]);
            w = 0.0;
        }
        w += iw;
        lines.last_mut().expect("one line at least").push(item);
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
    let (poly_w, poly_h) = (chain_box.width() / mu_p + 2.0 * POLY_PAD, chain_box.height() / mu_p + 2.0 * POLY_PAD);
    let w = (drawing_w + poly_w).max(120.0);
    let equation = equation_lines(inp, poly, w - 4.0);
    let h = CELL_TITLE + drawing_h.max(poly_h) + LINE * (equation.len() as f64 + 2.0) + 2.0;
    (GroupLayout { world, mu_l, drawing_w, mu_p, chain, chain_box, equation }, w, h)
}

fn cells(inp: &ForcesInput, s: Sizes) -> Vec<Cell> {
    let mut out = Vec::new();
    for (i, poly) in inp.fa.forces.polygons.iter().enumerate() {
        let (layout, w, h) = group_layout(inp, poly, s);
        out.push(Cell { w, h, content: Content::Polygon(i, layout) });
    }
    let lever = velocity_plan(inp.m, inp.state).turned(inp.m.omega1.signum());
    let bb = plan_bbox(&lever);
    let mu = scale::round_up(bb.width().max(bb.height()) / s.lever_box);
    let pad = MARGIN + ARROW_MAX + 4.0;
    let (w, h) = ((bb.width() / mu + 2.0 * pad).max(110.0), TITLE + bb.height() / mu + 2.0 * pad + 3.0 * LINE);
    out.push(Cell { w, h, content: Content::Lever(lever, mu) });
    for i in 0..inp.fa.model.loads.len() {
        out.push(Cell { w: LOAD_W, h: LOAD_H, content: Content::Load(i) });
    }
    for (i, t) in inp.tables.iter().enumerate() {
        let (w, h) = t.size();
        out.push(Cell { w: w + 2.0, h: h + 2.0, content: Content::Table(i) });
    }
    out
}

/// Places cells in rows, left to right, starting a row when the next cell would overflow.
fn pack(cells: &[Cell], body: Rect) -> Vec<Point> {
    let (mut x, mut y, mut row_h) = (body.x0, body.y0, 0.0f64);
    let mut out = Vec::new();
    for c in cells {
        if x > body.x0 && x + c.w > body.x1 {
            x = body.x0;
            y += row_h + GAP;
            row_h = 0.0;
        }
        out.push(Point::new(x, y));
        x += c.w + GAP;
        row_h = row_h.max(c.h);
    }
    out
}

fn fits(cells: &[Cell], at: &[Point], body: Rect) -> bool {
    cells.iter().zip(at).all(|(c, p)| p.x + c.w <= body.x1 + tol::PAPER && p.y + c.h <= body.y1 + tol::PAPER)
}

/// The label of a force: G₂, Pᵢ₂, P_c5, Rⁿ₁₂, Pₘ.
fn force_label(inp: &ForcesInput, kind: Kind, on: usize) -> LabelText {
    let n = |l: usize| if l == FRAME { 0 } else { inp.m.links[l].number };
    match kind {
        Kind::Weight => LabelText::new("G", n(on).to_string()),
        Kind::Inertia => LabelText::new("P", format!("i{}", n(on))),
        Kind::Load(i) => LabelText::new("P", format!("{}{}", load_letter(inp.fa.model.loads[i].kind), n(on))),
        Kind::Reaction { from, part } => {
            let main = match part {
                Part::Whole => "R",
                Part::Normal => "Rⁿ",
                Part::Tangential => "Rᵗ",
            };
            LabelText::new(main, format!("{}{}", n(from), n(on)))
        }
        Kind::Balancing => LabelText::new("P", "m"),
    }
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

/// A force arrow from `at` with its label (3.5 mm, with the value when the arrow had to be
/// lengthened; `small`: 2.5 mm and no value, for the crowded lever); nothing for a zero force.
fn force_arrow(
    g: &mut Group,
    placer: &mut Placer,
    inp: &ForcesInput,
    at: Point,
    (kind, on, force): (Kind, usize, Vec2),
    unit: f64,
    small: bool,
) {
    let f = force.norm();
    if f <= 0.0 {
        return;
    }
    let natural = f / unit;
    let len = natural.clamp(ARROW_MIN, ARROW_MAX);
    let d = paper_dir(force) / f;
    let tip = at + d * len;
    vector(g, at, tip, VECTOR);
    let mut label = force_label(inp, kind, on);
    if natural < ARROW_MIN && !small {
        label.tail = format!(" = {} {}", fmt::value(f, inp.lang), inp.c.unit_n());
    }
    place_label_h(g, placer, tip, d, &label, if small { 2.5 } else { 3.5 });
}

/// Places a label with a subscript beside `anchor`, preferring direction `pref`.
fn place_label(g: &mut Group, placer: &mut Placer, anchor: Point, pref: Vec2, label: &LabelText) {
    place_label_h(g, placer, anchor, pref, label, 3.5);
}

fn place_label_h(g: &mut Group, placer: &mut Placer, anchor: Point, pref: Vec2, label: &LabelText, h: f64) {
    let bb = measure(label, h);
    let r = placer.place_box(anchor, pref, bb.width() + 0.4, bb.height() + 0.4);
    label.draw(g, Point::new(r.center().x, r.y1 - 0.2 - bb.y1), h, Anchor::Middle);
}

fn cell_title(g: &mut Group, placer: &mut Placer, r: Rect, text: &str) {
    let t = Text::new(Point::new(r.x0 + 2.0, r.y0 + 5.0), text, 3.5, Anchor::Start);
    placer.block(t.bbox());
    g.text(t);
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

fn draw_group_cell(
    g: &mut Group,
    placer: &mut Placer,
    r: Rect,
    inp: &ForcesInput,
    poly: &Polygon,
    layout: &GroupLayout,
) {
    cell_title(g, placer, r, &group_title(inp, poly));
    let top = r.y0 + CELL_TITLE;
    let bottom = r.y1 - LINE * (layout.equation.len() as f64 + 2.0) - 2.0;
    let geo = Rect::new(r.x0, top, r.x0 + layout.drawing_w, bottom);
    draw_group_geometry(g, placer, inp, poly, geo, layout.world, layout.mu_l);
    let pr = Rect::new(r.x0 + layout.drawing_w, top, r.x1, bottom);
    draw_polygon(g, placer, inp, poly, layout, pr);
    let mut y = bottom + LINE;
    for line in &layout.equation {
        let mut x = r.x0 + 2.0;
        for item in line {
            let bb = item.draw(g, Point::new(x, y), 3.5, Anchor::Start);
            placer.block(bb);
            x = bb.x1 + 2.0;
        }
        y += LINE;
    }
    let scale_lines = [
        LabelText::new("μ", "l").with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(layout.mu_l), inp.lang),
            inp.c.unit_m_per_mm()
        )),
        LabelText::new("μ", "P").with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(layout.mu_p), inp.lang),
            inp.c.unit_n_per_mm()
        )),
    ];
    for line in scale_lines {
        placer.block(line.draw(g, Point::new(r.x0 + 2.0, y), 3.5, Anchor::Start));
        y += LINE;
    }
}

fn draw_group_geometry(
    g: &mut Group,
    placer: &mut Placer,
    inp: &ForcesInput,
    poly: &Polygon,
    r: Rect,
    wb: Rect,
    mu: f64,
) {
    let p = view(wb, r, mu);
    let m = inp.m;
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
                g.line(c - u * 14.0 + u.turn_90() * 2.5, c + u * 14.0 + u.turn_90() * 2.5, THIN);
            }
            LinkKind::Block => {
                slider(g, p(inp.state.points[first].p), paper_dir(inp.state.links[l].dir), 8.0, 4.0, MAIN)
            }
            _ => {
                for &q in &joints[1..] {
                    g.line(p(inp.state.points[first].p), p(inp.state.points[q].p), MAIN);
                }
            }
        }
    }
    // A joint shared by the group's two links is drawn and named once.
    let mut points: Vec<usize> = Vec::new();
    for &l in &links_of(inp, poly) {
        points.extend(m.links[l].points.iter().filter(|q| !points.contains(q)).collect::<Vec<_>>());
    }
    for q in points {
        let at = p(inp.state.points[q].p);
        if m.is_frame(q) {
            frame_pivot(g, at, 1.2);
        } else if m.is_mass_centre(q) {
            g.dot(at, 0.6);
        } else {
            g.circle(at, 1.0, THIN);
        }
        let (main, sub) = split_name(m.name(q));
        place_label(g, placer, at, Vec2::new(-1.0, -1.0), &LabelText::new(main, sub));
    }
    let unit = poly.terms.iter().map(|t| t.force.norm()).fold(0.0, f64::max) / ARROW_MAX;
    for t in &poly.terms {
        force_arrow(g, placer, inp, p(t.at), (t.kind, t.on, t.force), unit.max(f64::MIN_POSITIVE), false);
    }
    for il in inp.fa.forces.inertia.iter().filter(|il| links_of(inp, poly).contains(&il.link) && il.moment != 0.0) {
        let centre = m.mass_centres.iter().find(|c| c.0 == il.link).map_or(m.links[il.link].points[0], |c| c.1);
        let at = p(inp.state.points[centre].p);
        turn_arrow(g, at, 5.0, 200.0, 250.0, il.moment > 0.0, THIN);
        place_label(
            g,
            placer,
            at + Vec2::new(5.0, 5.0),
            Vec2::new(1.0, 1.0),
            &LabelText::new("M", format!("i{}", m.links[il.link].number)),
        );
    }
}

fn draw_polygon(g: &mut Group, placer: &mut Placer, inp: &ForcesInput, poly: &Polygon, layout: &GroupLayout, r: Rect) {
    let p = view(layout.chain_box, r, layout.mu_p);
    let pts = &layout.chain;
    for (k, t) in poly.terms.iter().enumerate() {
        let (a, b) = (p(pts[k]), p(pts[k + 1]));
        if (b - a).norm() < tol::PAPER_INVISIBLE {
            continue;
        }
        vector(g, a, b, VECTOR);
        let mid = a.midpoint(b);
        place_label(g, placer, mid, (b - a).turn_90(), &force_label(inp, t.kind, t.on));
    }
    if let Some(inner) = &poly.inner {
        let (a, b) = (p(pts[poly.split]), p(pts[0]));
        if (b - a).norm() >= tol::PAPER_INVISIBLE {
            vector(g, a, b, DASHED);
            place_label(g, placer, a.midpoint(b), (b - a).turn_90(), &force_label(inp, inner.kind, inner.on));
        }
    }
    g.dot(p(pts[0]), 0.5);
}

fn draw_lever(g: &mut Group, placer: &mut Placer, r: Rect, inp: &ForcesInput, plan: &Plan, mu: f64) {
    let f = &inp.fa.forces;
    let text_h = 3.0 * LINE;
    let plan_cell = Rect::new(r.x0, r.y0, r.x1, r.y1 - text_h);
    let pole = draw_plan_with(g, plan_cell, inp.l.lever_title(), plan, mu, "p", placer);
    let at = |v: Vec2| Point::new(pole.x + v.x / mu, pole.y - v.y / mu);
    let unit = f.lever.iter().map(|l| l.force.norm()).fold(f.p_m_lever.abs(), f64::max) / ARROW_MAX;
    for l in &f.lever {
        if l.couple {
            let d = paper_dir(l.force);
            vector(g, at(l.image), at(l.image) + d / d.norm().max(f64::MIN_POSITIVE) * ARROW_MIN, THIN);
            continue;
        }
        force_arrow(g, placer, inp, at(l.image), (l.kind, l.on, l.force), unit.max(f64::MIN_POSITIVE), true);
    }
    let crank = inp.m.crank();
    let a_img = inp.state.points[crank.pin].v.turn_90() * inp.m.omega1.signum();
    force_arrow(
        g,
        placer,
        inp,
        at(a_img),
        (Kind::Balancing, crank.link, f.dir_m * f.p_m_lever),
        unit.max(f64::MIN_POSITIVE),
        true,
    );
    let lang = inp.lang;
    let y0 = r.y1 - text_h + LINE;
    let lines = [
        LabelText::new("μ", "v").with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(mu), lang),
            inp.c.unit_v_per_mm()
        )),
        LabelText::new("P′", "m").with_tail(format!(" = {} {}", fmt::value(f.p_m_lever, lang), inp.c.unit_n())),
        LabelText::new("Δ", "")
            .with_tail(format!(" = (Pₘ − P′ₘ)/Pₘ·100 % = {} %", fmt::scientific(f.difference_percent(), lang))),
    ];
    for (k, line) in lines.iter().enumerate() {
        placer.block(line.draw(g, Point::new(r.x0 + 2.0, y0 + LINE * k as f64), 3.5, Anchor::Start));
    }
}

/// A load diagram: force against S/H for both strokes, the analysed position marked.
fn draw_load(g: &mut Group, placer: &mut Placer, r: Rect, inp: &ForcesInput, i: usize) {
    let load: &Load = &inp.fa.model.loads[i];
    let value = inp.fa.forces.loads[i];
    let n = inp.m.links[load.link].number;
    let lang = inp.lang;
    cell_title(g, placer, r, &inp.l.load_title(&n.to_string()));
    let area = Rect::new(r.x0 + 18.0, r.y0 + 20.0, r.x1 - 14.0, r.y1 - 22.0);
    let signed = |b: usize, y: f64| y * load.branches[b].scale;
    let values =
        || load.branches.iter().enumerate().flat_map(|(b, br)| br.curve.points.iter().map(move |p| signed(b, p.1)));
    let (least, most) = values().fold((f64::MAX, f64::MIN), |(lo, hi), y| (lo.min(y), hi.max(y)));
    // The drawing spans zero, where the S/H axis runs; the ticks mark the diagram's extremes.
    let (lo, hi) = (least.min(0.0), most.max(0.0));
    let mu = scale::round_up((hi - lo) / area.height());
    let x = Axis {
        lo: 0.0,
        hi: 1.0,
        mu: 1.0 / area.width(),
        name: "S/H".into(),
        ticks: [0.0, 0.5, 1.0].map(|v| (v, fmt::localise(&format!("{v}"), lang))).to_vec(),
    };
    let mut extremes: Vec<(f64, String)> = vec![(least, fmt::value(least, lang))];
    if most != least {
        extremes.push((most, fmt::value(most, lang)));
    }
    let y = Axis { lo, hi, mu, name: format!("P, {}", inp.c.unit_n()), ticks: extremes };
    let plot = Plot::in_area(Rect::new(area.x0, area.y1 - (hi - lo) / mu, area.x1, area.y1), x, y);
    plot.draw_axes(g, placer);
    for (b, br) in load.branches.iter().enumerate() {
        let data: Vec<(f64, f64)> = br.curve.points.iter().map(|&(s, y)| (s, signed(b, y))).collect();
        plot.line(g, &data, if b == 0 { MAIN } else { DASHED });
        let (s, y) = data[data.len() / 2];
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
        let t = placer.place(plot.at(s, y), Vec2::new(0.3, if b == 0 { -1.0 } else { 1.0 }), name, 2.5);
        g.text(t);
    }
    let along = value.force.dot(load.axis);
    let mark = plot.at(value.s, along);
    g.line(plot.at(value.s, 0.0), mark, THIN);
    g.circle(mark, 1.0, MAIN);
    place_label(g, placer, mark, Vec2::new(1.0, -1.0), &LabelText::new("φ", "1"));
    let lines = [
        LabelText::new("φ", "1").with_tail(format!(
            ": S/H = {}, P = {} {}",
            fmt::value(value.s, lang),
            fmt::value(along, lang),
            inp.c.unit_n()
        )),
        LabelText::new("μ", "P").with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(mu), lang),
            inp.c.unit_n_per_mm()
        )),
    ];
    for (k, line) in lines.iter().enumerate() {
        placer.block(line.draw(g, Point::new(r.x0 + 2.0, r.y1 - 2.0 - LINE * (1 - k) as f64), 3.5, Anchor::Start));
    }
}
