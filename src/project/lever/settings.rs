//! The `analysis` section resolved into the lever's analysis [`Settings`]: 8 or 12
//! positions, position 0, φ1 and the positions that get acceleration plans.

use super::super::mechanism::*;
use super::super::{Refusal, at, invalid};
use crate::lever::{Settings, Start};
use crate::num::Sense;
use crate::num::digits::written;

pub(super) fn settings(a: &AnalysisSpec, sense: Sense) -> Result<Settings, Refusal> {
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
            v
        }
        None => (0..4).map(|i| 1 + i * n as usize / 4).collect(),
    };
    Ok(Settings {
        sense,
        start,
        positions: n as usize,
        assigned_deg: a.assigned_deg.as_ref().map(|d| d.value.0),
        acceleration_plans,
    })
}
