//! From a project file to finished outputs: the one path the CLI, the tests and the
//! benchmarks share. It builds the sheets [`sheets::select`] picks, each computing only
//! what it needs, and never names a sheet.

pub use crate::backend::Format;
pub use crate::backend::dxf::DxfVersion;
use crate::backend::{self, BackendError, svg};
use crate::check;
use crate::project::{self, Project, Refusal, Warning};
use crate::report;
use crate::sheets::{self, Context, SheetOutput};
/// The course's sheets, their numbers and the project sections they draw.
pub use crate::sheets::{COURSE, LAYOUT_FAULTS};
use rayon::prelude::*;
use serde::Serialize;

/// The guide's worked example (the vibrating conveyor), embedded as the default project.
pub const DEFAULT_PROJECT: &str = include_str!("../fixtures/worked-example.yaml");

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The project, or a sheet asked for, is refused.
    #[error("{}", .0.refusal)]
    Refused(Box<Refused>),
    #[error("output")]
    Backend(#[from] BackendError),
}

/// A refusal (kind, field, place, cause) and what it means for the sheets.
#[derive(Debug, Clone, PartialEq)]
pub struct Refused {
    pub refusal: Refusal,
    /// The sheets it keeps from being built (every sheet when the whole file is refused).
    pub blocks: Vec<u32>,
    /// The sheets the project has a resolved section for (empty when the file is refused
    /// as a whole).
    pub buildable: Vec<u32>,
}

impl From<Refusal> for Error {
    fn from(refusal: Refusal) -> Error {
        let blocks = match refusal.section {
            Some(section) => COURSE.iter().filter(|k| k.section == section).map(|k| k.number).collect(),
            None => sheet_numbers().collect(),
        };
        Error::Refused(Box::new(Refused { refusal, blocks, buildable: Vec::new() }))
    }
}

/// The numbers of the course project's sheets, in order (for checking a request).
pub fn sheet_numbers() -> impl Iterator<Item = u32> {
    COURSE.iter().map(|k| k.number)
}

/// The sheets a project has a resolved section for.
pub fn buildable(p: &Project) -> Vec<u32> {
    COURSE.iter().filter(|k| (k.make)(p).is_some()).map(|k| k.number).collect()
}

/// Parses and resolves a project file; any refused section refuses it.
pub fn load(text: &str) -> Result<Project, Error> {
    load_for(text, &[])
}

/// Parses and resolves a project file for building the `requested` sheets (every sheet
/// when empty): a refused section of a sheet not requested is a warning, not an error.
pub fn load_for(text: &str, requested: &[u32]) -> Result<Project, Error> {
    let (mut project, refused) = project::load_sections(text)?;
    let buildable = buildable(&project);
    for refusal in refused {
        let Error::Refused(mut r) = Error::from(refusal) else { unreachable!("a refusal converts to Refused") };
        if requested.is_empty() || r.blocks.iter().any(|b| requested.contains(b)) {
            r.buildable = buildable;
            return Err(Error::Refused(r));
        }
        let Refused { refusal, blocks, .. } = *r;
        let sheets: Vec<String> = blocks.iter().map(u32::to_string).collect();
        project.warnings.push(Warning {
            line: refusal.line,
            column: refusal.column,
            field: refusal.path.clone(),
            message: format!(
                "{} (so sheet {} cannot be built; it was not asked for)",
                refusal.cause,
                sheets.join(", ")
            ),
        });
    }
    Ok(project)
}

/// A built sheet and its SVG text.
#[derive(Debug, Clone)]
pub struct Built {
    pub output: SheetOutput,
    pub svg: String,
}

/// Builds the `requested` sheets (all the project has sections for when empty), in order.
pub fn build(p: &Project, requested: &[u32]) -> Result<Vec<Built>, Error> {
    crate::sheets::new_build();
    // The title block's "sheet N of M": the sheets the project has sections for, in the
    // course's order (a kinematics exercise drawn on the first sheet alone is one sheet, not
    // "1 of 3"; a cam alone is one sheet too, not "3 of 3").
    let own = buildable(p);
    let sheet_count = if own.is_empty() { COURSE.len() as u32 } else { own.len() as u32 };
    let sheet_no = |n: u32| own.iter().position(|&k| k == n).map_or(n, |i| i as u32 + 1);
    // The note's tables are numbered once across the sheets the project has.
    // And every title block letters its sheet's name at the height all the names fit at.
    let own_sheets: Vec<_> = COURSE.iter().filter_map(|k| (k.make)(p)).collect();
    let counts: Vec<(u32, u32)> = own_sheets.iter().map(|s| (s.kind().number, s.table_count())).collect();
    let first_table = |n: u32| 1 + counts.iter().filter(|(k, _)| *k < n).map(|(_, c)| c).sum::<u32>();
    let sheet_names: Vec<String> = own_sheets.iter().map(|s| s.name(p.info.language)).collect();
    let refused = |r: Refusal| match Error::from(r) {
        Error::Refused(mut r) => {
            r.buildable = buildable(p);
            Error::Refused(r)
        }
        other => other,
    };
    // The sheets share nothing: built on rayon's pool (one thread where there are no threads,
    // as in the browser), collected in order.
    sheets::select(p, requested)
        .map_err(|e| refused(e.refusal()))?
        .par_iter()
        .map(|sheet| {
            let n = sheet.kind().number;
            let ctx = Context {
                info: &p.info,
                sheet_no: sheet_no(n),
                sheet_count,
                first_table: first_table(n),
                sheet_names: &sheet_names,
            };
            let output = sheet.build(&ctx).map_err(|e| refused(e.refusal(sheet.kind(), &p.places)))?;
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
    /// Every segment a student measures, under its identifier (`sheet<N>.plan.v.3.pb`).
    segments: serde_json::Map<String, serde_json::Value>,
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
    let segments = built
        .iter()
        .flat_map(|b| b.output.segments.iter().map(move |s| (b.output.number, s)))
        .map(|(n, s)| (format!("sheet{n}.{}", s.id), serde_json::to_value(s).expect("a segment serialises")))
        .collect();
    let units = "SI: m, m/s, m/s², rad, rad/s, rad/s², kg, N, N·m";
    let r = Results { units, title: p.info.title(), sheets, answers, segments };
    serde_json::to_string_pretty(&r).expect("results serialise")
}

/// The formats a build writes: the SVG always, then the PDF, the PNG preview (at
/// `png_dpi`) and the DXF (in `dxf`'s version) when asked for, in that order.
pub fn formats(pdf: bool, png_dpi: Option<f64>, dxf: Option<DxfVersion>) -> Vec<Format> {
    let mut f = vec![Format::Svg];
    if pdf {
        f.push(Format::Pdf);
    }
    f.extend(png_dpi.map(|dpi| Format::Png { dpi }));
    f.extend(dxf.map(Format::Dxf));
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

/// What `tmm check` compares a student's values with: every answer key and measured
/// segment of the sheets the project has (a section refused leaves its sheet out; the
/// others still count).
pub fn reference(p: &Project) -> Result<check::Reference, Error> {
    let mut reference = check::Reference::default();
    let built = match build(p, &[]) {
        Err(Error::Refused(r)) if !r.buildable.is_empty() => {
            let others: Vec<u32> = r.buildable.iter().copied().filter(|n| !r.blocks.contains(n)).collect();
            if others.is_empty() {
                return Err(Error::Refused(r));
            }
            let reason = Error::Refused(r.clone()).to_string();
            reference.missing = r.blocks.iter().map(|&n| (n, reason.clone())).collect();
            build(p, &others)?
        }
        other => other?,
    };
    for b in &built {
        let prefix = format!("sheet{}", b.output.number);
        reference.answers.extend(b.output.tables.iter().flat_map(|t| t.answers(&prefix)));
        reference.segments.extend(b.output.segments.iter().map(|s| (format!("{prefix}.{}", s.id), s.clone())));
    }
    Ok(reference)
}

pub use crate::sheets::check_report::Names as ReportNames;

/// `tmm check`'s report to hand back, as a PDF of A4 pages in the project's language (see
/// [`sheets::check_report`]).
pub fn check_report_pdf(p: &Project, verdicts: &[check::Verdict], names: &ReportNames) -> Result<Vec<u8>, Error> {
    Ok(backend::pdf::write_pages(&sheets::check_report::pages(verdicts, names, p.info.language))?)
}

/// The overlay of every built sheet (see [`sheets::scaffold::overlay`]) as
/// `sheet<N>-overlay.svg` and `.pdf`: its constructions alone, in one contrasting colour, at
/// their places on the A1 sheet.
pub fn overlays(built: &[Built]) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let per_sheet = built
        .par_iter()
        .map(|b| {
            let scene = sheets::scaffold::overlay(&b.output.scene);
            [Format::Svg, Format::Pdf]
                .into_iter()
                .map(|f| {
                    Ok((format!("sheet{}-overlay.{}", b.output.number, f.extension()), backend::write(&scene, f)?))
                })
                .collect::<Result<Vec<_>, Error>>()
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(per_sheet.into_iter().flatten().collect())
}

/// Every output file of a build as (name, bytes), in a fixed order: per sheet its files
/// ([`sheet_files`]); then `results.json`.
pub fn outputs(p: &Project, built: &[Built], formats: &[Format]) -> Result<Vec<(String, Vec<u8>)>, Error> {
    // Each sheet's files on rayon's pool (a PNG preview is drawn in strips, so two at once
    // stay within the memory budget); in order.
    let per_sheet = built.par_iter().map(|b| sheet_files(b, formats)).collect::<Result<Vec<_>, _>>()?;
    let mut files: Vec<(String, Vec<u8>)> = per_sheet.into_iter().flatten().collect();
    files.push(("results.json".into(), results_json(p, built).into_bytes()));
    Ok(files)
}

/// One built sheet's files as (name, bytes), in a fixed order: its drawing in each of
/// `formats` in their order, its tables as CSV and Markdown, its segments as CSV.
pub fn sheet_files(b: &Built, formats: &[Format]) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files = Vec::new();
    let stem = format!("sheet{}", b.output.number);
    for &f in formats {
        files.push((format!("{stem}.{}", f.extension()), render(b, f)?));
    }
    let mut md = String::new();
    for t in &b.output.tables {
        files.push((format!("{stem}-{}.csv", t.table.id), report::csv(t, &stem).into_bytes()));
        if !md.is_empty() {
            md.push('\n');
        }
        md.push_str(&report::markdown(t, &stem));
    }
    files.push((format!("{stem}-tables.md"), md.into_bytes()));
    if !b.output.segments.is_empty() {
        files.push((format!("{stem}-segments.csv"), report::segments_csv(&b.output.segments, &stem).into_bytes()));
    }
    Ok(files)
}
