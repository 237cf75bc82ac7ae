//! The segments a student measures on the force drawings: each side of a force polygon
//! (|F| / μ_P), each force's arm about the pole on the Zhukovsky lever (h, in the lever's
//! velocity scale: the arm times F is the force's power), and on a load diagram the
//! analysed position's force and S/H.
//!
//! Names are the same in every language (the sheet's subscripts are not): `G_2`, `P_i2`
//! (inertia), `P_c5` / `P_g5` (resistance, gas), `P_m` (balancing), `R_12` (link 1 on link 2,
//! 0 the frame), `Rn_12` / `Rt_12` (its components along and across the link), `h_G_2` (an
//! arm on the lever) — as the note's answer keys spell them.

use super::ForcesInput;
use super::inset::Inset;
use crate::lever::kinetostatics::{FRAME, Kind, Part, Polygon};
use crate::num::math::Norm;
use crate::num::tol;
use crate::report::lever::load_kind;
use crate::report::{AnswerKeys, Segment};
use kurbo::Vec2;

/// A force's name, and the note's answer key of its magnitude when the tables have one.
fn force_name(inp: &ForcesInput, kind: Kind, on: usize) -> (String, Option<String>) {
    let n = |l: usize| if l == FRAME { 0 } else { inp.m.links[l].number };
    match kind {
        Kind::Weight => (format!("G_{}", n(on)), Some(format!("inertia.G.{}", n(on)))),
        Kind::Inertia => (format!("P_i{}", n(on)), Some(format!("inertia.P_i.{}", n(on)))),
        Kind::Load(i) => {
            let name = format!("P_{}{}", load_kind(inp.fa.model.loads[i].kind).key(), n(on));
            (name.clone(), Some(format!("balancing.{name}")))
        }
        Kind::Reaction { from, part } => {
            let pair = format!("{}{}", n(from), n(on));
            match part {
                // The note lists each pair once, in the direction it met first.
                Part::Whole => (format!("R_{pair}"), Some(format!("reactions.R_{pair}.abs"))),
                Part::Normal => (format!("Rn_{pair}"), None),
                Part::Tangential => (format!("Rt_{pair}"), None),
            }
        }
        Kind::Balancing => ("P_m".into(), Some("balancing.P_m".into())),
    }
}

/// The same reaction from the other side: R_21 for R_12 (the note has one of the two).
fn reversed(key: &str) -> Option<String> {
    let pair = key.strip_prefix("reactions.R_")?.strip_suffix(".abs")?;
    let (a, b) = pair.split_at(pair.len() / 2);
    Some(format!("reactions.R_{b}{a}.abs"))
}

/// A segment under `part` named for its force, tied to the force's answer.
fn force_segment(part: &str, (name, key): (String, Option<String>), f: f64, mu: f64, answers: &AnswerKeys) -> Segment {
    let s = Segment::new(format!("{part}.{name}"), name, f, "N", mu);
    let Some(key) = key else { return s };
    // A two-digit pair (R_1011) cannot be split back; its own key is all it has.
    let other = reversed(&key).filter(|_| !answers.has(&answers.key(&key)));
    s.answering(other.as_deref().unwrap_or(&key), answers)
}

/// Each drawn side of a force polygon, the inner reaction included, at the μ_P of the
/// drawing that labels it: the polygon's, or its enlargement's for a side drawn again there
/// (R₀₅ of 885 N, 2.2 mm at 400 N/mm on the polygon, is measured 22 mm long at 40 N/mm).
pub(super) fn polygon(
    inp: &ForcesInput,
    (poly, mu_p, insets): (&Polygon, f64, &[Inset]),
    part: &str,
    answers: &AnswerKeys,
) -> Vec<Segment> {
    let mu_of = |k: usize| insets.iter().find(|i| i.terms.contains(&k)).map_or(mu_p, |i| i.mu);
    let terms = poly.terms.iter().enumerate().map(|(k, t)| (t, mu_of(k))).chain(poly.inner.iter().map(|t| (t, mu_p)));
    let out = terms
        .filter(|(t, mu)| t.force.norm() / mu >= tol::PAPER_INVISIBLE)
        .map(|(t, mu)| force_segment(part, force_name(inp, t.kind, t.on), t.force.norm(), mu, answers));
    unique(out.collect())
}

/// Each force's arm about the pole on the lever (velocity scale `mu`), and P′ₘ's.
pub(super) fn lever_arms(inp: &ForcesInput, mu: f64, part: &str) -> Vec<Segment> {
    let f = &inp.fa.forces;
    let arm = |at: Vec2, dir: Vec2| if dir.norm() > 0.0 { at.cross(dir).abs() / dir.norm() } else { 0.0 };
    let mut out: Vec<Segment> = Vec::new();
    for l in f.lever.iter().filter(|l| l.force.norm() > 0.0) {
        let (name, _) =
            if l.couple { (format!("P_M{}", inp.m.links[l.on].number), None) } else { force_name(inp, l.kind, l.on) };
        out.push(Segment::new(format!("{part}.h_{name}"), format!("h_{name}"), arm(l.image, l.force), "m/s", mu));
    }
    let a_img = super::zhukovsky::balancing_image(inp);
    out.push(Segment::new(format!("{part}.h_P_m"), "h_P_m", arm(a_img, f.dir_m), "m/s", mu));
    unique(out)
}

/// The analysed position on load diagram `i`: its force at μ_P and its S/H on an axis
/// `width` mm long.
pub(super) fn load(
    inp: &ForcesInput,
    i: usize,
    (mu_p, width): (f64, f64),
    part: &str,
    answers: &AnswerKeys,
) -> Vec<Segment> {
    let load = &inp.fa.model.loads[i];
    let value = inp.fa.forces.loads[i];
    let n = inp.m.links[load.link].number;
    let along = value.along.abs();
    let force = force_segment(part, force_name(inp, Kind::Load(i), load.link), along, mu_p, answers);
    let s = Segment::new(format!("{part}.S_H_{n}"), format!("S/H_{n}"), value.s, "", 1.0 / width)
        .answering(&format!("balancing.S_H_{n}"), answers);
    vec![force, s]
}

/// A name met again in one drawing (the second force of a couple) gets a prime: `P_M2′`
/// (`P_M2p` in its id).
fn unique(mut segments: Vec<Segment>) -> Vec<Segment> {
    for k in 1..segments.len() {
        while segments[..k].iter().any(|s| s.name == segments[k].name) {
            segments[k].name.push('′');
            segments[k].id.push('p');
        }
    }
    segments
}
