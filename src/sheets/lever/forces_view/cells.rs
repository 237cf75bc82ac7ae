//! The force analysis as cells packed into the regions: a cell per group drawing with its
//! polygon, the Zhukovsky lever, each load diagram and each table, at the sizes of one layout
//! attempt.

use super::group::{GroupLayout, group_layout};
use super::load::cell_size as load_cell;
use super::zhukovsky::{DESCENT, LEVER_LINES, lever_arrow_scale, lever_legend};
use super::{ARROW_MAX, ForcesInput, LINE};
use crate::drawing::scale;
use crate::lever::plans::{Plan, velocity_plan};
use crate::num::tol;
use crate::sheets::lever::plans_view::{MARGIN, TITLE, plan_bbox};
use kurbo::{Point, Rect};

const GAP: f64 = 6.0;

pub(super) enum Content {
    /// Index into the polygons, and the layout computed for the cell's size.
    Polygon(usize, GroupLayout),
    /// The turned velocity plan, its scale and the scale of its force arrows.
    Lever(Plan, f64, f64),
    Load(usize),
    Table(usize),
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
    /// Which polygons' cells (bit i: polygon i) may grow to enlarge their short sides
    /// beside them (tried only once the drawings fit without).
    pub(super) grow: u64,
}

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

pub(super) fn cells(inp: &ForcesInput, s: Sizes) -> Vec<Cell> {
    let mut out = Vec::new();
    for (i, poly) in inp.fa.forces.polygons.iter().enumerate() {
        let (layout, w, h) = group_layout(inp, poly, s, s.grow >> i & 1 == 1);
        out.push(Cell { w, h, content: Content::Polygon(i, layout) });
    }
    let lever = velocity_plan(inp.m, inp.state).turned(inp.m.sense());
    let bb = plan_bbox(&lever);
    let mu = s.round_up(bb.width().max(bb.height()) / s.lever_box);
    let mu_f = lever_arrow_scale(inp);
    let pad = MARGIN + ARROW_MAX + 4.0;
    let w = (bb.width() / mu + 2.0 * pad).max(110.0);
    let text_lines = LEVER_LINES + lever_legend(inp, mu_f, w - 4.0).len();
    let h = TITLE + bb.height() / mu + 2.0 * pad + text_lines as f64 * LINE + DESCENT;
    out.push(Cell { w, h, content: Content::Lever(lever, mu, mu_f) });
    for (i, load) in inp.fa.model.loads.iter().enumerate() {
        let (w, h) = load_cell(load);
        out.push(Cell { w, h, content: Content::Load(i) });
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
pub(super) fn pack(cells: &[Cell], bodies: &[Rect]) -> (Vec<(usize, Point)>, bool) {
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
