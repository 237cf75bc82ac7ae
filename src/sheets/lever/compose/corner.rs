//! Table 1 moved down into the corner beside the title block where the plans above it are
//! smaller than the guide draws them: the band left of the title block holds table 1 and
//! the notes, and the plans' column gets their height (the V-compressor's acceleration
//! plans, four beside twelve velocity plans, were 75 mm long; with the corner 90 mm). Tried only
//! where the plans are that small and taken only where the force drawings and the
//! mechanism keep their size: on task 1 variant 5 the taller column drew the plans 92 mm
//! long (73 under the tables) with the force column 80 mm narrower, its group drawings
//! 26 mm instead of 52.

use super::super::choice::{EMPTY_MOST, Floors, empty};
use super::super::plan_regions::{LARGEST_PLAN, PlanDrawn};
use super::{Composed, Variant};
use crate::drawing::text::TooLong;
use crate::num::tol;
use rayon::prelude::*;

/// The smaller of the two kinds' largest drawn plans, mm (the velocity plans' where there
/// are no acceleration plans; 0 without plans).
pub(super) fn largest_plans_mm(c: &Composed) -> f64 {
    let largest = |p: &[PlanDrawn]| p.iter().map(|d| d.size_mm[0].max(d.size_mm[1])).reduce(f64::max);
    let v = largest(&c.scales.velocity_plans).unwrap_or(0.0);
    largest(&c.scales.acceleration_plans).map_or(v, |a| v.min(a))
}

/// The sheet `out`, composed as `v`, or, where a kind's largest plan on it is under
/// [`LARGEST_PLAN`], the same variant with table 1 in the corner if that draws the plan
/// larger, keeps the floors of `out` that larger plans must keep (its smallest plan, polygon
/// side, tables 3–5 together; the lever to 80 mm, its group drawings three quarters of their
/// size: `Floors::for_larger_plans`) and its mechanism's scale, is as clean and at most half empty
/// (or no emptier than `out`); in either lettering of tables 3–5, composed on rayon's pool.
pub(super) fn with_larger_plans(
    variant: &(impl Fn(Variant) -> Result<Composed, TooLong> + Sync),
    (v, out): (Variant, Composed),
) -> Composed {
    let before = largest_plans_mm(&out);
    if v.corner || before >= LARGEST_PLAN - tol::PAPER {
        return out;
    }
    // The other lettering of tables 3–5 too: in the narrower force column the taller plans'
    // column may choose, the larger lettering may keep the drawings their size (5 more
    // catalogue sheets reach 80 mm).
    let corner = Variant { corner: true, ..v };
    let tried = [corner, corner.in_other_lettering()];
    let floors = Floors::of(&out).for_larger_plans();
    let admissible = |c: &Composed| {
        let clean = c.layout.is_clean() || !out.layout.is_clean();
        let full = empty(c) <= EMPTY_MOST.max(empty(&out));
        let mechanism = c.scales.mu_l <= out.scales.mu_l;
        largest_plans_mm(c) > before + tol::PAPER && clean && full && mechanism && floors.kept(c)
    };
    // Each candidate's largest plans found once, not at every comparison.
    let best = tried
        .into_par_iter()
        .filter_map(|v| variant(v).ok())
        .filter(admissible)
        .map(|c| (largest_plans_mm(&c), c))
        .max_by(|a, b| a.0.total_cmp(&b.0).then(empty(&b.1).total_cmp(&empty(&a.1))))
        .map(|(_, c)| c);
    best.unwrap_or(out)
}
