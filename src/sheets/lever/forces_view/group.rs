//! A group drawing (an Assur group or the crank, apart at its length scale, with its forces
//! and inertia moments) beside its force polygon, the vector equation, the legend and the
//! scales under them.

use super::arrows::{Arrows, Push, arrow_scale, twins_reach, unit_directions};
use super::cells::Sizes;
use super::inset::{self, Enlarge, Inset, Place};
use super::legend::{
    cell_title, decimals_of, equation_lines, equation_rows, force_label, scale_item, text_rows, value_item,
    with_semicolon, with_short_note, wrap_items,
};
use super::polygon::{bbox_of, chain, draw_polygon};
use super::{ARROW_MAX, ARROW_MIN, ForcesInput, LINE};
use crate::drawing::obstacles::{Obstacles, Piece};
use crate::drawing::place::Labels;
use crate::drawing::scene::{Group, MAIN, THIN};
use crate::drawing::symbols::{clear_turn_arrow, slider, turn_arrow_reach};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::kinetostatics::Polygon;
use crate::lever::linkage::LinkKind;
use crate::num::math::Norm;
use crate::report::ForceKind;
use crate::sheets::lever::mechanism_view::split_name;
use kurbo::{Point, Rect, Vec2};

/// Room around a group drawing for its arrows and labels, mm.
const PAD: f64 = ARROW_MAX + 6.0;
/// Room around a force polygon for its labels, mm.
const POLY_PAD: f64 = 9.0;
const CELL_TITLE: f64 = 8.0;

/// What sizes a group cell and then draws it: computed once per layout attempt.
pub(super) struct GroupLayout {
    /// The group's points in the world, m.
    pub(super) world: Rect,
    pub(super) mu_l: f64,
    /// Width and height of the group drawing with its room for arrows, mm.
    pub(super) drawing_w: f64,
    pub(super) drawing_h: f64,
    /// Whether the polygon stands under the drawing rather than beside it.
    pub(super) stacked: bool,
    pub(super) mu_p: f64,
    /// Scale of the force arrows on the group drawing, N/mm.
    pub(super) mu_f: f64,
    /// The polygon's vertices in newtons, from its start, and their box.
    pub(super) chain: Vec<Vec2>,
    pub(super) chain_box: Rect,
    pub(super) equation: Vec<Vec<LabelText>>,
    /// Each force's symbol and value, wrapped into lines.
    pub(super) legend: Vec<Vec<LabelText>>,
    /// The polygon's runs of short sides, enlarged where `place` says; the polygon's size
    /// with its room for labels, mm.
    pub(super) insets: Vec<Inset>,
    pub(super) place: Place,
    pub(super) poly_size: (f64, f64),
}

/// The world box of a polygon's group (or the crank): its links' points.
pub(super) fn world_box(inp: &ForcesInput, poly: &Polygon) -> Rect {
    let pts = drawn_points(inp, poly);
    let first = pts.first().map_or(Point::ZERO, |p| p.to_point());
    pts.iter().fold(Rect::from_points(first, first), |r, p| r.union_pt(p.to_point()))
}

pub(super) fn links_of(inp: &ForcesInput, poly: &Polygon) -> Vec<usize> {
    match poly.group {
        Some(gi) => inp.m.groups[gi].links.to_vec(),
        None => vec![inp.m.crank().link],
    }
}

fn drawn_points(inp: &ForcesInput, poly: &Polygon) -> Vec<Vec2> {
    links_of(inp, poly).iter().flat_map(|&l| inp.m.links[l].points.iter().map(|&p| inp.state.points[p].p)).collect()
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
        let label = force_label(inp, t.kind, t.on);
        items.push(value_item(inp, label, (f, decimals_of(inp, t.kind)), inp.words.common.unit_n(), s));
    }
    if let Some(inner) = &poly.inner {
        items.push(value_item(
            inp,
            force_label(inp, inner.kind, inner.on),
            (inner.force.norm(), decimals_of(inp, inner.kind)),
            inp.words.common.unit_n(),
            false,
        ));
    }
    for il in inp.fa.forces.inertia.iter().filter(|il| links_of(inp, poly).contains(&il.link) && il.moment != 0.0) {
        let label =
            LabelText::new("M", inp.words.sheet.force(ForceKind::Inertia, &inp.m.links[il.link].number.to_string()));
        let value = (il.moment.abs(), Some(inp.decimals.moment));
        items.push(value_item(inp, label, value, inp.words.common.unit_n_m(), false));
    }
    with_short_note(inp, wrap_items(items, width, ";", ""), short, width)
}

/// A group drawing's length scale and its polygon's μ_P at the sizes `s`, its polygon's box
/// `grown` times theirs: all its cell's layout depends on besides whether it may grow.
pub(super) fn group_scales(poly: &Polygon, inp: &ForcesInput, s: Sizes, grown: f64) -> (f64, f64) {
    let chain_box = bbox_of(&chain(poly));
    (s.mu_l(world_box(inp, poly)), s.round_up(chain_box.width().max(chain_box.height()) / (s.poly_box * grown)))
}

/// A group cell's layout at its scales (see [`group_scales`]), with its width and height.
pub(super) fn group_layout(
    inp: &ForcesInput,
    poly: &Polygon,
    (mu_l, mu_p): (f64, f64),
    (enlarge, inset_box): ((Enlarge, bool), f64),
    stacked: bool,
) -> (GroupLayout, f64, f64) {
    let world = world_box(inp, poly);
    let mu_f = arrow_scale(poly.terms.iter().map(|t| t.force.norm()).fold(0.0, f64::max));
    // Twin forces at one point are slid along their line past each other: room for the
    // longest such row (on paper the y axis turns over, which keeps every angle between
    // the forces, so the world's directions serve).
    let on_paper = |v: Vec2| Point::new(v.x / mu_l, v.y / mu_l);
    let reach = twins_reach(poly.terms.iter().map(|t| (on_paper(t.at), t.force)), mu_f);
    let pad = PAD.max(reach + PAD - ARROW_MAX);
    let (drawing_w, drawing_h) = (world.width() / mu_l + 2.0 * pad, world.height() / mu_l + 2.0 * pad);
    let chain = chain(poly);
    let chain_box = bbox_of(&chain);
    let (poly_w, poly_h) = (chain_box.width() / mu_p + 2.0 * POLY_PAD, chain_box.height() / mu_p + 2.0 * POLY_PAD);
    let poly_size = (poly_w, poly_h);
    let arrangement = Arrangement { drawing: (drawing_w, drawing_h), stacked };
    let title_w = |mu: f64| inset::title_width(inp, mu);
    let (insets, place, w, body_h) =
        with_insets(poly, (&chain, mu_p), arrangement, poly_size, (enlarge, inset_box, &title_w));
    let equation = equation_lines(inp, poly, w - 4.0);
    let legend = group_legend(inp, poly, mu_f, w - 4.0);
    let text_lines = equation.len() + legend.len() + SCALE_LINES;
    let h = CELL_TITLE + body_h + LINE * text_lines as f64 + 2.0;
    let layout = GroupLayout {
        world,
        mu_l,
        drawing_w,
        drawing_h,
        stacked,
        mu_p,
        mu_f,
        chain,
        chain_box,
        equation,
        legend,
        insets,
        place,
        poly_size,
    };
    (layout, w, h)
}

/// How a group cell holds its drawing (its size with its room for arrows, mm) and the
/// polygon's room: side by side, or the room under the drawing (`stacked`: a wide drawing
/// over its polygon takes less width, where the region is tall rather than wide).
#[derive(Clone, Copy)]
struct Arrangement {
    drawing: (f64, f64),
    stacked: bool,
}

/// A group cell's least width, mm: its equation and legend need lines this long.
const CELL_MIN_W: f64 = 120.0;

impl Arrangement {
    /// The cell's width and body height round a polygon's room `(w, h)`.
    fn cell(self, (w, h): (f64, f64)) -> (f64, f64) {
        let (dw, dh) = self.drawing;
        if self.stacked { (dw.max(w).max(CELL_MIN_W), dh + h) } else { ((dw + w).max(CELL_MIN_W), dh.max(h)) }
    }

    /// The room a cell sized for a polygon of `poly`'s size leaves the polygon.
    fn room(self, poly: (f64, f64)) -> (f64, f64) {
        let (w, h) = self.cell(poly);
        if self.stacked { (w, h - self.drawing.1) } else { (w - self.drawing.0, h) }
    }
}

/// The enlargements of a polygon's short sides and where they go, with the cell's width and
/// body height: in the room the cell leaves the polygon if they fit there; else, as
/// `enlarge` allows, in the least room grown for them or in cells of their own; else none.
fn with_insets(
    poly: &Polygon,
    (chain, mu_p): (&[Vec2], f64),
    arrangement: Arrangement,
    poly_size: (f64, f64),
    ((enlarge, titled), inset_box, title_w): ((Enlarge, bool), f64, &dyn Fn(f64) -> f64),
) -> (Vec<Inset>, Place, f64, f64) {
    let room = arrangement.room(poly_size);
    let (w, body_h) = arrangement.cell(room);
    let runs = inset::Runs::of(poly, chain, (mu_p, inset_box), title_w);
    if runs.is_empty() {
        return (Vec::new(), Place::None, w, body_h);
    }
    let places = [Place::Below, Place::Beside];
    let least = |is: &Vec<Inset>| is.iter().map(|i| mu_p / i.mu).fold(f64::INFINITY, f64::min);
    // Slots that hold their titles in 3.5 mm lettering, as every other enlargement's (a
    // narrower one set "T (μP = 1,25 N/mm)" in 2.5 mm beside "L (μP = 6 N/mm)", a teacher's
    // review): where they do not, the sheet tries grown cells and cells apart first
    // (`titled` false only as the last resort, `Sizes::narrow_titles`).
    let free = places
        .iter()
        .filter_map(|&p| runs.placed(p, room, poly_size, titled).map(|is| (is, p)))
        .reduce(|a, b| if least(&b.0) > least(&a.0) { b } else { a });
    let grown = match enlarge {
        Enlarge::InRoom => None,
        Enlarge::Grow => {
            let grown = places.iter().filter_map(|&p| {
                let room = runs.grown(p, room, poly_size, titled);
                runs.placed(p, room, poly_size, titled).map(|is| (is, p, room))
            });
            grown.min_by(|a, b| (a.2.0 * a.2.1).total_cmp(&(b.2.0 * b.2.1)))
        }
        // The cell keeps its size: the enlargements' cells are the caller's.
        Enlarge::Apart => runs.apart().map(|is| (is, Place::Apart, room)),
    };
    // The room the cell leaves serves unless a grown cell enlarges the runs more: a slot
    // squeezed under the polygon may enlarge a run only a few times, its sides still short.
    match (free, grown) {
        (Some((is, p)), Some(g)) if least(&g.0) <= least(&is) => (is, p, w, body_h),
        (_, Some((is, p, room))) => {
            let (w, h) = arrangement.cell(room);
            (is, p, w, h)
        }
        (Some((is, p)), None) => (is, p, w, body_h),
        (None, None) => (Vec::new(), Place::None, w, body_h),
    }
}

/// Lines of scales under a group drawing: μ_l, μ_F and μ_P.
const SCALE_LINES: usize = 2;

fn group_title(inp: &ForcesInput, poly: &Polygon) -> String {
    match poly.group {
        Some(gi) => {
            let links = inp.m.groups[gi].links.map(|l| inp.m.links[l].number);
            inp.words.sheet.group(&format!("II({},{})", links[0], links[1]))
        }
        None => inp.words.sheet.driving_link().to_string(),
    }
}

pub(super) fn draw_group_cell(
    g: &mut Group,
    labels: &mut Labels,
    r: Rect,
    inp: &ForcesInput,
    (poly, layout): (&Polygon, &GroupLayout),
    letters: &[String],
) {
    cell_title(g, r, &group_title(inp, poly));
    let top = r.y0 + CELL_TITLE;
    let lines = layout.equation.len() + layout.legend.len() + SCALE_LINES;
    let bottom = r.y1 - LINE * lines as f64 - 2.0;
    let (geo, room) = if layout.stacked {
        let under = top + layout.drawing_h;
        (Rect::new(r.x0, top, r.x1, under), Rect::new(r.x0, under, r.x1, bottom))
    } else {
        let beside = r.x0 + layout.drawing_w;
        (Rect::new(r.x0, top, beside, bottom), Rect::new(beside, top, r.x1, bottom))
    };
    draw_group_geometry(g, labels, inp, poly, geo, layout);
    let (w, h) = layout.poly_size;
    let pr = match layout.place {
        Place::None | Place::Apart => room,
        Place::Below => Rect::new(room.x0, room.y0, room.x1, room.y0 + h),
        Place::Beside => Rect::new(room.x0, room.y0, room.x0 + w, room.y1),
    };
    let named = inset::Named { insets: &layout.insets, letters };
    draw_polygon(g, labels, inp, (poly, layout), named, pr);
    if layout.place != Place::Apart {
        inset::draw(g, labels, inp, poly, &layout.chain, named, room);
    }
    let scales = vec![
        vec![
            with_semicolon(scale_item(inp, "l", layout.mu_l, inp.words.common.unit_m_per_mm())),
            scale_item(inp, "F", layout.mu_f, inp.words.common.unit_n_per_mm()),
        ],
        vec![scale_item(inp, "P", layout.mu_p, inp.words.common.unit_n_per_mm())],
    ];
    let y = equation_rows(g, r.x0 + 2.0, bottom + LINE, &layout.equation);
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
    let view = View::centred(layout.world, r, layout.mu_l);
    let p = |v: Vec2| view.p(v);
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
                slider(g, p(inp.state.points[first].p), view.dir(dir), 10.0, 5.0, MAIN);
                let c = p(inp.state.points[first].p);
                let u = view.dir(dir);
                blocks.push((c, u.unit(), 5.0, 2.5));
                g.line(c - u * 14.0 + u.turn_90() * 2.5, c + u * 14.0 + u.turn_90() * 2.5, THIN);
            }
            LinkKind::Block => {
                let (c, u) = (p(inp.state.points[first].p), view.dir(inp.state.links[l].dir));
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
        // A joint with the frame is drawn as a joint: the group is drawn released from the
        // mechanism, the frame's action on it being the reaction drawn there (a support
        // drawn too would show the frame twice, and the reaction through its hatching).
        // A point of one link only (a load's point, as a jaw crusher's K) is no joint: a dot.
        let links_at = m.links.iter().filter(|l| l.points.contains(&q)).count();
        let lone = links_at < 2 && !m.is_frame(q) && !m.is_kulisa_image(q);
        if (m.is_mass_centre(q) && !m.is_frame(q)) || lone {
            g.dot(at, 0.6);
        } else {
            g.circle(at, 1.0, THIN);
        }
    }
    let push = Push {
        lines: link_lines.clone(),
        points: points.iter().map(|&q| p(inp.state.points[q].p)).collect(),
        forces: unit_directions(poly.terms.iter().map(|t| (p(t.at), view.dir(t.force)))),
        within: r,
        keep_lines: false,
    };
    let mut arrows =
        Arrows { view, links: link_lines, push: Some(push), blocks, drawn: Vec::new(), mu_f: layout.mu_f, h: 3.5 };
    for t in &poly.terms {
        arrows.arrow(g, labels, p(t.at), t.force, force_label(inp, t.kind, t.on));
    }
    let moments: Vec<_> = inp
        .fa
        .forces
        .inertia
        .iter()
        .filter(|il| links_of(inp, poly).contains(&il.link) && il.moment != 0.0)
        .map(|il| {
            let centre = m.mass_centres.iter().find(|c| c.0 == il.link).map_or(m.links[il.link].points[0], |c| c.1);
            (il, p(inp.state.points[centre].p))
        })
        .collect();
    // Drawn after the force arrows, which keep their lines of action, so that an arc
    // turns its head away from them too (it met G's head at S4 on the worked example and
    // the jaw crusher, a teacher's review). What the arcs may cross: the lines and arrows
    // round their centres.
    let reach = moments.iter().map(|&(_, at)| turn_arrow_reach(at, MOMENT_R)).reduce(|a, b| a.union(b));
    let mut drawn = reach.map_or_else(Obstacles::default, |r| Obstacles::of_items_within(&g.items, r));
    // An arrow at an arc's centre shorter than the arc's radius would not be crossed, yet
    // the arc's head could stand on its head: each counts as a wedge reaching past the
    // circle.
    for &(at, e, far) in &arrows.drawn {
        if moments.iter().any(|&(_, c)| (c - at).norm() < MOMENT_R) {
            for turn in [-ARC_WEDGE, 0.0, ARC_WEDGE] {
                let ray = crate::num::math::rotate(e, turn.to_radians()) * far.max(MOMENT_R + ARC_CLEAR);
                drawn.add(Piece::Segment(at, at + ray), usize::MAX);
            }
        }
    }
    for (il, at) in moments {
        let start =
            clear_turn_arrow(g, &mut drawn, at, MOMENT_R, 200.0, MOMENT_SWEEP, il.moment > 0.0, (THIN, HEAD_ROOM));
        let sign = if il.moment > 0.0 { -1.0 } else { 1.0 };
        // Beside the arc's middle, else further along it: from the middle alone, between a
        // group's links, the name went 46 mm up a leader (task 15's II(2,3)).
        let spots: Vec<(Point, Vec2)> = MOMENT_NAME_AT
            .iter()
            .map(|&f| {
                let on = at + crate::num::math::from_angle((start + sign * MOMENT_SWEEP * f).to_radians()) * MOMENT_R;
                (on, on - at)
            })
            .collect();
        let name = LabelText::new("M", inp.words.sheet.force(ForceKind::Inertia, &m.links[il.link].number.to_string()));
        labels.add_at_any(&spots, name, 3.5);
    }
    // The letters last: they keep clear of the arrows.
    for &q in &points {
        let at = p(inp.state.points[q].p);
        let (main, sub) = split_name(m.name(q));
        labels.add(at, Vec2::new(-1.0, -1.0), LabelText::new(main, sub), 3.5);
    }
}

/// Where along an inertia moment's arc its name is tried, as shares of the arc, best first.
const MOMENT_NAME_AT: [f64; 5] = [0.5, 0.25, 0.75, 0.1, 0.9];

/// Radius and sweep of an inertia moment's arc, mm and degrees.
const MOMENT_R: f64 = 6.0;
const MOMENT_SWEEP: f64 = 120.0;
/// How far past an inertia moment's arc an arrow from its centre is taken to reach, mm:
/// the arc's head (about 2 mm) clear of the arrow's.
const ARC_CLEAR: f64 = 2.5;
/// The room round an inertia moment's head beyond which more does not count in turning
/// its arc, mm.
const HEAD_ROOM: f64 = 2.5;
/// The half angle of the wedge an arrow from an arc's centre keeps the arc's head out of,
/// degrees: 20° at the arc's 6 mm is 2 mm.
const ARC_WEDGE: f64 = 20.0;

#[cfg(test)]
mod tests {
    use super::{Arrangement, CELL_MIN_W};

    #[test]
    fn a_stacked_cell_is_as_wide_as_its_wider_part_and_as_tall_as_both() {
        let beside = Arrangement { drawing: (150.0, 60.0), stacked: false };
        let under = Arrangement { stacked: true, ..beside };
        let poly = (130.0, 100.0);
        assert_eq!(beside.cell(beside.room(poly)), (280.0, 100.0));
        assert_eq!(under.cell(under.room(poly)), (150.0, 160.0));
        // The polygon's room under the drawing spans the cell's width.
        assert_eq!(under.room(poly), (150.0, 100.0));
        let small = Arrangement { drawing: (40.0, 30.0), stacked: true };
        assert_eq!(small.cell(small.room((50.0, 20.0))), (CELL_MIN_W, 50.0));
    }
}
