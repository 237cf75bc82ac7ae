//! Sheet 1's split between the force column (left) and the plans (right): the widths
//! tried and which one wins.

use super::super::choice::{Floors, at_least, lever_measurable};
use super::super::forces_view::CellMemo;
use super::{Arrangement, Composed, FORCES_MIN_W, Input, PlansOf, Variant, arrange, draw, force_tables, widen};
use crate::drawing::fmt;
use crate::drawing::scale;
use crate::drawing::text::TooLong;
use crate::lever::analysis::Kinematics;

/// Lays out sheet 1 as the variant `v` asks.
pub(super) fn compose_variant(inp: &Input, k: &Kinematics, plans: &PlansOf, v: Variant) -> Result<Composed, TooLong> {
    let memo = CellMemo::default();
    // Tables 3–5 as this variant letters them, set once for every width tried.
    let force_tables = force_tables(inp, v);
    let arrange = |w: f64, memo| arrange(inp, k, plans, (w, v), (memo, &force_tables));
    if inp.forces.is_none() {
        return draw(inp, k, plans, arrange(FORCES_MIN_W, &memo)?);
    }
    // The split between the force drawings (left) and the plans (right): the widest force
    // column is tried first; a narrower one wins when the forces still fit comfortably and
    // the smallest plan grows by a tenth or more over the widest's, or the widest's layout is
    // not clean — of those, the one whose smallest plan is largest (a wider one on a tie).
    // Both conditions are known before anything is drawn, so a width that cannot win is
    // never drawn (drawing is nearly all of the time). Nor is the widest drawn before the
    // narrower ones that grow the plans: in that order they come first whether the widest
    // is clean or not, so the first of them that is clean wins either way.
    let widest = arrange(FORCES_WIDTHS[0], &memo)?;
    // Drawing fails only where the title block refuses the sheet's texts: then with the
    // widest's refusal, as when it was drawn first.
    title_block_refusal(inp, &widest)?;
    let (smallest, largest) = (widest.smallest_plan_reach(plans).unwrap_or(0.0), widest.largest_plan_mm(plans));
    let own = widest.own_scales();
    let mut narrower = Vec::new();
    for &w in &FORCES_WIDTHS[1..] {
        let next = arrange(w, &memo)?;
        let (grown, larger) = (next.smallest_plan_reach(plans).unwrap_or(0.0), next.largest_plan_mm(plans));
        if next.mech.comfortable {
            narrower.push(((next.own_scales(), grown, larger), (w, next)));
        }
    }
    // Fewest plans off their kind's scale first, then the largest smallest plan.
    narrower.sort_by(|a, b| a.0.0.cmp(&b.0.0).then(b.0.1.total_cmp(&a.0.1)));
    // A narrower column wins where it keeps more plans on their kind's one scale (task 4
    // variant 40: at 390 mm every acceleration plan is at μ_a, at the widest plan 1 is at its
    // own), or as many and its smallest plan grows by a tenth, or the smaller kind's largest
    // (to LARGEST_PLAN) does and the forces keep the widest's floors, or the lower floors
    // larger plans may take them to with the mechanism's scale kept (below). One taking
    // plans off their scale is tried only where the widest is not clean: a plan at a scale
    // of its own is drawn at least 25 mm long and reads as grown.
    let (growing, rest): (Vec<_>, Vec<_>) =
        narrower.into_iter().partition(|((n, grown, _), _)| *n < own || (*n == own && *grown > 1.1 * smallest));
    let (larger, rest): (Vec<_>, Vec<_>) =
        rest.into_iter().partition(|((n, _, larger), _)| *n <= own && *larger > 1.1 * largest);
    let narrow = |next| {
        if v.widen {
            widen::widened(|w| arrange(w, &memo), |a| draw(inp, k, plans, a), next)
        } else {
            draw(inp, k, plans, next.1)
        }
    };
    // The first clean one whose lever stays measurable wins; were none, the first clean one
    // wins unless the widest is clean with a measurable lever and the smaller kind's largest
    // plan within a tenth as large (both capped at LARGEST_PLAN: task 10 variant 24's widest
    // has 77.6 mm, and its narrowest 80 mm with a lever of 51 mm instead of 102).
    let mut short_lever = None;
    for ((_, _, larger), next) in growing {
        let drawn = narrow(next)?;
        if drawn.layout.is_clean() {
            if lever_measurable(&drawn) {
                return Ok(drawn);
            }
            short_lever.get_or_insert((larger, drawn));
        }
    }
    let widest = draw(inp, k, plans, widest)?;
    if let Some((larger, drawn)) = short_lever {
        let plans_kept = at_least(1.1 * largest, larger);
        if !(widest.layout.is_clean() && lever_measurable(&widest) && plans_kept) {
            return Ok(drawn);
        }
    }
    if widest.layout.is_clean() {
        let floors = Floors::of(&widest);
        // Or, keeping the mechanism's scale, the forces shrunk as far as larger plans may
        // shrink them.
        let for_plans = floors.for_larger_plans();
        let kept = |c: &Composed| floors.kept(c) || (for_plans.kept(c) && c.scales.mu_l <= widest.scales.mu_l);
        for (_, next) in larger {
            let drawn = narrow(next)?;
            if drawn.layout.is_clean() && kept(&drawn) {
                return Ok(drawn);
            }
        }
        return Ok(widest);
    }
    for (_, next) in larger.into_iter().chain(rest) {
        let drawn = narrow(next)?;
        if drawn.layout.is_clean() {
            return Ok(drawn);
        }
    }
    Ok(widest)
}

/// The refusal of the title block of the sheet arranged `a`, if any: the one way [`draw`]
/// fails.
fn title_block_refusal(inp: &Input, a: &Arrangement) -> Result<(), TooLong> {
    let l = a.words.sheet;
    let name = if inp.forces.is_some() { l.sheet_name_forces() } else { l.sheet_name() };
    let lang = inp.ctx.info.language;
    let scale = fmt::localise(&scale::ratio(a.mech.mu_l), lang);
    inp.ctx.title_block(crate::drawing::labels::Common::get(lang), name, &scale).map(|_| ())
}

/// Widths of the force column tried, mm.
pub(super) const FORCES_WIDTHS: [f64; 3] = [FORCES_MIN_W, 430.0, 390.0];
