//! Sheet 1's regions of plans: their scales and cells, the split of a column between the
//! velocity and the acceleration plans, and the plans drawn with their answer segments.

use super::compose::{HEADER, region_header};
use super::labels::LeverWords;
use super::plans_view::{
    GAP, MIN_PLAN, PlanBoxes, PlanCell, Sizing, draw_plan, label_bounds, plan_side, size_plans, title_box,
};
use super::segments::{PlanKind, plan_segments};
use crate::drawing::fmt;
use crate::drawing::labels::Language;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::Group;
use crate::drawing::text::LabelText;
use crate::lever::analysis::Position;
use crate::lever::plans::Plan;
use crate::report::{AnswerKeys, Segment, ascii_key};
use kurbo::Rect;
use std::borrow::Cow;
use std::sync::OnceLock;

/// One drawn plan: its position, scale and size on paper.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PlanDrawn {
    pub position: String,
    /// (m/s)/mm or (m/s²)/mm.
    pub mu: f64,
    /// Width and height of the plan on paper, mm.
    pub size_mm: [f64; 2],
}

/// A region of plans: its group's id and region, its title, the plans' pole and the
/// quantity and unit of their scale.
pub(super) struct PlansRegion<'a> {
    pub(super) id: &'a str,
    pub(super) kind: &'a PlanKind,
    pub(super) region: Rect,
    pub(super) title: &'a str,
    pub(super) pole: &'a str,
    pub(super) symbol: &'a str,
    pub(super) unit: &'a str,
}

impl PlansRegion<'_> {
    /// The scale line of a plan of this kind at `mu`.
    fn scale_line(&self, mu: f64, words: &LeverWords) -> LabelText {
        LabelText::new("μ", self.symbol).with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(mu), words.lang),
            self.unit
        ))
    }

    /// The plans' scales and cells below the region's header (see [`size_plans`]).
    pub(super) fn sizing(&self, twins: &Twins, words: &LeverWords) -> Sizing {
        self.sizing_of(&self.measured(twins, words))
    }

    /// [`PlansRegion::measure`] of `twins`, kept with them: every layout tried sizes the same
    /// plans, and a column's split (some fifty regions) measured them again for each.
    fn measured<'t>(&self, twins: &'t Twins, words: &LeverWords) -> Cow<'t, (PlanBoxes, f64)> {
        let key = (self.pole.to_string(), self.symbol.to_string(), self.unit.to_string(), words.lang);
        let kept = twins.measured.get_or_init(|| (key.clone(), self.measure(twins, words)));
        // Measured for another kind of region or in other words (not on a sheet: each kind's
        // plans are sized by their own region in the sheet's words): measured anew.
        if kept.0 == key { Cow::Borrowed(&kept.1) } else { Cow::Owned(self.measure(twins, words)) }
    }

    /// What [`PlansRegion::sizing`] asks of the plans whatever the region: their boxes and
    /// labels, and their cells' least width.
    fn measure(&self, twins: &Twins, words: &LeverWords) -> (PlanBoxes, f64) {
        // A cell holds its title (3.5 mm) and, at a scale of its own, its scale line (2.5 mm).
        let min_w = twins
            .runs
            .iter()
            .map(|run| LabelText::new(words.sheet.position(&joined_label(run)), "").width(3.5))
            .fold(self.scale_line(0.0025, words).width(2.5), f64::max)
            + 5.0;
        (PlanBoxes::of(&twins.plans, self.pole), min_w)
    }

    /// [`PlansRegion::sizing`] of plans measured `(boxes, min_w)`.
    fn sizing_of(&self, (boxes, min_w): &(PlanBoxes, f64)) -> Sizing {
        let body = Rect::new(self.region.x0, self.region.y0 + HEADER, self.region.x1, self.region.y1);
        size_plans(body, boxes, *min_w)
    }
}

/// Shares of a column tried for the velocity plans above the acceleration plans: 0.30 to
/// 0.76 in steps of 0.02 (the plans' round scales step by up to a third, so a coarser
/// split misses the height at which the next scale packs).
fn velocity_shares() -> impl Iterator<Item = f64> {
    (15..=38).map(|k| f64::from(k) / 50.0)
}

/// The largest plan of each kind is at least this long, mm, where the column allows: the
/// guide's plans are drawn that large, vectors read to a percent.
pub const LARGEST_PLAN: f64 = 80.0;

/// Splits `column` between two kinds of plans, the first above or, across, on the left (a
/// kulisa's one tall acceleration plan made a row as tall as itself, its three small
/// neighbours lost in it; beside the velocity plans it is a column of its own, and the
/// velocity plans take the height): at the share with the fewest plans drawn too small to
/// measure, then the fewest off their kind's one scale (none where every plan can be
/// measured at it); of those whose smallest plan is
/// within [`SMALLEST_GIVE`] of the largest smallest (twice [`MIN_PLAN`] is enough), the one
/// whose smaller kind's largest plan is largest (up to [`LARGEST_PLAN`]), then whose smallest
/// plan is largest, then whose two largest plans sum most — or, where a split draws the
/// largest plan of each kind [`LARGEST_PLAN`] long and keeps [`LARGEST_GIVE`] of that
/// smallest plan, it. Returns each kind's region and sizing.
pub(super) fn split_plans(column: Rect, kinds: [(&PlansRegion, &Twins); 2], words: &LeverWords) -> Split {
    // The same at every share.
    let measured = kinds.map(|(r, twins)| r.measured(twins, words));
    // A share over 1 splits the column across instead: the velocity plans on the left.
    let split = |share: f64| {
        let regions = if share <= 1.0 {
            let y = column.y0 + column.height() * share;
            [Rect::new(column.x0, column.y0, column.x1, y), Rect::new(column.x0, y + 4.0, column.x1, column.y1)]
        } else {
            let x = column.x0 + column.width() * (share - 1.0);
            [Rect::new(column.x0, column.y0, x, column.y1), Rect::new(x + 4.0, column.y0, column.x1, column.y1)]
        };
        let mut kind = kinds
            .iter()
            .zip(&measured)
            .zip(regions)
            .map(|(((r, ..), m), region)| (region, PlansRegion { region, ..**r }.sizing_of(m)));
        [kind.next().expect("two kinds"), kind.next().expect("two kinds")]
    };
    let score = |s: &[(Rect, Sizing); 2]| {
        let [(least_v, largest_v), (least_a, largest_a)] =
            [0, 1].map(|k| (s[k].1.least_measured(&kinds[k].1.plans), s[k].1.largest(&kinds[k].1.plans)));
        // Plans too small to measure first: a split fewest off their scale by leaving a
        // kulisa's slow plans 3 mm long at one μ_v beat one that enlarges them.
        let unmeasurable = s[0].1.unmeasurable(&kinds[0].1.plans) + s[1].1.unmeasurable(&kinds[1].1.plans);
        let own = (unmeasurable, s[0].1.own_count() + s[1].1.own_count());
        (own, least_v.min(least_a), largest_v.min(largest_a).min(LARGEST_PLAN), largest_v + largest_a)
    };
    let tried: Vec<_> = velocity_shares()
        .chain(velocity_shares().map(|s| 1.0 + s))
        .map(|share| {
            let s = split(share);
            (score(&s), s)
        })
        .collect();
    // The fewest plans off their kind's scale, then a smallest plan within SMALLEST_GIVE of
    // the best the column allows (or twice MIN_PLAN), then the largest of each kind, the
    // smallest (to twice MIN_PLAN), the sum.
    let own = tried.iter().map(|t| t.0.0).min().expect("shares to try");
    let least = tried.iter().filter(|t| t.0.0 == own).map(|t| t.0.1).fold(0.0, f64::max);
    let enough = (least - SMALLEST_GIVE).min(2.0 * MIN_PLAN);
    let enough_at_largest = (least * LARGEST_GIVE).min(enough);
    let kept = |t: &Tried| t.0.1 >= enough || (t.0.2 >= LARGEST_PLAN && t.0.1 >= enough_at_largest);
    let (score, kinds) = tried
        .into_iter()
        .filter(|t| t.0.0 == own && kept(t))
        .max_by(|a, b| {
            let smallest = |t: &Tried| t.0.1.min(2.0 * MIN_PLAN);
            a.0.2.total_cmp(&b.0.2).then(smallest(a).total_cmp(&smallest(b))).then(a.0.3.total_cmp(&b.0.3))
        })
        .expect("the best share is kept");
    Split { kinds, reach: (score.1 < enough).then_some(least) }
}

/// A column split between the two kinds of plans: each kind's region and sizing, and, where
/// the split gave more of its smallest plan than [`SMALLEST_GIVE`] for plans
/// [`LARGEST_PLAN`] long, the smallest plan the column could have drawn. The choice between
/// columns and compositions reads that reach: a column's smallest plan given for larger ones
/// has not shrunk (task 5 variant 2 took a force column 40 mm narrower, halving its lever, for
/// a smallest plan "grown" back to what its widest could draw).
#[derive(Clone)]
pub(super) struct Split {
    pub(super) kinds: [(Rect, Sizing); 2],
    pub(super) reach: Option<f64>,
}

/// A split tried: (plans too small to measure and plans off their kind's scale, smallest plan, the smaller kind's largest
/// plan up to [`LARGEST_PLAN`], the two largest plans' sum), and the split.
type Tried = (((usize, usize), f64, f64, f64), [(Rect, Sizing); 2]);

/// How much of its smallest plan a split may give for a larger largest plan of a kind, mm:
/// a step of the round scales at the smallest plans' 50 mm is 10–17 mm, so a 5 mm give
/// lets the largest plans grow a step where the smallest stay within a tenth.
const SMALLEST_GIVE: f64 = 5.0;

/// The share of its smallest plan a split may keep where that draws the largest plan of
/// each kind [`LARGEST_PLAN`] long: the course asks for plans that large, and a sheet's
/// smallest plan is most often a dead centre's, a line read by its length alone (task 10
/// variant 45: acceleration plans 62 → 83 mm for a smallest plan of 24 mm, not 30).
const LARGEST_GIVE: f64 = 0.75;

/// Two plans of a kind coincide on paper when no image or vector end of one is farther from
/// the other's than this share of the kind's largest plan: 0.45 mm where that plan is drawn
/// 300 mm long, the most a column allows.
const SAME_PLAN: f64 = 0.0015;

/// Plans of consecutive positions that coincide on paper, drawn once ("7 ≡ 7′", an extreme
/// position a hundredth of a degree from a numbered one); a few degrees apart they do not
/// (the extreme's slider at rest), and each keeps its cell.
pub(super) struct Twins<'a> {
    /// The plans drawn, the first of each run.
    pub(super) plans: Vec<Plan>,
    /// Each drawn plan's positions: its own first, then the ones it stands for.
    pub(super) runs: Vec<Vec<(&'a Position, Plan)>>,
    /// Their measure ([`PlansRegion::measured`]) with what it was measured for: a region's
    /// pole, symbol and unit, and the language.
    measured: OnceLock<(MeasureKey, (PlanBoxes, f64))>,
}

/// What a region's measure of its plans depends on besides them.
type MeasureKey = (String, String, String, Language);

impl<'a> Twins<'a> {
    /// Groups `plans` of `positions` (in order) into runs that coincide on paper.
    pub(super) fn of(plans: Vec<Plan>, positions: &[&'a Position]) -> Twins<'a> {
        let largest = plans.iter().map(plan_side).fold(0.0, f64::max);
        let mut runs: Vec<Vec<(&'a Position, Plan)>> = Vec::new();
        for (plan, &pos) in plans.into_iter().zip(positions) {
            match runs.last_mut() {
                Some(run) if coincide(&run[0].1, &plan, SAME_PLAN * largest) => run.push((pos, plan)),
                _ => runs.push(vec![(pos, plan)]),
            }
        }
        Twins { plans: runs.iter().map(|r| r[0].1.clone()).collect(), runs, measured: OnceLock::new() }
    }
}

/// Whether plans `a` and `b` (of one mechanism: the same images and vectors in the same
/// order) put every image and vector end within `tol` of each other.
fn coincide(a: &Plan, b: &Plan, tol: f64) -> bool {
    use crate::num::math::Norm;
    let near = |p: kurbo::Vec2, q: kurbo::Vec2| (p - q).norm() <= tol;
    a.images.len() == b.images.len()
        && a.segs.len() == b.segs.len()
        && a.images.iter().zip(&b.images).all(|(i, j)| i.label == j.label && near(i.at, j.at))
        && a.segs.iter().zip(&b.segs).all(|(s, t)| s.of == t.of && near(s.from, t.from) && near(s.to, t.to))
}

/// The name of a run of coinciding positions: "7 ≡ 7′".
fn joined_label(run: &[(&Position, Plan)]) -> String {
    run.iter().map(|(p, _)| p.label.as_str()).collect::<Vec<_>>().join(" ≡ ")
}

/// Draws plans in the cells of their `sizing` (see [`size_plans`]) below the region's header; returns
/// the group, what each plan became and the scale they share, if one.
pub(super) fn plans_group(
    r: &PlansRegion,
    twins: &Twins,
    sizing: Sizing,
    words: &LeverWords,
    answer: &AnswerKeys,
) -> (Group, Vec<PlanDrawn>, Option<f64>, Vec<Segment>) {
    let plans = &twins.plans;
    let l = words.sheet;
    let mut g = Group::new(r.id, r.region);
    let scale_line = |mu: f64| r.scale_line(mu, words);
    region_header(&mut g, r.region, r.title, &[scale_line(sizing.common)]);
    let mut segments = Vec::new();
    let titles: Vec<String> = twins.runs.iter().map(|run| l.position(&joined_label(run))).collect();
    let cells: Vec<PlanCell> = plans
        .iter()
        .zip(&sizing.cells)
        .zip(&titles)
        .enumerate()
        .map(|(i, ((plan, &cell), title))| PlanCell {
            cell,
            title,
            plan,
            mu: sizing.mu[i],
            pole: r.pole,
            scale_line: sizing.own(i).then(|| scale_line(sizing.mu[i])),
            extent: None,
        })
        .collect();
    let title_boxes: Vec<Rect> = cells.iter().map(title_box).collect();
    for (i, (c, run)) in cells.iter().zip(&twins.runs).enumerate() {
        let (mu, pos) = (c.mu, run[0].0);
        let mut labels = Labels::new();
        let start = g.mark();
        draw_plan(&mut g, c, &mut labels);
        // The letters at a plan's foot may reach into the gap over the next row, clear of
        // its titles: a plan filling its cell left "d=s5" at its foot no room but 58 mm up on
        // a leader across the plan (task 12 variant 25 in Russian). Only those: the pole's
        // names at a plan's top took the room at its foot on a 47 mm leader hidden in a
        // vector (task 10 variant 10).
        let bounds = label_bounds(c.cell);
        if let Some(y1) = gap_below(c.cell, &sizing.cells) {
            labels.reach_below(y1, FOOT);
            let strip = Rect { y0: bounds.y1, y1, ..bounds };
            // A label just over the next row's title would read as its cell's.
            for (j, t) in title_boxes.iter().enumerate() {
                let room = t.inflate(TITLE_ROOM, TITLE_ROOM);
                if j != i && room.overlaps(strip) {
                    labels.keep_clear(room);
                }
            }
        }
        labels.place(&mut g, bounds);
        g.part_from(format!("plan.{}.{}", r.symbol, ascii_key(&pos.label)), start);
        // Each position's own values: a twin's differ from the drawn ones below the paper's
        // precision, and the student may measure either.
        segments.extend(run.iter().flat_map(|(p, plan)| plan_segments(plan, r.kind, &p.label, mu, answer)));
    }
    let drawn = twins
        .runs
        .iter()
        .zip(sizing.drawn(plans))
        .zip(&sizing.mu)
        .map(|((run, size_mm), &mu)| PlanDrawn { position: joined_label(run), mu, size_mm })
        .collect();
    (g, drawn, (!plans.is_empty()).then_some(sizing.common), segments)
}

/// How far below a cell its foot's labels may reach where a row of cells is below it: into
/// the gap between the rows, 0.5 mm short of the next cell's top (its title is kept clear
/// of by the caller).
fn gap_below(cell: Rect, cells: &[Rect]) -> Option<f64> {
    let row_below = cells.iter().any(|c| c.y0 > cell.y1 && c.x0 < cell.x1 && c.x1 > cell.x0);
    row_below.then_some(cell.y1 + GAP - 0.5)
}

/// How far a label reaching below its cell keeps from the next row's titles, mm.
const TITLE_ROOM: f64 = 2.0;

/// A label anchored this near its cell's foot (mm, from the bottom of its room) may reach
/// below it ([`gap_below`]): the foot's letters and the row of names under them.
const FOOT: f64 = 15.0;
