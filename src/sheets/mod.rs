//! The sheets of the course project, each a value the pipeline iterates over: it computes
//! what it needs from its section of the project and returns its [`SheetOutput`] (scene,
//! note tables, its `results.json` section, diagnostics). Nothing outside this module names
//! a sheet by its number.
//!
//! **Architecture invariant:** sheets compose; they read domain results and produce a scene
//! of paper-millimetre primitives, never bytes.

pub mod cam;
pub mod check_report;
pub mod gears;
pub mod lever;
pub mod notes;
pub mod scaffold;
pub mod words;

/// The layout measure's faults as `results.json` names them (a clean sheet has none).
pub use crate::drawing::layout::FAULTS as LAYOUT_FAULTS;
use crate::drawing::scene::Scene;
use crate::drawing::text::TooLong;
use crate::lever::analysis::AnalysisError;
use crate::project::{Kind, Places, Project, ProjectInfo, Refusal};
use crate::report::NoteTable;

/// The course project's sheets: number, what the sheet draws, the section it needs, and
/// whether this version draws it.
pub const COURSE: [SheetKind; 3] = [
    SheetKind {
        number: 1,
        subject: "the lever mechanism",
        section: "mechanism",
        available: true,
        make: lever::LeverSheet::of,
    },
    SheetKind { number: 2, subject: "the gears", section: "gears", available: true, make: gears::GearsSheet::of },
    SheetKind { number: 3, subject: "the cam", section: "cam", available: true, make: cam::CamSheet::of },
];

/// Builds a sheet from a project that has its section.
pub type MakeSheet = for<'a> fn(&'a Project) -> Option<Box<dyn Sheet + 'a>>;

#[derive(Clone, Copy)]
pub struct SheetKind {
    pub number: u32,
    pub subject: &'static str,
    /// The section of the project file the sheet draws.
    pub section: &'static str,
    pub available: bool,
    pub make: MakeSheet,
}

impl std::fmt::Debug for SheetKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "sheet {} ({})", self.number, self.subject)
    }
}

impl PartialEq for SheetKind {
    fn eq(&self, other: &Self) -> bool {
        self.number == other.number
    }
}

/// What every sheet is given besides its own section.
pub struct Context<'a> {
    pub info: &'a ProjectInfo,
    /// The sheet's place among the project's sheets and their number, for the title block:
    /// a project of the cam alone is sheet 1 of 1, not "3 of 3".
    pub sheet_no: u32,
    pub sheet_count: u32,
    /// The number of the sheet's first table in the explanatory note: the tables are
    /// numbered once across the project's sheets (see [`Sheet::table_count`]).
    pub first_table: u32,
    /// The names of the project's sheets (this one's among them), so that every title block
    /// letters its sheet's name at one height: the largest at which each of them fits.
    pub sheet_names: &'a [String],
}

impl Context<'_> {
    /// The GOST 2.104 title block of the sheet, named `sheet_name`, at `scale`, filled from
    /// the project's information.
    pub fn title_block(
        &self,
        c: &crate::drawing::labels::Common,
        sheet_name: &str,
        scale: &str,
    ) -> Result<crate::drawing::scene::Group, TooLong> {
        use crate::drawing::frame::{self, TitleBlock};
        let mut tb = crate::drawing::scene::Group::new(scaffold::TITLE_BLOCK, frame::title_block_rect());
        frame::title_block(
            &mut tb,
            c,
            &TitleBlock {
                designation: self.info.designation(),
                sheet_name,
                project_title: self.info.title(),
                student: &self.info.student,
                supervisor: &self.info.supervisor,
                organisation: &self.info.organisation(),
                scale,
                sheet_no: self.sheet_no,
                sheet_count: self.sheet_count,
                project_sheet_names: self.sheet_names,
            },
        )?;
        Ok(tb)
    }
}

/// A finished sheet.
#[derive(Debug, Clone)]
pub struct SheetOutput {
    pub number: u32,
    pub scene: Scene,
    /// The note's tables, in order.
    pub tables: Vec<NoteTable>,
    /// The sheet's section of `results.json`.
    pub results: serde_json::Value,
    /// Things the user should know about this sheet (printed, the build continues).
    pub diagnostics: Vec<String>,
    /// The segments a student measures on its drawings (`sheetN-segments.csv`).
    pub segments: Vec<crate::report::Segment>,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SheetError {
    #[error(transparent)]
    Lever(#[from] AnalysisError),
    #[error(transparent)]
    TooLong(#[from] TooLong),
}

impl SheetError {
    /// The error as a refusal of the field that causes it, placed in the project file.
    pub fn refusal(&self, kind: SheetKind, places: &Places) -> Refusal {
        let r = match self {
            SheetError::Lever(e) => crate::project::refusal_of_analysis(e, places),
            SheetError::TooLong(t) => {
                let text = t.to_string();
                let cause = text.strip_prefix(&format!("{}: ", t.field)).unwrap_or(&text);
                Refusal::new(Kind::Text, (0, 0), t.field.clone(), cause).placed(places)
            }
        };
        // A title-block text is on every sheet: refusing it refuses them all.
        if r.path.starts_with("project") { r } else { r.in_section(kind.section) }
    }
}

/// One sheet, ready to build from its project section; `Sync`, so that a project's sheets
/// are built in parallel (`pipeline::build`).
pub trait Sheet: Sync {
    fn kind(&self) -> SheetKind;
    /// How many numbered tables the sheet gives the note.
    fn table_count(&self) -> u32;
    /// The sheet's name in its title block, in `lang`.
    fn name(&self, lang: crate::drawing::labels::Language) -> String;
    /// The sheet's drawings, tables and results, without the frame and the title block.
    fn compose(&self, ctx: &Context) -> Result<scaffold::Composition, SheetError>;
    /// The finished sheet: the composition with the frame, the title block and the layout
    /// measured ([`scaffold::finish`]).
    fn build(&self, ctx: &Context) -> Result<SheetOutput, SheetError> {
        scaffold::finish(ctx, self.kind(), self.compose(ctx)?)
    }
}

/// Why a requested sheet cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SelectError {
    #[error("there is no sheet {0}: the course project has sheets 1 to {n}", n = COURSE.len())]
    NoSuchSheet(u32),
    #[error("sheet {number} ({subject}) is not available in this version", number = .0.number, subject = .0.subject)]
    NotAvailable(SheetKind),
    #[error("sheet {number} ({subject}) needs a `{section}` section in the project file", number = .0.number, subject = .0.subject, section = .0.section)]
    MissingSection(SheetKind),
}

impl SelectError {
    /// The error as a refusal of the project (a sheet it cannot have).
    pub fn refusal(&self) -> Refusal {
        let path = match self {
            SelectError::MissingSection(k) => k.section,
            _ => "",
        };
        Refusal::new(Kind::Section, (1, 1), path, self.to_string())
    }
}

/// Starts a build: what the drawings remember to compose faster (the circles flattened for
/// their indexes, drawing::obstacles::memo) is kept within one build, not across builds.
pub fn new_build() {
    crate::drawing::obstacles::new_build();
}

/// The sheets to build: the requested ones (each must exist and have its section), or, with
/// no request, every available sheet the project has a section for, in order.
pub fn select<'a>(project: &'a Project, requested: &[u32]) -> Result<Vec<Box<dyn Sheet + 'a>>, SelectError> {
    if requested.is_empty() {
        return Ok(COURSE.iter().filter(|k| k.available).filter_map(|k| (k.make)(project)).collect());
    }
    let mut out: Vec<Box<dyn Sheet + 'a>> = Vec::new();
    for &n in requested {
        let kind = *COURSE.iter().find(|k| k.number == n).ok_or(SelectError::NoSuchSheet(n))?;
        if !kind.available {
            return Err(SelectError::NotAvailable(kind));
        }
        if out.iter().any(|s| s.kind() == kind) {
            continue;
        }
        out.push((kind.make)(project).ok_or(SelectError::MissingSection(kind))?);
    }
    out.sort_by_key(|s| s.kind().number);
    Ok(out)
}
