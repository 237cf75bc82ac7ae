//! Velocity and acceleration plans, each position in its own cell.
//!
//! Course drawings either overlay all velocity plans on one pole or give each position
//! its own plan. Overlaid, 9–13 plans share their vectors' directions near the pole and
//! their labels collide; separate cells keep every image point readable, so each position
//! gets its own plan here.
//!
//! Scales: one round μ for all plans of a kind, as the guide draws them (μ_v for every
//! velocity plan, μ_a for every acceleration plan), so their vectors compare at a glance;
//! the smallest μ of the plans' series at which the cells pack, so the largest plan is as
//! large as the region allows. A plan's side is then at least its crank vector (pa = ω1·l_OA
//! is the same in every velocity plan, πa = ω1²·l_OA in every acceleration plan), and a
//! kulisa's plan near its fast stroke may be ten times its slowest: its cell grows to hold
//! it and the rest keep the one μ while they are at least [`MEASURABLE_PLAN`] long (every
//! variant of the guide's catalogue: its smallest is 20.3 mm). Only where one μ would draw
//! a plan shorter than that (a ratio beyond any task of the guide) do the fewest plans
//! possible leave the common scale: a plan under [`MIN_PLAN`] is enlarged, one over
//! [`MAX_PLAN`] reduced, each to a round μ of its own written in its cell.
//! Cells are sized by their plans and packed in rows that fill the region.

use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, DASHED, Group, Pen, THIN, Text, VECTOR};
use crate::drawing::symbols::vector;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::plans::{Plan, SegKind};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// Room left around a plan inside its cell for the labels, mm.
pub const MARGIN: f64 = 7.0;
/// Images closer than this (mm) share one label, e.g. "p=b=d".
const SHARED_LABEL: f64 = 0.8;
/// Height of a cell's title strip, mm.
pub const TITLE: f64 = 6.0;
/// A title ends at least this far inside its cell's right side, mm: with the next cell's
/// title 2 mm inside its left side, two titles on one line stand 5 mm apart (1 mm inside,
/// "Положение 0 Положение 1" stood 4 mm apart and read as one caption).
const TITLE_END: f64 = 2.5;
/// Gap between cells, mm.
pub const GAP: f64 = 2.0;
/// A plan's longer side is at least this long, mm: measured with a ruler to 0.5 mm, its
/// vectors read to 2 % (the guide draws pa = 40 mm).
pub const MIN_PLAN: f64 = 25.0;
/// The least a plan is drawn at its kind's one scale, mm: read with a ruler to 0.5 mm, its
/// longest vector to 2.5 %. Shorter, the plan leaves the common scale for one of its own.
pub const MEASURABLE_PLAN: f64 = 20.0;
/// A plan leaving the common scale for a smaller one is drawn this long, mm.
const MAX_PLAN: f64 = 70.0;
/// A plan in a cell taller than it stands at most this far below the room under its title,
/// mm (centred below that).
const PLAN_DROP: f64 = 10.0;
/// The own scale's line under a cell's title, mm.
const SCALE_LINE: f64 = 5.0;

/// Bounding box of a plan in its own units (m/s or m/s²), pole included.
pub fn plan_bbox(plan: &Plan) -> Rect {
    let mut r = Rect::from_points(Point::ZERO, Point::ZERO);
    for s in &plan.segs {
        r = r.union_pt(s.from.to_point()).union_pt(s.to.to_point());
    }
    for i in &plan.images {
        r = r.union_pt(i.at.to_point());
    }
    r
}

/// A plan's longer side, in its units (m/s or m/s²).
pub fn plan_side(plan: &Plan) -> f64 {
    let b = plan_bbox(plan);
    b.width().max(b.height())
}

/// How a region's plans are drawn: each plan's cell and scale.
#[derive(Debug, Clone, PartialEq)]
pub struct Sizing {
    pub cells: Vec<Rect>,
    /// The scale the plans share.
    pub common: f64,
    /// Each plan's scale: `common` but for the few that cannot be measured at it.
    pub mu: Vec<f64>,
}

impl Sizing {
    /// Each plan's drawn size (width, height), mm.
    pub fn drawn(&self, plans: &[Plan]) -> Vec<[f64; 2]> {
        plans.iter().map(plan_bbox).zip(&self.mu).map(|(b, mu)| [b.width() / mu, b.height() / mu]).collect()
    }

    /// Each plan's longer side drawn, mm.
    fn sides(&self, plans: &[Plan]) -> impl Iterator<Item = f64> {
        self.drawn(plans).into_iter().map(|[w, h]| w.max(h))
    }

    /// The largest plan's longer side, mm.
    pub fn largest(&self, plans: &[Plan]) -> f64 {
        self.sides(plans).fold(0.0, f64::max)
    }

    /// The smallest longer side of the plans at the common scale, mm (those with a scale
    /// of their own left out: [`Sizing::own_count`] counts them).
    pub fn least_measured(&self, plans: &[Plan]) -> f64 {
        self.sides(plans).enumerate().filter(|&(i, _)| !self.own(i)).map(|(_, d)| d).fold(f64::MAX, f64::min)
    }

    /// How many plans are drawn shorter than [`MEASURABLE_PLAN`].
    pub fn unmeasurable(&self, plans: &[Plan]) -> usize {
        self.sides(plans).filter(|&d| d < MEASURABLE_PLAN).count()
    }

    /// How many plans have a scale of their own.
    pub fn own_count(&self) -> usize {
        (0..self.mu.len()).filter(|&i| self.own(i)).count()
    }

    /// Whether plan `i` has a scale of its own.
    pub fn own(&self, i: usize) -> bool {
        off_scale(self.mu[i], self.common)
    }
}

/// Whether a plan drawn at `mu` is off its kind's one scale `common`.
pub fn off_scale(mu: f64, common: f64) -> bool {
    (mu / common - 1.0).abs() > tol::SAME_SCALE
}

/// A cell's size for a plan of box `bb` at `mu`: the plan with room around it for its
/// labels, at least `min_w` wide (its title) and as wide as its longest label (`label_w`),
/// which may then stand above or below the point it names; a plan at its own scale has that
/// scale's line under the title.
fn cell_size(bb: Rect, mu: f64, own_scale: bool, min_w: f64, label_w: f64) -> (f64, f64) {
    let title = TITLE + if own_scale { SCALE_LINE } else { 0.0 };
    let w = (bb.width() / mu + 2.0 * MARGIN + 2.0).max(min_w).max(label_w + 4.0);
    (w, bb.height() / mu + 2.0 * MARGIN + title + 1.0)
}

/// The width of a plan's longest label line at 3.5 mm: the images that coincide (at any
/// scale) share one label, "p=b=s3=" over "c".
fn longest_label(plan: &Plan, pole: &str) -> f64 {
    let size = plan_bbox(plan).size();
    let same = tol::SAME_POINT * size.width.max(size.height).max(f64::MIN_POSITIVE);
    let mut groups: Vec<(Vec2, Vec<String>)> = vec![(Vec2::ZERO, vec![pole.to_string()])];
    for img in &plan.images {
        match groups.iter_mut().find(|(at, _)| (*at - img.at).norm() <= same) {
            Some((_, names)) => names.push(img.label.clone()),
            None => groups.push((img.at, vec![img.label.clone()])),
        }
    }
    groups.iter().flat_map(|(_, names)| label_lines(names)).map(|l| l.width(3.5)).fold(0.0, f64::max)
}

/// Names sharing one point as the lines of one stacked label, at most [`SHARED_PER_LABEL`]
/// names a line, each line but the last ending with "=" so that the chain reads on: "p=b=s3=" over
/// "c=s4=s5" (a second label starting with "=" read as a stray sign).
fn lines(names: &[String]) -> Vec<String> {
    let n = names.len().div_ceil(SHARED_PER_LABEL);
    // As even as the lines allow: four names are "b=d=" over "s4=s5", not three and one.
    names
        .chunks(names.len().div_ceil(n.max(1)).max(1))
        .enumerate()
        .map(|(k, c)| format!("{}{}", c.join("="), if k + 1 < n { "=" } else { "" }))
        .collect()
}

const SHARED_PER_LABEL: usize = 3;

/// The rows of cells `sizes` at most `width` wide, in order, whose tallest cells (and the
/// gaps between rows) sum least (shortest path over the break points): each row's first
/// cell, then `sizes.len()` (no cells: one empty row). `None` when a cell is wider than `width`.
fn row_breaks(sizes: &[(f64, f64)], width: f64) -> Option<Vec<usize>> {
    let n = sizes.len();
    if sizes.iter().any(|&(w, _)| w > width) {
        return None;
    }
    // best[j]: the least height of cells 0..j in rows, and where its last row starts.
    let mut best: Vec<(f64, usize)> = vec![(f64::INFINITY, 0); n + 1];
    best[0] = (0.0, 0);
    for j in 1..=n {
        let (mut w, mut h) = (-GAP, 0.0_f64);
        for i in (0..j).rev() {
            w += sizes[i].0 + GAP;
            if w > width {
                break;
            }
            h = h.max(sizes[i].1);
            let total = best[i].0 + h + if i > 0 { GAP } else { 0.0 };
            // Ties keep the fuller last row (the greedy's choice).
            if total < best[j].0 - 1e-9 {
                best[j] = (total, i);
            }
        }
    }
    let mut starts = vec![n];
    let mut j = n;
    while j > 0 {
        j = best[j].1;
        starts.push(j);
    }
    if n == 0 {
        starts.push(0);
    }
    starts.reverse();
    Some(starts)
}

/// Packs cells of `sizes` in rows inside `body`, in order, breaking the rows where their
/// heights sum least (a tall plan's row holds the other tall ones where the width allows,
/// rather than each row filled greedily and as tall as its tallest); the rows are then
/// stretched to fill the body's width and height. `None` when they do not fit.
fn pack(sizes: &[(f64, f64)], body: Rect) -> Option<Vec<Rect>> {
    let starts = row_breaks(sizes, body.width())?;
    // Each row's cells as a range (no list of lists: most packings tried fail).
    let rows = || starts.windows(2).map(|w| w[0]..w[1]);
    let height = |row: std::ops::Range<usize>| sizes[row].iter().map(|s| s.1).fold(0.0, f64::max);
    let n_rows = starts.len() - 1;
    let total_h = rows().map(height).sum::<f64>() + GAP * (n_rows - 1) as f64;
    if total_h > body.height() {
        return None;
    }
    let extra_h = (body.height() - total_h) / n_rows as f64;
    let mut out = vec![Rect::ZERO; sizes.len()];
    let mut y = body.y0;
    for row in rows() {
        let h = height(row.clone());
        let used: f64 = sizes[row.clone()].iter().map(|s| s.0).sum::<f64>() + GAP * (row.len() - 1) as f64;
        let extra_w = (body.width() - used) / row.len() as f64;
        let mut x = body.x0;
        for i in row {
            let w = sizes[i].0 + extra_w;
            out[i] = Rect::new(x, y, x + w, y + h + extra_h);
            x += w + GAP;
        }
        y += h + extra_h + GAP;
    }
    Some(out)
}

/// What sizing a kind's plans asks of each, whatever the region: its box and its longest
/// label's width. Found once: a column's split tries some fifty regions.
#[derive(Clone)]
pub struct PlanBoxes {
    boxes: Vec<Rect>,
    labels: Vec<f64>,
}

impl PlanBoxes {
    /// The boxes and longest labels of `plans` drawn from the pole named `pole`.
    pub fn of(plans: &[Plan], pole: &str) -> PlanBoxes {
        PlanBoxes {
            boxes: plans.iter().map(plan_bbox).collect(),
            labels: plans.iter().map(|p| longest_label(p, pole)).collect(),
        }
    }
}

/// Chooses the scales and cells in `body` of the plans measured `measured` (see the
/// module's note on scales); a cell is at least `min_w` wide (its title and scale line).
pub fn size_plans(body: Rect, measured: &PlanBoxes, min_w: f64) -> Sizing {
    let PlanBoxes { boxes, labels } = measured;
    let sides: Vec<f64> = boxes.iter().map(|b| b.width().max(b.height()).max(f64::MIN_POSITIVE)).collect();
    let largest = sides.iter().copied().fold(f64::MIN_POSITIVE, f64::max);
    // Buffers reused from one scale tried to the next (a column's split sizes fifty regions).
    let (mut mus, mut sizes) = (Vec::with_capacity(boxes.len()), Vec::with_capacity(boxes.len()));
    let mut fit = |common: f64, outliers: bool| -> Option<Sizing> {
        mus.clear();
        mus.extend(sides.iter().map(|&s| if outliers { own_scale(s, common) } else { common }));
        sizes.clear();
        sizes.extend((0..boxes.len()).map(|i| cell_size(boxes[i], mus[i], mus[i] != common, min_w, labels[i])));
        pack(&sizes, body).map(|cells| Sizing { cells, common, mu: mus.clone() })
    };
    // Every plan at one scale: the smallest that packs.
    let mut mu = scale::plan_round_up(largest / body.width().max(body.height()));
    let mut all = None;
    for _ in 0..400 {
        if let Some(s) = fit(mu, false) {
            all = Some(s);
            break;
        }
        mu = scale::plan_next_round(mu);
    }
    let Some(all) = all else {
        // Nothing packs (a region too small for its plans' titles): the grid overflowing,
        // so the layout measurement reports it.
        let sizes: Vec<_> = boxes.iter().zip(labels).map(|(&b, &lw)| cell_size(b, mu, false, min_w, lw)).collect();
        let cells = pack(&sizes, Rect::new(body.x0, body.y0, body.x0 + 1e6, body.y0 + 1e6)).unwrap_or_default();
        return Sizing { cells, common: mu, mu: vec![mu; boxes.len()] };
    };
    if sides.iter().all(|&s| s / all.common >= MEASURABLE_PLAN) {
        return all;
    }
    // Some would be too small to measure: the common scale with the fewest plans of their own (then
    // the largest drawing), over every scale from the one that draws the smallest plan at
    // MAX_PLAN to the one that fits them all.
    let smallest = sides.iter().copied().fold(f64::MAX, f64::min);
    let top = all.common;
    let mut best = all;
    // What a sizing costs: first the plans drawn too small to measure, then those off the
    // common scale or under MIN_PLAN on it. (Counted alike, one scale leaving a kulisa's
    // slow plans 5.6 mm long tied with the same scale enlarging them, and was kept.)
    let unmeasurable = |s: &Sizing| (0..boxes.len()).filter(|&i| sides[i] / s.mu[i] < MEASURABLE_PLAN).count();
    let own_count = |s: &Sizing| (0..boxes.len()).filter(|&i| s.own(i) || sides[i] / s.mu[i] < MIN_PLAN).count();
    let cost = |s: &Sizing| (unmeasurable(s), own_count(s));
    // Up to a few scales coarser than the one that fits them all at one scale: enlarged,
    // the small plans' cells may not pack at that one.
    let mut mu = scale::plan_round_up(smallest / MAX_PLAN);
    while mu <= top * COARSER_AT_MOST {
        if let Some(s) = fit(mu, true)
            && cost(&s) < cost(&best)
        {
            best = s;
        }
        mu = scale::plan_next_round(mu);
    }
    best
}

/// How much coarser than the one fitting every plan at one scale the common scale may be
/// made so that plans too small to measure on it can be enlarged.
const COARSER_AT_MOST: f64 = 4.0;

/// A plan's scale beside the common one: its own when it would be under [`MIN_PLAN`] (the
/// coarsest round μ that draws it at least that long) or over [`MAX_PLAN`] (the finest that
/// draws it at most that long).
fn own_scale(side: f64, common: f64) -> f64 {
    if side / common < MIN_PLAN {
        scale::plan_round_down(side / MIN_PLAN)
    } else if side / common > MAX_PLAN {
        scale::plan_round_up(side / MAX_PLAN)
    } else {
        common
    }
}

fn pen_of(kind: SegKind) -> Pen {
    match kind {
        SegKind::Absolute => VECTOR,
        SegKind::Relative | SegKind::Normal | SegKind::Coriolis => THIN,
        SegKind::Tangential | SegKind::Sliding => DASHED,
    }
}

/// One plan to draw in a cell.
pub struct PlanCell<'a> {
    pub cell: Rect,
    pub title: &'a str,
    pub plan: &'a Plan,
    pub mu: f64,
    pub pole: &'a str,
    /// The plan's own scale line, when it has one.
    pub scale_line: Option<LabelText>,
    /// The box (plan units) centred in the cell: the plan's own when none, the lever's with
    /// its force arrows.
    pub extent: Option<Rect>,
}

/// Draws a plan's title, vectors and image points, and asks `labels` for its letters;
/// returns the paper position of the pole. The caller places the labels.
pub fn draw_plan(g: &mut Group, c: &PlanCell, labels: &mut Labels) -> Point {
    let (plan, mu) = (c.plan, c.mu);
    let bb = c.extent.unwrap_or_else(|| plan_bbox(plan));
    let (area_c, x) = placing(c);
    g.text(title_text(c, x));
    if let Some(line) = &c.scale_line {
        line.draw(g, Point::new(x, c.cell.y0 + TITLE + 3.5), 2.5, Anchor::Start);
    }
    // Paper position of the pole.
    let pole_p = Point::new(area_c.x - (bb.center().x) / mu, area_c.y + (bb.center().y) / mu);
    let view = View::new(pole_p, mu);
    let p = |v: Vec2| view.p(v);
    for s in &plan.segs {
        vector(g, p(s.from), p(s.to), pen_of(s.kind));
    }
    g.dot(pole_p, 0.5);
    // Labels: images closer than 0.8 mm share one label, e.g. "p=b=d".
    let mut clusters: Vec<(Point, Vec<String>)> = vec![(pole_p, vec![c.pole.to_string()])];
    for img in &plan.images {
        let at = p(img.at);
        match clusters.iter_mut().find(|(c, _)| (*c - at).norm() < SHARED_LABEL) {
            Some((_, names)) => names.push(img.label.clone()),
            None => clusters.push((at, vec![img.label.clone()])),
        }
    }
    let centre = {
        let pts: Vec<Point> = clusters.iter().map(|c| c.0).collect();
        crate::drawing::scene::points_bbox(&pts).center()
    };
    for (at, names) in &clusters {
        if *at != pole_p {
            g.dot(*at, 0.35);
        }
        let pref = if (*at - centre).norm() < tol::PAPER { Vec2::new(-1.0, 1.0) } else { *at - centre };
        labels.add_label_lines(*at, pref, label_lines(names), 3.5);
    }
    pole_p
}

/// The lines of names sharing a point as labels, each name's index set as a subscript
/// (see [`subscripted`]).
fn label_lines(names: &[String]) -> Vec<LabelText> {
    lines(names).iter().map(|l| subscripted(l)).collect()
}

/// One label line, "p=b=s3=", as a label with each name's index as a subscript: a normal's
/// pair after its "_" ("n_BA": n with BA below), a point's digits after its letter ("s3":
/// s with 3 below, as the mechanism writes S₃; plain, it read as a name of its own).
fn subscripted(line: &str) -> LabelText {
    // Each run of text before a subscript, with the subscript; then the text after the last.
    let mut pieces: Vec<(String, String)> = Vec::new();
    let mut text = String::new();
    for (k, name) in line.split('=').enumerate() {
        if k > 0 {
            text.push('=');
        }
        let (letter, index) = name_and_index(name);
        text.push_str(letter);
        if !index.is_empty() {
            pieces.push((std::mem::take(&mut text), index.to_string()));
        }
    }
    let mut tails = pieces.iter().skip(1).map(|(before, _)| before.clone()).chain([text]);
    let Some(((main, sub), rest)) = pieces.split_first() else {
        return LabelText::new(tails.next().unwrap_or_default(), "");
    };
    let tail = tails.next().unwrap_or_default();
    let then = rest.iter().map(|(_, sub)| sub.clone()).zip(tails).collect();
    LabelText::new(main.as_str(), sub.as_str()).with_tail(tail).with_then(then)
}

/// A plan point's name split into its letter(s) and its index: "n_BA" into "n" and "BA",
/// "s3" into "s" and "3"; a name without either ("b", "k") whole.
fn name_and_index(name: &str) -> (&str, &str) {
    if let Some(split) = name.split_once('_') {
        return split;
    }
    let first = name.chars().next().map_or(0, char::len_utf8);
    let (letter, digits) = name.split_at(first);
    if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) { (letter, digits) } else { (name, "") }
}

/// Where a plan stands in its cell: the paper centre of its box, and the left end of its
/// title (and own scale line).
fn placing(c: &PlanCell) -> (Point, f64) {
    let cell = c.cell;
    let top = cell.y0 + TITLE + if c.scale_line.is_some() { SCALE_LINE } else { 0.0 };
    let inner = Rect::new(cell.x0 + 1.0, top, cell.x1 - 1.0, cell.y1 - 1.0);
    let bb = c.extent.unwrap_or_else(|| plan_bbox(c.plan));
    let area = inner.inflate(-MARGIN, -MARGIN);
    // The plan's box centred in the cell across, and down as far as PLAN_DROP below the
    // room under its title: a small plan in a row a large one makes tall stands under its
    // title, not 40 mm below it.
    let drop = ((area.height() - bb.height() / c.mu) / 2.0).clamp(0.0, PLAN_DROP);
    let area_c = Point::new(area.center().x, area.y0 + drop + bb.height() / c.mu / 2.0);
    // The title (and own scale) over the plan's left edge and its letters' room there, not
    // at the cell's: a cell stretched across a row put it 90 mm left of a small plan.
    let title_w = title_width(c);
    let x = (area_c.x - bb.width() / c.mu / 2.0 - MARGIN).min(cell.x1 - TITLE_END - title_w).max(cell.x0 + 2.0);
    (area_c, x)
}

/// The wider of a cell's title and its own scale line, mm.
fn title_width(c: &PlanCell) -> f64 {
    let title = Text::new(Point::ZERO, c.title, 3.5, Anchor::Start);
    title.advance().max(c.scale_line.as_ref().map_or(0.0, |l| l.width(2.5)))
}

/// The box of a cell's title as [`draw_plan`] writes it (the room a label of the cell above
/// keeps clear of).
pub fn title_box(c: &PlanCell) -> Rect {
    title_text(c, placing(c).1).bbox()
}

/// A cell's title starting at `x`.
fn title_text(c: &PlanCell, x: f64) -> Text {
    Text::new(Point::new(x, c.cell.y0 + 4.5), c.title, 3.5, Anchor::Start)
}

/// The box inside a cell that its labels may use.
pub fn label_bounds(cell: Rect) -> Rect {
    Rect::new(cell.x0 + 0.5, cell.y0 + TITLE - 1.0, cell.x1 - 0.5, cell.y1 - 0.5)
}

#[cfg(test)]
#[path = "plans_view_tests.rs"]
mod tests;
