//! The force analysis on sheet 1: each Assur group and the crank drawn apart at one length
//! scale with their forces, each force polygon at its own round μ_P with its vector
//! equation, the Zhukovsky lever, the load diagrams and tables 3–5. The cells are packed
//! in rows; when they do not fit, the drawings get smaller scales, never smaller text. Where
//! they fit, the polygons and the lever take the plans' finer series of scales if the cells
//! still pack at it: larger drawings, nothing else smaller.

mod arrows;
mod cells;
mod group;
mod growth;
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
use crate::report::lever::LegendDecimals;
use crate::report::{AnswerKeys, Segment};
pub use cells::CellMemo;
use cells::{Bodies, Cell, Content, GROWN_POLYGONS, Sizes, cells, pack};
pub(super) use growth::{DRAWING_READABLE, LEVER_READABLE};
use growth::{finer, larger_drawings, larger_lever, larger_loads, smallest_drawing_mm};
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
    /// The decimals tables 3 and 4 print the legends' quantities with.
    pub decimals: LegendDecimals,
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
    let title = section_title(inp);
    let side_region = side.as_ref().map(|g| g.region);
    let (cells, at, beside) = titled_layout(inp, region, side_region, title.advance());
    match (side.as_deref_mut(), side_region) {
        (Some(sg), Some(r)) if beside => sg.text(Text { at: Point::new(r.x0 + 2.0, r.y0 + 6.0), ..title }),
        _ => main.text(Text { at: Point::new(region.x0 + 2.0, region.y0 + 6.0), ..title }),
    }
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
    // Each polygon's enlargements' letters, given where the polygon is drawn (before its
    // enlargements' own cells, which follow it).
    let mut lettered: Vec<(usize, Vec<String>)> = Vec::new();
    for (cell, &(body, origin)) in cells.iter().zip(&at) {
        let g: &mut Group = match (body, side.as_deref_mut()) {
            (b, Some(sg)) if (b == 1) != inp.side_first => sg,
            _ => &mut *main,
        };
        let r = Rect::new(origin.x, origin.y, origin.x + cell.w, origin.y + cell.h);
        // Each cell places its own labels inside itself, so cells never collide.
        let mut labels = Labels::new();
        let start = g.mark();
        let letter_of = |i: usize, j: usize| {
            let of = lettered.iter().find(|(k, _)| *k == i);
            of.and_then(|(_, l)| l.get(j).cloned()).unwrap_or_default()
        };
        let part = part_id(inp, &cell.content, letter_of);
        match cell.content {
            Content::Polygon(i, ref layout) => {
                let poly = &inp.fa.forces.polygons[i];
                let letters = letters.take(layout.insets.len());
                group::draw_group_cell(g, &mut labels, r, inp, (poly, layout), &letters);
                lettered.push((i, letters));
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
                scales.lever_mm = zhukovsky::lever_side_mm(plan, mu);
                measured.extend(segments::lever_arms(inp, mu, &part));
            }
            Content::Load(i, grown) => {
                let drawn = load::draw_load(g, &mut labels, r, inp, (i, grown));
                measured.extend(segments::load(inp, i, drawn, &part, answers));
            }
            Content::Table(i) => {
                inp.tables[i].draw(g, origin);
            }
            Content::Enlargement(i, j, ref layout) => {
                let letter = [letter_of(i, j)];
                let named = inset::Named { insets: &layout.insets[j..=j], letters: &letter };
                inset::draw(g, &mut labels, inp, &inp.fa.forces.polygons[i], &layout.chain, named, r);
            }
        }
        labels.place(g, r.inflate(-0.5, -0.5));
        g.part_from(part, start);
    }
    (scales, measured)
}

/// A force cell's id: `forces.group.2-3` (an Assur group by its links' numbers),
/// `forces.crank`, `forces.lever`, `forces.load.5` (by the loaded link), `forces.table.1`,
/// and a polygon's enlargement in a cell of its own by its letter, `forces.group.2-3.K`
/// (`letter_of(polygon, enlargement)`).
fn part_id(inp: &ForcesInput, content: &Content, letter_of: impl Fn(usize, usize) -> String) -> String {
    let number = |l: usize| inp.m.links[l].number.to_string();
    let polygon = |i: usize| match inp.fa.forces.polygons[i].group {
        Some(k) => format!("forces.group.{}", inp.m.groups[k].links.map(number).join("-")),
        None => "forces.crank".into(),
    };
    match content {
        Content::Polygon(i, _) => polygon(*i),
        Content::Enlargement(i, j, _) => format!("{}.{}", polygon(*i), letter_of(*i, *j)),
        Content::Lever(..) => "forces.lever".into(),
        Content::Load(i, _) => format!("forces.load.{}", number(inp.fa.model.loads[*i].link)),
        Content::Table(i) => format!("forces.table.{}", i + 1),
    }
}

/// The cells laid out in the region below the mechanism and the one beside it, and whether
/// the section's title heads the region beside it. The title heads the section where its
/// first drawing stands: where a drawing goes beside the mechanism (it read below drawings
/// of its own), the title goes there and the cells below the mechanism rise into its strip;
/// the cells beside move down under the title where they leave room below, else they are
/// laid out again with the strip kept there, and kept so if a drawing still goes beside
/// and reads as well.
fn titled_layout(
    inp: &ForcesInput,
    region: Rect,
    side: Option<Rect>,
    title_w: f64,
) -> (Vec<Cell>, Vec<(usize, Point)>, bool) {
    let flags = (inp.side_first, inp.tables_beside);
    let laid_out = |bodies: &Bodies| {
        let start = Sizes { compact: inp.compact_groups, ..DRAWN };
        let arranged = larger_lever(inp, bodies, finer(inp, bodies, arrange(inp, bodies, start, SHRINK_TRIES)));
        let (cells, at, _, _) = larger_drawings(inp, bodies, larger_loads(inp, bodies, arranged));
        (cells, at)
    };
    let below = bodies(region, side, flags, None);
    let (cells, mut at) = laid_out(&below);
    let titled_side = side.filter(|s| title_w + 4.0 <= s.width());
    let Some((s, side_body)) = titled_side.zip(below.side).filter(|_| drawing_in(&cells, &at, below.side)) else {
        return (cells, at, false);
    };
    let lowest = (cells.iter().zip(&at)).filter(|(_, (b, _))| *b == side_body).map(|(c, (_, p))| p.y + c.h);
    if lowest.fold(s.y0, f64::max) + TITLE_STRIP <= s.y1 {
        for (body, origin) in &mut at {
            origin.y += if *body == side_body { TITLE_STRIP } else { UNTITLED_TOP - TITLE_STRIP };
        }
        return (cells, at, true);
    }
    let titled = bodies(region, Some(s), flags, Some(s));
    let (c, a) = laid_out(&titled);
    if drawing_in(&c, &a, titled.side) && readable(inp, &cells).kept_by(readable(inp, &c)) {
        (c, a, true)
    } else {
        (cells, at, false)
    }
}

/// The force analysis's title, "Kinetostatic analysis of the mechanism, φ₁ = 30.0°", at
/// the origin.
fn section_title(inp: &ForcesInput) -> Text {
    let title = inp.words.sheet.forces_title(&fmt::localise(&format!("{:.1}", inp.phi_deg), inp.words.lang));
    Text::new(Point::ZERO, title, 5.0, Anchor::Start)
}

/// The title's strip above a region's cells, mm.
const TITLE_STRIP: f64 = 10.0;
/// The cells below the mechanism stand this far below its region's top where the title
/// went beside the mechanism, mm.
const UNTITLED_TOP: f64 = 2.0;

/// The areas the cells may use: the main region below its title, then the side region (or
/// the side region first, `side_first`); with `tables_beside`, tables 3–5 try the side
/// region first whatever the drawings do. With `titled_side`, the title's strip is kept at
/// the top of the side region instead, and the main region's cells start near its top.
fn bodies(
    main: Rect,
    side: Option<Rect>,
    (side_first, tables_beside): (bool, bool),
    titled_side: Option<Rect>,
) -> Bodies {
    let main_top = if titled_side.is_some() { UNTITLED_TOP } else { TITLE_STRIP };
    let mut rects = vec![Rect::new(main.x0, main.y0 + main_top, main.x1, main.y1)];
    rects.extend(titled_side.map(|s| Rect::new(s.x0, s.y0 + TITLE_STRIP, s.x1, s.y1)).or(side));
    let side_at = (rects.len() == 2).then_some(if side_first { 0 } else { 1 });
    if side_first {
        rects.reverse();
    }
    let tables_first = if tables_beside && !side_first { side_at } else { None };
    Bodies { rects, tables_first, beside: tables_beside, side: side_at }
}

/// What a layout's drawings must keep where another is tried for them: the lever's
/// length and the shortest labelled polygon side (enlargements' included), mm.
struct Readable {
    lever: f64,
    side: f64,
}

impl Readable {
    /// Whether `other` keeps these, each up to what reads plainly.
    fn kept_by(&self, other: Readable) -> bool {
        let kept = |size: f64, floor: f64| size >= floor - crate::num::tol::PAPER;
        kept(other.lever, self.lever.min(LEVER_READABLE)) && kept(other.side, self.side.min(SIDE_MIN))
    }
}

fn readable(inp: &ForcesInput, cells: &[Cell]) -> Readable {
    let mut r = Readable { lever: f64::MAX, side: f64::MAX };
    for c in cells {
        match c.content {
            Content::Lever(ref plan, mu, ..) => r.lever = zhukovsky::lever_side_mm(plan, mu),
            Content::Polygon(i, ref layout) => {
                let (on, enlarged) = polygon::shortest_sides(&inp.fa.forces.polygons[i], layout);
                r.side = on.into_iter().chain(enlarged).fold(r.side, f64::min);
            }
            _ => {}
        }
    }
    r
}

/// Whether a drawing (a group, the crank, an enlargement or the lever; not a table or a
/// load diagram, titled by themselves) stands in the body `side`.
fn drawing_in(cells: &[Cell], at: &[(usize, Point)], side: Option<usize>) -> bool {
    cells
        .iter()
        .zip(at)
        .any(|(c, &(body, _))| Some(body) == side && !matches!(c.content, Content::Table(_) | Content::Load(..)))
}

/// How many times the drawings may shrink by 10 % to fit; a region that needs more than
/// [`COMFORTABLE`] shrinks is cramped.
const SHRINK_TRIES: usize = 12;
const COMFORTABLE: usize = 3;
/// The lever's cell's least width, mm.
const LEVER_W: f64 = 110.0;
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
    apart: 0,
    load: 1.0,
    poly_grown: [1.0; GROWN_POLYGONS],
    compact: false,
    inset_box: inset::INSET_BOX,
    narrow_titles: false,
    lever_w: LEVER_W,
};
const DRAWN: Sizes = Sizes {
    group_box: 170.0,
    poly_box: 120.0,
    lever_box: 150.0,
    widest: 0.0,
    fine: false,
    lever_fine: false,
    grow: 0,
    apart: 0,
    load: 1.0,
    poly_grown: [1.0; GROWN_POLYGONS],
    compact: false,
    inset_box: inset::INSET_BOX,
    narrow_titles: false,
    lever_w: LEVER_W,
};

/// Cells, where they are, whether they all fit, and the sizes they were made at.
type Arranged = (Vec<Cell>, Vec<(usize, Point)>, bool, Sizes);

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
    arrange(inp, &bodies(main, side, (false, false), None), COMFORTABLE_START, COMFORTABLE + 1).2
}
