//! Resolves the `mechanism`, `analysis` and `forces` sections into the lever domain: a
//! [`Mechanism`], its analysis [`Settings`] and [`ForceModel`], checking every
//! cross-reference (point names, link numbers) with its location.

mod build;
mod forces;
mod plausibility;
mod settings;

use super::forces::ForcesSpec;
use super::mechanism::*;
use super::text::{self, Lines};
use super::values::Name;
use super::{Kind, Places, Refusal, Warning, at, invalid};
use crate::lever::Settings;
use crate::lever::analysis::AnalysisError;
use crate::lever::kinetostatics::ForceModel;
use crate::lever::linkage::{LinkId, LinkKind, Mechanism, Output, Step};
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

/// Resolves the lever sections; plausibility warnings go to `warnings`.
pub fn resolve(
    spec: &Spanned<MechanismSpec>,
    analysis: Option<&Spanned<AnalysisSpec>>,
    forces: Option<&Spanned<ForcesSpec>>,
    warnings: &mut Vec<Warning>,
) -> Result<LeverProject, Refusal> {
    let spec = &spec.value;
    check_texts(spec)?;
    plausibility::plausibility(spec, warnings);
    let sense = spec.crank.sense;
    let omega1 = sense.sign() * crank_speed(&spec.crank)?;
    let mut b = build::Builder {
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
    build::attach_ready(&mut b, &mut pending)?;
    let mut kulisa_lengths = vec![];
    for (gi, g) in spec.groups.iter().enumerate() {
        let field = format!("mechanism.groups[{gi}]");
        if let Some(k) = build::add_group(&mut b, g, &field)? {
            kulisa_lengths.push(k);
        }
        build::attach_ready(&mut b, &mut pending)?;
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
    b.m.output = build::resolve_output(&b, spec)?;
    b.m.size = b.m.measure_size();
    let default = Spanned::new(AnalysisSpec::default(), Location::UNKNOWN, Location::UNKNOWN);
    let settings = settings::settings(&analysis.unwrap_or(&default).value, sense, forces.is_some(), warnings)?;
    let forces = forces.map(|f| forces::build_forces(f, &b.m, warnings)).transpose()?;
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
