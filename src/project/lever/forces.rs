//! Turns the project file's `forces` section into the mechanics' [`ForceModel`]: masses with
//! their centres, moments of inertia (given, or m·l²/12), and the loads on sliders.

use super::super::forces::*;
use super::super::values::Name;
use super::super::{Kind, Refusal, Warning, at, invalid, warning};
use crate::lever::indicators::{self, Indicator};
use crate::lever::kinetostatics::{ForceModel, LinkMass};
use crate::lever::linkage::{LinkId, LinkKind, Mechanism, PointId, Step};
use crate::lever::load::{Branch, Curve, Load, LoadKind, Stroke, Swing};
use crate::num::digits::written;
use crate::num::limits;
use crate::num::math::Norm;
use kurbo::Vec2;
use serde_saphyr::Spanned;

const G: f64 = 9.81;

pub fn build_forces(
    spec: &Spanned<ForcesSpec>,
    m: &Mechanism,
    warnings: &mut Vec<Warning>,
) -> Result<ForceModel, Refusal> {
    let f = &spec.value;
    let mut masses: Vec<LinkMass> = Vec::new();
    for (i, lm) in f.links.iter().enumerate() {
        let field = format!("forces.links[{i}]");
        let link = m.link_by_number(lm.link.value).ok_or_else(|| {
            invalid(at(&lm.link), format!("{field}.link"), format!("there is no link {}", lm.link.value))
                .kind(Kind::Reference)
        })?;
        if masses.iter().any(|x| x.link == link) {
            return Err(invalid(
                at(&lm.link),
                format!("{field}.link"),
                format!("link {} is listed twice", lm.link.value),
            )
            .kind(Kind::Reference));
        }
        let mass = link_mass(m, lm, link, &field, warnings)?;
        if mass.mass > limits::MASS_PLAUSIBLE_MAX {
            warnings.push(warning(
                at(&lm.link),
                &field,
                format!(
                    "{} kg is more than {} kg: masses are in kilograms",
                    written(mass.mass),
                    written(limits::MASS_PLAUSIBLE_MAX)
                ),
            ));
        }
        masses.push(mass);
    }
    let missing: Vec<String> = (0..m.links.len())
        .filter(|&l| m.links[l].kind != LinkKind::Crank && !masses.iter().any(|x| x.link == l))
        .map(|l| m.links[l].number.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(invalid(
            at(spec),
            "forces.links",
            format!(
                "no mass for link(s) {}: the force analysis needs the mass of every moving link but the crank (write `mass: 0` for a light link)",
                missing.join(", ")
            ),
        ));
    }
    let loads =
        f.loads.iter().enumerate().map(|(i, l)| load(m, l, &format!("forces.loads[{i}]"))).collect::<Result<_, _>>()?;
    Ok(ForceModel { g: f.g.map_or(G, |g| g.0), masses, loads })
}

fn link_mass(
    m: &Mechanism,
    lm: &LinkMassSpec,
    link: LinkId,
    field: &str,
    warnings: &mut Vec<Warning>,
) -> Result<LinkMass, Refusal> {
    let loc = at(&lm.link);
    let full = full_length(m, link);
    let length = || {
        full.as_ref().map(|f| f.length).ok_or_else(|| invalid(loc, field, format!("link {} has no fixed length between two joints, so m = q·l and J = m·l²/12 cannot be used; give `mass` and `inertia`", lm.link.value)))
    };
    let uses_length = lm.q.is_some() || matches!(lm.inertia, Some(Inertia::Rod));
    // Only where the full length is not the side the link's group gives it (a point between
    // its two joints, as a jaw crusher's K, leaves no doubt which length is meant).
    let other_than_defined = |f: &&FullLength| defined_length(m, link).is_none_or(|d| (d - f.length).abs() > 1e-9 * d);
    if let Some(f) = full.as_ref().filter(|f| uses_length && f.joints > 2).filter(other_than_defined) {
        warnings.push(warning(
            loc,
            field,
            format!(
                "link {} has {} joints: m = q·l and J = m·l²/12 use its full length {}{} = {} m, the largest distance between its joints",
                lm.link.value, f.joints, f.from, f.to, crate::num::digits::significant(f.length)
            ),
        ));
    }
    let mass = match (lm.mass, lm.q) {
        (Some(x), None) => x.0,
        (None, Some(q)) => q.0 * length()?,
        (Some(_), Some(_)) => return Err(invalid(loc, field, "give either `mass` or `q` (m = q·l), not both")),
        (None, None) => {
            return Err(invalid(loc, field, format!("link {} needs `mass` (kg) or `q` (kg/m)", lm.link.value)));
        }
    };
    let j = match (lm.inertia, lm.q) {
        (Some(Inertia::Value(j)), _) => j,
        (Some(Inertia::Rod), _) | (None, Some(_)) => mass * length()?.powi(2) / 12.0,
        (None, None) => 0.0,
    };
    // A massless link loads nothing, so any of its points serves as its centre.
    let massless = mass == 0.0 && j == 0.0;
    let centre = mass_centre(m, link)
        .or(if massless { m.links[link].points.first().copied() } else { None })
        .ok_or_else(|| {
            invalid(
                loc,
                field,
                format!(
                    "link {} has a mass but no centre of mass: add a point on it with `mass_centre: true`",
                    lm.link.value
                ),
            )
        })?;
    Ok(LinkMass { link, mass, j, centre })
}

/// The declared centre of mass; a slider's or block's joint, or the crank's pivot, by default.
fn mass_centre(m: &Mechanism, link: LinkId) -> Option<PointId> {
    if let Some(&(_, p)) = m.mass_centres.iter().find(|(l, _)| *l == link) {
        return Some(p);
    }
    match m.links[link].kind {
        LinkKind::Slider | LinkKind::Block | LinkKind::Crank => m.links[link].points.first().copied(),
        LinkKind::Rocker | LinkKind::Coupler => None,
    }
}

/// The fixed distance between the two joints that define a link.
/// A link's full length: the largest distance between two of its joints (its centre of
/// mass and a kulisa's image point are not joints), and which joints they are.
struct FullLength {
    length: f64,
    from: String,
    to: String,
    joints: usize,
}

/// The link's [`FullLength`], measured on the mechanism assembled at the first crank angle
/// (every 5°) where it assembles; `None` for a link with one joint, or one whose joints'
/// distance changes (a kulisa's block slides along it).
fn full_length(m: &Mechanism, link: LinkId) -> Option<FullLength> {
    let joints: Vec<PointId> =
        m.links[link].points.iter().copied().filter(|&p| !m.is_mass_centre(p) && !m.is_kulisa_image(p)).collect();
    if joints.len() < 2 {
        return None;
    }
    let Some(state) = (0..72).find_map(|k| m.solve(k as f64 * std::f64::consts::TAU / 72.0).ok()) else {
        // A mechanism that never assembles is refused by the motion analysis, which says
        // why; until then the group's own side length stands in.
        return defined_length(m, link).map(|length| FullLength {
            length,
            from: String::new(),
            to: String::new(),
            joints: 2,
        });
    };
    let mut best: Option<FullLength> = None;
    for (i, &a) in joints.iter().enumerate() {
        for &b in &joints[i + 1..] {
            let d = (state.points[a].p - state.points[b].p).norm();
            if best.as_ref().is_none_or(|f| d > f.length) {
                best =
                    Some(FullLength { length: d, from: m.name(a).into(), to: m.name(b).into(), joints: joints.len() });
            }
        }
    }
    best.filter(|f| f.length > 0.0)
}

/// The length a group's definition gives the link (its side from the joint it is built on).
fn defined_length(m: &Mechanism, link: LinkId) -> Option<f64> {
    m.steps.iter().find_map(|s| match *s {
        Step::Crank { length, link: l, .. } if l == link => Some(length),
        Step::Rrr { l_pb, l_qb, links, .. } if links.contains(&link) => {
            Some(if links[0] == link { l_pb } else { l_qb })
        }
        Step::Rrp { length, links, .. } if links[0] == link => Some(length),
        _ => None,
    })
}

/// The slider of an RRP group at `name`: (link, point, guide point, guide direction).
fn slider(m: &Mechanism, name: &Name, field: &str) -> Result<(LinkId, PointId, Vec2, Vec2), Refusal> {
    let found = m.point_id(&name.value).and_then(|id| {
        m.steps.iter().find_map(|s| match *s {
            Step::Rrp { d, through, dir, links, .. } if d == id => Some((links[1], d, through, dir)),
            _ => None,
        })
    });
    found.ok_or_else(|| {
        invalid(
            at(name),
            field,
            format!(
                "'{}' is not the slider point of an RRP group; loads act on sliders along their guides",
                name.value
            ),
        )
        .kind(Kind::Reference)
    })
}

/// The rocker carrying the point `name`: a link turning about a frame pivot (its link,
/// the point, the pivot's position).
fn rocker(m: &Mechanism, name: &Name, field: &str) -> Result<(LinkId, PointId, Vec2), Refusal> {
    let found = m.point_id(&name.value).and_then(|id| {
        m.links.iter().enumerate().find_map(|(link, l)| {
            let pivot = l.points.iter().filter(|&&q| q != id).find_map(|&q| m.frame.iter().find(|f| f.0 == q));
            pivot.filter(|_| l.points.contains(&id) && l.number > 1).map(|f| (link, id, f.1))
        })
    });
    found.ok_or_else(|| {
        invalid(
            at(name),
            field,
            format!(
                "'{}' is not a point of a rocker (a link turning about a frame pivot, the crank's excepted): a working stroke `cw` or `ccw` is a rocker's; a slider's is `forward` or `backward`",
                name.value
            ),
        )
        .kind(Kind::Reference)
    })
}

fn load(m: &Mechanism, spec: &Spanned<LoadSpec>, field: &str) -> Result<Load, Refusal> {
    match &spec.value {
        LoadSpec::Resistance(r) => {
            let at_point = format!("{field}.resistance.point");
            let (link, point, through, dir, swing) = match r.working {
                Working::Forward | Working::Backward => {
                    let (link, point, through, dir) = slider(m, &r.point, &at_point)?;
                    let dir = if r.working == Working::Forward { dir } else { -dir };
                    (link, point, through, dir, None)
                }
                Working::Cw | Working::Ccw => {
                    let sense = if r.working == Working::Ccw { 1.0 } else { -1.0 };
                    let (link, point, pivot) = rocker(m, &r.point, &at_point)?;
                    // The reference direction is fixed once the mechanism is solved.
                    (link, point, pivot, Vec2::ZERO, Some(Swing { pivot, reference: Vec2::ZERO, sense }))
                }
            };
            let working = match &r.diagram {
                Some(d) => diagram(d, &format!("{field}.resistance.diagram"))?,
                None => Curve::constant(1.0),
            };
            let axis = dir;
            let idle = r.idle_force.map_or(0.0, |x| x.0);
            let branches = [
                Branch { curve: working, scale: -r.force.0, name: Stroke::Working },
                Branch { curve: Curve::constant(1.0), scale: idle, name: Stroke::Idle },
            ];
            Ok(Load {
                kind: LoadKind::Resistance,
                link,
                point,
                axis,
                through,
                swing,
                from_head: false,
                origin: 0.0,
                stroke: 0.0,
                branches,
                line: at(spec).line(),
            })
        }
        LoadSpec::Gas(g) => {
            let f = format!("{field}.gas");
            let (link, point, through, dir) = slider(m, &g.point, &format!("{f}.point"))?;
            let force = match (g.force, g.bore, g.pressure) {
                (Some(f), None, None) => f.0,
                (None, Some(d), Some(p)) => p.0 * std::f64::consts::PI * d.0 * d.0 / 4.0,
                _ => return Err(invalid(at(spec), &f, "give either `force` (N), or `bore` (m) and `pressure` (Pa)")),
            };
            let ind = indicator(g, &f)?;
            let branch =
                |(rows, name): (Vec<(f64, f64)>, Stroke)| Branch { curve: Curve { points: rows }, scale: force, name };
            let branches = [branch((ind.away.0, ind.away.1)), branch((ind.toward.0, ind.toward.1))];
            Ok(Load {
                kind: LoadKind::Gas,
                link,
                point,
                axis: dir,
                through,
                swing: None,
                from_head: true,
                origin: 0.0,
                stroke: 0.0,
                branches,
                line: at(spec).line(),
            })
        }
    }
}

fn indicator(g: &GasSpec, field: &str) -> Result<Indicator, Refusal> {
    let loc = at(&g.indicator);
    let revolution = g.revolution.as_ref().map_or(1, |r| r.value);
    if let Some(r) = g.revolution.as_ref().filter(|r| r.value != 1 && r.value != 2) {
        return Err(invalid(
            at(r),
            format!("{field}.revolution"),
            format!("an engine's cycle has revolutions 1 and 2, not {}", r.value),
        ));
    }
    if g.revolution.is_some() && g.indicator.value != IndicatorName::Engine {
        return Err(invalid(loc, format!("{field}.revolution"), "`revolution` is for `indicator: engine` only"));
    }
    match (g.indicator.value, &g.table) {
        (IndicatorName::CompressorStage1, None) => Ok(indicators::compressor(1)),
        (IndicatorName::CompressorStage2, None) => Ok(indicators::compressor(2)),
        (IndicatorName::Engine, None) => Ok(indicators::engine(revolution)),
        (IndicatorName::Table, Some(t)) => Ok(Indicator {
            away: (diagram(&t.away_from_head, &format!("{field}.table.away_from_head"))?.points, Stroke::AwayFromHead),
            toward: (diagram(&t.toward_head, &format!("{field}.table.toward_head"))?.points, Stroke::TowardHead),
        }),
        (IndicatorName::Table, None) => Err(invalid(
            loc,
            format!("{field}.table"),
            "`indicator: table` needs `table` with `toward_head` and `away_from_head`",
        )),
        (_, Some(_)) => Err(invalid(loc, format!("{field}.table"), "`table` is for `indicator: table` only")),
    }
}

/// A written diagram, checked: at least two rows, stroke fractions from 0 to 1, strictly
/// increasing.
fn diagram(d: &DiagramSpec, field: &str) -> Result<Curve, Refusal> {
    let rows: Vec<(f64, f64)> = d.value.iter().map(|r| (r[0].0, r[1].0)).collect();
    let bad = |msg: String| Err(invalid(at(d), field, msg));
    if rows.len() < 2 {
        return bad("a diagram needs at least two rows [stroke fraction, value]".into());
    }
    if let Some(w) = rows.windows(2).position(|w| w[1].0 <= w[0].0) {
        return bad(format!(
            "the stroke fractions must increase: row {} ({}) does not come after row {} ({})",
            w + 2,
            written(rows[w + 1].0),
            w + 1,
            written(rows[w].0)
        ));
    }
    if rows[0].0 != 0.0 || rows[rows.len() - 1].0 != 1.0 {
        return bad(format!(
            "the stroke fractions must run from 0 to 1, not {} to {}",
            written(rows[0].0),
            written(rows[rows.len() - 1].0)
        ));
    }
    Ok(Curve { points: rows })
}
