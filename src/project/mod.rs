//! The project file (YAML) and its resolution into the domains' inputs.
//!
//! One file per section of the file format (`info`, `mechanism`, `forces`, `gears`, `cam`);
//! `lever` and `lever_forces` resolve the lever sections into [`crate::lever`] types, `gears`
//! sheet 2's section and `cam` sheet 3's, checking every cross-reference with its line and
//! column. Text that reaches a sheet is checked in [`text`]; input that is valid but almost
//! surely a mistake gives a [`Warning`].

pub mod cam;
mod cam_design;
pub mod forces;
pub mod gears;
pub mod info;
mod lever;
mod lever_forces;
pub mod mechanism;
pub mod text;
pub mod values;

pub use cam::CamProject;
pub use gears::GearsProject;
pub use info::ProjectInfo;
pub use lever::LeverProject;

use forces::ForcesSpec;
use info::InfoSpec;
use mechanism::{AnalysisSpec, MechanismSpec};
use serde::Deserialize;
use serde_saphyr::{Location, Spanned};

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProjectFile {
    pub project: InfoSpec,
    /// The lever mechanism of sheet 1.
    #[serde(default)]
    pub mechanism: Option<Spanned<MechanismSpec>>,
    #[serde(default)]
    pub analysis: Option<Spanned<AnalysisSpec>>,
    /// The force analysis at φ1 (`analysis.assigned_deg`); absent: sheet 1 has kinematics only.
    #[serde(default)]
    pub forces: Option<Spanned<ForcesSpec>>,
    /// The external pair and the planetary stage of sheet 2.
    #[serde(default)]
    pub gears: Option<Spanned<gears::GearsSpec>>,
    /// The cam of sheet 3.
    #[serde(default)]
    pub cam: Option<Spanned<cam::CamSpecFile>>,
}

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
}

/// An error in the user's project file, always with where it is.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The YAML does not parse or does not fit the schema (the message has line and column).
    #[error("{0}")]
    Yaml(String),
    #[error("line {line}, column {column}: {field}: {message}")]
    Invalid { line: u64, column: u64, field: String, message: String },
}

/// Input that builds but is almost surely a mistake (printed; the build continues).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}, column {column}: {field}: {message}")]
pub struct Warning {
    pub line: u64,
    pub column: u64,
    pub field: String,
    pub message: String,
}

/// Where a value was written, for error messages.
pub(crate) fn at<T>(s: &Spanned<T>) -> Location {
    s.referenced
}

pub(crate) fn invalid(loc: Location, field: impl Into<String>, message: impl Into<String>) -> ModelError {
    ModelError::Invalid { line: loc.line(), column: loc.column(), field: field.into(), message: message.into() }
}

pub(crate) fn warning(loc: Location, field: impl Into<String>, message: impl Into<String>) -> Warning {
    Warning { line: loc.line(), column: loc.column(), field: field.into(), message: message.into() }
}

/// Parses a project file from YAML text.
pub fn parse(text: &str) -> Result<ProjectFile, ModelError> {
    serde_saphyr::from_str(text).map_err(|e| {
        let msg = e.to_string();
        ModelError::Yaml(msg.strip_prefix("error: ").unwrap_or(&msg).to_string())
    })
}

/// Parses and resolves a project file.
pub fn load(text: &str) -> Result<Project, ModelError> {
    resolve(&parse(text)?)
}

/// Checks the file's text and resolves each section it has.
pub fn resolve(file: &ProjectFile) -> Result<Project, ModelError> {
    for (field, t) in file.project.texts() {
        text::check(field, t, text::Lines::One)?;
    }
    for (field, t) in file.project.local_texts() {
        text::check_local(field, t, text::Lines::One)?;
    }
    let mut warnings = Vec::new();
    let lever = match &file.mechanism {
        Some(m) => Some(lever::resolve(m, file.analysis.as_ref(), file.forces.as_ref(), &mut warnings)?),
        None => {
            let orphan = [
                file.analysis.as_ref().map(|a| ("analysis", a.referenced)),
                file.forces.as_ref().map(|f| ("forces", f.referenced)),
            ];
            if let Some((section, loc)) = orphan.into_iter().flatten().next() {
                return Err(invalid(
                    loc,
                    section,
                    "this section belongs to the lever mechanism: add a `mechanism` section",
                ));
            }
            None
        }
    };
    let crank_rpm = lever.as_ref().map(|l| l.mechanism.omega1.abs() * 30.0 / std::f64::consts::PI);
    let gears = match &file.gears {
        Some(g) => Some(gears::resolve(g, crank_rpm, &mut warnings)?),
        None => None,
    };
    let cam = match &file.cam {
        Some(c) => Some(cam::resolve(c, &mut warnings)?),
        None => None,
    };
    if lever.is_none() && gears.is_none() && cam.is_none() {
        return Err(ModelError::Yaml(
            "the project has nothing to draw: add a `mechanism` section (sheet 1), a `gears` section (sheet 2) or a `cam` section (sheet 3); `tmm example` prints one".into(),
        ));
    }
    Ok(Project { info: file.project.resolve(), lever, gears, cam, warnings })
}
