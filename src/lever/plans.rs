//! The vector plans of the course, computed exactly: which image points a velocity or
//! acceleration plan has and which vectors join them. The sheet layer only scales them.
//!
//! A plan is drawn from a pole (p for velocities, π for accelerations); the image of a
//! point X lies at its absolute velocity (acceleration) vector from the pole.

use super::kin::relative;
use super::linkage::{LinkId, Mechanism, PointId, State, Step};
use crate::num::Sense;
use crate::num::math::Norm;
use kurbo::Vec2;

/// A relative motion the note tabulates: point `x` relative to point `y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Relation {
    pub x: PointId,
    pub y: PointId,
    /// The link carrying both points (turning relation), or the kulisa for sliding.
    pub link: LinkId,
    /// True for the sliding of a block along its kulisa (x = block pin, y = kulisa point).
    pub sliding: bool,
}

impl Relation {
    /// The course's subscript, e.g. "BA" for v_BA.
    pub fn name(&self, m: &Mechanism) -> String {
        format!("{}{}", m.name(self.x), m.name(self.y))
    }
}

/// The relative motions of every group, in order of formation.
pub fn relations(m: &Mechanism) -> Vec<Relation> {
    let mut out = Vec::new();
    let rel = |x, y, link| Relation { x, y, link, sliding: false };
    for step in &m.steps {
        match *step {
            Step::Crank { .. } | Step::Attach { .. } => {}
            Step::Rrr { p, q, b, links, .. } => {
                out.push(rel(b, p, links[0]));
                out.push(rel(b, q, links[1]));
            }
            Step::Rrp { p, d, links, .. } => out.push(rel(d, p, links[0])),
            Step::Rpr { a, c, a3, links } => {
                out.push(rel(a3, c, links[1]));
                out.push(Relation { x: a, y: a3, link: links[1], sliding: true });
            }
        }
    }
    out
}

/// What a plan vector stands for; decides its line and label on the sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SegKind {
    /// From the pole to an image: an absolute velocity or acceleration.
    Absolute,
    /// Between two images: a relative velocity of two points of one link.
    Relative,
    /// Normal (centripetal) acceleration component, towards the centre of relative rotation.
    Normal,
    /// Tangential acceleration component, perpendicular to the link.
    Tangential,
    /// Coriolis acceleration 2ω·v_r (v_r turned 90° in the sense of ω).
    Coriolis,
    /// Relative sliding of a block along its kulisa.
    Sliding,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Seg {
    pub from: Vec2,
    pub to: Vec2,
    pub kind: SegKind,
    /// The points it belongs to, as the mechanism names them: the point X of an absolute
    /// vector (and ""), the pair (X, Y) of a relative one or of its components (v_XY, aⁿ_XY).
    pub of: (String, String),
    /// Whether it starts at the pole: an absolute vector, or a component relative to a point
    /// of the frame (πn_BC).
    pub from_pole: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Lowercase label of the point ("b", "s2"); auxiliary points are "k" and the normal
    /// components' ends named by their pair, "n_BA" (what follows "_" is a subscript).
    pub label: String,
    pub at: Vec2,
}

/// One plan: images relative to the pole, and the vectors of its construction.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Plan {
    pub images: Vec<Image>,
    pub segs: Vec<Seg>,
}

impl Plan {
    fn image(&mut self, label: impl Into<String>, at: Vec2) {
        self.images.push(Image { label: label.into(), at });
    }
    fn seg(&mut self, from: Vec2, to: Vec2, kind: SegKind, of: (String, String), from_pole: bool) {
        self.segs.push(Seg { from, to, kind, of, from_pole });
    }
    /// The plan turned 90° in `sense` about its pole,
    /// as the Zhukovsky lever uses it.
    pub fn turned(&self, sense: Sense) -> Plan {
        let t = |v: Vec2| v.turn_90() * sense.sign();
        Plan {
            images: self.images.iter().map(|i| Image { label: i.label.clone(), at: t(i.at) }).collect(),
            segs: self.segs.iter().map(|s| Seg { from: t(s.from), to: t(s.to), ..s.clone() }).collect(),
        }
    }

    /// Largest distance of any image or vector end from the pole.
    pub fn extent(&self) -> f64 {
        let ends = self.segs.iter().flat_map(|s| [s.from, s.to]);
        ends.chain(self.images.iter().map(|i| i.at)).map(Norm::norm).fold(0.0, f64::max)
    }
}

/// A relation's points by their names: (X, Y) of v_XY.
fn pair(m: &Mechanism, r: &Relation) -> (String, String) {
    (m.name(r.x).to_string(), m.name(r.y).to_string())
}

fn label(m: &Mechanism, id: PointId) -> String {
    m.name(id).to_lowercase()
}

/// Images of the moving points and absolute vectors of the joints (not of attached points,
/// whose images follow by similarity and are shown as points only).
fn images_and_absolutes(m: &Mechanism, s: &State, plan: &mut Plan, acc: bool) {
    for (id, _) in m.point_names.iter().enumerate() {
        if m.is_frame(id) {
            continue;
        }
        let k = s.points[id];
        let at = if acc { k.a } else { k.v };
        plan.image(label(m, id), at);
        if !m.is_mass_centre(id) {
            plan.seg(Vec2::ZERO, at, SegKind::Absolute, (m.name(id).to_string(), String::new()), true);
        }
    }
}

/// The velocity plan at state `s`.
pub fn velocity_plan(m: &Mechanism, s: &State) -> Plan {
    let mut plan = Plan::default();
    images_and_absolutes(m, s, &mut plan, false);
    for r in relations(m) {
        let (from, to) = (s.points[r.y].v, s.points[r.x].v);
        if m.is_frame(r.y) && !r.sliding {
            continue; // the relative vector is the absolute one already drawn
        }
        let kind = if r.sliding { SegKind::Sliding } else { SegKind::Relative };
        plan.seg(from, to, kind, pair(m, &r), m.is_frame(r.y));
    }
    plan
}

/// The acceleration plan at state `s`: normal and tangential components and the whole
/// relative acceleration of every turning relation (of a link between two moving joints),
/// Coriolis and relative components of every sliding one.
pub fn acceleration_plan(m: &Mechanism, s: &State) -> Plan {
    let mut plan = Plan::default();
    images_and_absolutes(m, s, &mut plan, true);
    for r in relations(m) {
        let (x, y) = (s.points[r.x], s.points[r.y]);
        let link = &s.links[r.link];
        if r.sliding {
            let v_rel = x.v - y.v;
            let cor = v_rel.turn_90() * (2.0 * link.omega);
            let k = y.a + cor;
            plan.seg(y.a, k, SegKind::Coriolis, pair(m, &r), m.is_frame(r.y));
            plan.image("k", k);
            plan.seg(k, x.a, SegKind::Sliding, pair(m, &r), false);
            continue;
        }
        let (_, an, _) = relative(x.p - y.p, link);
        let corner = y.a + an;
        let (xn, yn) = pair(m, &r);
        // Named by its pair, as the guide names it: n_BA ends aⁿ_BA.
        plan.image(format!("n_{xn}{yn}"), corner);
        plan.seg(y.a, corner, SegKind::Normal, (xn, yn), m.is_frame(r.y));
        plan.seg(corner, x.a, SegKind::Tangential, pair(m, &r), false);
        // The whole relative acceleration: the line on which the images of the link's other
        // points (its centre of mass) lie by similarity.
        if !m.is_frame(r.y) {
            plan.seg(y.a, x.a, SegKind::Relative, pair(m, &r), false);
        }
    }
    plan
}

/// Speeds, accelerations and their components for the tables of the note.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RelationValues {
    pub name: String,
    /// |v_xy| (m/s); for sliding, the sliding speed.
    pub v: f64,
    /// |aⁿ_xy| (m/s²); for sliding, the Coriolis acceleration.
    pub a_n: f64,
    /// |aᵗ_xy| (m/s²); for sliding, the relative (sliding) acceleration.
    pub a_t: f64,
    pub sliding: bool,
}

pub fn relation_values(m: &Mechanism, s: &State) -> Vec<RelationValues> {
    relations(m)
        .into_iter()
        .map(|r| {
            let (x, y) = (s.points[r.x], s.points[r.y]);
            let link = &s.links[r.link];
            if r.sliding {
                let v_rel = x.v - y.v;
                let cor = v_rel.turn_90() * (2.0 * link.omega);
                let a_rel = x.a - y.a - cor;
                return RelationValues {
                    name: r.name(m),
                    v: v_rel.norm(),
                    a_n: cor.norm(),
                    a_t: a_rel.norm(),
                    sliding: true,
                };
            }
            let (v, an, at) = relative(x.p - y.p, link);
            RelationValues { name: r.name(m), v: v.norm(), a_n: an.norm(), a_t: at.norm(), sliding: false }
        })
        .collect()
}
