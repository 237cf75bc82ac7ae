//! Warnings about the mechanism's input that builds but is almost surely a mistake: lengths
//! that look like millimetres or are vanishingly small, and absurd crank speeds.

use super::super::mechanism::*;
use super::super::{Warning, at, warning};
use crate::num::digits::{sig, written};
use crate::num::limits;
use crate::num::math::Norm;
use crate::num::units::mm;
use kurbo::Vec2;
use serde_saphyr::Location;

/// Lengths that look like millimetres or are vanishingly small, and absurd speeds.
pub(super) fn plausibility(spec: &MechanismSpec, warnings: &mut Vec<Warning>) {
    let mut length = |loc: Location, field: &str, x: f64| {
        if x > limits::LENGTH_LOOKS_LIKE_MM {
            warnings.push(warning(
                loc,
                field,
                format!(
                    "{} m is longer than {} m: lengths are in metres; is it millimetres?",
                    written(x),
                    written(limits::LENGTH_LOOKS_LIKE_MM)
                ),
            ));
        } else if x > 0.0 && x < limits::LENGTH_TINY {
            warnings.push(warning(
                loc,
                field,
                format!(
                    "{} m is shorter than {} mm: lengths are in metres",
                    written(x),
                    written(mm(limits::LENGTH_TINY))
                ),
            ));
        }
    };
    length(at(&spec.crank.length), "mechanism.crank.length", spec.crank.length.value.0);
    for (i, g) in spec.groups.iter().enumerate() {
        let field = format!("mechanism.groups[{i}]");
        match &g.value {
            GroupSpec::Rrr(r) => r.lengths.iter().for_each(|l| length(at(g), &format!("{field}.rrr.lengths"), l.0)),
            GroupSpec::Rrp(r) => length(at(g), &format!("{field}.rrp.length"), r.length.0),
            GroupSpec::Rpr(r) => r.length.iter().for_each(|l| length(at(g), &format!("{field}.rpr.length"), l.0)),
        }
    }
    for f in &spec.frame {
        let r = Vec2::new(f.at[0].0, f.at[1].0).norm();
        if r > limits::LENGTH_LOOKS_LIKE_MM {
            warnings.push(warning(
                at(&f.name),
                "mechanism.frame.at",
                format!(
                    "point {} lies {} m from the origin: coordinates are in metres; is it millimetres?",
                    f.name.value,
                    sig(r, 4)
                ),
            ));
        }
    }
    if let Some(n) = &spec.crank.rpm
        && n.value.0 > limits::RPM_PLAUSIBLE_MAX
    {
        warnings.push(warning(
            at(n),
            "mechanism.crank.rpm",
            format!(
                "{} rev/min is above {}: is the crank speed in rev/min?",
                written(n.value.0),
                written(limits::RPM_PLAUSIBLE_MAX)
            ),
        ));
    }
    if let Some(w) = &spec.crank.omega
        && w.value.0 * 30.0 / std::f64::consts::PI > limits::RPM_PLAUSIBLE_MAX
    {
        warnings.push(warning(
            at(w),
            "mechanism.crank.omega",
            format!(
                "ω1 = {} 1/s is above {} rev/min: is ω1 in 1/s (rad/s)?",
                written(w.value.0),
                written(limits::RPM_PLAUSIBLE_MAX)
            ),
        ));
    }
}
