//! Sheet 1's force column widened into the room its plans leave. The plans' scales go in
//! round steps, so a force column a few mm wider than the width chosen often leaves every
//! plan exactly as it was while the force drawings get the room: the kulisa's group
//! polygon went from μ_P = 1 to 0.6 N/mm and its sheet from 51.5 % empty to under half.

use super::super::choice::empty;
use super::{Arrangement, Composed, FORCES_WIDTHS, Variant};
use crate::drawing::text::TooLong;
use rayon::prelude::*;

/// How many of the least empty variants are composed again with the force column widened.
const WIDENED: usize = 3;

/// The [`WIDENED`] least empty of the variants `kept` (each with how empty it is) composed
/// by `variant` again with their force column widened, on rayon's pool, each with its variant.
pub(super) fn least_empty_widened(
    variant: &(impl Fn(Variant) -> Result<Composed, TooLong> + Sync),
    mut kept: Vec<(f64, Variant)>,
) -> Vec<(Variant, Composed)> {
    kept.sort_by(|a, b| a.0.total_cmp(&b.0));
    kept.truncate(WIDENED);
    kept.into_par_iter()
        .filter_map(|(_, v)| {
            let v = Variant { widen: true, ..v };
            variant(v).ok().map(|c| (v, c))
        })
        .collect()
}

/// How many widths are drawn, [`STEP`] mm apart down from the widest that keeps the plans:
/// which leaves least paper empty turns on where the cells fall on the 20 mm grid.
const DRAWN: usize = 3;
const STEP: f64 = 1.0;

/// The sheet arranged `a` with a force column `w` wide, drawn at the widest whole-mm width
/// below the widest tried ([`FORCES_WIDTHS`]) at which every plan keeps its scale, the
/// mechanism its scale or a larger one and the force drawings their comfort, and at
/// [`DRAWN`] − 1 widths below it: the least empty clean one, else `a` drawn as it was.
pub(super) fn widened<'a>(
    arrange: impl Fn(f64) -> Result<Arrangement<'a>, TooLong>,
    draw: impl Fn(Arrangement<'a>) -> Result<Composed, TooLong>,
    (w, a): (f64, Arrangement<'a>),
) -> Result<Composed, TooLong> {
    let keeps = |b: &Arrangement| {
        b.mech.comfortable && b.mech.mu_l <= a.mech.mu_l && b.vsizing.mu == a.vsizing.mu && b.asizing.mu == a.asizing.mu
    };
    // A wider column leaves the plans less room, so the widths that keep them run from
    // `w` up to some limit: found by bisection on whole mm.
    // The widest's arrangement is kept from the search: drawn first below.
    let (mut lo, mut hi, mut widest) = (w, FORCES_WIDTHS[0], None);
    while hi - lo > 1.0 {
        let mid = ((lo + hi) / 2.0).floor();
        let b = arrange(mid)?;
        if keeps(&b) {
            (lo, widest) = (mid, Some(b));
        } else {
            hi = mid;
        }
    }
    let mut best: Option<Composed> = None;
    for i in 0..DRAWN {
        let width = lo - STEP * i as f64;
        if width <= w {
            break;
        }
        let b = match widest.take() {
            Some(b) => b,
            None => arrange(width)?,
        };
        if !keeps(&b) {
            continue;
        }
        let drawn = draw(b)?;
        if drawn.layout.is_clean() && best.as_ref().is_none_or(|c| empty(&drawn) < empty(c)) {
            best = Some(drawn);
        }
    }
    match best {
        Some(c) => Ok(c),
        None => draw(a),
    }
}
