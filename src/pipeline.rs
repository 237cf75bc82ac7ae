//! From a project file to finished outputs: the one path the CLI, the tests and the
//! benchmarks share. It builds the sheets [`sheets::select`] picks, each computing only
//! what it needs, and never names a sheet.

pub use crate::backend::Format;
use crate::backend::{self, BackendError, svg};
use crate::project::{self, ModelError, Project};
use crate::report;
use crate::sheets::{self, COURSE, Context, SelectError, SheetError, SheetOutput};
use serde::Serialize;

/// The guide's worked example (the vibrating conveyor), embedded as the default project.
pub const DEFAULT_PROJECT: &str = include_str!("../fixtures/worked-example.yaml");

#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error("project file")]
    Project(#[from] ModelError),
    #[error(transparent)]
    Select(#[from] SelectError),
    #[error("sheet {number}")]
    Sheet { number: u32, source: SheetError },
    #[error("output")]
    Backend(#[from] BackendError),
}

/// Parses and resolves a project file.
pub fn load(text: &str) -> Result<Project, Error> {
    Ok(project::load(text)?)
}

/// A built sheet and its SVG text.
#[derive(Debug, Clone)]
pub struct Built {
    pub output: SheetOutput,
    pub svg: String,
}

/// Builds the `requested` sheets (all the project has sections for when empty), in order.
pub fn build(p: &Project, requested: &[u32]) -> Result<Vec<Built>, Error> {
    let ctx = Context { info: &p.info, sheet_count: COURSE.len() as u32 };
    sheets::select(p, requested)?
        .iter()
        .map(|sheet| {
            let number = sheet.kind().number;
            let output = sheet.build(&ctx).map_err(|source| Error::Sheet { number, source })?;
            let svg = svg::write(&output.scene)?;
            Ok(Built { output, svg })
        })
        .collect()
}

#[derive(Serialize)]
struct Results<'a> {
    units: &'static str,
    title: &'a str,
    #[serde(flatten)]
    sheets: serde_json::Map<String, serde_json::Value>,
}

/// `results.json`: the title and each built sheet's section under `sheet<N>`.
pub fn results_json(p: &Project, built: &[Built]) -> String {
    let sheets = built.iter().map(|b| (format!("sheet{}", b.output.number), b.output.results.clone())).collect();
    let r = Results { units: "SI: m, m/s, m/s², rad, rad/s, rad/s², kg, N, N·m", title: p.info.title(), sheets };
    serde_json::to_string_pretty(&r).expect("results serialise")
}

/// The formats a build writes: the SVG always, then the PDF and the PNG preview (at
/// `png_dpi`) when asked for, in that order.
pub fn formats(pdf: bool, png_dpi: Option<f64>) -> Vec<Format> {
    let mut f = vec![Format::Svg];
    if pdf {
        f.push(Format::Pdf);
    }
    f.extend(png_dpi.map(|dpi| Format::Png { dpi }));
    f
}

/// A built sheet in one format: its SVG as [`build`] wrote it, or what the format's backend
/// draws from the scene.
pub fn render(b: &Built, format: Format) -> Result<Vec<u8>, Error> {
    match format {
        Format::Svg => Ok(b.svg.clone().into_bytes()),
        _ => Ok(backend::write(&b.output.scene, format)?),
    }
}

/// Every output file of a build as (name, bytes), in a fixed order: per sheet its drawing in
/// each of `formats` in their order, its tables as CSV and Markdown; then `results.json`.
pub fn outputs(p: &Project, built: &[Built], formats: &[Format]) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files = Vec::new();
    for b in built {
        let stem = format!("sheet{}", b.output.number);
        for &f in formats {
            files.push((format!("{stem}.{}", f.extension()), render(b, f)?));
        }
        let mut md = String::new();
        for t in &b.output.tables {
            files.push((format!("{stem}-{}.csv", t.stem), report::csv(&t.table).into_bytes()));
            if !md.is_empty() {
                md.push('\n');
            }
            md.push_str(&report::markdown(t));
        }
        files.push((format!("{stem}-tables.md"), md.into_bytes()));
    }
    files.push(("results.json".into(), results_json(p, built).into_bytes()));
    Ok(files)
}
