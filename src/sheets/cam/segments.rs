//! The segments a student draws or measures on sheet 3: each diagram's ordinate at each
//! numbered position (the displacement and its first analog as integrated by chords, the
//! second analog as the law gives it), r_min and a_w (or the offset e) on the nomogram, and
//! the pitch and working profiles' radii at the positions. Values in the note's units: mm
//! (or ° for a rocker's swing), the analogs in mm (none for a rocker).

use super::DIVISIONS;
use super::diagrams::Scales;
use crate::cams::Design;
use crate::cams::follower::Follower;
use crate::cams::integrate::Integrated;
use crate::num::units::mm;
use crate::report::cam::{analog, law_at, lift, polar_at};
use crate::report::{AnswerKeys, Segment};

/// The law tables' ids, a phase each, and their first position's number.
const PHASES: [(&str, usize); 2] = [("law-rise", 0), ("law-return", DIVISIONS + 1)];

/// The ordinates of the three diagrams (parts `diagram.s|v|a`) at the positions `phis`
/// (both phases, [`DIVISIONS`] + 1 each).
pub fn diagrams(
    d: &Design,
    sc: &Scales,
    integrated: &[Integrated; 2],
    phis: &[f64],
    answers: &AnswerKeys,
) -> Vec<Segment> {
    let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
    let dds_key = if rocker { "d2beta_dphi2" } else { "d2s_dphi2" };
    // The lift's and the analogs' scales in the tables' units per mm.
    let (unit_s, unit_v) = if rocker { ("°", "") } else { ("mm", "mm") };
    let (mu_s, mu_v, mu_a) = (lift(d, sc.mu_s), analog(d, sc.mu_ds), analog(d, sc.mu_dds));
    let mut out = Vec::new();
    for (phase, ((table, first), integ)) in PHASES.iter().zip(integrated).enumerate() {
        let positions = &phis[phase * (DIVISIONS + 1)..(phase + 1) * (DIVISIONS + 1)];
        for k in 0..positions.len() {
            let n = first + k;
            let y = |diagram: &str, value: f64, unit, mu| {
                Segment::new(format!("diagram.{diagram}.y{n}"), format!("y{n}"), value, unit, mu)
            };
            // The position's point of the integrated curves (a division may have several chords).
            let at = k * integ.chords;
            out.push(y("s", lift(d, integ.s[at]), unit_s, mu_s));
            out.push(y("v", analog(d, integ.ds[at]), unit_v, mu_v));
            let exact = analog(d, law_at(d, positions, k).dds);
            out.push(y("a", exact, unit_v, mu_a).answering(&format!("{table}.{dds_key}.{n}"), answers));
        }
    }
    out
}

/// r_min and the rocker's centre distance a_w (where the pivot is drawn: `pivot_drawn`) or
/// the translating follower's offset e on the nomogram drawn at `mu` (m/mm).
pub fn nomogram(d: &Design, (mu, pivot_drawn): (f64, bool), answers: &AnswerKeys) -> Vec<Segment> {
    let seg = |name: &str, value: f64| {
        Segment::new(format!("nomogram.{name}"), name, mm(value), "mm", mm(mu))
            .answering(&format!("results.{name}"), answers)
    };
    let mut out = vec![seg("r_min", d.centre.r_min)];
    out.extend(d.centre_distance().filter(|_| pivot_drawn).map(|a| seg("a_w", a)));
    out.extend(d.offset().filter(|e| e.abs() > 0.0).map(|e| seg("e", e.abs())));
    out
}

/// The pitch and working profiles' radii at the positions, on the profile drawn at `mu`.
pub fn profile(d: &Design, mu: f64, phis: &[f64], answers: &AnswerKeys) -> Vec<Segment> {
    let mut out = Vec::new();
    let kinds: &[(&str, bool)] = if d.roller > 0.0 { &[("pitch", false), ("work", true)] } else { &[("pitch", false)] };
    for (phase, (_, first)) in PHASES.iter().enumerate() {
        let table = ["profile-rise", "profile-return"][phase];
        let positions = &phis[phase * (DIVISIONS + 1)..(phase + 1) * (DIVISIONS + 1)];
        for (k, &phi) in positions.iter().enumerate() {
            let n = first + k;
            for &(kind, working) in kinds {
                let r = polar_at(d, phi, working).0;
                let name = format!("r_{kind}{n}");
                out.push(
                    Segment::new(format!("profile.r_{kind}.{n}"), name, mm(r), "mm", mm(mu))
                        .answering(&format!("{table}.r_{kind}.{n}"), answers),
                );
            }
        }
    }
    out
}
