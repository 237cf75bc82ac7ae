//! From a project file to finished outputs: the one path the CLI, the tests and the
//! benchmarks share. It builds the sheets [`sheets::select`] picks, each computing only
//! what it needs, and never names a sheet.

use crate::backend::{raster, svg};
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
    Backend(#[from] raster::BackendError),
}

/// The numbers of the course project's sheets, in order (for checking a request).
pub fn sheet_numbers() -> impl Iterator<Item = u32> {
    COURSE.iter().map(|k| k.number)
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
    /// Every value of every note table under its identifier, in the table's unit.
    answers: serde_json::Map<String, serde_json::Value>,
}

/// `results.json`: the title, each built sheet's section under `sheet<N>`, and the answers
/// of the note's tables under their identifiers (`sheet<N>.<table>.<row>.<column>`).
pub fn results_json(p: &Project, built: &[Built]) -> String {
    let sheets = built.iter().map(|b| (format!("sheet{}", b.output.number), b.output.results.clone())).collect();
    let answers = built
        .iter()
        .flat_map(|b| {
            let prefix = format!("sheet{}", b.output.number);
            b.output.tables.iter().flat_map(move |t| t.answers(&prefix)).collect::<Vec<_>>()
        })
        .map(|a| (a.id.clone(), serde_json::to_value(&a).expect("an answer serialises")))
        .collect();
    let r =
        Results {
            units: "SI: m, m/s, m/s², rad, rad/s, rad/s², kg, N, N·m", title: p.info.title(), sheets, answers
        };
    serde_json::to_string_pretty(&r).expect("results serialise")
}

/// Which of the slower formats to produce besides the SVG.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Formats {
    pub pdf: bool,
    /// The PNG preview's resolution, dots per inch; `None`: no PNG.
    pub png_dpi: Option<f64>,
}

/// A sheet's PDF and PNG, each when asked for.
#[derive(Debug, Clone, Default)]
pub struct Rendered {
    pub pdf: Option<Vec<u8>>,
    pub png: Option<Vec<u8>>,
}

/// The PDF and PNG of a built sheet, only those asked for (the usvg tree is parsed once).
pub fn render(b: &Built, formats: Formats) -> Result<Rendered, Error> {
    if !formats.pdf && formats.png_dpi.is_none() {
        return Ok(Rendered::default());
    }
    let (w, h) = (b.output.scene.width, b.output.scene.height);
    let tree = raster::parse(&b.svg)?;
    let pdf = if formats.pdf { Some(raster::pdf(&tree, w, h)?) } else { None };
    let png = match formats.png_dpi {
        Some(dpi) => Some(raster::png(&tree, w, h, dpi)?),
        None => None,
    };
    Ok(Rendered { pdf, png })
}

/// Every output file of a build as (name, bytes), in a fixed order: per sheet its SVG, PDF,
/// PNG, tables as CSV and Markdown; then `results.json`.
pub fn outputs(p: &Project, built: &[Built], formats: Formats) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files = Vec::new();
    for b in built {
        let stem = format!("sheet{}", b.output.number);
        files.push((format!("{stem}.svg"), b.svg.clone().into_bytes()));
        let Rendered { pdf, png } = render(b, formats)?;
        files.extend(pdf.map(|x| (format!("{stem}.pdf"), x)));
        files.extend(png.map(|x| (format!("{stem}.png"), x)));
        let mut md = String::new();
        for t in &b.output.tables {
            files.push((format!("{stem}-{}.csv", t.table.id), report::csv(t, &stem).into_bytes()));
            if !md.is_empty() {
                md.push('\n');
            }
            md.push_str(&report::markdown(t, &stem));
        }
        files.push((format!("{stem}-tables.md"), md.into_bytes()));
    }
    files.push(("results.json".into(), results_json(p, built).into_bytes()));
    Ok(files)
}
