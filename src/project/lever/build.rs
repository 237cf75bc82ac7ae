//! The mechanism laid out step by step as the file writes it: frame points, the crank, each
//! Assur group in order of formation and the points fixed to links, every name and link
//! number checked where it is written; the output link or slider that defines position 0.

use super::super::mechanism::*;
use super::super::values::Name;
use super::super::{Kind, Refusal, at, invalid};
use crate::lever::DyadKind;
use crate::lever::linkage::{Group, Link, LinkId, LinkKind, Mechanism, Output, PointId, Step};
use crate::num::math;
use kurbo::Vec2;
use serde_saphyr::{Location, Spanned};

/// Collects points and links while the steps are laid out.
pub(super) struct Builder {
    pub(super) m: Mechanism,
}

impl Builder {
    pub(super) fn new_point(&mut self, name: &Name, field: &str) -> Result<PointId, Refusal> {
        if name.value.trim().is_empty() {
            return Err(invalid(at(name), field, "a point name must not be empty"));
        }
        if self.m.point_id(&name.value).is_some() {
            return Err(
                invalid(at(name), field, format!("point '{}' is defined twice", name.value)).kind(Kind::Reference)
            );
        }
        self.m.point_names.push(name.value.clone());
        Ok(self.m.point_names.len() - 1)
    }

    pub(super) fn known_point(&self, name: &Name, field: &str) -> Result<PointId, Refusal> {
        self.m.point_id(&name.value).ok_or_else(|| {
            let known = self.m.point_names.join(", ");
            invalid(at(name), field, format!("unknown point '{}' (points defined before it: {known})", name.value))
                .kind(Kind::Reference)
        })
    }

    pub(super) fn new_link(
        &mut self,
        number: u32,
        kind: LinkKind,
        points: Vec<PointId>,
        loc: Location,
        field: &str,
    ) -> Result<LinkId, Refusal> {
        if number == 0 {
            return Err(invalid(loc, field, "link 0 is the frame; moving links are numbered from 1"));
        }
        if self.m.link_by_number(number).is_some() {
            return Err(invalid(loc, field, format!("link {number} is used twice")).kind(Kind::Reference));
        }
        self.m.links.push(Link { number, kind, points });
        Ok(self.m.links.len() - 1)
    }

    pub(super) fn is_frame(&self, id: PointId) -> bool {
        self.m.is_frame(id)
    }
}

pub(super) fn add_group(
    b: &mut Builder,
    g: &Spanned<GroupSpec>,
    field: &str,
) -> Result<Option<(LinkId, Option<f64>)>, Refusal> {
    let step = b.m.steps.len();
    let loc = at(g);
    let (kind, links, point, inputs, kulisa) = match &g.value {
        GroupSpec::Rrr(r) => {
            let p = b.known_point(&r.joints[0], &format!("{field}.rrr.joints[0]"))?;
            let q = b.known_point(&r.joints[1], &format!("{field}.rrr.joints[1]"))?;
            let pt = b.new_point(&r.point, &format!("{field}.rrr.point"))?;
            let kind_of =
                |end: PointId, b: &Builder| if b.is_frame(end) { LinkKind::Rocker } else { LinkKind::Coupler };
            let (k0, k1) = (kind_of(p, b), kind_of(q, b));
            let l0 = b.new_link(r.links[0], k0, vec![p, pt], loc, &format!("{field}.rrr.links[0]"))?;
            let l1 = b.new_link(r.links[1], k1, vec![q, pt], loc, &format!("{field}.rrr.links[1]"))?;
            let branch = if r.branch == Side::Left { 1.0 } else { -1.0 };
            b.m.steps.push(Step::Rrr {
                p,
                q,
                b: pt,
                l_pb: r.lengths[0].0,
                l_qb: r.lengths[1].0,
                branch,
                links: [l0, l1],
            });
            (DyadKind::Rrr, [l0, l1], pt, vec![p, q], None)
        }
        GroupSpec::Rrp(r) => {
            let p = b.known_point(&r.joint, &format!("{field}.rrp.joint"))?;
            let pt = b.new_point(&r.point, &format!("{field}.rrp.point"))?;
            let l0 = b.new_link(r.links[0], LinkKind::Coupler, vec![p, pt], loc, &format!("{field}.rrp.links[0]"))?;
            let l1 = b.new_link(r.links[1], LinkKind::Slider, vec![pt], loc, &format!("{field}.rrp.links[1]"))?;
            let dir = math::from_angle(r.guide.angle_deg.0.to_radians());
            let through = Vec2::new(r.guide.through[0].0, r.guide.through[1].0);
            let branch = if r.branch == Along::Forward { 1.0 } else { -1.0 };
            b.m.steps.push(Step::Rrp { p, d: pt, length: r.length.0, through, dir, branch, links: [l0, l1] });
            (DyadKind::Rrp, [l0, l1], pt, vec![p], None)
        }
        GroupSpec::Rpr(r) => {
            let a = b.known_point(&r.block_at, &format!("{field}.rpr.block_at"))?;
            let c = b.known_point(&r.pivot, &format!("{field}.rpr.pivot"))?;
            let image = match &r.image {
                Some(n) => n.clone(),
                None => Spanned::new(format!("{}3", r.block_at.value), loc, loc),
            };
            let a3 = b.new_point(&image, &format!("{field}.rpr.image"))?;
            let l0 = b.new_link(r.links[0], LinkKind::Block, vec![a], loc, &format!("{field}.rpr.links[0]"))?;
            let kk = if b.is_frame(c) { LinkKind::Rocker } else { LinkKind::Coupler };
            let l1 = b.new_link(r.links[1], kk, vec![c, a3], loc, &format!("{field}.rpr.links[1]"))?;
            b.m.steps.push(Step::Rpr { a, c, a3, links: [l0, l1] });
            (DyadKind::Rpr, [l0, l1], a3, vec![a, c], Some((l1, r.length.map(|x| x.0))))
        }
    };
    b.m.groups.push(Group { kind, step, links, point, inputs, line: loc.line() });
    Ok(kulisa)
}

/// Adds, in the file's order, every pending point whose link and reference points exist.
pub(super) fn attach_ready(b: &mut Builder, pending: &mut Vec<(usize, &PointSpec)>) -> Result<(), Refusal> {
    loop {
        let ready = pending.iter().position(|(_, p)| {
            let link_ok = b.m.link_by_number(p.link.value).is_some();
            let refs_ok = b.m.point_id(&p.from.value).is_some()
                && p.toward.as_ref().is_none_or(|t| b.m.point_id(&t.value).is_some());
            link_ok && refs_ok
        });
        let Some(i) = ready else { return Ok(()) };
        let (index, p) = pending.remove(i);
        attach(b, index, p)?;
    }
}

fn attach(b: &mut Builder, index: usize, p: &PointSpec) -> Result<(), Refusal> {
    let field = format!("mechanism.points[{index}]");
    let link = b.m.link_by_number(p.link.value).expect("checked by attach_ready");
    let from = b.known_point(&p.from, &format!("{field}.from"))?;
    let on_link = |id: PointId, b: &Builder| b.m.links[link].points.contains(&id);
    if !on_link(from, b) {
        return Err(invalid(
            at(&p.from),
            format!("{field}.from"),
            format!("point '{}' is not on link {}", p.from.value, p.link.value),
        )
        .kind(Kind::Reference));
    }
    let (toward, distance) = match &p.toward {
        None => {
            if p.ratio.is_some() || p.distance.is_some_and(|d| d.0 != 0.0) {
                return Err(invalid(at(&p.name), &field, "`ratio` or `distance` needs `toward` to give the direction"));
            }
            (from, 0.0)
        }
        Some(t) => {
            let toward = b.known_point(t, &format!("{field}.toward"))?;
            if !on_link(toward, b) || toward == from {
                return Err(invalid(
                    at(t),
                    format!("{field}.toward"),
                    format!("point '{}' must be another point of link {}", t.value, p.link.value),
                )
                .kind(Kind::Reference));
            }
            let d = match (p.ratio, p.distance) {
                (Some(r), None) => {
                    r.0 * link_span(b, from, toward).ok_or_else(|| {
                        invalid(
                            at(t),
                            format!("{field}.ratio"),
                            "a ratio needs a fixed distance between `from` and `toward`; give `distance` instead",
                        )
                    })?
                }
                (None, Some(d)) => d.0,
                _ => return Err(invalid(at(&p.name), &field, "give exactly one of `ratio` and `distance`")),
            };
            (toward, d)
        }
    };
    let point = b.new_point(&p.name, &format!("{field}.name"))?;
    b.m.links[link].points.push(point);
    let angle = p.angle_deg.map_or(0.0, |a| a.0.to_radians());
    let ratio = if toward == from { None } else { link_span(b, from, toward).map(|span| distance / span) };
    b.m.steps.push(Step::Attach { point, link, from, toward, distance, angle, ratio });
    if p.mass_centre {
        if b.m.mass_centres.iter().any(|&(l, _)| l == link) {
            return Err(invalid(
                at(&p.name),
                format!("{field}.mass_centre"),
                format!("link {} already has a centre of mass", p.link.value),
            ));
        }
        b.m.mass_centres.push((link, point));
    }
    Ok(())
}

/// The fixed distance between two points of a link, when the steps define one.
fn link_span(b: &Builder, x: PointId, y: PointId) -> Option<f64> {
    let same = |a: PointId, c: PointId| (a == x && c == y) || (a == y && c == x);
    b.m.steps.iter().find_map(|s| match *s {
        Step::Crank { pivot, pin, length, .. } if same(pivot, pin) => Some(length),
        Step::Rrr { p, q, b: pt, l_pb, l_qb, .. } => {
            if same(p, pt) {
                Some(l_pb)
            } else if same(q, pt) {
                Some(l_qb)
            } else {
                None
            }
        }
        Step::Rrp { p, d, length, .. } if same(p, d) => Some(length),
        Step::Attach { point, from, distance, .. } if same(point, from) => Some(distance.abs()),
        _ => None,
    })
}

pub(super) fn resolve_output(b: &Builder, spec: &MechanismSpec) -> Result<Output, Refusal> {
    if let Some(n) = &spec.output_link {
        let link = b.m.link_by_number(n.value).ok_or_else(|| {
            invalid(at(n), "mechanism.output_link", format!("no link {}", n.value)).kind(Kind::Reference)
        })?;
        return Ok(Output::Rocker { link });
    }
    let slider_of = |id: PointId| {
        b.m.steps.iter().find_map(|s| match *s {
            Step::Rrp { d, dir, .. } if d == id => Some(Output::Slider { point: d, dir }),
            _ => None,
        })
    };
    if let Some(n) = &spec.output_point {
        let id = b.known_point(n, "mechanism.output_point")?;
        return slider_of(id).ok_or_else(|| {
            invalid(
                at(n),
                "mechanism.output_point",
                format!("'{}' is not a slider point; use output_link for a rocker", n.value),
            )
            .kind(Kind::Reference)
        });
    }
    let Some(last) = b.m.groups.last() else {
        return Ok(Output::Rocker { link: 0 });
    };
    Ok(match last.kind {
        DyadKind::Rrp => slider_of(last.point).expect("an RRP group has a slider"),
        DyadKind::Rpr => Output::Rocker { link: last.links[1] },
        DyadKind::Rrr => {
            let frame_side = last.links.iter().copied().find(|&l| b.m.links[l].kind == LinkKind::Rocker);
            Output::Rocker { link: frame_side.unwrap_or(last.links[1]) }
        }
    })
}
