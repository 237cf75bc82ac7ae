//! The force analysis on sheet 1: each Assur group and the crank drawn apart at one length
//! scale with their forces, each force polygon at its own round μ_P with its vector
//! equation, the Zhukovsky lever, the load diagrams and tables 3–5. The cells are packed
//! in rows; when they do not fit, the drawings get smaller scales, never smaller text. Where
//! they fit, the polygons and the lever take the plans' finer series of scales if the cells
//! still pack at it: larger drawings, nothing else smaller.

mod arrows;
mod cells;
mod group;
mod inset;
mod legend;
mod load;
mod polygon;
mod segments;
mod skyline;
mod zhukovsky;

use super::labels::LeverWords;
use crate::drawing::fmt;
use crate::drawing::place::Labels;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::table::Table;
use crate::lever::analysis::ForceAnalysis;
use crate::lever::linkage::{Mechanism, State};
use crate::report::{AnswerKeys, Segment};
pub use cells::CellMemo;
use cells::{Bodies, Cell, Content, GROWN_POLYGONS, Sizes, cells, pack};
pub use inset::SIDE_MIN;
use kurbo::{Point, Rect};

/// Longest and shortest force arrow on a group drawing or the lever, mm. A force whose
/// arrow would be shorter is drawn at the minimum with its value written.
const ARROW_MAX: f64 = 20.0;
const ARROW_MIN: f64 = 7.0;
/// Between the lines of text under a drawing, mm.
const LINE: f64 = 5.5;

pub struct ForcesInput<'a> {
    pub m: &'a Mechanism,
    pub fa: &'a ForceAnalysis,
    /// The state at φ1.
    pub state: &'a State,
    pub phi_deg: f64,
    pub words: LeverWords,
    /// Tables 3–5 as drawn.
    pub tables: Vec<Table>,
    /// The cells laid out so far, shared by every layout the sheet tries.
    pub memo: &'a CellMemo,
    /// Whether the group drawings and polygons grow into the room the cells leave (see
    /// [`draw_forces`]).
    pub grow_drawings: bool,
    /// Whether the cells fill the region beside the mechanism before the one below it (a
    /// side region the cells below did not need stood empty).
    pub side_first: bool,
    /// Whether tables 3–5 go beside the mechanism where they fit there, leaving the region
    /// below to the drawings (a kulisa's lever left the side region two-thirds empty while
    /// the tables took the room its polygon could grow into).
    pub tables_beside: bool,
    /// Whether each group cell stands its polygon under its drawing where that makes the
    /// cell smaller (a kulisa's crank drawn wide beside its polygon took the width its
    /// lever could grow into).
    pub compact_groups: bool,
}

/// The scales the force drawings got.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ForceScales {
    /// Length scale of each group drawing (groups from the last, then the crank), m/mm.
    pub mu_l: Vec<f64>,
    /// μ_P of each polygon (groups from the last, then the crank), N/mm.
    pub mu_p: Vec<f64>,
    /// μ_P of each enlargement of a polygon's short sides, in the order they are lettered
    /// (K, L …), N/mm.
    pub mu_p_enlarged: Vec<f64>,
    /// The scale of the force arrows on each group drawing, N/mm.
    pub mu_f: Vec<f64>,
    /// Velocity scale of the Zhukovsky lever, (m/s)/mm.
    pub mu_lever: f64,
    /// The scale of the force arrows on the lever, N/mm.
    pub mu_f_lever: f64,
    /// The lever's longer side on paper (its turned velocity plan's box), mm.
    pub lever_mm: f64,
    /// The shortest labelled side of any force polygon at its μ_P on paper, mm (a force
    /// too small to draw is not a side: its value is in the legend; a side labelled in an
    /// enlargement is counted there).
    pub smallest_polygon_side_mm: Option<f64>,
    /// The shortest side labelled in the polygons' enlargements of their short sides, mm.
    pub smallest_enlarged_side_mm: Option<f64>,
    /// Whether tables 3–5 stand in one region, each beside another (the sheet's choice
    /// between its layouts keeps them so where the rule's did).
    #[serde(skip)]
    pub tables_together: bool,
    /// The smallest group (or crank) drawing's longer side on paper, mm: what a fuller
    /// composition must not halve.
    #[serde(skip)]
    pub smallest_drawing_mm: f64,
}

/// Draws the force analysis into `main` (the region below the mechanism, titled) and, when
/// the mechanism leaves room beside it, `side`; returns the scales the drawings got and the
/// segments a student measures on them, tied to `answers`. The drawings start as large as
/// they fit, the polygons' enlargements get room, then the lever and the load diagrams grow
/// into what is left, and, where the input asks, the group drawings and polygons.
pub fn draw_forces(
    main: &mut Group,
    mut side: Option<&mut Group>,
    inp: &ForcesInput,
    answers: &AnswerKeys,
) -> (ForceScales, Vec<Segment>) {
    let region = main.region;
    let title = inp.words.sheet.forces_title(&fmt::localise(&format!("{:.1}", inp.phi_deg), inp.words.lang));
    main.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, 5.0, Anchor::Start));
    let bodies = bodies(region, side.as_ref().map(|g| g.region), (inp.side_first, inp.tables_beside));
    let arranged = larger_lever(
        inp,
        &bodies,
        finer(inp, &bodies, arrange(inp, &bodies, Sizes { compact: inp.compact_groups, ..DRAWN }, SHRINK_TRIES)),
    );
    let (cells, at, _, _) = larger_drawings(inp, &bodies, larger_loads(inp, &bodies, arranged));
    let mut scales = ForceScales {
        mu_l: vec![],
        mu_p: vec![],
        mu_p_enlarged: vec![],
        mu_f: vec![],
        mu_lever: 0.0,
        mu_f_lever: 0.0,
        lever_mm: 0.0,
        smallest_polygon_side_mm: None,
        smallest_enlarged_side_mm: None,
        tables_together: cells::tables_together(&cells, &at),
        smallest_drawing_mm: smallest_drawing_mm(&cells),
    };
    let mut measured = Vec::new();
    let mut letters = inset::Letters::of(inp);
    for (cell, &(body, origin)) in cells.iter().zip(&at) {
        let g: &mut Group = match (body, side.as_deref_mut()) {
            (b, Some(sg)) if (b == 1) != inp.side_first => sg,
            _ => &mut *main,
        };
        let r = Rect::new(origin.x, origin.y, origin.x + cell.w, origin.y + cell.h);
        // Each cell places its own labels inside itself, so cells never collide.
        let mut labels = Labels::new();
        let start = g.mark();
        let part = part_id(inp, &cell.content);
        match cell.content {
            Content::Polygon(i, ref layout) => {
                let poly = &inp.fa.forces.polygons[i];
                let letters = letters.take(layout.insets.len());
                group::draw_group_cell(g, &mut labels, r, inp, (poly, layout), &letters);
                scales.mu_l.push(layout.mu_l);
                scales.mu_p.push(layout.mu_p);
                scales.mu_p_enlarged.extend(layout.insets.iter().map(|i| i.mu));
                scales.mu_f.push(layout.mu_f);
                let (on_polygon, enlarged) = polygon::shortest_sides(poly, layout);
                let least = |a: Option<f64>, b: Option<f64>| a.into_iter().chain(b).reduce(f64::min);
                scales.smallest_polygon_side_mm = least(scales.smallest_polygon_side_mm, on_polygon);
                scales.smallest_enlarged_side_mm = least(scales.smallest_enlarged_side_mm, enlarged);
                measured.extend(segments::polygon(inp, (poly, layout.mu_p, &layout.insets), &part, answers));
            }
            Content::Lever(ref plan, mu, mu_f, extent) => {
                zhukovsky::draw_lever(g, &mut labels, r, inp, (plan, extent), (mu, mu_f));
                scales.mu_lever = mu;
                scales.mu_f_lever = mu_f;
                let bb = crate::sheets::lever::plans_view::plan_bbox(plan);
                scales.lever_mm = bb.width().max(bb.height()) / mu;
                measured.extend(segments::lever_arms(inp, mu, &part));
            }
            Content::Load(i, grown) => {
                let drawn = load::draw_load(g, &mut labels, r, inp, (i, grown));
                measured.extend(segments::load(inp, i, drawn, &part, answers));
            }
            Content::Table(i) => {
                inp.tables[i].draw(g, origin);
            }
        }
        labels.place(g, r.inflate(-0.5, -0.5));
        g.part_from(part, start);
    }
    (scales, measured)
}

/// A force cell's id: `forces.group.2-3` (an Assur group by its links' numbers),
/// `forces.crank`, `forces.lever`, `forces.load.5` (by the loaded link), `forces.table.1`.
fn part_id(inp: &ForcesInput, content: &Content) -> String {
    let number = |l: usize| inp.m.links[l].number.to_string();
    match content {
        Content::Polygon(i, _) => match inp.fa.forces.polygons[*i].group {
            Some(k) => format!("forces.group.{}", inp.m.groups[k].links.map(number).join("-")),
            None => "forces.crank".into(),
        },
        Content::Lever(..) => "forces.lever".into(),
        Content::Load(i, _) => format!("forces.load.{}", number(inp.fa.model.loads[*i].link)),
        Content::Table(i) => format!("forces.table.{}", i + 1),
    }
}

/// The areas the cells may use: the main region below its title, then the side region (or
/// the side region first, `side_first`); with `tables_beside`, tables 3–5 try the side
/// region first whatever the drawings do.
fn bodies(main: Rect, side: Option<Rect>, (side_first, tables_beside): (bool, bool)) -> Bodies {
    let mut rects = vec![Rect::new(main.x0, main.y0 + 10.0, main.x1, main.y1)];
    rects.extend(side);
    let side_at = (rects.len() == 2).then_some(1);
    if side_first {
        rects.reverse();
    }
    let tables_first = if tables_beside && !side_first { side_at } else { None };
    Bodies { rects, tables_first, beside: tables_beside }
}

/// How many times the drawings may shrink by 10 % to fit; a region that needs more than
/// [`COMFORTABLE`] shrinks is cramped.
const SHRINK_TRIES: usize = 12;
const COMFORTABLE: usize = 3;
/// The sizes a comfortable layout starts from (the mechanism above gets the rest), and the
/// larger ones the drawings start from, shrinking until they fit what they got.
const COMFORTABLE_START: Sizes = Sizes {
    group_box: 130.0,
    poly_box: 90.0,
    lever_box: 110.0,
    widest: 0.0,
    fine: false,
    lever_fine: false,
    grow: 0,
    load: 1.0,
    poly_grown: [1.0; GROWN_POLYGONS],
    compact: false,
    inset_box: inset::INSET_BOX,
};
const DRAWN: Sizes = Sizes {
    group_box: 170.0,
    poly_box: 120.0,
    lever_box: 150.0,
    widest: 0.0,
    fine: false,
    lever_fine: false,
    grow: 0,
    load: 1.0,
    poly_grown: [1.0; GROWN_POLYGONS],
    compact: false,
    inset_box: inset::INSET_BOX,
};

/// Cells, where they are, whether they all fit, and the sizes they were made at.
type Arranged = (Vec<Cell>, Vec<(usize, Point)>, bool, Sizes);

/// A fitting arrangement's boxes with the polygons' short sides enlarged beside them and
/// the polygons and the lever at the finer series' scales, where those still fit: nothing
/// else smaller. Only for drawing (the comfort test needs no more than whether the coarse
/// cells fit).
fn finer(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
    if ok {
        // The polygons' enlargements beside them (a knot of labels unread is worse than a
        // polygon a scale step smaller): every polygon's cell grown, at the finer series,
        // else at the coarse; else one polygon's cell grown after another while the cells
        // still pack; else, where some polygon has sides to enlarge, the same with the
        // drawings a step smaller (up to [`ENLARGE_SHRINKS`] steps: the skyline packs the
        // drawings large and leaves the enlargements no room); else the finer series
        // alone where it packs.
        // A step that enlarges only some polygons' short sides is kept only if no smaller
        // step, nor smaller enlargements, enlarge them all: one knot left on the sheet is
        // what a teacher marks. But not at any price: a step that enlarges them all while
        // it draws a group smaller than [`DRAWING_READABLE`] and than 0.8 of the smallest
        // drawing before is not taken for it (task 4 variant 42's II(2,3) went from 0.015 to
        // 0.04 m/mm, and a halved drawing is as unreadable as the knot).
        let count = inp.fa.forces.polygons.len().min(64);
        let floor = (smallest_drawing_mm(&cells) * ENLARGE_SHRUNK_MOST).min(DRAWING_READABLE);
        // The first that packs, kept where nothing better does (the search before stopped
        // there): some polygons enlarged, or all with a drawing below the floor.
        let mut first = None;
        for inset_box in [inset::INSET_BOX, inset::INSET_BOX_CRAMPED] {
            let mut base = Sizes { inset_box, ..sizes };
            for _ in 0..=ENLARGE_SHRINKS {
                if let Some(grown) = grown(inp, bodies, base, count) {
                    let complete = !short_sides(inp, &grown.0);
                    if complete && smallest_drawing_mm(&grown.0) >= floor - crate::num::tol::PAPER {
                        return grown;
                    }
                    first.get_or_insert(grown);
                }
                if !short_sides(inp, &self::cells::cells(inp, base)) {
                    break;
                }
                base = base.shrunk();
            }
        }
        if let Some(first) = first {
            return first;
        }
        let fine = Sizes { fine: true, ..sizes };
        let tried = self::cells::cells(inp, fine);
        if let (tried_at, true) = pack(&tried, bodies) {
            return (tried, tried_at, true, fine);
        }
    }
    (cells, at, ok, sizes)
}

/// How many steps smaller the drawings may get to make room for the polygons' enlargements.
const ENLARGE_SHRINKS: usize = 8;

/// A group drawing this long reads its forces' points and arms plainly, mm (its longer
/// side): the drawings are not shrunk below it (or below what they were) to make room for
/// enlargements, nor does a fuller composition shrink them below it (`choice::Floors`).
pub(super) const DRAWING_READABLE: f64 = 80.0;

/// The least share of its size a drawing under [`DRAWING_READABLE`] keeps where the
/// drawings shrink to make room for every polygon's enlargements (two of the 0.9 steps).
const ENLARGE_SHRUNK_MOST: f64 = 0.8;

/// The smallest group (or crank) drawing's longer side on paper, mm.
fn smallest_drawing_mm(cells: &[Cell]) -> f64 {
    let drawn = cells.iter().filter_map(|c| match &c.content {
        Content::Polygon(_, l) => Some(l.world.width().max(l.world.height()) / l.mu_l),
        _ => None,
    });
    drawn.fold(f64::MAX, f64::min)
}

/// The cells at `sizes` with the polygons' short sides enlarged beside them, if they pack:
/// every polygon's cell grown, at the finer series, else at the coarse; else one polygon's
/// cell grown after another while the cells still pack.
fn grown(inp: &ForcesInput, bodies: &Bodies, sizes: Sizes, count: usize) -> Option<Arranged> {
    let fine = Sizes { fine: true, ..sizes };
    for s in [fine, sizes] {
        let all = Sizes { grow: (1u64 << count) - 1, ..s };
        let cells = self::cells::cells(inp, all);
        if let (cells_at, true) = pack(&cells, bodies)
            && enlarged(&cells)
        {
            return Some((cells, cells_at, true, all));
        }
    }
    for mut s in [fine, sizes] {
        let mut grown = None;
        for i in 0..count {
            let tried = Sizes { grow: s.grow | 1 << i, ..s };
            let cells = self::cells::cells(inp, tried);
            if let (cells_at, true) = pack(&cells, bodies) {
                grown = Some((cells, cells_at));
                s = tried;
            }
        }
        if let Some((cells, cells_at)) = grown.filter(|(c, _)| enlarged(c)) {
            return Some((cells, cells_at, true, s));
        }
    }
    None
}

/// The largest box the lever is tried at, mm: beyond it its arrows stay at most
/// [`ARROW_MAX`] while its arms grow, and the forces read no better.
const LEVER_LARGEST: f64 = 200.0;

/// A fitting arrangement with the Zhukovsky lever as large as the cells still pack: its box
/// from [`LEVER_LARGEST`] down to the one it got, at the finer series' scales (the lever's
/// sides are the arms its forces are read by; the knot of a dozen arrows round p, b and s4
/// at the coarse scale is what a teacher marks down).
fn larger_lever(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
    if ok {
        let mut lever_box = LEVER_LARGEST;
        while lever_box > sizes.lever_box {
            let tried = Sizes { lever_box, lever_fine: true, ..sizes };
            let tried_cells = self::cells::cells(inp, tried);
            if let (tried_at, true) = pack(&tried_cells, bodies) {
                return (tried_cells, tried_at, true, tried);
            }
            lever_box *= 0.9;
        }
    }
    (cells, at, ok, sizes)
}

/// How many times the least a load diagram's plot is tried at, largest first.
const LOAD_GROWN: [f64; 4] = [1.6, 1.45, 1.3, 1.15];

/// A fitting arrangement with the load diagrams as large as the cells still pack (up to
/// [`LOAD_GROWN`]'s first): last, so that nothing read by a ruler is smaller for them.
fn larger_loads(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
    if ok && !inp.fa.model.loads.is_empty() {
        for load in LOAD_GROWN {
            let tried = Sizes { load, ..sizes };
            let tried_cells = self::cells::cells(inp, tried);
            if let (tried_at, true) = pack(&tried_cells, bodies) {
                return (tried_cells, tried_at, true, tried);
            }
        }
    }
    (cells, at, ok, sizes)
}

/// How many times their boxes the group drawings and the polygons are tried at, largest
/// first, both together and then the polygons alone.
const DRAWINGS_GROWN: [f64; 5] = [1.8, 1.6, 1.4, 1.25, 1.12];
/// How many times its box one polygon is tried at, beyond what they all got, largest first.
const POLYGON_GROWN: [f64; 7] = [2.5, 2.2, 1.9, 1.6, 1.4, 1.25, 1.12];

/// A fitting arrangement with the group drawings and their polygons as large as the cells
/// still pack: last, after the lever and the load diagrams — both together, else the
/// polygons alone; then, where the tables go beside the mechanism, each polygon in turn larger still where the cells pack (a tall polygon may grow down into room its
/// wide neighbour's growth would overflow). Larger
/// polygons are not always a fuller sheet (a thin triangle's inside is empty paper too), so
/// the sheet composes with and without and measures which leaves less empty.
fn larger_drawings(inp: &ForcesInput, bodies: &Bodies, arranged: Arranged) -> Arranged {
    let (cells, at, ok, sizes) = arranged;
    if !(ok && inp.grow_drawings) {
        return (cells, at, ok, sizes);
    }
    let both = DRAWINGS_GROWN.map(|f| Sizes { group_box: sizes.group_box * f, poly_box: sizes.poly_box * f, ..sizes });
    let polygons = DRAWINGS_GROWN.map(|f| Sizes { poly_box: sizes.poly_box * f, ..sizes });
    let packed = |tried: Sizes| {
        let tried_cells = self::cells::cells(inp, tried);
        let (tried_at, fits) = pack(&tried_cells, bodies);
        fits.then_some((tried_cells, tried_at, true, tried))
    };
    let mut out = both.into_iter().chain(polygons).find_map(packed).unwrap_or((cells, at, ok, sizes));
    let one_by_one = if bodies.beside { inp.fa.forces.polygons.len().min(GROWN_POLYGONS) } else { 0 };
    for i in 0..one_by_one {
        let base = out.3;
        // At the finer series too: the course's steps up to 2× skip the size that fits.
        // The course's series only where the finer was not tried already.
        let series: &[bool] = if base.fine { &[true] } else { &[true, false] };
        let each = series.iter().flat_map(|&fine| {
            POLYGON_GROWN.map(|f| {
                let mut poly_grown = base.poly_grown;
                poly_grown[i] *= f;
                Sizes { poly_grown, fine, ..base }
            })
        });
        if let Some(grown) = each.into_iter().find_map(packed) {
            out = grown;
        }
    }
    out
}

/// Whether any polygon labels a side shorter than [`SIDE_MIN`] on itself.
fn short_sides(inp: &ForcesInput, cells: &[Cell]) -> bool {
    cells.iter().any(|c| match &c.content {
        Content::Polygon(i, l) => {
            polygon::shortest_sides(&inp.fa.forces.polygons[*i], l).0.is_some_and(|s| s < SIDE_MIN)
        }
        _ => false,
    })
}

/// Whether any polygon's cell draws enlargements.
fn enlarged(cells: &[Cell]) -> bool {
    cells.iter().any(|c| matches!(&c.content, Content::Polygon(_, l) if !l.insets.is_empty()))
}

/// Cells packed into the bodies, shrinking the drawings up to `tries − 1` times until they
/// fit; the last attempt is returned even if it does not (the layout measurement then
/// reports it), with whether it fits.
fn arrange(inp: &ForcesInput, bodies: &Bodies, start: Sizes, tries: usize) -> Arranged {
    let widest = inp
        .fa
        .forces
        .polygons
        .iter()
        .map(|p| group::world_box(inp, p))
        .map(|b| b.width().max(b.height()))
        .fold(0.0, f64::max);
    let mut attempt = Sizes { widest, ..start };
    let mut k = 0;
    loop {
        let cells = cells(inp, attempt);
        let (at, ok) = pack(&cells, bodies);
        k += 1;
        if ok || k >= tries {
            return (cells, at, ok, attempt);
        }
        attempt = attempt.shrunk();
    }
}

/// Whether the force drawings fit the main region (and the side region, if any) without
/// being cramped.
pub fn fit_comfortably(inp: &ForcesInput, main: Rect, side: Option<Rect>) -> bool {
    arrange(inp, &bodies(main, side, (false, false)), COMFORTABLE_START, COMFORTABLE + 1).2
}
