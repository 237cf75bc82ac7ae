//! How sheet 1 chooses between its compositions: what a variant must keep of the rule's
//! (its [`Floors`]) and how empty a sheet may be before fuller variants are tried.

use super::compose::Composed;
use super::forces_view::SIDE_MIN as POLYGON_SIDE_MIN;
use super::forces_view::{DRAWING_READABLE, LEVER_READABLE};
use super::plan_regions::LARGEST_PLAN;

/// The least share of its size a group drawing keeps where the force column narrows (or
/// table 1 moves into the corner) for plans under 80 mm: task 10 variant 16's crank drawing
/// went from 45.6 to 34.9 mm for velocity plans of 84.5 mm instead of 63.4 and a lever of
/// 127 mm instead of 95.
const SHRUNK_FOR_PLANS: f64 = 0.75;

/// How much smaller than the rule's a variant may draw the mechanism (its μ_l this many
/// times coarser): one or two GOST steps (1:4 → 1:5, 1:5 → 1:10), not more (task 8 variant
/// 29 in Russian took the larger lettering, 0.006 less empty, with its V-compressor at 1:10
/// instead of 1:4 and its crank in a detail) — unless a lever under [`LEVER_READABLE`] grows
/// by [`LEVER_WORTH_IT`] (task 8 variant 19: 1:4 → 1:10 for a lever of 110 mm, not 66;
/// variant 45 in Russian: 85 mm, not 42).
const MECHANISM_SHRUNK_MOST: f64 = 2.0;

/// How many times longer a lever under [`LEVER_READABLE`] must grow to be worth drawing the
/// mechanism more than [`MECHANISM_SHRUNK_MOST`] times smaller.
const LEVER_WORTH_IT: f64 = 1.5;

/// The shortest Zhukovsky lever a narrower force column may leave where its plans grow by a
/// tenth, mm: shorter, its arrows and labels knot (task 8 variant 45: 42 mm, with fourteen
/// arrows about p, a, b, c); the widest column is taken where its lever is at least this.
pub(super) const LEVER_SHORTEST: f64 = 60.0;

/// Whether `c`'s lever (if it has one) is at least [`LEVER_SHORTEST`].
pub(super) fn lever_measurable(c: &Composed) -> bool {
    c.force_scales.as_ref().is_none_or(|f| at_least(f.lever_mm, LEVER_SHORTEST))
}

/// Whether a size on paper reaches `floor`, mm, to within drawing precision.
pub(super) fn at_least(size: f64, floor: f64) -> bool {
    size >= floor - crate::num::tol::PAPER
}

/// The share of empty 20 mm cells above which a sheet is too empty (issue 22's bound).
pub(super) const EMPTY_MOST: f64 = 0.5;

pub(super) fn empty(c: &Composed) -> f64 {
    c.layout.empty_share.unwrap_or(1.0)
}

/// Whether `l` is better than the rule's composition `rule`: as clean, keeping its
/// [`Floors`] but for the tables' togetherness (the larger tables may not fit as one
/// block), and less empty by more than `margin` (on a tie the rule's) — or, where it grows
/// a lever under [`LEVER_READABLE`] by [`LEVER_WORTH_IT`], no emptier by more than
/// `margin`: task 8 variant 19 in Uzbek kept a 66 mm lever for 0.003 of empty share once
/// its load diagrams' stroke names moved beside their arrows (110 mm before, 0.005 emptier).
pub(super) fn better(l: &Composed, rule: &Composed, margin: f64) -> bool {
    let floors = Floors { together: false, ..Floors::of(rule) };
    let emptier_by = empty(rule) - empty(l);
    (l.layout.is_clean() || !rule.layout.is_clean())
        && floors.kept(l)
        && (emptier_by > margin || (floors.lever_grown(l) && emptier_by >= -margin))
}

/// What a variant must keep of the rule's composition: the mechanism's scale, its smallest
/// plan, its shortest labelled polygon side, lever and group drawing where those are under
/// what reads plainly (`POLYGON_SIDE_MIN`, [`LEVER_READABLE`], [`DRAWING_READABLE`]), and
/// tables 3–5 together where they were.
#[derive(Clone, Copy)]
pub(super) struct Floors {
    /// The mechanism's μ_l, m/mm: a variant may draw it at most [`MECHANISM_SHRUNK_MOST`]
    /// times smaller, or more where its lever grows by [`LEVER_WORTH_IT`].
    mu_l: f64,
    plan: f64,
    /// How many plans may leave their kind's one scale: a plan at a scale of its own is
    /// drawn at least 25 mm long, so a variant taking one off it reads as grown (task 4
    /// variant 40 in Uzbek: acceleration plan 1 at its own μ_a, the rest 58 mm).
    own_scales: usize,
    side: f64,
    lever: f64,
    drawing: f64,
    /// Whether tables 3–5 must stand together.
    together: bool,
}

impl Floors {
    pub(super) fn of(c: &Composed) -> Floors {
        Floors {
            mu_l: c.scales.mu_l,
            plan: plan_mm(c),
            own_scales: c.scales.own_scales(),
            side: side_mm(c).min(POLYGON_SIDE_MIN),
            lever: lever_mm(c).min(LEVER_READABLE),
            // The worked example in Russian took a fuller variant with its group drawings
            // halved (0.428 empty against 0.445).
            drawing: drawing_mm(c).min(DRAWING_READABLE),
            together: together(c),
        }
    }

    /// These floors as a composition that draws plans under [`LARGEST_PLAN`] larger must
    /// keep them: the lever, a velocity plan turned, may shrink to what a plan is drawn
    /// ([`LARGEST_PLAN`]), and a group drawing to [`SHRUNK_FOR_PLANS`] of its size.
    pub(super) fn for_larger_plans(self) -> Floors {
        Floors { lever: self.lever.min(LARGEST_PLAN), drawing: self.drawing * SHRUNK_FOR_PLANS, ..self }
    }

    /// These floors with tables 3–5 kept together where `c` has them so.
    pub(super) fn with_tables_of(self, c: &Composed) -> Floors {
        Floors { together: together(c), ..self }
    }

    /// Whether `c` grows a lever under [`LEVER_READABLE`] by [`LEVER_WORTH_IT`].
    fn lever_grown(&self, c: &Composed) -> bool {
        !at_least(self.lever, LEVER_READABLE) && at_least(lever_mm(c), LEVER_WORTH_IT * self.lever)
    }

    pub(super) fn kept(&self, c: &Composed) -> bool {
        let mechanism_kept = c.scales.mu_l <= self.mu_l * MECHANISM_SHRUNK_MOST * (1.0 + crate::num::tol::ROUND_VALUE);
        (mechanism_kept || self.lever_grown(c))
            && at_least(plan_mm(c), self.plan)
            && c.scales.own_scales() <= self.own_scales
            && at_least(side_mm(c), self.side)
            && at_least(lever_mm(c), self.lever)
            && at_least(drawing_mm(c), self.drawing)
            && (together(c) || !self.together)
    }
}

/// The smallest plan as choices read it: the plans' column's reach (`Composed::plan_reach_mm`).
fn plan_mm(c: &Composed) -> f64 {
    c.plan_reach_mm.unwrap_or(0.0)
}

fn side_mm(c: &Composed) -> f64 {
    c.force_scales.as_ref().and_then(|f| f.smallest_polygon_side_mm).unwrap_or(f64::MAX)
}

pub(super) fn together(c: &Composed) -> bool {
    c.force_scales.as_ref().is_some_and(|f| f.tables_together)
}

fn drawing_mm(c: &Composed) -> f64 {
    c.force_scales.as_ref().map_or(0.0, |f| f.smallest_drawing_mm)
}

fn lever_mm(c: &Composed) -> f64 {
    c.force_scales.as_ref().map_or(0.0, |f| f.lever_mm)
}
