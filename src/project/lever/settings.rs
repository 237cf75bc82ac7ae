//! The `analysis` section resolved into the lever's analysis [`Settings`]: 8 or 12
//! positions, position 0, φ1 and the positions that get acceleration plans.

use super::super::mechanism::*;
use super::super::{Refusal, Warning, at, invalid, warning};
use crate::lever::{Settings, Start};
use crate::num::Sense;
use crate::num::digits::written;
use crate::num::tol;

/// Warns (into `warnings`) where a force analysis (`forces`) is done at a regular position
/// that the given `acceleration_plans` leave without a plan.
pub(super) fn settings(
    a: &AnalysisSpec,
    sense: Sense,
    forces: bool,
    warnings: &mut Vec<Warning>,
) -> Result<Settings, Refusal> {
    let n = a.positions.value;
    if n != 8 && n != 12 {
        return Err(invalid(
            at(&a.positions),
            "analysis.positions",
            format!("the course draws 8 or 12 crank positions, not {n}"),
        ));
    }
    let start = match a.start_deg {
        Some(d) => Start::Angle(d.0.to_radians()),
        None if a.start == StartExtreme::Max => Start::Max,
        None => Start::Min,
    };
    if let Some(d) = a.assigned_deg.as_ref().filter(|d| !(0.0..360.0).contains(&d.value.0)) {
        return Err(invalid(
            at(d),
            "analysis.assigned_deg",
            format!("φ1 must lie in 0…360°, got {}°", written(d.value.0)),
        ));
    }
    let on_grid = assigned_position(a, n as usize);
    if let Some(d) = a.assigned_deg.as_ref().filter(|_| forces && on_grid.is_none()) {
        let step = 360 / n;
        warnings.push(warning(
            at(d),
            "analysis.assigned_deg",
            format!(
                "φ1 = {}° is none of the {n} positions (every {step}°): the force analysis there gets no \
                 acceleration plan to read its inertia forces off; the course takes φ1 at a multiple of {step}°",
                written(d.value.0)
            ),
        ));
    }
    let acceleration_plans = match &a.acceleration_plans {
        Some(list) => {
            if list.value.is_empty() || list.value.len() > 6 {
                return Err(invalid(
                    at(list),
                    "analysis.acceleration_plans",
                    "give 1 to 6 positions (the course asks for 4–6)",
                ));
            }
            let mut v = vec![];
            for &k in &list.value {
                if k as usize >= n as usize {
                    return Err(invalid(
                        at(list),
                        "analysis.acceleration_plans",
                        format!("position {k} does not exist: positions are 0…{}", n - 1),
                    ));
                }
                if v.contains(&(k as usize)) {
                    return Err(invalid(
                        at(list),
                        "analysis.acceleration_plans",
                        format!("position {k} is listed twice"),
                    ));
                }
                v.push(k as usize);
            }
            match on_grid {
                Some(k) if forces && !v.contains(&k) => warnings.push(warning(
                    at(list),
                    "analysis.acceleration_plans",
                    format!(
                        "the force analysis is done at φ1's position {k}, which gets no acceleration plan: \
                         the inertia forces are read off that plan; add {k} to the list"
                    ),
                )),
                _ => {}
            }
            v
        }
        // Four plans about a quarter turn apart, 1, n/4 + 1, …, the one nearest φ1's position
        // moved onto it where φ1 is a regular position: the force analysis reads its inertia
        // forces off that plan.
        None => {
            let n = n as usize;
            let mut plans: Vec<usize> = (0..4).map(|i| 1 + i * n / 4).collect();
            if let Some(k) = on_grid.filter(|k| !plans.contains(k)) {
                let apart = |p: usize| p.abs_diff(k).min(n - p.abs_diff(k));
                let nearest = (0..4).min_by_key(|&i| apart(plans[i])).expect("four plans");
                plans[nearest] = k;
                plans.sort_unstable();
            }
            plans
        }
    };
    Ok(Settings {
        sense,
        start,
        positions: n as usize,
        assigned_deg: a.assigned_deg.as_ref().map(|d| d.value.0),
        acceleration_plans,
    })
}

/// The regular position φ1 falls on, if it falls on one: within the tolerance by which the
/// analysis takes φ1 for a drawn position ([`tol::SAME_ANGLE`]).
fn assigned_position(a: &AnalysisSpec, n: usize) -> Option<usize> {
    let phi = a.assigned_deg.as_ref()?.value.0.to_radians();
    let step = std::f64::consts::TAU / n as f64;
    let k = (phi / step).round();
    ((phi - k * step).abs() < tol::SAME_ANGLE && (k as usize) < n).then_some(k as usize)
}
