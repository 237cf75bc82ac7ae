//! Sheet 3's tables for the note: the law at the numbered positions (one table a phase), the
//! profiles' polar coordinates (mm and degrees, as the drawing is measured) and the results.

use super::{NumTable, Row, row};
use crate::cams::Design;
use crate::cams::follower::Follower;

const MM: f64 = 1e3;

/// The lift's unit as the tables write it: mm for a translating follower (as its drawing is
/// measured), ° for a rocker.
fn lift(d: &Design, x: f64) -> f64 {
    match d.spec.follower {
        Follower::Translating => x * MM,
        Follower::Rocker { .. } => x.to_degrees(),
    }
}

/// The analogs' unit: mm for a translating follower, none for a rocker (radians per radian).
fn analog(d: &Design, x: f64) -> f64 {
    match d.spec.follower {
        Follower::Translating => x * MM,
        Follower::Rocker { .. } => x,
    }
}

/// The law and the pressure angle at positions `first..` (cam angles `phis`), as one table.
pub fn law(d: &Design, name: &str, first: usize, phis: &[f64]) -> NumTable {
    let p = &d.spec.program;
    let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
    // Each position from inside its phase: at the ends `at` belongs to the dwell, and where the
    // acceleration jumps the table gives the phase's own value.
    let at = |phi: f64, k: usize| {
        p.at(if k + 1 == phis.len() {
            phi - 1e-12
        } else if k == 0 {
            phi + 1e-12
        } else {
            phi
        })
    };
    let col = |f: &dyn Fn(f64, usize) -> f64| phis.iter().enumerate().map(|(k, &phi)| f(phi, k)).collect::<Vec<_>>();
    let (s, v, a) = if rocker { ("β", "dβ/dφ", "d²β/dφ²") } else { ("s", "ds/dφ", "d²s/dφ²") };
    let (us, uv) = if rocker { ("°", "") } else { ("mm", "mm") };
    NumTable {
        name: name.into(),
        columns: (first..first + phis.len()).map(|k| k.to_string()).collect(),
        rows: vec![
            row("φ", "", "°", col(&|phi, _| phi.to_degrees())),
            row(s, "", us, col(&|phi, k| lift(d, at(phi, k).s))),
            row(v, "", uv, col(&|phi, k| analog(d, at(phi, k).ds))),
            row(a, "", uv, col(&|phi, k| analog(d, at(phi, k).dds))),
            row("α", "", "°", col(&|phi, _| d.profile.pressure_angle_on_profile(phi).to_degrees())),
        ],
    }
}

/// The pitch and working profiles' polar coordinates at the positions (r in mm, θ in
/// degrees from the start of the rise's radius, turning against the cam).
pub fn profile(d: &Design, name: &str, first: usize, phis: &[f64]) -> NumTable {
    let pr = &d.profile;
    let polar = |phi: f64, working: bool| {
        let p = if working { pr.working(d.roller, phi).0 } else { pr.pitch(phi).p };
        pr.polar(p)
    };
    let col = |f: &dyn Fn(f64) -> f64| phis.iter().map(|&phi| f(phi)).collect::<Vec<_>>();
    let mut rows = vec![
        row("φ", "", "°", col(&|phi| phi.to_degrees())),
        row("r", "pitch", "mm", col(&|phi| polar(phi, false).0 * MM)),
        row("θ", "pitch", "°", col(&|phi| polar(phi, false).1.to_degrees())),
    ];
    if d.roller > 0.0 {
        rows.push(row("r", "work", "mm", col(&|phi| polar(phi, true).0 * MM)));
        rows.push(row("θ", "work", "°", col(&|phi| polar(phi, true).1.to_degrees())));
    }
    NumTable { name: name.into(), columns: (first..first + phis.len()).map(|k| k.to_string()).collect(), rows }
}

/// The results: r_min, the offset, or the rocker's length and swing with the centre distance
/// and start angle; the roller (none for a knife edge), ρ_min, each phase's allowed and
/// largest pressure angle, and the drawing's integration errors (percent).
pub fn results(d: &Design, errors: (f64, f64)) -> NumTable {
    let one = |x: f64| vec![x];
    let mut rows: Vec<Row> = vec![row("r", "min", "mm", one(d.centre.r_min * MM))];
    if let Some(e) = d.offset() {
        rows.push(row("e", "", "mm", one(e * MM)));
    }
    if let Follower::Rocker { length } = d.spec.follower {
        rows.push(row("l", "", "mm", one(length * MM)));
        rows.push(row("β", "max", "°", one(d.spec.program.lift.to_degrees())));
    }
    if let (Some(a), Some(psi)) = (d.centre_distance(), d.rocker_start()) {
        rows.push(row("a", "w", "mm", one(a * MM)));
        rows.push(row("ψ", "0", "°", one(psi.to_degrees())));
    }
    if d.roller > 0.0 {
        rows.push(row("r", "roller", "mm", one(d.roller * MM)));
    }
    rows.push(row("ρ", "min", "mm", one(d.rho_min * MM)));
    rows.push(row("α", "allowed_rise", "°", one(d.spec.allowed.rise.to_degrees())));
    rows.push(row("α", "max_rise", "°", one(d.max_pressure[0].0.to_degrees())));
    rows.push(row("α", "allowed_return", "°", one(d.spec.allowed.ret.to_degrees())));
    rows.push(row("α", "max_return", "°", one(d.max_pressure[1].0.to_degrees())));
    let (s, v) = match d.spec.follower {
        Follower::Translating => ("δs", "δ(ds/dφ)"),
        Follower::Rocker { .. } => ("δβ", "δ(dβ/dφ)"),
    };
    rows.push(row(s, "", "%", one(errors.0)));
    rows.push(row(v, "", "%", one(errors.1)));
    NumTable { name: "results".into(), columns: vec!["".into()], rows }
}
