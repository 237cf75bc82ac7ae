//! The force analysis as cells packed into the regions: a cell per group drawing with its
//! polygon, the Zhukovsky lever, each load diagram and each table, at the sizes of one layout
//! attempt.

use super::group::{GroupLayout, group_layout, group_scales};
use super::inset::{Enlarge, Place};
use super::load::cell_size as load_cell;
use super::zhukovsky::{DESCENT, lever_arrow_scale, lever_extent, lever_legend, lever_lines};
use super::{ForcesInput, LINE};
use crate::drawing::scale;
use crate::lever::plans::{Plan, velocity_plan};
use crate::num::tol;
use crate::sheets::lever::plans_view::{MARGIN, TITLE, plan_bbox};
use kurbo::{Point, Rect};
use std::cell::{OnceCell, RefCell};
use std::collections::HashMap;
use std::rc::Rc;

const GAP: f64 = 6.0;

pub(super) enum Content {
    /// Index into the polygons, and the layout computed for the cell's size.
    Polygon(usize, Rc<GroupLayout>),
    /// The turned velocity plan, its scale, the scale of its force arrows and the box its
    /// cell was sized round (the plan and its arrows' tips, plan units).
    Lever(Rc<Plan>, f64, f64, Rect),
    /// Index into the loads, and how many times the least its plot is.
    Load(usize, f64),
    Table(usize),
    /// A polygon's enlargement in a cell of its own ([`super::inset::Place::Apart`]): the
    /// polygon's index, the enlargement's among its own, and the polygon's layout.
    Enlargement(usize, usize, Rc<GroupLayout>),
}

pub(super) struct Cell {
    pub(super) w: f64,
    pub(super) h: f64,
    pub(super) content: Content,
}

/// Sizes that one layout attempt uses, mm: the largest group drawing's longest side (at a
/// GOST scale no larger), each force polygon's and the lever's.
#[derive(Clone, Copy)]
pub(super) struct Sizes {
    pub(super) group_box: f64,
    pub(super) poly_box: f64,
    pub(super) lever_box: f64,
    /// Longest side of the largest group (or crank) in the world, m.
    pub(super) widest: f64,
    /// Whether the polygons' μ_P and the lever's μ come from the plans' finer series (steps
    /// of at most a third) rather than the course's {1, 2, 2.5, 4, 5} (steps up to 2×, which
    /// draw a polygon meant for 60 mm at 30).
    pub(super) fine: bool,
    /// Whether the lever's μ comes from the finer series whatever the polygons' do.
    pub(super) lever_fine: bool,
    /// Which polygons' cells (bit i: polygon i) may grow to enlarge their short sides
    /// beside them (tried only once the drawings fit without).
    pub(super) grow: u64,
    /// Which polygons (bit i: polygon i) set their enlargements in cells of their own where
    /// their cell leaves no room (before `grow`).
    pub(super) apart: u64,
    /// How many times the least the load diagrams' plots are.
    pub(super) load: f64,
    /// How many times `poly_box` each of the first [`GROWN_POLYGONS`] polygons' boxes is
    /// (one polygon may grow where the others' cells leave it no room to).
    pub(super) poly_grown: [f64; 8],
    /// Whether each group cell takes the more compact of its polygon beside its drawing and
    /// under it, rather than always beside.
    pub(super) compact: bool,
    /// The enlargements' longer side at most, mm (`inset::INSET_BOX`, smaller where the
    /// cells are cramped).
    pub(super) inset_box: f64,
    /// Whether the enlargements beside their polygons may take slots too narrow for their
    /// titles in 3.5 mm and set them in 2.5 mm: the last resort before short sides left on
    /// a polygon.
    pub(super) narrow_titles: bool,
    /// The lever's cell is at least this wide, mm: wider, its list of forces wraps into
    /// fewer lines and leaves the lever more of the cell's height.
    pub(super) lever_w: f64,
}

/// How many polygons may grow one by one: a mechanism has at most a few groups.
pub(super) const GROWN_POLYGONS: usize = 8;

impl Sizes {
    /// A round scale for `x` units a mm in the series [`Sizes::fine`] picks.
    pub(super) fn round_up(&self, x: f64) -> f64 {
        if self.fine { scale::plan_round_up(x) } else { scale::round_up(x) }
    }

    /// A drawing's length scale: the common GOST scale that fits the largest group into its
    /// box, unless that leaves this drawing shorter than half the box (a crank beside a
    /// long rod); then its own GOST scale for that half.
    pub(super) fn mu_l(&self, wb: Rect) -> f64 {
        let common = scale::length_scale(self.widest / self.group_box);
        let side = wb.width().max(wb.height());
        let least = self.group_box / 2.0;
        if side / common >= least { common } else { scale::length_scale(side / least) }
    }

    pub(super) fn shrunk(self) -> Sizes {
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

/// The cells already laid out, by what each depends on: a polygon's cell on its μ_l, its
/// μ_P and whether it may grow, the lever's on its μ, the tables on nothing (the load
/// diagrams' cells are sized each time from a few dozen points). The layout attempts (up to a dozen shrinks for each mechanism height tried,
/// then the enlargements and the finer scales, for each width of the force column) ask
/// for the same cells again and again: each is laid out once a sheet.
#[derive(Default)]
pub struct CellMemo {
    polygons: RefCell<HashMap<PolygonKey, LaidOut>>,
    /// The turned velocity plan with its box, and the lever's cell at each μ and least
    /// width: its size and the box it is sized round.
    lever: OnceCell<(Rc<Plan>, Rect, f64)>,
    lever_cells: RefCell<HashMap<(u64, u64), LeverCell>>,
    /// The tables' sizes, in the cells' order.
    fixed: OnceCell<Vec<(f64, f64)>>,
}

/// The lever's cell at a μ and least width (their bits): its width, height and the box it
/// is sized round.
type LeverCell = (f64, f64, Rect);

/// A polygon's index, its μ_l's and μ_P's bits, where its enlargements may go, their box's
/// bits and whether its polygon stands under its drawing.
type PolygonKey = (usize, u64, u64, (Enlarge, bool), u64, bool);
/// A group cell's layout, width and height.
type LaidOut = (Rc<GroupLayout>, f64, f64);

/// Room round the lever's box (its plan and its arrows' tips) for the letters and the
/// force labels set beside the arrows, mm.
const LEVER_LABEL_ROOM: f64 = 6.0;

pub(super) fn cells(inp: &ForcesInput, s: Sizes) -> Vec<Cell> {
    let memo = inp.memo;
    let mut out = Vec::new();
    let mut enlargements = Vec::new();
    for (i, poly) in inp.fa.forces.polygons.iter().enumerate() {
        let enlarge = match (s.apart >> i & 1 == 1, s.grow >> i & 1 == 1) {
            (true, _) => Enlarge::Apart,
            (false, true) => Enlarge::Grow,
            (false, false) => Enlarge::InRoom,
        };
        let titled = !s.narrow_titles;
        let (mu_l, mu_p) = group_scales(poly, inp, s, s.poly_grown.get(i).copied().unwrap_or(1.0));
        let laid_out = |stacked: bool| {
            memo.polygons
                .borrow_mut()
                .entry((i, mu_l.to_bits(), mu_p.to_bits(), (enlarge, titled), s.inset_box.to_bits(), stacked))
                .or_insert_with(|| {
                    let (layout, w, h) =
                        group_layout(inp, poly, (mu_l, mu_p), ((enlarge, titled), s.inset_box), stacked);
                    (Rc::new(layout), w, h)
                })
                .clone()
        };
        let beside = laid_out(false);
        let (layout, w, h) = match s.compact.then(|| laid_out(true)) {
            Some(under) if under.1 * under.2 < beside.1 * beside.2 => under,
            _ => beside,
        };
        // Its enlargements' own cells after the drawings and before the tables: small, they
        // fill what the larger cells leave.
        let apart: Vec<Cell> = match layout.place {
            Place::Apart => (layout.insets.iter().enumerate())
                .map(|(j, inset)| {
                    let (w, h) = (inset.slot.width(), inset.slot.height());
                    Cell { w, h, content: Content::Enlargement(i, j, Rc::clone(&layout)) }
                })
                .collect(),
            _ => Vec::new(),
        };
        out.push(Cell { w, h, content: Content::Polygon(i, layout) });
        enlargements.extend(apart);
    }
    let (lever, bb, mu_f) = memo.lever.get_or_init(|| {
        let lever = velocity_plan(inp.m, inp.state).turned(inp.m.sense());
        let bb = plan_bbox(&lever);
        (Rc::new(lever), bb, lever_arrow_scale(inp))
    });
    let (bb, mu_f) = (*bb, *mu_f);
    let need = bb.width().max(bb.height()) / s.lever_box;
    let mu = if s.lever_fine { scale::plan_round_up(need) } else { s.round_up(need) };
    let (w, h, ext) = *memo.lever_cells.borrow_mut().entry((mu.to_bits(), s.lever_w.to_bits())).or_insert_with(|| {
        let ext = lever_extent(inp, lever, mu, mu_f);
        let pad = MARGIN + LEVER_LABEL_ROOM;
        let w = (ext.width() / mu + 2.0 * pad).max(s.lever_w);
        let text_lines = lever_lines(inp, w - 4.0) + lever_legend(inp, mu_f, w - 4.0).len();
        let h = TITLE + ext.height() / mu + 2.0 * pad + text_lines as f64 * LINE + DESCENT;
        (w, h, ext)
    });
    out.push(Cell { w, h, content: Content::Lever(Rc::clone(lever), mu, mu_f, ext) });
    for (i, load) in inp.fa.model.loads.iter().enumerate() {
        let (w, h) = load_cell(load, s.load);
        out.push(Cell { w, h, content: Content::Load(i, s.load) });
    }
    out.extend(enlargements);
    let fixed =
        memo.fixed.get_or_init(|| inp.tables.iter().map(|t| t.size()).map(|(w, h)| (w + 2.0, h + 2.0)).collect());
    out.extend(fixed.iter().enumerate().map(|(i, &(w, h))| Cell { w, h, content: Content::Table(i) }));
    out
}

/// Places cells bottom-left under a skyline (see [`super::skyline`]), each into the first
/// body where it fits; where that leaves one out, in rows (a skyline made uneven by short
/// cells can leave no step wide enough for a later wide one, which a fresh row has). Tables
/// 3–5 go together where they can, side by side, else one above the other (packed apart,
/// table 5 could stand beside the mechanism, away from 3 and 4). Returns each cell's body
/// and corner, and whether all fit (a cell that fits nowhere overflows the first body).
pub(super) fn pack(cells: &[Cell], bodies: &Bodies) -> (Vec<(usize, Point)>, bool) {
    let sizes: Vec<(f64, f64)> = cells.iter().map(|c| (c.w, c.h)).collect();
    match together(cells, &sizes, bodies) {
        Some(at) => (at, true),
        None => apart(&sizes, &bodies.rects, None),
    }
}

/// The areas the force cells may use, in the order each cell tries them, and the one
/// tables 3–5 (packed together) try first, if not the first.
pub(super) struct Bodies {
    pub(super) rects: Vec<Rect>,
    pub(super) tables_first: Option<usize>,
    /// Whether the layout puts its tables beside the mechanism where they fit: then tables
    /// 3–5 may also stand two over one, and the polygons grow one by one.
    pub(super) beside: bool,
    /// The body beside the mechanism, if any.
    pub(super) side: Option<usize>,
}

/// Whether the tables among `cells` placed `at` stand in one body, each within a gap of
/// another.
pub(super) fn tables_together(cells: &[Cell], at: &[(usize, Point)]) -> bool {
    let tables: Vec<(usize, Rect)> = cells
        .iter()
        .zip(at)
        .filter(|(c, _)| matches!(c.content, Content::Table(_)))
        .map(|(c, &(body, p))| (body, Rect::new(p.x, p.y, p.x + c.w, p.y + c.h)))
        .collect();
    let near = |a: Rect, b: Rect| a.inflate(GAP + 1.0, GAP + 1.0).intersect(b).area() > 0.0;
    tables.iter().all(|&(body, r)| {
        body == tables[0].0 && (tables.len() < 2 || tables.iter().any(|&(b2, r2)| b2 == body && r2 != r && near(r, r2)))
    })
}

/// The cells (sized `sizes`) packed with tables 3–5 together (see [`pack`]), if they all
/// fit so: side by side, else (where the layout puts them beside the mechanism) two
/// beside each other over the third, else one above the other.
fn together(cells: &[Cell], sizes: &[(f64, f64)], bodies: &Bodies) -> Option<Vec<(usize, Point)>> {
    // The tables are the last cells.
    let first = cells.iter().position(|c| matches!(c.content, Content::Table(_))).unwrap_or(cells.len());
    let n = cells.len() - first;
    if n < 2 || !cells[first..].iter().all(|c| matches!(c.content, Content::Table(_))) {
        return None;
    }
    let across: Vec<Vec<usize>> = vec![(0..n).collect()];
    let stacked: Vec<Vec<usize>> = (0..n).map(|i| vec![i]).collect();
    let mut arrangements = vec![across];
    // Two over one only where the tables go beside the mechanism: elsewhere the rule's
    // layouts stand as they were.
    if n == 3 && bodies.beside {
        arrangements.extend([vec![vec![0, 2], vec![1]], vec![vec![0, 1], vec![2]]]);
    }
    arrangements.push(stacked);
    let packed = |rows: &Vec<Vec<usize>>| with_tables_together(sizes, first, rows, bodies);
    // In the body the tables try first if any arrangement lands there, else wherever.
    let preferred = bodies
        .tables_first
        .and_then(|k| arrangements.iter().filter_map(&packed).find(|at| at.last().is_some_and(|&(b, _)| b == k)));
    preferred.or_else(|| arrangements.iter().find_map(packed))
}

/// The cells packed with the tables from `first` on as one block, in `rows` (each row's
/// tables side by side, the rows one above the other), if all fit.
fn with_tables_together(
    sizes: &[(f64, f64)],
    first: usize,
    rows: &[Vec<usize>],
    bodies: &Bodies,
) -> Option<Vec<(usize, Point)>> {
    let tables = &sizes[first..];
    let mut offsets = vec![kurbo::Vec2::ZERO; tables.len()];
    let (mut w, mut y) = (0.0f64, 0.0f64);
    for row in rows {
        let mut x = 0.0f64;
        let mut row_h = 0.0f64;
        for &i in row {
            offsets[i] = kurbo::Vec2::new(x, y);
            x += tables[i].0 + GAP;
            row_h = row_h.max(tables[i].1);
        }
        w = w.max(x - GAP);
        y += row_h + GAP;
    }
    let mut merged = sizes[..first].to_vec();
    merged.push((w, y - GAP));
    let (mut at, all) = apart(&merged, &bodies.rects, bodies.tables_first);
    let (body, corner) = at.pop()?;
    all.then(|| at.into_iter().chain(offsets.into_iter().map(|o| (body, corner + o))).collect())
}

/// The cells packed each on its own: under a skyline (the last trying body `last_first`
/// first, if any), else in rows.
fn apart(sizes: &[(f64, f64)], bodies: &[Rect], last_first: Option<usize>) -> (Vec<(usize, Point)>, bool) {
    let skyline = super::skyline::pack(sizes, bodies, GAP, last_first);
    if skyline.1 || last_first.is_some() {
        return skyline;
    }
    match in_rows(sizes, bodies) {
        rows @ (_, true) => rows,
        _ => skyline,
    }
}

/// Places cells in rows, first fit: each cell goes into the first body where it fits, in
/// that body's current row or a new one.
fn in_rows(cells: &[(f64, f64)], bodies: &[Rect]) -> (Vec<(usize, Point)>, bool) {
    // Per body: the next cell's x, its row's top and the row's height so far.
    let mut rows: Vec<(f64, f64, f64)> = bodies.iter().map(|b| (b.x0, b.y0, 0.0)).collect();
    let mut out = Vec::new();
    let mut all = true;
    for &(w, h) in cells {
        let mut spot = None;
        for (i, b) in bodies.iter().enumerate() {
            let (x, y, row_h) = rows[i];
            let fits = |x: f64, y: f64| x + w <= b.x1 + tol::PAPER && y + h <= b.y1 + tol::PAPER;
            if fits(x, y) {
                spot = Some((i, Point::new(x, y), (x + w + GAP, y, row_h.max(h))));
            } else if row_h > 0.0 && fits(b.x0, y + row_h + GAP) {
                let y = y + row_h + GAP;
                spot = Some((i, Point::new(b.x0, y), (b.x0 + w + GAP, y, h)));
            }
            if spot.is_some() {
                break;
            }
        }
        let Some((i, at, next)) = spot else {
            all = false;
            out.push((0, Point::new(bodies[0].x0, rows[0].1 + rows[0].2 + GAP)));
            continue;
        };
        rows[i] = next;
        out.push((i, at));
    }
    (out, all)
}
