//! P_m two more ways, each independent of the polygons: the Zhukovsky lever (every active
//! force turned about its point's image on the velocity plan) and the power balance.

use super::{Applied, InertiaLoad, Kind, LeverForce, snap_value};
use crate::lever::linkage::{LinkId, Mechanism, PointId, State, Step};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::Vec2;

/// Forces that do work: everything but reactions and the balancing force.
fn is_active(a: &Applied) -> bool {
    matches!(a.kind, Kind::Weight | Kind::Inertia | Kind::Load(_))
}

pub(super) fn power_balance(s: &State, applied: &[Applied], inertia: &[InertiaLoad], v_a: Vec2) -> f64 {
    let forces: f64 = applied
        .iter()
        .filter(|a| is_active(a))
        .map(|a| a.force.dot(s.points[a.point.expect("active forces act at points")].v))
        .sum();
    let moments: f64 = inertia.iter().map(|i| i.moment * s.links[i.link].omega).sum();
    let p = -(forces + moments) / v_a.norm();
    // Zero where it is round-off of the powers it balances (see `zhukovsky`).
    let active = applied.iter().filter(|a| is_active(a));
    let largest = active
        .map(|a| a.force.norm() * s.points[a.point.expect("active forces act at points")].v.norm())
        .chain(inertia.iter().map(|i| (i.moment * s.links[i.link].omega).abs()))
        .fold(0.0, f64::max)
        / v_a.norm();
    snap_value(p, largest)
}

/// The Zhukovsky lever: every active force at its point's image on the velocity plan turned
/// 90° in the sense of ω1, inertia moments as couples; moments about the pole give P'_m.
pub(super) fn zhukovsky(
    m: &Mechanism,
    s: &State,
    applied: &[Applied],
    inertia: &[InertiaLoad],
    pin: PointId,
    v_a: Vec2,
) -> (Vec<LeverForce>, Vec<f64>, f64) {
    let sense = m.sense().sign();
    let turn = |v: Vec2| v.turn_90() * sense;
    let mut lever: Vec<LeverForce> = applied
        .iter()
        .filter(|a| is_active(a))
        .map(|a| LeverForce {
            kind: a.kind,
            on: a.on,
            image: turn(s.points[a.point.expect("active forces act at points")].v),
            force: a.force,
            couple: false,
        })
        .collect();
    for i in inertia.iter().filter(|i| i.moment != 0.0) {
        let ((p0, v0), (p1, v1)) = couple_points(m, s, i.link);
        let f = (p0 - p1).turn_90() * (i.moment / (p0 - p1).hypot2());
        lever.push(LeverForce { kind: Kind::Inertia, on: i.link, image: turn(v0), force: f, couple: true });
        lever.push(LeverForce { kind: Kind::Inertia, on: i.link, image: turn(v1), force: -f, couple: true });
    }
    let moments: Vec<f64> = lever.iter().map(|l| l.image.cross(l.force)).collect();
    let a_image = turn(s.points[pin].v);
    let arm = a_image.cross(v_a.unit());
    let p = -moments.iter().sum::<f64>() / arm;
    // As for P_m from the polygon: the round-off of a vanishing force is zero.
    // (Each moment may itself be round-off, a force along its image's line: compare with
    // what it would be across it.)
    let largest = lever.iter().map(|l| l.force.norm() * l.image.norm()).fold(0.0, f64::max) / arm.abs();
    let p = snap_value(p, largest);
    let mut all = moments;
    all.push(arm * p);
    (lever, all, p)
}

/// Two points (position, velocity) for `link`'s inertia couple: its first two distinct
/// points; for a kulisa's block (one joint), the kulisa's, which it turns with — a
/// couple's power is M·ω, so the lever takes the same moment, and the couple stands along
/// the kulisa's image (at the block's joint and a point a metre along it, its second arrow
/// stood 120 mm off the lever, alone); else its joint and the point along it as far as the
/// mechanism's nearest other point.
fn couple_points(m: &Mechanism, s: &State, link: LinkId) -> ((Vec2, Vec2), (Vec2, Vec2)) {
    let apart = |a: Vec2, b: Vec2| (a - b).norm() > tol::SAME_POINT * m.size;
    let two = |l: LinkId| {
        let pts = &m.links[l].points;
        let k0 = s.points[pts[0]];
        pts.iter().skip(1).map(|&q| s.points[q]).find(|k1| apart(k1.p, k0.p)).map(|k1| ((k0.p, k0.v), (k1.p, k1.v)))
    };
    if let Some(found) = two(link).or_else(|| kulisa_of(m, link).and_then(two)) {
        return found;
    }
    let k0 = s.points[m.links[link].points[0]];
    let nearest =
        s.points.iter().filter(|q| apart(q.p, k0.p)).map(|q| (q.p - k0.p).norm()).fold(f64::INFINITY, f64::min);
    let d = if nearest.is_finite() { nearest } else { m.size };
    let lk = s.links[link];
    ((k0.p, k0.v), (k0.p + lk.dir * d, k0.v + lk.dir.turn_90() * (lk.omega * d)))
}

/// The kulisa a block slides on (the other link of its RPR group).
fn kulisa_of(m: &Mechanism, block: LinkId) -> Option<LinkId> {
    m.steps.iter().find_map(|step| match *step {
        Step::Rpr { links, .. } if links.contains(&block) => links.into_iter().find(|&l| l != block),
        _ => None,
    })
}
