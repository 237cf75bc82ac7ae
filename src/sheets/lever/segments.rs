//! The segments of a velocity or acceleration plan as the student measures them: `pb` (the
//! pole to an image: v_B), `ab` (v_BA), `πb` (a_B), `an_BA` and `n_BAb` (the normal and
//! tangential components of a_BA), each tied to its answer key when the note's tables have it.

use crate::lever::analysis::Position;
use crate::lever::linkage::Mechanism;
use crate::lever::plans::{Plan, SegKind};
use crate::num::math::Norm;
use crate::num::units::mm;
use crate::report::{AnswerKeys, Segment, ascii_key};

/// A plan's kind: its id letter, its pole's letter, the note's table and the quantity's
/// letter and unit.
pub struct PlanKind {
    pub symbol: &'static str,
    pub pole: &'static str,
    pub table: &'static str,
    pub unit: &'static str,
}

pub const VELOCITY: PlanKind = PlanKind { symbol: "v", pole: "p", table: "velocities", unit: "m/s" };
pub const ACCELERATION: PlanKind = PlanKind { symbol: "a", pole: "π", table: "accelerations", unit: "m/s²" };

/// Every vector of `plan` (drawn at `mu`, unit per mm) at position `label` as a segment,
/// tied to its answer key (`sheet1.velocities.v_B.3`) when the note has one.
pub fn plan_segments(plan: &Plan, kind: &PlanKind, label: &str, mu: f64, answers: &AnswerKeys) -> Vec<Segment> {
    let position = ascii_key(label);
    // (name as the course writes it, the answer table's row, magnitude)
    let mut drawn: Vec<(String, String, f64)> = Vec::new();
    for s in &plan.segs {
        let (x, y) = (s.of.0.as_str(), s.of.1.as_str());
        // A component from a point of the frame starts at the pole: πn_BC.
        let (lx, ly) = (x.to_lowercase(), if s.from_pole { kind.pole.to_string() } else { y.to_lowercase() });
        let (name, row) = match (s.kind, kind.symbol) {
            (SegKind::Absolute, q) => (format!("{}{lx}", kind.pole), format!("{q}_{x}")),
            (SegKind::Relative, q) => (format!("{ly}{lx}"), format!("{q}_{x}{y}")),
            (SegKind::Normal, _) => (format!("{ly}n_{x}{y}"), format!("an_{x}{y}")),
            (SegKind::Tangential, _) => (format!("n_{x}{y}{lx}"), format!("at_{x}{y}")),
            (SegKind::Coriolis, _) => (format!("{ly}k_{x}{y}"), format!("ak_{x}{y}")),
            (SegKind::Sliding, "v") => (format!("{ly}{lx}"), format!("v_{x}{y}")),
            (SegKind::Sliding, _) => (format!("k_{x}{y}{lx}"), format!("ar_{x}{y}")),
        };
        drawn.push((name, row, (s.to - s.from).norm()));
    }
    // A centre of mass is marked as a point (its image, by similarity), not drawn as a
    // vector, but the student measures its distance from the pole all the same: ps2, πs2.
    for img in plan.images.iter().filter(|i| i.label.starts_with('s') && i.label[1..].parse::<u32>().is_ok()) {
        let row = format!("{}_{}", kind.symbol, img.label.to_uppercase());
        drawn.push((format!("{}{}", kind.pole, img.label), row, img.at.norm()));
    }
    let mut out: Vec<Segment> = Vec::new();
    for (name, row, value) in drawn {
        let key = format!("{}.{}.{position}", kind.table, ascii_key(&row));
        let id = format!("plan.{}.{position}.{}", kind.symbol, ascii_key(&name));
        // A plan draws a vector once; a name met twice (never, by construction) keeps the first.
        if out.iter().any(|o| o.id == id) {
            continue;
        }
        out.push(Segment::new(id, name, value, kind.unit, mu).answering(&key, answers));
    }
    out
}

/// The links' lengths as the student sets them on the mechanism's drawing at μ_l (m/mm):
/// every pair of a link's joints whose distance is the same in every position (a kulisa's
/// sliding point is not), in mm; centres of mass left out (their places are given as
/// shares of a link).
pub fn link_segments(m: &Mechanism, positions: &[Position], mu_l: f64) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    let centre = |p: usize| m.mass_centres.iter().any(|&(_, c)| c == p);
    for link in m.links.iter().filter(|l| l.number > 0) {
        let joints: Vec<usize> = link.points.iter().copied().filter(|&p| !centre(p)).collect();
        for (i, &a) in joints.iter().enumerate() {
            for &b in &joints[i + 1..] {
                let at = |pos: &Position| (pos.state.points[a].p - pos.state.points[b].p).norm();
                let Some(first) = positions.first().map(at) else { continue };
                let rigid = positions.iter().all(|p| (at(p) - first).abs() <= 1e-9 * m.size);
                let name = format!("{}{}", m.point_names[a], m.point_names[b]);
                let id = format!("mechanism.l_{}", ascii_key(&name));
                if rigid && first > 0.0 && !out.iter().any(|o| o.id == id) {
                    out.push(Segment::new(id, format!("l_{name}"), mm(first), "mm", mm(mu_l)));
                }
            }
        }
    }
    out
}
