//! Sheet 3's tables for the note: the law at the numbered positions (one table a phase), the
//! profiles' polar coordinates (mm and degrees, as the drawing is measured) and the results.

use super::{Column, NumTable, Row, Sub, SubWord, Unit, share_decimals, share_exact_decimals};
use crate::cams::Design;
use crate::cams::follower::Follower;
use crate::cams::laws::Derivs;
use crate::num::tol;
use crate::num::units::mm;
use std::f64::consts::{PI, TAU};

/// The lift's unit as the tables write it: mm for a translating follower (as its drawing is
/// measured), ° for a rocker.
pub fn lift(d: &Design, x: f64) -> f64 {
    match d.spec.follower {
        Follower::Translating => mm(x),
        Follower::Rocker { .. } => x.to_degrees(),
    }
}

/// The analogs' unit: mm for a translating follower, none for a rocker (radians per radian).
pub fn analog(d: &Design, x: f64) -> f64 {
    match d.spec.follower {
        Follower::Translating => mm(x),
        Follower::Rocker { .. } => x,
    }
}

fn plain(symbol: &'static str, unit: Unit, values: Vec<f64>) -> Row {
    Row::new(symbol, Sub::None, unit, values)
}

/// Columns headed by the positions `first..first + n`.
fn positions(first: usize, n: usize) -> Vec<Column> {
    (first..first + n).map(|k| Column::labelled(&k.to_string())).collect()
}

/// The cam angle at which a phase's table reads its law at position `k` of the phase's
/// positions `phis`, from inside the phase: at the ends the program's `at` belongs to the
/// dwell, and where the acceleration jumps the table (and the drawing's ordinate) gives the
/// phase's own value.
fn inside(phis: &[f64], k: usize) -> f64 {
    let phi = phis[k];
    if k + 1 == phis.len() {
        phi - tol::INSIDE_PHASE
    } else if k == 0 {
        phi + tol::INSIDE_PHASE
    } else {
        phi
    }
}

/// The law at position `k` of a phase's positions `phis`, from inside the phase: at the
/// ends the phase's own value, not the dwell's.
pub fn law_at(d: &Design, phis: &[f64], k: usize) -> Derivs {
    d.spec.program.at(inside(phis, k))
}

/// A row of `f` at the positions `phis`, with the value after each inner position where
/// `f` jumps there (see [`Row::jumps`]): the cell then holds the value just before.
fn jumping_row(symbol: &'static str, unit: Unit, phis: &[f64], f: &dyn Fn(f64) -> f64) -> Row {
    let inner = |k: usize| k > 0 && k + 1 < phis.len();
    let sides = |k: usize| (f(phis[k] - tol::INSIDE_PHASE), f(phis[k] + tol::INSIDE_PHASE));
    let at: Vec<f64> = (0..phis.len()).map(|k| f(inside(phis, k))).collect();
    let largest = at.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    let jumps: Vec<Option<(f64, f64)>> = (0..phis.len())
        .map(|k| inner(k).then(|| sides(k)).filter(|(a, b)| (b - a).abs() > tol::JUMP_RELATIVE * largest.max(a.abs())))
        .collect();
    let values = at.iter().zip(&jumps).map(|(&v, j)| j.map_or(v, |(before, _)| before)).collect();
    plain(symbol, unit, values).jumping(jumps.iter().map(|j| j.map(|(_, after)| after)).collect())
}

/// The law and the pressure angle at positions `first..` (cam angles `phis`), as one table.
/// Where the analogs (or with them the pressure angle) jump at a position, its cell holds
/// the values before and after.
pub fn law(d: &Design, id: &'static str, first: usize, phis: &[f64]) -> NumTable {
    let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
    let at = |phi: f64| d.spec.program.at(phi);
    let (s, v, a) = if rocker { ("β", "dβ/dφ", "d²β/dφ²") } else { ("s", "ds/dφ", "d²s/dφ²") };
    let (us, uv) = if rocker { (Unit::Deg, Unit::None) } else { (Unit::Mm, Unit::Mm) };
    let phi_deg = phis.iter().map(|phi| phi.to_degrees()).collect();
    let lifts = (0..phis.len()).map(|k| lift(d, law_at(d, phis, k).s)).collect();
    NumTable {
        id,
        columns: positions(first, phis.len()),
        rows: vec![
            plain("φ", Unit::Deg, phi_deg).exactly(),
            plain(s, us, lifts),
            jumping_row(v, uv, phis, &|phi| analog(d, at(phi).ds)),
            jumping_row(a, uv, phis, &|phi| analog(d, at(phi).dds)),
            jumping_row("α", Unit::Deg, phis, &|phi| d.profile.pressure_angle_on_profile(phi).to_degrees()),
        ],
    }
}

/// The rise's and the return's twin tables (the law's, or the profiles') with one
/// quantity's rows at one precision across both (GOST 2.105): a row of one and its twin
/// in the other (the cam angle φ, the lift, …) share their decimals, and so do the pitch
/// and the working profile's radii (at least 0,01 mm, as the results write r_min) and
/// their angles.
pub fn share_twin_decimals(rise: &mut NumTable, ret: &mut NumTable) {
    let keys: Vec<String> = rise.rows.iter().map(|r| r.key.clone()).collect();
    let both = |rise: &mut NumTable, ret: &mut NumTable, keep: &dyn Fn(&str) -> bool, at_least: usize| {
        let rows = rise.rows.iter_mut().chain(ret.rows.iter_mut()).filter(|r| keep(&r.key));
        let (exact, computed): (Vec<&mut Row>, Vec<&mut Row>) = rows.partition(|r| r.exact);
        share_exact_decimals(exact);
        share_decimals(computed, at_least);
    };
    let radius = |k: &str| k.starts_with("r_");
    let angle = |k: &str| k.starts_with("theta_");
    both(rise, ret, &radius, 2);
    both(rise, ret, &angle, 2);
    for key in keys.iter().filter(|k| !radius(k) && !angle(k)) {
        both(rise, ret, &|k: &str| k == key, 0);
    }
}

/// The pitch (or working) profile's point at cam angle `phi` in polar coordinates (r, θ):
/// metres, radians from the start of the rise's radius, turning against the cam.
pub fn polar_at(d: &Design, phi: f64, working: bool) -> (f64, f64) {
    let pr = &d.profile;
    pr.polar(if working { pr.working(d.roller, phi).0 } else { pr.pitch(phi).p })
}

/// The pitch and working profiles' polar coordinates at the positions (r in mm, θ in
/// degrees from the start of the rise's radius, turning against the cam).
pub fn profile(d: &Design, id: &'static str, first: usize, phis: &[f64]) -> NumTable {
    let polar = |phi: f64, working: bool| polar_at(d, phi, working);
    let col = |f: &dyn Fn(f64) -> f64| phis.iter().map(|&phi| f(phi)).collect::<Vec<_>>();
    // θ counted on from φ, the turn it is nearest: the working profile's point at the rise's
    // start lies a hair behind its radius, and a table that read 360,00 there (task 11
    // variant 30) beside 16,04 at the next position reads 0,00 now.
    let theta = |phi: f64, working: bool| (phi + (polar(phi, working).1 - phi + PI).rem_euclid(TAU) - PI).to_degrees();
    let (pitch, work) = (|| Sub::Word(SubWord::Pitch), || Sub::Word(SubWord::Work));
    let mut rows = vec![
        plain("φ", Unit::Deg, col(&|phi| phi.to_degrees())).exactly(),
        Row::new("r", pitch(), Unit::Mm, col(&|phi| mm(polar(phi, false).0))),
        Row::new("θ", pitch(), Unit::Deg, col(&|phi| theta(phi, false))),
    ];
    if d.roller > 0.0 {
        rows.push(Row::new("r", work(), Unit::Mm, col(&|phi| mm(polar(phi, true).0))));
        rows.push(Row::new("θ", work(), Unit::Deg, col(&|phi| theta(phi, true))));
    }
    NumTable { id, columns: positions(first, phis.len()), rows }
}

/// The results: r_min, the offset, or the rocker's length and swing with the centre distance
/// and start angle; the roller (none for a knife edge), ρ_min, each phase's allowed and
/// largest pressure angle, and the drawing's integration errors (percent).
pub fn results(d: &Design, errors: (f64, f64)) -> NumTable {
    let one = |x: f64| vec![x];
    let name = |symbol: &'static str, sub: &str, unit: Unit, x: f64| Row::new(symbol, Sub::name(sub), unit, one(x));
    let word = |symbol: &'static str, w: SubWord, unit: Unit, x: f64| Row::new(symbol, Sub::Word(w), unit, one(x));
    let mut rows: Vec<Row> = vec![name("r", "min", Unit::Mm, mm(d.centre.r_min))];
    if let Some(e) = d.offset() {
        // The given values as given (e = 10, r_rol = 14, not 10,00 and 14,00); a computed
        // one exact to three decimals too, else with four significant digits.
        rows.push(plain("e", Unit::Mm, one(mm(e))).exactly());
    }
    if let Follower::Rocker { length } = d.spec.follower {
        rows.push(plain("l", Unit::Mm, one(mm(length))).exactly());
        rows.push(name("β", "max", Unit::Deg, d.spec.program.lift.to_degrees()).exactly());
    }
    if let (Some(a), Some(psi)) = (d.centre_distance(), d.rocker_start()) {
        rows.push(name("a", "w", Unit::Mm, mm(a)));
        rows.push(name("ψ", "0", Unit::Deg, psi.to_degrees()));
    }
    if d.roller > 0.0 {
        rows.push(word("r", SubWord::Roller, Unit::Mm, mm(d.roller)).exactly());
    }
    rows.push(name("ρ", "min", Unit::Mm, mm(d.rho_min)));
    rows.push(word("α", SubWord::AllowedRise, Unit::Deg, d.spec.allowed.rise.to_degrees()).exactly());
    rows.push(word("α", SubWord::MaxRise, Unit::Deg, d.max_pressure[0].0.to_degrees()));
    rows.push(word("α", SubWord::AllowedReturn, Unit::Deg, d.spec.allowed.ret.to_degrees()).exactly());
    rows.push(word("α", SubWord::MaxReturn, Unit::Deg, d.max_pressure[1].0.to_degrees()));
    let (s, v) = match d.spec.follower {
        Follower::Translating => ("δs", "δ(ds/dφ)"),
        Follower::Rocker { .. } => ("δβ", "δ(dβ/dφ)"),
    };
    rows.push(plain(s, Unit::Percent, one(errors.0)).keyed("error_s"));
    rows.push(plain(v, Unit::Percent, one(errors.1)).keyed("error_ds"));
    NumTable::single("results", rows)
}
