//! The program as library calls for an embedder — the web page (`web/`): a project's text
//! in, its files out, with no file system, no terminal and no threads. A build goes sheet by
//! sheet, so that the caller can show progress between them; the files, their names, order
//! and bytes are exactly `tmm build`'s (tests/session.rs compares them). Refusals and
//! warnings come back as data with their line and column, for an editor to point at.

use crate::catalogue::{Catalogue, Variant};
use crate::drawing::labels::Language;
use crate::pipeline::{self, Built, DxfVersion, Format};
use crate::project::Project;
use serde::Serialize;

/// What to build: the sheets (every sheet the project has a section for when empty), the
/// language (the project file's when `None`) and the formats beside the SVG, as `tmm build`'s
/// options say them.
#[derive(Debug, Clone, Default)]
pub struct Request {
    pub sheets: Vec<u32>,
    pub lang: Option<Language>,
    pub pdf: bool,
    pub dxf: Option<DxfVersion>,
    pub overlay: bool,
}

/// A refusal, or an output that could not be made, as data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Problem {
    /// The refusal's kind (`syntax`, `value`, … as a batch counts them), or `output`.
    pub kind: &'static str,
    /// 1-based; 0 when the problem has no place in the file (an output).
    pub line: u64,
    pub column: u64,
    /// The field's path (`gears.pair.z[1]`); empty for the document as a whole.
    pub field: String,
    pub cause: String,
    /// The whole message as the command line prints it after `in FILE: `.
    pub message: String,
    /// The sheets the problem keeps from being built, and those the project could build.
    pub blocks: Vec<u32>,
    pub buildable: Vec<u32>,
}

impl From<pipeline::Error> for Box<Problem> {
    fn from(e: pipeline::Error) -> Box<Problem> {
        Box::new(match e {
            pipeline::Error::Refused(r) => {
                let pipeline::Refused { refusal, blocks, buildable } = *r;
                Problem {
                    kind: refusal.kind.key(),
                    line: refusal.line,
                    column: refusal.column,
                    message: refusal.to_string(),
                    field: refusal.path,
                    cause: refusal.cause,
                    blocks,
                    buildable,
                }
            }
            other => Problem::unplaced("output", format!("{:#}", anyhow::Error::from(other))),
        })
    }
}

impl Problem {
    /// A problem with no place in the project file: an output that could not be made, an
    /// embedder's bad option.
    pub fn unplaced(kind: &'static str, message: String) -> Problem {
        Problem {
            kind,
            line: 0,
            column: 0,
            field: String::new(),
            cause: message.clone(),
            message,
            blocks: Vec::new(),
            buildable: Vec::new(),
        }
    }
}

/// A warning: input that builds but is almost surely a mistake, or a sheet's layout defect.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Note {
    /// 0 when the note has no place in the file (a sheet's own diagnostic).
    pub line: u64,
    pub column: u64,
    pub field: String,
    /// The whole warning as the command line prints it after `warning: in FILE: `.
    pub message: String,
}

/// Files as (name, bytes).
pub type Files = Vec<(String, Vec<u8>)>;

/// A project read and being built, one sheet at a time.
#[derive(Debug)]
pub struct Session {
    project: Project,
    sheets: Vec<u32>,
    formats: Vec<Format>,
    overlay: bool,
    built: Vec<Built>,
    notes: Vec<Note>,
}

impl Session {
    /// Reads and resolves the project for the request: a refusal of a section whose sheet is
    /// not asked for is a warning, as with `tmm build --sheet`.
    pub fn open(text: &str, request: &Request) -> Result<Session, Box<Problem>> {
        let mut project = pipeline::load_for(text, &request.sheets)?;
        if let Some(l) = request.lang {
            project.info.language = l;
        }
        let sheets = if request.sheets.is_empty() { pipeline::buildable(&project) } else { request.sheets.clone() };
        let notes = project
            .warnings
            .iter()
            .map(|w| Note { line: w.line, column: w.column, field: w.field.clone(), message: w.to_string() })
            .collect();
        let formats = pipeline::formats(request.pdf, None, request.dxf);
        Ok(Session { project, sheets, formats, overlay: request.overlay, built: Vec::new(), notes })
    }

    /// The sheets to build, in order.
    pub fn sheets(&self) -> &[u32] {
        &self.sheets
    }

    /// The project's title (the title block's).
    pub fn title(&self) -> &str {
        self.project.info.title()
    }

    /// The warnings so far: the project's, then each built sheet's layout diagnostics.
    pub fn notes(&self) -> &[Note] {
        &self.notes
    }

    /// Builds sheet `number` and returns its files (drawing formats, tables, segments).
    pub fn build_sheet(&mut self, number: u32) -> Result<Files, Box<Problem>> {
        let built = pipeline::build(&self.project, &[number])?;
        let mut files = Vec::new();
        for b in built {
            self.notes.extend(b.output.diagnostics.iter().map(|d| Note {
                line: 0,
                column: 0,
                field: String::new(),
                message: format!("sheet {}, {d}", b.output.number),
            }));
            files.extend(pipeline::sheet_files(&b, &self.formats)?);
            self.built.push(b);
        }
        Ok(files)
    }

    /// The files after the sheets': `results.json`, then the overlays when asked for.
    pub fn finish(&self) -> Result<Files, Box<Problem>> {
        let mut files =
            vec![("results.json".to_string(), pipeline::results_json(&self.project, &self.built).into_bytes())];
        if self.overlay {
            files.extend(pipeline::overlays(&self.built)?);
        }
        Ok(files)
    }
}

/// Every file of a build in `tmm build`'s order, in one call.
pub fn build(text: &str, request: &Request) -> Result<(Files, Vec<Note>), Box<Problem>> {
    let mut session = Session::open(text, request)?;
    let mut files = Vec::new();
    for n in session.sheets().to_vec() {
        files.extend(session.build_sheet(n)?);
    }
    files.extend(session.finish()?);
    Ok((files, session.notes))
}

/// A task of the catalogue as a chooser lists it.
#[derive(Debug, Clone, Serialize)]
pub struct TaskEntry {
    pub id: String,
    pub name: String,
    pub kind: String,
    /// A practice set of the manual, not a task of the guide.
    pub practice: bool,
    pub variants: Vec<VariantEntry>,
}

/// A variant and whether it builds as the guide prints it.
#[derive(Debug, Clone, Serialize)]
pub struct VariantEntry {
    pub number: u32,
    /// `complete`, `partial` (some sheets' values lost in the guide), `incomplete` (no
    /// project file) or `refused` (refused as printed, with why).
    pub status: &'static str,
    pub note: String,
}

/// The embedded catalogue's tasks and variants, named in `lang`.
pub fn catalogue(lang: Language) -> Result<Vec<TaskEntry>, String> {
    let cat = Catalogue::embedded()?;
    cat.tasks
        .iter()
        .map(|t| {
            let variants = t
                .variants()
                .map(|v| {
                    let (status, note) = match (t.project(v, lang, "")?, t.refusal_explained(v)) {
                        (Variant::Incomplete { lost, .. }, _) => ("incomplete", lost),
                        (_, Some(n)) => ("refused", n.why.pick(lang).to_string()),
                        (Variant::Project { left_out, .. }, None) if !left_out.is_empty() => {
                            ("partial", left_out.join("; "))
                        }
                        (Variant::Project { .. }, None) => ("complete", String::new()),
                    };
                    Ok(VariantEntry { number: v, status, note })
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok(TaskEntry {
                id: t.id(),
                name: t.name(lang).to_string(),
                kind: t.kind(lang).to_string(),
                practice: t.is_practice(),
                variants,
            })
        })
        .collect()
}

/// A catalogue variant's project file, as `tmm init --task T --variant V --lang L` writes
/// it; an incomplete variant's message when it has none.
pub fn variant(task: &str, variant: u32, lang: Language) -> Result<String, String> {
    let cat = Catalogue::embedded()?;
    let t = cat.task(task)?;
    t.row(variant)?;
    let command = format!("tmm init --task {} --variant {variant}", t.id());
    match t.project(variant, lang, &command)? {
        Variant::Project { text, .. } => Ok(text),
        Variant::Incomplete { message, .. } => Err(message),
    }
}
