//! The force cells' layout once the drawings fit: the polygons' short sides enlarged (beside
//! their polygons, in cells grown for them, or in cells of their own), the finer series of
//! scales, then the Zhukovsky lever, the load diagrams and the drawings grown into the room
//! left — each step kept only where the cells still pack.

use super::cells::{self, Bodies, Cell, Content, GROWN_POLYGONS, Sizes, pack};
use super::{Arranged, ForcesInput, SIDE_MIN, inset, polygon};

/// A fitting arrangement's boxes with the polygons' short sides enlarged beside them and
/// the polygons and the lever at the finer series' scales, where those still fit: nothing
/// else smaller. Only for drawing (the comfort test needs no more than whether the coarse
/// cells fit).
pub(super) fn finer(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
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
        let readable = |a: &Arranged| smallest_drawing_mm(&a.0) >= floor - crate::num::tol::PAPER;
        for inset_box in [inset::INSET_BOX, inset::INSET_BOX_CRAMPED] {
            for base in shrink_steps(Sizes { inset_box, ..sizes }) {
                if let Some(grown) = grown(inp, bodies, base, count) {
                    if !short_sides(inp, &grown.0) && readable(&grown) {
                        return grown;
                    }
                    first.get_or_insert(grown);
                }
                if !short_sides(inp, &self::cells::cells(inp, base)) {
                    break;
                }
            }
        }
        let fine = Sizes { fine: true, ..sizes };
        let tried = self::cells::cells(inp, fine);
        let fine = match pack(&tried, bodies) {
            (tried_at, true) => Some((tried, tried_at, true, fine)),
            _ => None,
        };
        // Where every polygon's enlargements beside it leave a knot on some polygon (or
        // none pack) and the finer series alone does not undo it, the enlargements each in
        // a cell of its own, packed wherever the cells leave room: a polygon's cell grown
        // for them may fit nowhere on a full sheet.
        let knotted = |a: &Option<Arranged>| a.as_ref().is_none_or(|a| short_sides(inp, &a.0));
        if short_sides(inp, &cells)
            && knotted(&first)
            && knotted(&fine)
            && let Some(apart) = {
                // The lever keeps [`LEVER_KEPT`] of what it grows to without them.
                let lever_floor = (largest_lever_mm(inp, bodies, sizes) * LEVER_KEPT).min(LEVER_KEPT_ABOVE);
                // Only the polygons the enlargements beside them left knotted, the others as
                // enlarged there, or every polygon's apart; each at 40 mm or 25 mm: of those
                // that pack, the one whose lever grows largest (on a tie the first; task 8
                // variant 20's lever kept 121 mm with 25 mm enlargements, 91 with 40 mm).
                let beside = first.as_ref().map_or(0, |a| a.3.grow);
                let knotted = knotted_polygons(inp, first.as_ref().map_or(&cells, |a| &a.0));
                let all = (1u64 << count) - 1;
                let masks = [(beside, knotted), (0, all)];
                // Each lever measured once: the floor and the choice read the same length.
                let found = masks
                    .into_iter()
                    .flat_map(|(grow, mask)| apart(inp, bodies, Sizes { grow, ..sizes }, mask, readable))
                    .map(|a| (largest_lever_mm(inp, bodies, a.3), a))
                    .filter(|(lever, _)| *lever >= lever_floor - crate::num::tol::PAPER);
                found.reduce(|a, b| if b.0 > a.0 + crate::num::tol::PAPER { b } else { a }).map(|(_, a)| a)
            }
        {
            return apart;
        }
        // What is left keeps short sides on a polygon: rather than that, the whole search
        // again with the enlargements' titles in 2.5 mm where a slot is too narrow for 3.5
        // (task 15 variant 7's II(2,3) kept a side of 0.1 mm).
        let chosen = first.or(fine).unwrap_or((cells, at, ok, sizes));
        if short_sides(inp, &chosen.0) && !sizes.narrow_titles {
            let s = Sizes { narrow_titles: true, ..sizes };
            let cells = self::cells::cells(inp, s);
            let (at, ok) = pack(&cells, bodies);
            let narrow = finer(inp, bodies, (cells, at, ok, s));
            if !short_sides(inp, &narrow.0) {
                return narrow;
            }
        }
        return chosen;
    }
    (cells, at, ok, sizes)
}

/// How many steps smaller the drawings may get to make room for the polygons' enlargements.
const ENLARGE_SHRINKS: usize = 8;

/// `sizes`, then the drawings a step smaller at a time, up to [`ENLARGE_SHRINKS`] steps.
fn shrink_steps(sizes: Sizes) -> impl Iterator<Item = Sizes> {
    std::iter::successors(Some(sizes), |s| Some(s.shrunk())).take(ENLARGE_SHRINKS + 1)
}

/// A group drawing this long reads its forces' points and arms plainly, mm (its longer
/// side): the drawings are not shrunk below it (or below what they were) to make room for
/// enlargements, nor does a fuller composition shrink them below it (`choice::Floors`).
pub(in crate::sheets::lever) const DRAWING_READABLE: f64 = 80.0;

/// A Zhukovsky lever this long reads its arms and forces plainly, mm: the larger lettering
/// may take the rest of the lever's growth.
pub(in crate::sheets::lever) const LEVER_READABLE: f64 = 100.0;

/// The least share of its size a drawing under [`DRAWING_READABLE`] keeps where the
/// drawings shrink to make room for every polygon's enlargements (two of the 0.9 steps).
const ENLARGE_SHRUNK_MOST: f64 = 0.8;

/// The least share of the lever it would grow to without them that the enlargements in
/// cells of their own may leave it, where it is under [`LEVER_KEPT_ABOVE`]: task 12 variant
/// 10's lever went from 87 to 52 mm, a knot of a dozen arrows for the polygon's knot undone
/// (at 0.8, task 15 variant 3's II(2,3) kept sides of 0.5–2.7 mm on its polygon for a lever
/// of 98 mm against 125).
const LEVER_KEPT: f64 = 0.75;
const LEVER_KEPT_ABOVE: f64 = 100.0;

/// The Zhukovsky lever's longer side on paper once it grows as large as the cells at
/// `sizes` still pack ([`larger_lever`]), mm.
fn largest_lever_mm(inp: &ForcesInput, bodies: &Bodies, sizes: Sizes) -> f64 {
    let cells = self::cells::cells(inp, sizes);
    let (at, ok) = pack(&cells, bodies);
    let (cells, ..) = larger_lever(inp, bodies, (cells, at, ok, sizes));
    let lever = cells.iter().find_map(|c| match &c.content {
        Content::Lever(plan, mu, _, _) => Some(super::zhukovsky::lever_side_mm(plan, *mu)),
        _ => None,
    });
    lever.unwrap_or(0.0)
}

/// The smallest group (or crank) drawing's longer side on paper, mm.
pub(super) fn smallest_drawing_mm(cells: &[Cell]) -> f64 {
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

/// The cells with the `mask` polygons' enlargements in cells of their own (the others' as
/// `sizes` places them), where they pack, no polygon labels a short side on itself and the
/// drawings stay `readable`: at `sizes`, else with the drawings a step smaller (as [`finer`]
/// shrinks them for enlargements beside the polygons), the finer series first — the first
/// found with the enlargements at their full box and the first at the cramped one.
fn apart(
    inp: &ForcesInput,
    bodies: &Bodies,
    sizes: Sizes,
    mask: u64,
    readable: impl Fn(&Arranged) -> bool,
) -> Vec<Arranged> {
    let mut found = Vec::new();
    for inset_box in [inset::INSET_BOX, inset::INSET_BOX_CRAMPED] {
        for base in shrink_steps(Sizes { inset_box, apart: mask, ..sizes }) {
            let packed = [true, false].into_iter().find_map(|fine| {
                let s = Sizes { fine, ..base };
                let cells = self::cells::cells(inp, s);
                match pack(&cells, bodies) {
                    (at, true) if !short_sides(inp, &cells) => Some((cells, at, true, s)),
                    _ => None,
                }
            });
            // Smaller drawings only get less readable: the next box size, if any.
            if let Some(packed) = packed {
                found.extend(readable(&packed).then_some(packed));
                break;
            }
        }
    }
    found
}

/// The largest box the lever is tried at, mm: beyond it its arrows stay at most
/// [`ARROW_MAX`] while its arms grow, and the forces read no better.
const LEVER_LARGEST: f64 = 200.0;

/// The widths the lever's cell is tried at, mm.
const LEVER_WIDER: [f64; 5] = [super::LEVER_W, 130.0, 140.0, 160.0, 190.0];

/// A fitting arrangement with the Zhukovsky lever as large as the cells still pack: its box
/// from [`LEVER_LARGEST`] down to the one it got, at the finer series' scales (the lever's
/// sides are the arms its forces are read by; the knot of a dozen arrows round p, b and s4
/// at the coarse scale is what a teacher marks down).
pub(super) fn larger_lever(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
    if ok {
        // From the largest down by tenths, then the box it got, at the finer series.
        let boxes = std::iter::successors(Some(LEVER_LARGEST), |&b| Some(b * 0.9))
            .take_while(|&b| b > sizes.lever_box)
            .chain([sizes.lever_box]);
        for lever_box in boxes {
            for lever_w in LEVER_WIDER {
                let tried = Sizes { lever_box, lever_fine: true, lever_w, ..sizes };
                let tried_cells = self::cells::cells(inp, tried);
                if let (tried_at, true) = pack(&tried_cells, bodies) {
                    return (tried_cells, tried_at, true, tried);
                }
            }
        }
    }
    (cells, at, ok, sizes)
}

/// How many times the least a load diagram's plot is tried at, largest first.
const LOAD_GROWN: [f64; 4] = [1.6, 1.45, 1.3, 1.15];

/// A fitting arrangement with the load diagrams as large as the cells still pack (up to
/// [`LOAD_GROWN`]'s first): last, so that nothing read by a ruler is smaller for them.
pub(super) fn larger_loads(inp: &ForcesInput, bodies: &Bodies, (cells, at, ok, sizes): Arranged) -> Arranged {
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
pub(super) fn larger_drawings(inp: &ForcesInput, bodies: &Bodies, arranged: Arranged) -> Arranged {
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
pub(super) fn short_sides(inp: &ForcesInput, cells: &[Cell]) -> bool {
    knotted_polygons(inp, cells) != 0
}

/// The polygons (bit i: polygon i) that label a side shorter than [`SIDE_MIN`] on
/// themselves.
fn knotted_polygons(inp: &ForcesInput, cells: &[Cell]) -> u64 {
    let knotted = cells.iter().filter_map(|c| match &c.content {
        Content::Polygon(i, l) => {
            let short = polygon::shortest_sides(&inp.fa.forces.polygons[*i], l).0.is_some_and(|s| s < SIDE_MIN);
            (short && *i < 64).then_some(1u64 << i)
        }
        _ => None,
    });
    knotted.fold(0, |m, b| m | b)
}

/// Whether any polygon's cell draws enlargements.
fn enlarged(cells: &[Cell]) -> bool {
    cells.iter().any(|c| matches!(&c.content, Content::Polygon(_, l) if !l.insets.is_empty()))
}
