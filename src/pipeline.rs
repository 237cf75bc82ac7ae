//! From a project file to finished outputs: the one path the CLI, the tests and the
//! benchmarks share. Computes only what the requested sheets need.

use crate::analysis::{self, AnalysisError, Kinematics};
use crate::backend::{raster, svg};
use crate::mechanics::Mechanism;
use crate::model::{self, ModelError, ProjectFile, Settings};
use crate::report::{self, NumTable};
use crate::sheet::scene::Scene;
use crate::sheet::sheet1::{self, Scales, Sheet1Input};

/// The guide's worked example (the vibrating conveyor), embedded as the default project.
pub const DEFAULT_PROJECT: &str = include_str!("../fixtures/worked-example.yaml");

#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error("project file")]
    Model(#[from] ModelError),
    #[error("mechanism")]
    Analysis(#[from] AnalysisError),
    #[error("output")]
    Backend(#[from] raster::BackendError),
}

/// A parsed and resolved project.
pub struct Project {
    pub file: ProjectFile,
    pub mechanism: Mechanism,
    pub settings: Settings,
}

pub fn load(text: &str) -> Result<Project, Error> {
    let file = model::parse(text)?;
    let (mechanism, settings) = model::build(&file)?;
    Ok(Project { file, mechanism, settings })
}

/// Sheet 1 with everything computed for it.
pub struct Sheet1Result {
    pub kinematics: Kinematics,
    pub scene: Scene,
    pub scales: Scales,
    pub svg: String,
    pub tables: (NumTable, NumTable),
}

pub fn sheet1(p: &Project) -> Result<Sheet1Result, Error> {
    let kinematics = analysis::kinematics(&p.mechanism, &p.settings)?;
    let tables = report::sheet1_tables(&p.mechanism, &kinematics);
    let input = Sheet1Input { info: &p.file.project, settings: &p.settings, assumptions: &p.file.mechanism.assumptions, tables: &tables };
    let s = sheet1::compose(&input, &p.mechanism, &kinematics);
    let svg = svg::write(&s.scene);
    Ok(Sheet1Result { kinematics, scene: s.scene, scales: s.scales, svg, tables })
}

/// PDF and PNG of a written SVG.
pub fn pdf_and_png(svg_text: &str, scene: &Scene, png_dpi: Option<f64>) -> Result<(Vec<u8>, Option<Vec<u8>>), Error> {
    let tree = raster::parse(svg_text)?;
    let pdf = raster::pdf(&tree, scene.width, scene.height)?;
    let png = match png_dpi {
        Some(dpi) => Some(raster::png(&tree, scene.width, scene.height, dpi)?),
        None => None,
    };
    Ok((pdf, png))
}
