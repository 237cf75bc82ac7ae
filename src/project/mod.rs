//! The project file (YAML) and its resolution into the domains' inputs.
//!
//! One file per section of the file format (`info`, `mechanism`, `forces`, `gears`, `cam`);
//! `lever` resolves the lever sections into [`crate::lever`] types, `gears`
//! sheet 2's section and `cam` sheet 3's, checking every cross-reference with its line and
//! column. Text that reaches a sheet is checked in [`text`]; input that is valid but almost
//! surely a mistake gives a [`Warning`].

pub mod cam;
pub mod forces;
pub mod gears;
pub mod info;
mod lever;
pub mod mechanism;
pub mod places;
mod refusal;
pub mod text;
pub mod values;
mod yaml;

pub use cam::CamProject;
pub use gears::GearsProject;
pub use info::ProjectInfo;
pub use lever::{LeverProject, refusal_of_analysis};
pub use places::Places;
pub use refusal::{Kind, Refusal, Warning};

pub(crate) use refusal::{invalid, warning};

use crate::drawing::labels::Language;
use forces::ForcesSpec;
use info::InfoSpec;
use mechanism::{AnalysisSpec, MechanismSpec};
use serde::Deserialize;
use serde::de::IgnoredAny;
use serde_saphyr::{Location, Spanned};

/// The file's top level. Each sheet's sections are read on their own (the others as
/// [`IgnoredAny`]), so that a broken `cam` section leaves sheets 1 and 2 buildable.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Sections<P, M, A, F, G, C> {
    project: P,
    /// The lever mechanism of sheet 1.
    #[serde(default = "Option::default")]
    mechanism: Option<M>,
    #[serde(default = "Option::default")]
    analysis: Option<A>,
    /// The force analysis at φ1 (`analysis.assigned_deg`); absent: sheet 1 has kinematics only.
    #[serde(default = "Option::default")]
    forces: Option<F>,
    /// The external pair and the planetary stage of sheet 2.
    #[serde(default = "Option::default")]
    gears: Option<G>,
    /// The cam of sheet 3.
    #[serde(default = "Option::default")]
    cam: Option<C>,
}

type Any = IgnoredAny;
type Shape = Sections<Any, Any, Any, Any, Any, Any>;
type InfoPart = Sections<InfoSpec, Any, Any, Any, Any, Any>;
type LeverPart = Sections<Any, Spanned<MechanismSpec>, Spanned<AnalysisSpec>, Spanned<ForcesSpec>, Any, Any>;
type GearsPart = Sections<Any, Any, Any, Any, Spanned<gears::GearsSpec>, Any>;
type CamPart = Sections<Any, Any, Any, Any, Any, Spanned<cam::CamSpecFile>>;

/// A resolved project: what each sheet needs, and the warnings about its input.
#[derive(Debug, Clone)]
pub struct Project {
    pub info: ProjectInfo,
    /// Sheet 1's mechanism, when the file has a `mechanism` section.
    pub lever: Option<LeverProject>,
    /// Sheet 2's gears, when the file has a `gears` section.
    pub gears: Option<GearsProject>,
    /// Sheet 3's cam, when the file has a `cam` section.
    pub cam: Option<CamProject>,
    pub warnings: Vec<Warning>,
    /// Where every field is written, to place a refusal found later by its field.
    pub places: Places,
}

/// Where a value was written, for error messages.
pub(crate) fn at<T>(s: &Spanned<T>) -> Location {
    s.referenced
}

/// The section a field's path belongs to: the lever's three sections are one.
fn section_of(path: &str) -> Option<&'static str> {
    match path.split(['.', '[']).next() {
        Some("mechanism" | "analysis" | "forces") => Some("mechanism"),
        Some("gears") => Some("gears"),
        Some("cam") => Some("cam"),
        _ => None,
    }
}

/// Parses and resolves a project file; refuses it when any section is refused.
pub fn load(text: &str) -> Result<Project, Refusal> {
    let (project, refused) = load_sections(text)?;
    match refused.into_iter().next() {
        Some(r) => Err(r),
        None => Ok(project),
    }
}

/// Parses and resolves a project file section by section: the project, and the refusal of
/// each section that cannot be resolved (its sheet cannot be built; the others can). A
/// refusal of the whole file (its syntax, its top level, the `project` section) is the error.
pub fn load_sections(text: &str) -> Result<(Project, Vec<Refusal>), Refusal> {
    let places = Places::of(text);
    let blank = |l: &str| l.trim().is_empty() || l.trim_start().starts_with('#');
    if places.is_empty() && text.lines().all(blank) {
        return Err(Refusal::new(
            Kind::Section,
            (1, 1),
            "",
            "the file is empty: a project file starts with a `project` section; `tmm example` prints one",
        ));
    }
    yaml::read::<Shape>(text, &places)?;
    let duplicates: Vec<Refusal> = places
        .duplicates
        .iter()
        .map(|d| {
            let cause = format!("the key `{}` is written twice in one mapping", d.key);
            let r = Refusal::new(Kind::Key, (d.line, d.column), d.path.clone(), cause);
            match section_of(&d.path) {
                Some(s) => r.in_section(s),
                None => r,
            }
        })
        .collect();
    if let Some(global) = duplicates.iter().find(|r| r.section.is_none()) {
        return Err(global.clone());
    }
    let info = resolve_info(&yaml::read::<InfoPart>(text, &places)?.project)?;
    let mut warnings = Vec::new();
    if let Some(w) = blank_designation(&info, &places) {
        warnings.push(w);
    }
    let mut refused: Vec<Refusal> = Vec::new();
    let mut sections = Sectioned { duplicates: &duplicates, places: &places, refused: &mut refused };
    let lever = sections.take("mechanism", read_lever(text, &places, &mut warnings));
    let crank_rpm = match &lever {
        Some(l) => Some(l.mechanism.omega1.abs() * 30.0 / std::f64::consts::PI),
        None => written_crank_rpm(text, &places),
    };
    let omega = places.has("mechanism.crank.omega");
    let field = if omega { "mechanism.crank.omega" } else { "mechanism.crank.rpm" };
    let crank = crank_rpm.map(|rpm| gears::CrankSpeed { rpm, field });
    let gears = read_gears(text, &places, crank, &mut warnings).map_err(|r| {
        // n1 defaults to the crank's speed: say why it is missing when the crank is refused.
        let mechanism_refused = sections.refused.iter().any(|m| m.section == Some("mechanism"));
        if r.path == "gears.output_rpm" && crank_rpm.is_none() && mechanism_refused {
            let cause =
                format!("{} (the crank's speed would give it, but the `mechanism` section is refused)", r.cause);
            Refusal { cause, ..r }
        } else {
            r
        }
    });
    let gears = sections.take("gears", gears);
    let cam = sections.take("cam", read_cam(text, &places, &mut warnings));
    if lever.is_none() && gears.is_none() && cam.is_none() && refused.is_empty() {
        return Err(Refusal::new(
            Kind::Section,
            (1, 1),
            "",
            "the project has nothing to draw: add a `mechanism` section (sheet 1), a `gears` section (sheet 2) or a `cam` section (sheet 3); `tmm example` prints one",
        ));
    }
    refused.sort_by_key(|r| (r.line, r.column));
    Ok((Project { info, lever, gears, cam, warnings, places }, refused))
}

/// Collects the sections' refusals: a key written twice in a section refuses it first.
struct Sectioned<'a> {
    duplicates: &'a [Refusal],
    places: &'a Places,
    refused: &'a mut Vec<Refusal>,
}

impl Sectioned<'_> {
    /// The section's value, or `None` with its refusal recorded.
    fn take<T>(&mut self, section: &'static str, result: Result<Option<T>, Refusal>) -> Option<T> {
        let duplicate = self.duplicates.iter().find(|r| r.section == Some(section)).cloned();
        match duplicate.map(Err).unwrap_or(result) {
            Ok(v) => v,
            Err(r) => {
                self.refused.push(r.in_section(section).placed(self.places));
                None
            }
        }
    }
}

/// A sheet without a designation (GOST 2.104's main field) is almost surely unfinished: said
/// where it belongs (at the `project` section when the key is absent).
fn blank_designation(info: &ProjectInfo, places: &Places) -> Option<Warning> {
    let blank = Language::ALL.iter().all(|&l| info.designation.get(l).trim().is_empty());
    let (line, column) =
        places.place_of("project.designation").or_else(|| places.place_of("project")).unwrap_or((1, 1));
    blank.then(|| Warning {
        line,
        column,
        field: "project.designation".into(),
        message:
            "no designation: the title block's main field stays empty (the course writes e.g. \"MMN KL 01.00.00\")"
                .into(),
    })
}

/// Checks the `project` section's texts and resolves it.
fn resolve_info(spec: &InfoSpec) -> Result<ProjectInfo, Refusal> {
    for (field, t) in spec.texts() {
        text::check(field, t, text::Lines::One)?;
    }
    for (field, t) in spec.local_texts() {
        text::check_local(field, t, text::Lines::One)?;
    }
    Ok(spec.resolve())
}

/// Sheet 1's sections, when the file has a `mechanism` (an `analysis` or `forces` section
/// without one is refused).
fn read_lever(text: &str, places: &Places, warnings: &mut Vec<Warning>) -> Result<Option<LeverProject>, Refusal> {
    let part: LeverPart = yaml::read(text, places)?;
    match &part.mechanism {
        Some(m) => Ok(Some(lever::resolve(m, part.analysis.as_ref(), part.forces.as_ref(), warnings)?)),
        None => {
            let orphan = [
                part.analysis.as_ref().map(|a| ("analysis", a.referenced)),
                part.forces.as_ref().map(|f| ("forces", f.referenced)),
            ];
            match orphan.into_iter().flatten().next() {
                Some((section, loc)) => {
                    Err(invalid(loc, section, "this section belongs to the lever mechanism: add a `mechanism` section")
                        .kind(Kind::Section))
                }
                None => Ok(None),
            }
        }
    }
}

/// The crank's speed as written, rev/min, when the mechanism section is refused for
/// another reason: sheet 2 takes n1 from it all the same.
fn written_crank_rpm(text: &str, places: &Places) -> Option<f64> {
    let part: LeverPart = yaml::read(text, places).ok()?;
    let crank = &part.mechanism?.value.crank;
    match (&crank.rpm, &crank.omega) {
        (Some(n), None) => Some(n.value.0),
        (None, Some(w)) => Some(w.value.0 * 30.0 / std::f64::consts::PI),
        _ => None,
    }
}

/// Sheet 2's section; `crank` is the mechanism's crank speed when there is one.
fn read_gears(
    text: &str,
    places: &Places,
    crank: Option<gears::CrankSpeed>,
    warnings: &mut Vec<Warning>,
) -> Result<Option<GearsProject>, Refusal> {
    let part: GearsPart = yaml::read(text, places)?;
    part.gears.as_ref().map(|g| gears::resolve(g, crank, warnings)).transpose()
}

/// Sheet 3's section.
fn read_cam(text: &str, places: &Places, warnings: &mut Vec<Warning>) -> Result<Option<CamProject>, Refusal> {
    let part: CamPart = yaml::read(text, places)?;
    part.cam.as_ref().map(|c| cam::resolve(c, warnings)).transpose()
}
