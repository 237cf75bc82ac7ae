//! Sheet 1's section of `results.json`: every quantity computed for it, in SI units (m,
//! m/s, m/s², rad, rad/s, rad/s²); angles of positions also in degrees. Documented in the
//! README.

use super::compose::{Composed, Scales};
use super::forces_view::ForceScales;
use crate::lever::Mechanism;
use crate::lever::analysis::{ForceAnalysis, Kinematics, Position};
use crate::lever::plans::{RelationValues, relation_values};
use crate::num::Sense;
use crate::report::lever::reactions;
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Serialize)]
struct PointOut {
    p: [f64; 2],
    v: [f64; 2],
    a: [f64; 2],
}

#[derive(Serialize)]
struct LinkOut {
    angle: f64,
    omega: f64,
    epsilon: f64,
}

#[derive(Serialize)]
struct PositionOut {
    label: String,
    phi_deg: f64,
    crank_angle_deg: f64,
    extreme: bool,
    points: BTreeMap<String, PointOut>,
    links: BTreeMap<String, LinkOut>,
    relative: Vec<RelationValues>,
}

#[derive(Serialize)]
struct Sheet1Out<'a> {
    omega1: f64,
    crank_sense: Sense,
    position0_crank_angle_deg: f64,
    other_extreme_phi_deg: Option<f64>,
    structure: &'a crate::lever::structure::Structure,
    scales: &'a Scales,
    positions: Vec<PositionOut>,
    assigned: PositionOut,
    acceleration_plan_positions: Vec<String>,
    trajectories: BTreeMap<String, Vec<[f64; 2]>>,
    /// How far the drawn trajectories (cubic pieces) stray from the exact paths, paper mm.
    trajectory_fit_error_mm: f64,
    /// The sheet's measurement of its own layout.
    layout: &'a crate::drawing::layout::Layout,
    #[serde(skip_serializing_if = "Option::is_none")]
    forces: Option<ForcesOut>,
}

#[derive(Serialize)]
struct InertiaOut {
    mass: f64,
    j_s: f64,
    a_s: [f64; 2],
    epsilon: f64,
    inertia_force: [f64; 2],
    inertia_moment: f64,
    weight: f64,
}

#[derive(Serialize)]
struct LoadOut {
    link: u32,
    point: String,
    stroke_fraction: f64,
    stroke: f64,
    moving_along_axis: bool,
    force: [f64; 2],
}

#[derive(Serialize)]
struct ForcesOut {
    phi_deg: f64,
    inertia: BTreeMap<String, InertiaOut>,
    loads: Vec<LoadOut>,
    reactions: BTreeMap<String, [f64; 2]>,
    balancing_force: f64,
    balancing_direction: [f64; 2],
    balancing_moment: f64,
    balancing_force_lever: f64,
    balancing_force_power: f64,
    difference_percent: f64,
    scales: ForceScales,
}

fn v2(v: kurbo::Vec2) -> [f64; 2] {
    [v.x, v.y]
}

fn position_out(m: &Mechanism, k: &Kinematics, p: &Position) -> PositionOut {
    let points = m.point_names.iter().enumerate().map(|(i, n)| {
        let q = p.state.points[i];
        (n.clone(), PointOut { p: v2(q.p), v: v2(q.v), a: v2(q.a) })
    });
    let links = m.links.iter().enumerate().map(|(i, l)| {
        let s = p.state.links[i];
        (l.number.to_string(), LinkOut { angle: s.angle(), omega: s.omega, epsilon: s.eps })
    });
    PositionOut {
        label: p.label.clone(),
        phi_deg: p.phi.to_degrees(),
        crank_angle_deg: k.motion.theta(p.phi).to_degrees().rem_euclid(360.0),
        extreme: p.extreme,
        points: points.collect(),
        links: links.collect(),
        relative: relation_values(m, &p.state),
    }
}

fn forces_out(m: &Mechanism, k: &Kinematics, fa: &ForceAnalysis, scales: &ForceScales) -> ForcesOut {
    let f = &fa.forces;
    let inertia = f
        .inertia
        .iter()
        .map(|i| {
            let out = InertiaOut {
                mass: i.mass,
                j_s: i.j,
                a_s: v2(i.a_s),
                epsilon: i.eps,
                inertia_force: v2(i.force),
                inertia_moment: i.moment,
                weight: i.weight,
            };
            (m.links[i.link].number.to_string(), out)
        })
        .collect();
    let loads = fa
        .model
        .loads
        .iter()
        .zip(&f.loads)
        .map(|(l, v)| LoadOut {
            link: m.links[l.link].number,
            point: m.name(l.point).into(),
            stroke_fraction: v.s,
            stroke: l.stroke,
            moving_along_axis: v.branch == 0,
            force: v2(v.force),
        })
        .collect();
    ForcesOut {
        phi_deg: k.assigned.phi.to_degrees(),
        inertia,
        loads,
        reactions: reactions(m, f).into_iter().map(|(name, r)| (format!("R{name}"), v2(r))).collect(),
        balancing_force: f.p_m,
        balancing_direction: v2(f.dir_m),
        balancing_moment: f.m_m,
        balancing_force_lever: f.p_m_lever,
        balancing_force_power: f.p_m_power,
        difference_percent: f.difference_percent(),
        scales: scales.clone(),
    }
}

pub fn section(
    m: &Mechanism,
    k: &Kinematics,
    composed: &Composed,
    forces: Option<&ForceAnalysis>,
) -> serde_json::Value {
    let out = Sheet1Out {
        omega1: m.omega1,
        crank_sense: k.motion.sense,
        position0_crank_angle_deg: k.motion.theta0.to_degrees().rem_euclid(360.0),
        other_extreme_phi_deg: k.motion.other_extreme.map(f64::to_degrees),
        structure: &k.structure,
        scales: &composed.scales,
        positions: k.positions.iter().map(|p| position_out(m, k, p)).collect(),
        assigned: position_out(m, k, &k.assigned),
        acceleration_plan_positions: k.acceleration.iter().map(|&i| k.positions[i].label.clone()).collect(),
        trajectories: k
            .trajectories
            .iter()
            .map(|t| (m.name(t.point).to_string(), t.samples.iter().map(|&v| v2(v)).collect()))
            .collect(),
        trajectory_fit_error_mm: composed.trajectory_error_mm,
        layout: &composed.layout,
        forces: forces.zip(composed.force_scales.as_ref()).map(|(fa, sc)| forces_out(m, k, fa, sc)),
    };
    serde_json::to_value(out).expect("results serialise")
}
