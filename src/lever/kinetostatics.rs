//! Kinetostatics at one crank angle, the course's way and exactly: inertia forces and
//! moments, weights and loads; the Assur groups from the last formed to the first
//! (tangential reactions from moments about the inner joint, then the force polygon for the
//! normal components); the crank's balancing force; and two independent checks of it, the
//! Zhukovsky lever and the power balance.

use super::linkage::{Crank, LinkId, Mechanism, PointId, State, Step};
use super::load::{Load, LoadValue};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::Vec2;

mod checks;
mod order;
use checks::{power_balance, zhukovsky};

/// The frame, as the body a reaction comes from.
pub const FRAME: usize = usize::MAX;

/// Mass properties of one link.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkMass {
    pub link: LinkId,
    /// kg
    pub mass: f64,
    /// Moment of inertia about the centre of mass, kg·m².
    pub j: f64,
    pub centre: PointId,
}

/// Everything the force analysis needs beyond the kinematics.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceModel {
    /// m/s²
    pub g: f64,
    pub masses: Vec<LinkMass>,
    pub loads: Vec<Load>,
}

/// Which part of a reaction an arrow shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    Whole,
    /// Perpendicular to the link (from the moment equation).
    Tangential,
    /// Along the link (from the force polygon).
    Normal,
}

/// What a force is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Weight,
    Inertia,
    /// Index into [`ForceModel::loads`].
    Load(usize),
    /// From body `from` (a link or [`FRAME`]).
    Reaction {
        from: usize,
        part: Part,
    },
    Balancing,
}

/// A force on link `on`, applied at `at`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Applied {
    pub on: LinkId,
    pub kind: Kind,
    pub at: Vec2,
    /// The mechanism's point it is applied at, when it is one.
    pub point: Option<PointId>,
    pub force: Vec2,
}

/// The polygon of one group (or of the crank): vectors summing to zero, in the order of its
/// vector equation. The first `split` terms act on the group's first link, so the vector
/// from the end of term `split − 1` back to the start is the inner reaction on that link.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    /// Index into [`Mechanism::groups`]; `None` for the crank.
    pub group: Option<usize>,
    pub terms: Vec<Applied>,
    pub split: usize,
    /// The inner reaction on the first link from the second, when the group has one.
    pub inner: Option<Applied>,
}

/// Inertia load of one link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaLoad {
    pub link: LinkId,
    pub mass: f64,
    pub j: f64,
    /// Acceleration of the centre of mass, m/s².
    pub a_s: Vec2,
    pub eps: f64,
    /// P_i = −m·a_S, N.
    pub force: Vec2,
    /// M_i = −J_S·ε, N·m (counter-clockwise positive).
    pub moment: f64,
    /// G = m·g, N.
    pub weight: f64,
}

/// One force of the Zhukovsky lever: applied at the image of its point on the velocity plan
/// turned 90° in the sense of ω1 (m/s); inertia moments become couples of two such forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeverForce {
    pub kind: Kind,
    pub on: LinkId,
    pub image: Vec2,
    pub force: Vec2,
    /// Part of an inertia-moment couple.
    pub couple: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Forces {
    /// Every force on every link: weights, inertia forces, loads, both directions of every
    /// reaction, and the balancing force.
    pub applied: Vec<Applied>,
    pub inertia: Vec<InertiaLoad>,
    pub loads: Vec<LoadValue>,
    /// Groups from the last formed to the first, then the crank.
    pub polygons: Vec<Polygon>,
    /// Balancing force at the crank pin, perpendicular to the crank, signed along v_A
    /// (positive: it drives the crank), N.
    pub p_m: f64,
    /// Its direction (the direction of v_A).
    pub dir_m: Vec2,
    /// Balancing moment P_m·l_OA, positive in the sense of ω1, N·m.
    pub m_m: f64,
    /// P'_m from the Zhukovsky lever, N.
    pub p_m_lever: f64,
    /// P_m from the power balance ΣF·v + ΣM·ω + P_m·v_A = 0, N.
    pub p_m_power: f64,
    pub lever: Vec<LeverForce>,
    /// Moment of every lever force about the pole, N·m/s, in the order of `lever`, then P'_m's.
    pub lever_moments: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ForceError {
    #[error(
        "group {group} cannot carry loads at this position: its {what} are parallel, so the force polygon has no solution (a dead point of the group)"
    )]
    Singular { group: String, what: &'static str },
    #[error("the crank pin has no velocity, so no balancing force can be found")]
    CrankAtRest,
}

impl Forces {
    /// All forces on `link`.
    pub fn on(&self, link: LinkId) -> impl Iterator<Item = &Applied> {
        self.applied.iter().filter(move |f| f.on == link)
    }

    /// Residual force and moment (about the origin) on `link`; zero in equilibrium.
    pub fn residual(&self, link: LinkId) -> (Vec2, f64) {
        resultant(&self.applied, &self.inertia, link, Vec2::ZERO)
    }

    /// Δ = (P_m − P′_m)/P_m·100 %, the course's check of the lever against kinetostatics.
    pub fn difference_percent(&self) -> f64 {
        if self.p_m != 0.0 { (self.p_m - self.p_m_lever) / self.p_m * 100.0 } else { 0.0 }
    }
}

/// Sum of forces on `link` and their moment about `about`, including its inertia moment.
fn resultant(applied: &[Applied], inertia: &[InertiaLoad], link: LinkId, about: Vec2) -> (Vec2, f64) {
    let mut f = Vec2::ZERO;
    let mut m = inertia.iter().filter(|i| i.link == link).map(|i| i.moment).sum::<f64>();
    for a in applied.iter().filter(|a| a.on == link) {
        f += a.force;
        m += (a.at - about).cross(a.force);
    }
    (f, m)
}

/// The body that joins `point` to a group from outside it: the frame, or the first link
/// (other than the group's) that carries the point.
fn owner(m: &Mechanism, point: PointId, group_links: [LinkId; 2]) -> usize {
    if m.is_frame(point) {
        return FRAME;
    }
    (0..m.links.len()).find(|l| !group_links.contains(l) && m.links[*l].points.contains(&point)).unwrap_or(FRAME)
}

fn unit(v: Vec2) -> (Vec2, f64) {
    let l = v.norm();
    (v / l, l)
}

/// `v` itself, or exactly zero where it is below [`tol::ZERO_FORCE`] of `scale` (the
/// largest force it balances): the round-off of a reaction that vanishes (a guide's normal
/// force at a dead centre, 10⁻¹⁶ of the group's forces), which a sheet would otherwise
/// enlarge to a drawing "at μP = 0 N/mm" or draw as an arrow with a made-up sense.
fn snap(v: Vec2, scale: f64) -> Vec2 {
    if v.norm() <= tol::ZERO_FORCE * scale { Vec2::ZERO } else { v }
}

/// [`snap`] for a signed magnitude: `x`, or 0 where it is below [`tol::ZERO_FORCE`] of `scale`.
fn snap_value(x: f64, scale: f64) -> f64 {
    if x.abs() <= tol::ZERO_FORCE * scale { 0.0 } else { x }
}

/// The largest of the forces `known` on a group and of `moments` turned into forces, N.
fn force_scale(known: &[&[Applied]], moments: &[f64]) -> f64 {
    let forces = known.iter().flat_map(|k| k.iter()).map(|a| a.force.norm());
    forces.chain(moments.iter().map(|m| m.abs())).fold(0.0, f64::max)
}

/// Solves n_a·a + n_b·b = −k for the magnitudes along the known directions `a`, `b`.
fn polygon_pair(a: Vec2, b: Vec2, k: Vec2) -> Option<(f64, f64)> {
    let det = a.cross(b);
    if det.abs() < tol::PARALLEL_SIN {
        return None;
    }
    Some((-k.cross(b) / det, -a.cross(k) / det))
}

pub fn analyse(m: &Mechanism, s: &State, model: &ForceModel) -> Result<Forces, ForceError> {
    let mut applied = Vec::new();
    let mut inertia = Vec::new();
    let raw: Vec<InertiaLoad> = model
        .masses
        .iter()
        .map(|lm| {
            let (k, eps) = (s.points[lm.centre], s.links[lm.link].eps);
            let (force, moment) = (-k.a * lm.mass, -lm.j * eps);
            InertiaLoad {
                link: lm.link,
                mass: lm.mass,
                j: lm.j,
                a_s: k.a,
                eps,
                force,
                moment,
                weight: lm.mass * model.g,
            }
        })
        .collect();
    // An inertia force or moment of a link at rest at this instant is the round-off of an
    // acceleration that vanishes (ε of a rod at a dead centre, 10⁻¹³ 1/s²): zero, or the
    // group drawing and the lever show it with a sense round-off chose.
    let big = raw.iter().map(|i| i.force.norm().max(i.weight)).fold(0.0, f64::max);
    let reach =
        s.points.iter().map(|a| s.points.iter().map(|b| (a.p - b.p).norm()).fold(0.0, f64::max)).fold(0.0, f64::max);
    for (lm, il) in model.masses.iter().zip(raw) {
        let moment = snap_value(il.moment, big * reach);
        let il = InertiaLoad { force: snap(il.force, big), moment, ..il };
        let at = s.points[lm.centre].p;
        if il.weight != 0.0 {
            let weight = Vec2::new(0.0, -il.weight);
            applied.push(Applied { on: lm.link, kind: Kind::Weight, at, point: Some(lm.centre), force: weight });
        }
        applied.push(Applied { on: lm.link, kind: Kind::Inertia, at, point: Some(lm.centre), force: il.force });
        inertia.push(il);
    }
    let mut loads = Vec::new();
    for (i, load) in model.loads.iter().enumerate() {
        let k = s.points[load.point];
        let v = load.value(k.p, k.v, k.a);
        applied.push(Applied { on: load.link, kind: Kind::Load(i), at: k.p, point: Some(load.point), force: v.force });
        loads.push(v);
    }
    let mut polygons = Vec::new();
    for gi in (0..m.groups.len()).rev() {
        polygons.push(solve_group(m, s, gi, &mut applied, &inertia)?);
    }
    let crank = solve_crank(m, s, &mut applied, &inertia)?;
    polygons.push(crank.polygon);
    let p_m_power = power_balance(s, &applied, &inertia, crank.v_a);
    let (lever, lever_moments, p_m_lever) = zhukovsky(m, s, &applied, &inertia, crank.a, crank.v_a);
    Ok(Forces {
        applied,
        inertia,
        loads,
        polygons,
        p_m: crank.p_m,
        dir_m: crank.dir,
        m_m: crank.p_m * crank.l,
        p_m_lever,
        p_m_power,
        lever,
        lever_moments,
    })
}

fn describe(m: &Mechanism, gi: usize) -> String {
    let g = &m.groups[gi];
    format!("{} ({}, links {}–{})", gi + 1, g.kind.code(), m.links[g.links[0]].number, m.links[g.links[1]].number)
}

/// Pushes the reaction `force` of `from` on `on` at `at`, and its opposite on `from` unless
/// `from` is the frame.
fn react(
    applied: &mut Vec<Applied>,
    from: usize,
    on: LinkId,
    at: Vec2,
    point: Option<PointId>,
    force: Vec2,
) -> Applied {
    let r = Applied { on, kind: Kind::Reaction { from, part: Part::Whole }, at, point, force };
    applied.push(r);
    if from != FRAME {
        applied.push(Applied {
            on: from,
            kind: Kind::Reaction { from: on, part: Part::Whole },
            at,
            point,
            // Not `-force`: a vanishing reaction's opposite stays +0, not −0 in results.json.
            force: Vec2::ZERO - force,
        });
    }
    r
}

fn part(r: &Applied, part: Part, force: Vec2) -> Applied {
    let Kind::Reaction { from, .. } = r.kind else { unreachable!("only reactions have parts") };
    Applied { kind: Kind::Reaction { from, part }, force, ..*r }
}

fn solve_group(
    m: &Mechanism,
    s: &State,
    gi: usize,
    applied: &mut Vec<Applied>,
    inertia: &[InertiaLoad],
) -> Result<Polygon, ForceError> {
    let g = &m.groups[gi];
    let [l0, l1] = g.links;
    let known0: Vec<Applied> = applied.iter().filter(|a| a.on == l0).copied().collect();
    let known1: Vec<Applied> = applied.iter().filter(|a| a.on == l1).copied().collect();
    let known = (known0.len(), known1.len());
    let singular = |what| ForceError::Singular { group: describe(m, gi), what };
    let p = |id: PointId| s.points[id].p;
    let (terms0, terms1, inner) = match m.steps[g.step] {
        Step::Rrr { p: jp, q: jq, b, .. } => {
            let (pb, pp) = (p(b), p(jp));
            let (e0, len0) = unit(pb - pp);
            let (e1, len1) = unit(pb - p(jq));
            let (sum0, mom0) = resultant(applied, inertia, l0, pb);
            let (sum1, mom1) = resultant(applied, inertia, l1, pb);
            let big = force_scale(&[&known0, &known1], &[mom0 / len0, mom1 / len1]);
            let (t0, t1) = (snap(e0.turn_90() * (mom0 / len0), big), snap(e1.turn_90() * (mom1 / len1), big));
            let (n0, n1) = polygon_pair(e0, e1, t0 + t1 + sum0 + sum1).ok_or_else(|| singular("two links"))?;
            let (n0, n1) = (snap(e0 * n0, big), snap(e1 * n1, big));
            let r0 = react(applied, owner(m, jp, g.links), l0, pp, Some(jp), n0 + t0);
            let r1 = react(applied, owner(m, jq, g.links), l1, p(jq), Some(jq), n1 + t1);
            let inner = react(applied, l1, l0, pb, Some(b), snap(-(r0.force + sum0), big));
            let mut terms0 = vec![part(&r0, Part::Normal, n0), part(&r0, Part::Tangential, t0)];
            terms0.extend(known0);
            let mut terms1 = known1;
            terms1.extend([part(&r1, Part::Tangential, t1), part(&r1, Part::Normal, n1)]);
            (terms0, terms1, inner)
        }
        Step::Rrp { p: jp, d, dir, .. } => {
            let pd = p(d);
            let (e0, len0) = unit(pd - p(jp));
            let normal = dir.turn_90();
            let (sum0, mom0) = resultant(applied, inertia, l0, pd);
            let (sum1, mom1) = resultant(applied, inertia, l1, pd);
            let big = force_scale(&[&known0, &known1], &[mom0 / len0]);
            let t0 = snap(e0.turn_90() * (mom0 / len0), big);
            let (n0, nf) =
                polygon_pair(e0, normal, t0 + sum0 + sum1).ok_or_else(|| singular("rod and guide normal"))?;
            let n0 = snap(e0 * n0, big);
            let nf = snap_value(nf, big);
            // The guide's reaction passes at h along the guide from D, so that the slider's
            // moments about D balance: h·N + M_D = 0 (a vanishing N acts anywhere: at D).
            let scale = sum0.norm() + sum1.norm() + t0.norm() + n0.norm();
            let h = if nf.abs() > tol::ZERO_FORCE * scale { -mom1 / nf } else { 0.0 };
            let r0 = react(applied, owner(m, jp, g.links), l0, p(jp), Some(jp), n0 + t0);
            let r1 =
                react(applied, FRAME, l1, pd + dir * h, if h == 0.0 { Some(d) } else { None }, snap(normal * nf, big));
            let inner = react(applied, l1, l0, pd, Some(d), snap(-(r0.force + sum0), big));
            let mut terms0 = vec![part(&r0, Part::Normal, n0), part(&r0, Part::Tangential, t0)];
            terms0.extend(known0);
            let mut terms1 = known1;
            terms1.push(r1);
            (terms0, terms1, inner)
        }
        Step::Rpr { a, c, .. } => {
            let (pa, pc) = (p(a), p(c));
            let (e, len) = unit(pa - pc);
            let normal = e.turn_90();
            let (sum0, mom0) = resultant(applied, inertia, l0, pa);
            let (sum1, mom1) = resultant(applied, inertia, l1, pc);
            // Block about A: h·N + M_A = 0; kulisa about C: (l + h)·N = M_C; hence l·N = M_C + M_A.
            let big = force_scale(&[&known0, &known1], &[mom0 / len, mom1 / len]);
            let nf = (mom1 + mom0) / len;
            let nf = snap_value(nf, big);
            let scale = sum0.norm() + sum1.norm() + (mom0.abs() + mom1.abs()) / len;
            let h = if nf.abs() > tol::ZERO_FORCE * scale { -mom0 / nf } else { 0.0 };
            let inner =
                react(applied, l1, l0, pa + e * h, if h == 0.0 { Some(a) } else { None }, snap(normal * nf, big));
            let r0 = react(applied, owner(m, a, g.links), l0, pa, Some(a), snap(-(sum0 + inner.force), big));
            let r1 = react(applied, owner(m, c, g.links), l1, pc, Some(c), snap(-(sum1 - inner.force), big));
            let mut terms0 = vec![r0];
            terms0.extend(known0);
            let mut terms1 = known1;
            terms1.push(r1);
            (terms0, terms1, inner)
        }
        Step::Crank { .. } | Step::Attach { .. } => unreachable!("groups are dyad steps"),
    };
    let split = terms0.len();
    let mut terms = terms0;
    terms.extend(terms1);
    let terms = order::unfolded(terms, [(split - known.0, known.0), (split, known.1)]);
    Ok(Polygon { group: Some(gi), terms, split, inner: Some(inner) })
}

struct CrankSolution {
    polygon: Polygon,
    p_m: f64,
    dir: Vec2,
    l: f64,
    a: PointId,
    v_a: Vec2,
}

fn solve_crank(
    m: &Mechanism,
    s: &State,
    applied: &mut Vec<Applied>,
    inertia: &[InertiaLoad],
) -> Result<CrankSolution, ForceError> {
    let Crank { pivot, pin, link, .. } = m.crank();
    let (po, pa) = (s.points[pivot].p, s.points[pin].p);
    let v_a = s.points[pin].v;
    if v_a.norm() == 0.0 {
        return Err(ForceError::CrankAtRest);
    }
    let dir = v_a.unit();
    let known: Vec<Applied> = applied.iter().filter(|a| a.on == link).copied().collect();
    let (sum, mom) = resultant(applied, inertia, link, po);
    let arm = (pa - po).cross(dir);
    let big = force_scale(&[&known], &[]);
    let force = snap(dir * (-mom / arm), big);
    let p_m = if force == Vec2::ZERO { 0.0 } else { -mom / arm };
    let bal = Applied { on: link, kind: Kind::Balancing, at: pa, point: Some(pin), force };
    applied.push(bal);
    let r01 = react(applied, FRAME, link, po, Some(pivot), snap(-(sum + bal.force), big));
    let mut terms = order::uncrossed(known, &[bal, r01]);
    terms.extend([bal, r01]);
    let split = terms.len();
    Ok(CrankSolution {
        polygon: Polygon { group: None, terms, split, inner: None },
        p_m,
        dir,
        l: (pa - po).norm(),
        a: pin,
        v_a,
    })
}
