//! From a project file to finished outputs: the one path the CLI, the tests and the
//! benchmarks share. Computes only what the requested sheets need.

use crate::analysis::{self, AnalysisError, ForceAnalysis, Kinematics};
use crate::sheet::forces_view::ForceScales;
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
    /// The force analysis at φ1 with tables 3–5, when the project asks for one.
    pub forces: Option<(ForceAnalysis, (NumTable, NumTable, NumTable))>,
    pub force_scales: Option<ForceScales>,
    pub scene: Scene,
    pub scales: Scales,
    pub svg: String,
    pub tables: (NumTable, NumTable),
}

pub fn sheet1(p: &Project) -> Result<Sheet1Result, Error> {
    let kinematics = analysis::kinematics(&p.mechanism, &p.settings)?;
    let tables = report::sheet1_tables(&p.mechanism, &kinematics);
    let forces = match &p.settings.forces {
        Some(model) => {
            let fa = analysis::forces(&p.mechanism, &kinematics, model)?;
            let t = report::force_tables(&p.mechanism, &fa);
            Some((fa, t))
        }
        None => None,
    };
    let input = Sheet1Input {
        info: &p.file.project,
        settings: &p.settings,
        assumptions: &p.file.mechanism.assumptions,
        tables: &tables,
        forces: forces.as_ref().map(|(fa, t)| (fa, t)),
    };
    let s = sheet1::compose(&input, &p.mechanism, &kinematics);
    let svg = svg::write(&s.scene);
    Ok(Sheet1Result { kinematics, forces, force_scales: s.force_scales, scene: s.scene, scales: s.scales, svg, tables })
}

/// PDF and PNG of a written SVG.
impl Sheet1Result {
    /// `results.json` for this sheet.
    pub fn json(&self, p: &Project) -> String {
        let forces = self.forces.as_ref().zip(self.force_scales.as_ref()).map(|((fa, _), sc)| (fa, sc));
        crate::results::json(&p.file.project.title, &p.mechanism, &self.kinematics, &self.scales, forces)
    }
}

pub fn pdf_and_png(svg_text: &str, scene: &Scene, png_dpi: Option<f64>) -> Result<(Vec<u8>, Option<Vec<u8>>), Error> {
    let tree = raster::parse(svg_text)?;
    let pdf = raster::pdf(&tree, scene.width, scene.height)?;
    let png = match png_dpi {
        Some(dpi) => Some(raster::png(&tree, scene.width, scene.height, dpi)?),
        None => None,
    };
    Ok((pdf, png))
}
