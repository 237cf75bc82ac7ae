//! Resolves the `mechanism`, `analysis` and `forces` sections into the lever domain: a
//! [`Mechanism`], its analysis [`Settings`] and [`ForceModel`], checking every
//! cross-reference (point names, link numbers) with its location.

use super::forces::ForcesSpec;
use super::mechanism::*;
use super::text::{self, Lines};
use super::values::Name;
use super::{Kind, Places, Refusal, Warning, at, invalid, warning};
use crate::lever::analysis::AnalysisError;
use crate::lever::kinetostatics::ForceModel;
use crate::lever::linkage::{Group, Link, LinkId, LinkKind, Mechanism, Output, PointId, Step};
use crate::lever::{DyadKind, Settings, Start};
use crate::num::limits;
use crate::num::math::{self, Norm};
use kurbo::Vec2;
use serde_saphyr::{Location, Spanned};

/// Everything sheet 1 needs from the project file.
#[derive(Debug, Clone)]
pub struct LeverProject {
    pub mechanism: Mechanism,
    pub settings: Settings,
    /// Masses and loads, when the project asks for a force analysis.
    pub forces: Option<ForceModel>,
    /// Drawn lengths of kulisas, by link (`None`: the longest reach plus 15 %).
    pub kulisa_lengths: Vec<(LinkId, Option<f64>)>,
    /// Printed on the sheet: what was assumed where the figure was lost.
    pub assumptions: Vec<crate::project::values::LocalText>,
}

/// Collects points and links while the steps are laid out.
struct Builder {
    m: Mechanism,
}

impl Builder {
    fn new_point(&mut self, name: &Name, field: &str) -> Result<PointId, Refusal> {
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

    fn known_point(&self, name: &Name, field: &str) -> Result<PointId, Refusal> {
        self.m.point_id(&name.value).ok_or_else(|| {
            let known = self.m.point_names.join(", ");
            invalid(at(name), field, format!("unknown point '{}' (points defined before it: {known})", name.value))
                .kind(Kind::Reference)
        })
    }

    fn new_link(
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

    fn is_frame(&self, id: PointId) -> bool {
        self.m.is_frame(id)
    }
}

/// Resolves the lever sections; plausibility warnings go to `warnings`.
pub fn resolve(
    spec: &Spanned<MechanismSpec>,
    analysis: Option<&Spanned<AnalysisSpec>>,
    forces: Option<&Spanned<ForcesSpec>>,
    warnings: &mut Vec<Warning>,
) -> Result<LeverProject, Refusal> {
    let spec = &spec.value;
    check_texts(spec)?;
    plausibility(spec, warnings);
    let sense = if spec.crank.sense == Sense::Ccw { 1.0 } else { -1.0 };
    let omega1 = sense * crank_speed(&spec.crank)?;
    let mut b = Builder {
        m: Mechanism {
            point_names: vec![],
            frame: vec![],
            links: vec![],
            steps: vec![],
            groups: vec![],
            omega1,
            output: Output::Rocker { link: 0 },
            mass_centres: vec![],
            size: 0.0,
        },
    };
    for (i, fp) in spec.frame.iter().enumerate() {
        let id = b.new_point(&fp.name, &format!("mechanism.frame[{i}].name"))?;
        b.m.frame.push((id, Vec2::new(fp.at[0].0, fp.at[1].0)));
    }
    let c = &spec.crank;
    let pivot = b.known_point(&c.pivot, "mechanism.crank.pivot")?;
    if !b.is_frame(pivot) {
        return Err(invalid(at(&c.pivot), "mechanism.crank.pivot", "the crank must turn about a frame point")
            .kind(Kind::Reference));
    }
    let pin = b.new_point(&c.pin, "mechanism.crank.pin")?;
    let link = b.new_link(c.link, LinkKind::Crank, vec![pivot, pin], at(&c.pin), "mechanism.crank.link")?;
    b.m.steps.push(Step::Crank { pivot, pin, length: c.length.value.0, link });
    let mut pending: Vec<(usize, &PointSpec)> = spec.points.iter().enumerate().collect();
    attach_ready(&mut b, &mut pending)?;
    let mut kulisa_lengths = vec![];
    for (gi, g) in spec.groups.iter().enumerate() {
        let field = format!("mechanism.groups[{gi}]");
        if let Some(k) = add_group(&mut b, g, &field)? {
            kulisa_lengths.push(k);
        }
        attach_ready(&mut b, &mut pending)?;
    }
    if let Some(&(i, p)) = pending.first() {
        let (field, why) = if b.m.link_by_number(p.link.value).is_none() {
            ("link", format!("link {} is not formed by the crank or any group", p.link.value))
        } else {
            ("from", "it refers to a point that is never defined on that link".to_string())
        };
        return Err(invalid(
            at(&p.name),
            format!("mechanism.points[{i}].{field}"),
            format!("point '{}' cannot be placed: {why}", p.name.value),
        )
        .kind(Kind::Reference));
    }
    b.m.output = resolve_output(&b, spec)?;
    b.m.size = b.m.measure_size();
    let default = Spanned::new(AnalysisSpec::default(), Location::UNKNOWN, Location::UNKNOWN);
    let settings = settings(&analysis.unwrap_or(&default).value, sense)?;
    let forces = forces.map(|f| super::lever_forces::build_forces(f, &b.m, warnings)).transpose()?;
    let assumptions = spec.assumptions.iter().map(|a| a.value.clone()).collect();
    Ok(LeverProject { mechanism: b.m, settings, forces, kulisa_lengths, assumptions })
}

/// Point names and assumptions reach the sheet: the checks of [`text`].
fn check_texts(spec: &MechanismSpec) -> Result<(), Refusal> {
    let mut names: Vec<(String, &Name)> =
        spec.frame.iter().enumerate().map(|(i, f)| (format!("mechanism.frame[{i}].name"), &f.name)).collect();
    names.push(("mechanism.crank.pin".into(), &spec.crank.pin));
    names.extend(spec.points.iter().enumerate().map(|(i, p)| (format!("mechanism.points[{i}].name"), &p.name)));
    for (i, g) in spec.groups.iter().enumerate() {
        match &g.value {
            GroupSpec::Rrr(r) => names.push((format!("mechanism.groups[{i}].rrr.point"), &r.point)),
            GroupSpec::Rrp(r) => names.push((format!("mechanism.groups[{i}].rrp.point"), &r.point)),
            GroupSpec::Rpr(r) => {
                names.extend(r.image.as_ref().map(|n| (format!("mechanism.groups[{i}].rpr.image"), n)))
            }
        }
    }
    for (field, n) in names {
        text::check(&field, n, Lines::One)?;
    }
    for (i, a) in spec.assumptions.iter().enumerate() {
        text::check_local(&format!("mechanism.assumptions[{i}]"), a, Lines::Many)?;
    }
    Ok(())
}

/// Lengths that look like millimetres or are vanishingly small, and absurd speeds.
fn plausibility(spec: &MechanismSpec, warnings: &mut Vec<Warning>) {
    let mut length = |loc: Location, field: &str, x: f64| {
        if x > limits::LENGTH_LOOKS_LIKE_MM {
            warnings.push(warning(
                loc,
                field,
                format!(
                    "{x} m is longer than {} m: lengths are in metres; is it millimetres?",
                    limits::LENGTH_LOOKS_LIKE_MM
                ),
            ));
        } else if x > 0.0 && x < limits::LENGTH_TINY {
            warnings.push(warning(
                loc,
                field,
                format!("{x} m is shorter than {} mm: lengths are in metres", limits::LENGTH_TINY * 1e3),
            ));
        }
    };
    length(at(&spec.crank.length), "mechanism.crank.length", spec.crank.length.value.0);
    for (i, g) in spec.groups.iter().enumerate() {
        let field = format!("mechanism.groups[{i}]");
        match &g.value {
            GroupSpec::Rrr(r) => r.lengths.iter().for_each(|l| length(at(g), &format!("{field}.rrr.lengths"), l.0)),
            GroupSpec::Rrp(r) => length(at(g), &format!("{field}.rrp.length"), r.length.0),
            GroupSpec::Rpr(r) => r.length.iter().for_each(|l| length(at(g), &format!("{field}.rpr.length"), l.0)),
        }
    }
    for f in &spec.frame {
        let r = Vec2::new(f.at[0].0, f.at[1].0).norm();
        if r > limits::LENGTH_LOOKS_LIKE_MM {
            warnings.push(warning(
                at(&f.name),
                "mechanism.frame.at",
                format!(
                    "point {} lies {r} m from the origin: coordinates are in metres; is it millimetres?",
                    f.name.value
                ),
            ));
        }
    }
    if let Some(n) = &spec.crank.rpm
        && n.value.0 > limits::RPM_PLAUSIBLE_MAX
    {
        warnings.push(warning(
            at(n),
            "mechanism.crank.rpm",
            format!("{} rev/min is above {:e}: is the crank speed in rev/min?", n.value.0, limits::RPM_PLAUSIBLE_MAX),
        ));
    }
    if let Some(w) = &spec.crank.omega
        && w.value.0 * 30.0 / std::f64::consts::PI > limits::RPM_PLAUSIBLE_MAX
    {
        warnings.push(warning(
            at(w),
            "mechanism.crank.omega",
            format!("ω1 = {} 1/s is above {:e} rev/min: is ω1 in 1/s (rad/s)?", w.value.0, limits::RPM_PLAUSIBLE_MAX),
        ));
    }
}

/// |ω1|, 1/s, from `rpm` (ω = π·n/30) or `omega`: exactly one of them.
fn crank_speed(c: &CrankSpec) -> Result<f64, Refusal> {
    match (&c.rpm, &c.omega) {
        (Some(n), None) => Ok(std::f64::consts::PI * n.value.0 / 30.0),
        (None, Some(w)) => Ok(w.value.0),
        (Some(_), Some(w)) => Err(invalid(
            at(w),
            "mechanism.crank.omega",
            "give the crank's speed once: `rpm` (rev/min) or `omega` (1/s)",
        )),
        (None, None) => {
            Err(invalid(at(&c.pivot), "mechanism.crank", "the crank needs its speed: `rpm` (rev/min) or `omega` (1/s)"))
        }
    }
}

fn add_group(b: &mut Builder, g: &Spanned<GroupSpec>, field: &str) -> Result<Option<(LinkId, Option<f64>)>, Refusal> {
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
fn attach_ready(b: &mut Builder, pending: &mut Vec<(usize, &PointSpec)>) -> Result<(), Refusal> {
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

fn resolve_output(b: &Builder, spec: &MechanismSpec) -> Result<Output, Refusal> {
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

fn settings(a: &AnalysisSpec, sense: f64) -> Result<Settings, Refusal> {
    let n = a.positions.value;
    if n != 8 && n != 12 {
        return Err(invalid(
            at(&a.positions),
            "analysis.positions",
            format!("the course draws 8 or 12 crank positions, not {n}"),
        ));
    }
    let start = match a.start_deg {
        Some(d) => Start::Angle(d.0.to_radians()),
        None if a.start == StartExtreme::Max => Start::Max,
        None => Start::Min,
    };
    if let Some(d) = a.assigned_deg.as_ref().filter(|d| !(0.0..360.0).contains(&d.value.0)) {
        return Err(invalid(at(d), "analysis.assigned_deg", format!("φ1 must lie in 0…360°, got {}°", d.value.0)));
    }
    let acceleration_plans = match &a.acceleration_plans {
        Some(list) => {
            if list.value.is_empty() || list.value.len() > 6 {
                return Err(invalid(
                    at(list),
                    "analysis.acceleration_plans",
                    "give 1 to 6 positions (the course asks for 4–6)",
                ));
            }
            let mut v = vec![];
            for &k in &list.value {
                if k as usize >= n as usize {
                    return Err(invalid(
                        at(list),
                        "analysis.acceleration_plans",
                        format!("position {k} does not exist: positions are 0…{}", n - 1),
                    ));
                }
                if v.contains(&(k as usize)) {
                    return Err(invalid(
                        at(list),
                        "analysis.acceleration_plans",
                        format!("position {k} is listed twice"),
                    ));
                }
                v.push(k as usize);
            }
            v
        }
        None => (0..4).map(|i| 1 + i * n as usize / 4).collect(),
    };
    Ok(Settings {
        sense,
        start,
        positions: n as usize,
        assigned_deg: a.assigned_deg.as_ref().map(|d| d.value.0),
        acceleration_plans,
    })
}

/// A sheet-1 analysis error as a refusal of the field that causes it: an Assur group that
/// cannot be assembled or passes a dead point is its entry in `mechanism.groups` (the crank,
/// `mechanism.crank`), a force analysis that has no solution is φ1 (`analysis.assigned_deg`),
/// a load on a slider that does not move is the load.
pub fn refusal_of_analysis(e: &AnalysisError, places: &Places) -> Refusal {
    use crate::lever::motion::MotionError as M;
    let path = match e {
        AnalysisError::Motion(M::NeverAssembles { index, .. })
        | AnalysisError::Motion(M::CannotAssemble { index, .. })
        | AnalysisError::Motion(M::DeadPoint { index, .. }) => match index {
            Some(g) => format!("mechanism.groups[{g}]"),
            None => "mechanism.crank".to_string(),
        },
        AnalysisError::Motion(M::NoExtreme { .. }) => "analysis.start".to_string(),
        AnalysisError::Motion(M::Search { .. }) | AnalysisError::NotFinite { .. } => "mechanism".to_string(),
        AnalysisError::Force { .. } | AnalysisError::ForceNotFinite { .. } => "analysis.assigned_deg".to_string(),
        AnalysisError::ZeroStroke { .. } => "forces.loads".to_string(),
    };
    Refusal::new(Kind::Design, (0, 0), path, e.to_string()).placed(places)
}
