//! Sheet 1's mechanism region: the largest GOST μ_l that fits its box (with a force
//! analysis, the tallest box that leaves the force drawings below it room), and the
//! mechanism drawn there with its header and the trajectories' legend.

use super::compose::{Column, HEADER, Input, TOP, force_region_below, region_header, side_region};
use super::forces_view::{ForcesInput, fit_comfortably};
use super::labels::LeverWords;
use super::mechanism_view::{
    DETAIL_GAP, DetailAt, DetailPlace, MechanismView, SLIDER_SAME_MM, TRAJECTORY, detail_place, mu_l_text, world_extent,
};
use crate::drawing::obstacles::Obstacles;
use crate::drawing::path::Path;
use crate::drawing::place::{Labels, NUMBERS_RANK};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Item, Text};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::analysis::Kinematics;
use crate::lever::linkage::{Mechanism, Step};
use crate::num::math::lines_cross;
use kurbo::{Point, Rect};

/// The mechanism's region at most, mm; it shrinks to the drawing at the chosen μ_l.
const MECH_MAX_W: f64 = 450.0;
const MECH_MAX_H: f64 = 300.0;
/// The least width of the mechanism's drawing, mm.
const MECH_MIN_W: f64 = 200.0;
/// The least where tables 3–5 go beside the mechanism, mm: its region is at least as wide
/// as its header and legend too.
const MECH_MIN_W_BESIDE: f64 = 120.0;
/// With a force analysis the mechanism's box is the first of these heights that leaves the
/// force drawings enough room.
const MECH_HEIGHTS_FORCES: [f64; 7] = [300.0, 260.0, 230.0, 200.0, 175.0, 150.0, 130.0];
/// Space around the mechanism drawing for its letters, pivots and guides.
const MECH_PAD: f64 = 14.0;
/// The mechanism's region and scale, before it is drawn.
#[derive(Clone, PartialEq)]
pub(super) struct MechanismPlace {
    world: Rect,
    pub(super) region: Rect,
    pub(super) mu_l: f64,
    /// The drawing's height at `mu_l`, mm.
    draw_h: f64,
    /// Whether the force drawings fit below it comfortably.
    pub(super) comfortable: bool,
    /// The crank's enlarged detail beside the drawing, when the crank is too small on paper.
    detail: Option<DetailPlace>,
}

/// The mechanism drawn in its region.
#[derive(Clone)]
pub(super) struct MechanismDrawn {
    pub(super) group: Group,
    pub(super) region: Rect,
    pub(super) mu_l: f64,
    /// The crank's detail's μ_l, m/mm, where it has one.
    pub(super) detail_mu_l: Option<f64>,
}

/// How a slider's positions are numbered (see [`MechanismView`]'s fields of those names).
#[derive(Clone, Copy)]
struct SliderNumbering {
    short_strokes: bool,
    beyond_hatching: bool,
}

/// One drawing of the mechanism, and how its labels stand: the longest number's leader,
/// the labels without a clean spot, whether a short stroke's number is far or unclean, and
/// how many leaders cross a stroke's dimension line.
struct Attempt {
    mech: MechanismDrawn,
    farthest: f64,
    unplaced: usize,
    short_far: bool,
    across: usize,
}

/// How many of `g`'s leaders cross one of `lines`.
fn leaders_across(g: &Group, lines: &[(Point, Point)]) -> usize {
    let leader = |&k: &usize| match &g.items[k] {
        Item::Path { path, .. } => Some((path.start, path.end())),
        _ => None,
    };
    g.leaders.iter().filter_map(leader).map(|l| lines.iter().filter(|&&d| lines_cross(l, d)).count()).sum()
}

/// The mechanism's place: the largest GOST μ_l that fits its box, the region shrunk to the
/// drawing. With a force analysis the box is the tallest that leaves the force drawings
/// below it room without cramping them.
pub(super) fn mechanism_place(
    inp: &Input,
    k: &Kinematics,
    forces: Option<&ForcesInput>,
    column: Column,
) -> MechanismPlace {
    let world = world_extent(&inp.project.mechanism, k, &inp.project.kulisa_lengths);
    let words = LeverWords::new(inp.ctx.info.language);
    let m = &inp.project.mechanism;
    let left = crank_on_left(m, k, world);
    let detail = |mu_l: f64| detail_place(m, mu_l, left, &words, false);
    // Where the tables go beside the mechanism, a region wider than its drawing leaves
    // paper empty that they could use; narrower than its header, it would cross the
    // region beside it.
    let beside = forces.is_some_and(|f| f.tables_beside);
    let header_w = |mu_l: f64| if beside { header_width(mu_l, k, &words).max(MECH_MIN_W_BESIDE) } else { MECH_MIN_W };
    let heights: &[f64] = if forces.is_some() { &MECH_HEIGHTS_FORCES } else { &[MECH_MAX_H] };
    let fits = |h: f64| {
        let r = mechanism_region(world, h, column.inner, header_w, &detail).region;
        let below = force_region_below(r, column);
        forces.is_none_or(|fi| fit_comfortably(fi, below, side_region(r, below)))
    };
    let comfortable = heights.iter().copied().find(|&h| fits(h));
    let max_h = comfortable.unwrap_or(heights[heights.len() - 1]);
    let Sized { region, mu_l, draw_h, detail } = mechanism_region(world, max_h, column.inner, header_w, &detail);
    MechanismPlace { world, region, mu_l, draw_h, comfortable: comfortable.is_some(), detail }
}

/// The mechanism drawn at its place.
pub(super) fn mechanism_group(
    inp: &Input,
    k: &Kinematics,
    words: &LeverWords,
    place: MechanismPlace,
) -> MechanismDrawn {
    crate::num::work::count(crate::num::work::Step::MechanismDrawing);
    let MechanismPlace { world, region, mu_l, draw_h, detail, .. } = place;
    let m = &inp.project.mechanism;
    // The drawing centred in what a detail beside or below it leaves of the region.
    let at = detail.map(|d| d.at);
    let band_h = if at == Some(DetailAt::Below) { world.height() / mu_l } else { draw_h };
    let beside = detail.filter(|d| d.at == DetailAt::Beside).map(|d| beside_detail(region, &d));
    let drawing = beside.map_or(region, |b| b.0);
    let origin = Point::new(
        drawing.center().x - world.center().x / mu_l,
        region.y0 + HEADER + MECH_PAD + band_h / 2.0 + world.center().y / mu_l,
    );
    let detail = detail.map(|d| match d.at {
        DetailAt::Beside => (d, beside.map(|b| b.1)),
        DetailAt::Below => {
            let crank_x = origin.x + k.assigned.state.points[m.crank().pivot].p.x / mu_l;
            (d, Some(below_detail(region, band_h, crank_x, &d)))
        }
        DetailAt::Inside => (d, None),
    });
    let draw_as = |detail: Option<(DetailPlace, Option<Rect>)>, slider_same_mm: f64, numbers: SliderNumbering| {
        let mut group = Group::new("mechanism", region);
        mechanism_header(&mut group, region, mu_l, k, words);
        let legend = trajectory_legend(&mut group, region, words);
        let mut labels = Labels::new();
        let kulisa = &inp.project.kulisa_lengths;
        let view = View::new(origin, mu_l);
        let mv = MechanismView {
            m,
            k,
            view,
            kulisa,
            words,
            detail,
            slider_same_mm,
            number_short_strokes: numbers.short_strokes,
            numbers_beyond_hatching: numbers.beyond_hatching,
        };
        let drawn = mv.draw(&mut group, &mut labels);
        legend_off_the_drawing(&mut group, legend, region, words);
        let placed = labels.place_measured(&mut group, region.inflate(-0.5, -0.5));
        let farthest = placed.iter().filter(|p| p.rank >= NUMBERS_RANK).map(|p| p.leader).fold(0.0, f64::max);
        let unplaced = placed.iter().filter(|p| !p.clean).count();
        let short_far =
            drawn.short_stroke_numbers.iter().any(|&i| !placed[i].clean || placed[i].leader > SHORT_STROKE_FAR);
        let across = leaders_across(&group, &drawn.dimension_lines);
        let detail_mu_l = drawn.detail_mu_l;
        let mech = MechanismDrawn { group, region, mu_l, detail_mu_l };
        Attempt { mech, farthest, unplaced, short_far, across }
    };
    // A short stroke's numbers are kept where each stands near its point, clean; where a
    // number crowded off its side crosses its stroke's dimension line beyond the hatching,
    // the line is drawn again further off, leaving them room, if that leaves fewer across
    // and no more labels without a clean spot.
    let numbered = |detail, slider_same_mm| {
        let mut numbers = SliderNumbering { short_strokes: true, beyond_hatching: false };
        let mut first = draw_as(detail, slider_same_mm, numbers);
        if first.short_far {
            numbers.short_strokes = false;
            first = draw_as(detail, slider_same_mm, numbers);
        }
        if first.across > 0 {
            let roomy = draw_as(detail, slider_same_mm, SliderNumbering { beyond_hatching: true, ..numbers });
            if roomy.unplaced <= first.unplaced && roomy.across < first.across {
                first = roomy;
            }
        }
        (first.mech, first.farthest, first.unplaced)
    };
    // A slider's numbers that leave a label no clean spot share one where they stand within
    // SLIDER_SAME_MM, if that leaves fewer without.
    let draw = |detail| {
        let (drawn, farthest, unplaced) = numbered(detail, 0.0);
        if unplaced == 0 || !m.steps.iter().any(|s| matches!(s, Step::Rrp { .. })) {
            return (drawn, farthest, unplaced);
        }
        let (merged, nearest, left) = numbered(detail, SLIDER_SAME_MM);
        if left < unplaced { (merged, nearest, left) } else { (drawn, farthest, unplaced) }
    };
    let (drawn, farthest, unplaced) = draw(detail);
    // A crank large enough on paper may still be crowded: the rods' lines, its letters and
    // ω₁ round it pushed its numbers off on long leaders (task 1's tall two-slider
    // mechanisms: 58–78 mm) or left one on a line (a six-bar's 9.3 mm crank among its
    // rods' twelve positions). Its detail then, in a free spot of the region, if it leaves
    // fewer labels without a clean spot, or as few nearer.
    if detail.is_some() || (farthest < NUMBERS_FAR_MM && unplaced == 0) {
        return drawn;
    }
    let left = crank_on_left(m, k, world);
    let Some(crowded) = detail_place(m, mu_l, left, words, true) else { return drawn };
    let (redrawn, nearer, left_over) = draw(Some((crowded, None)));
    let better = (left_over, nearer) < (unplaced, farthest);
    if redrawn.detail_mu_l.is_some() && better { redrawn } else { drawn }
}

/// A short stroke's number this far off its point on a leader, mm, or with no clean spot,
/// has the stroke drawn unnumbered: a six-bar's «11» hung 46 mm off across its crank's
/// circle, where its rod's twelve positions fan over the guide.
const SHORT_STROKE_FAR: f64 = 20.0;

/// Whether the crank's pivot is left of the mechanism's middle (its detail goes that side).
fn crank_on_left(m: &Mechanism, k: &Kinematics, world: Rect) -> bool {
    k.assigned.state.points[m.crank().pivot].p.x < world.center().x
}

/// A position number this far off its point on a leader, mm, calls for the crank's detail.
const NUMBERS_FAR_MM: f64 = 20.0;

/// The mechanism's title, μ_l, the structure formula and the degrees of freedom.
fn mechanism_header(g: &mut Group, region: Rect, mu_l: f64, k: &Kinematics, words: &LeverWords) {
    region_header(g, region, words.sheet.positions_title(), &header_lines(mu_l, k, words));
}

/// The header's line under its title: μ_l, the structure formula and the degrees of freedom.
fn header_lines(mu_l: f64, k: &Kinematics, words: &LeverWords) -> [LabelText; 3] {
    let (l, s) = (words.sheet, &k.structure);
    [
        mu_l_text(mu_l, words),
        LabelText::new(format!("{}: {}", l.structure(), s.formula), ""),
        LabelText::new(format!("W = 3·{} − 2·{} − {} = {}", s.moving_links, s.p5, s.p4, s.dof), ""),
    ]
}

/// The drawing's width that leaves its header and the trajectories' legend room at
/// `mu_l`, mm (as
/// [`region_header`] and [`trajectory_legend`] set them, with a margin).
fn header_width(mu_l: f64, k: &Kinematics, words: &LeverWords) -> f64 {
    let lines = header_lines(mu_l, k, words);
    let line = lines.iter().map(|l| l.width(3.5) + 8.0).sum::<f64>() - 8.0;
    let title = LabelText::new(words.sheet.positions_title(), "").width(5.0);
    let legend = LEGEND_SAMPLE + LabelText::new(words.sheet.trajectories(), "").width(2.5);
    line.max(title).max(legend) + 6.0 - 2.0 * MECH_PAD
}

/// The legend shows the trajectories' own line type, then says what it is: drawn in the
/// region's bottom left corner (the drawing keeps off it where it can), its two items.
fn trajectory_legend(g: &mut Group, region: Rect, words: &LeverWords) -> [usize; 2] {
    let k = g.mark();
    for item in legend_items(region, words, Corner::BottomLeft) {
        g.items.push(item);
    }
    g.writing.push(k);
    [k, k + 1]
}

/// A corner of the mechanism's region the legend may stand in.
#[derive(Clone, Copy)]
enum Corner {
    BottomLeft,
    BottomRight,
    TopLeft,
    TopRight,
}

/// The legend's sample line and its words in `corner` of `region` (a top corner under
/// the header).
fn legend_items(region: Rect, words: &LeverWords, corner: Corner) -> [Item; 2] {
    let text = words.sheet.trajectories();
    let w = LEGEND_SAMPLE + LabelText::new(text, "").width(2.5);
    let x0 = match corner {
        Corner::BottomLeft | Corner::TopLeft => region.x0 + 2.0,
        Corner::BottomRight | Corner::TopRight => region.x1 - 2.0 - w,
    };
    let y = match corner {
        Corner::BottomLeft | Corner::BottomRight => region.y1 - 2.0,
        Corner::TopLeft | Corner::TopRight => region.y0 + HEADER + 3.0,
    };
    let sample = Path::polyline(&[Point::new(x0, y - 1.2), Point::new(x0 + 14.0, y - 1.2)], false);
    [
        Item::Path { path: sample, pen: TRAJECTORY },
        Item::Text(Text::new(Point::new(x0 + LEGEND_SAMPLE, y), text, 2.5, Anchor::Start)),
    ]
}

/// From the legend's sample line's start to its words, mm.
const LEGEND_SAMPLE: f64 = 16.0;

/// Moves the legend (its `items`) to the first corner of `region` where no line of the
/// drawing meets it, if one meets it where it stands: a stroke's dimension, with no
/// offset left clear of it, ran its extension line through the words (a crank-slider with
/// its guide at 214°, found by the random sweep).
fn legend_off_the_drawing(g: &mut Group, items: [usize; 2], region: Rect, words: &LeverWords) {
    let room = |line: &Item, text: &Item| line.bbox().union(text.bbox()).inflate(1.0, 1.0);
    let here = room(&g.items[items[0]], &g.items[items[1]]);
    let drawing = &g.items[items[1] + 1..];
    // Nothing drawn even near it, mostly: the drawing is not indexed for nothing.
    if drawing.iter().all(|i| !i.bbox().overlaps(here)) {
        return;
    }
    let drawn = Obstacles::of_items(drawing);
    if drawn.is_clear(here) {
        return;
    }
    let corners = [Corner::BottomRight, Corner::TopLeft, Corner::TopRight];
    let clear = |[line, text]: &[Item; 2]| drawn.is_clear(room(line, text));
    if let Some([line, text]) = corners.iter().map(|&c| legend_items(region, words, c)).find(clear) {
        g.items[items[0]] = line;
        g.items[items[1]] = text;
    }
}

/// A mechanism region, its scale, the drawing's height and the crank's detail.
struct Sized {
    region: Rect,
    mu_l: f64,
    draw_h: f64,
    detail: Option<DetailPlace>,
}

/// The mechanism's region for a box at most `max_h` tall, its drawing at least
/// `least_w(μ_l)` wide at the scale chosen: its scale, the drawing's height and, for a crank
/// too small on paper, its detail and where it goes.
fn mechanism_region(
    world: Rect,
    max_h: f64,
    inner: Rect,
    least_w: impl Fn(f64) -> f64,
    detail: &dyn Fn(f64) -> Option<DetailPlace>,
) -> Sized {
    let (avail_w, avail_h) = (MECH_MAX_W - 2.0 * MECH_PAD, max_h - HEADER - 2.0 * MECH_PAD);
    let mu_l = scale::length_scale((world.width() / avail_w).max(world.height() / avail_h));
    let (world_w, world_h) = (world.width() / mu_l, world.height() / mu_l);
    // Beside the drawing where the box has room for it; under a drawing whose band it would
    // fill more than half of (the drawing leaves such a band no free box that tall: a long
    // rod runs across it), where the box is tall enough; else in a free spot of the region.
    let detail = detail(mu_l).map(|d| {
        let (w, h) = d.size;
        let at = if world_w + w + DETAIL_GAP <= avail_w && h <= avail_h + 2.0 * MECH_PAD {
            DetailAt::Beside
        } else if 2.0 * h > world_h + 2.0 * MECH_PAD && world_h + DETAIL_GAP + h <= avail_h {
            DetailAt::Below
        } else {
            DetailAt::Inside
        };
        DetailPlace { at, ..d }
    });
    let (mut draw_w, mut draw_h) = (world_w, world_h);
    match detail {
        Some(d) if d.at == DetailAt::Beside => {
            draw_w += d.size.0 + DETAIL_GAP;
            draw_h = draw_h.max(d.size.1 - 2.0 * MECH_PAD);
        }
        Some(d) if d.at == DetailAt::Below => {
            draw_w = draw_w.max(d.size.0);
            draw_h += DETAIL_GAP + d.size.1;
        }
        _ => {}
    }
    let draw_w = draw_w.max(least_w(mu_l));
    let r = Rect::new(
        inner.x0 + 5.0,
        TOP,
        inner.x0 + 5.0 + draw_w + 2.0 * MECH_PAD,
        TOP + HEADER + draw_h + 2.0 * MECH_PAD + 4.0,
    );
    Sized { region: r, mu_l, draw_h, detail }
}

/// The part of the region the mechanism's drawing is centred in, and the detail's box on
/// the crank's side (between the header and the legend).
fn beside_detail(region: Rect, d: &DetailPlace) -> (Rect, Rect) {
    let (w, h) = d.size;
    let band = (region.y0 + HEADER, region.y1 - 6.0);
    let y0 = (band.0 + band.1 - h) / 2.0;
    if d.left {
        let x0 = region.x0 + MECH_PAD;
        (Rect::new(region.x0 + w + DETAIL_GAP, region.y0, region.x1, region.y1), Rect::new(x0, y0, x0 + w, y0 + h))
    } else {
        let x1 = region.x1 - MECH_PAD;
        (Rect::new(region.x0, region.y0, region.x1 - w - DETAIL_GAP, region.y1), Rect::new(x1 - w, y0, x1, y0 + h))
    }
}

/// The detail's box under the drawing (whose band is `band_h` tall), centred under the
/// crank's pivot at `crank_x` as far as the region allows.
fn below_detail(region: Rect, band_h: f64, crank_x: f64, d: &DetailPlace) -> Rect {
    let (w, h) = d.size;
    let (lo, hi) = (region.x0 + MECH_PAD, (region.x1 - MECH_PAD - w).max(region.x0 + MECH_PAD));
    let x0 = (crank_x - w / 2.0).clamp(lo, hi);
    let y0 = region.y0 + HEADER + MECH_PAD + band_h + DETAIL_GAP;
    Rect::new(x0, y0, x0 + w, y0 + h)
}
