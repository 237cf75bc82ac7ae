//! `tmm build --all`: every variant of every task, in parallel, into
//! `OUT/<task folder>/variant-NN/`, with `summary.csv` and `summary.md`. One variant's
//! refusal, incompleteness or failure to write never stops the others.

use super::write;
use crate::catalogue::{Catalogue, Task, Variant};
use crate::drawing::labels::Language;
use crate::pipeline::COURSE;
use crate::pipeline::{self, Built, Format};
use anyhow::{Context, Result, anyhow};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// How a variant ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    Built,
    BuiltWithWarnings,
    /// Built the sheets whose sections the guide's data fill; the others' values are lost.
    BuiltInPart,
    Refused,
    Incomplete,
    /// Has none of the sheets `--sheet` asked for (a kinematics exercise has no sheet 2).
    WithoutSheet,
    /// Its files could not be written (or the program failed on it).
    Failed,
}

impl Status {
    pub fn key(self) -> &'static str {
        match self {
            Status::Built => "built",
            Status::BuiltWithWarnings => "built with warnings",
            Status::BuiltInPart => "built in part (the guide lost the rest)",
            Status::Refused => "refused",
            Status::Incomplete => "incomplete in the guide",
            Status::WithoutSheet => "without the sheets asked for",
            Status::Failed => "failed",
        }
    }
}

/// The answers the summary reports, by their stable identifiers.
pub const KEY_ANSWERS: [&str; 11] = [
    "sheet1.balancing.P_m",
    "sheet1.balancing.delta",
    "sheet2.pair.epsilon",
    "sheet2.pair.epsilon_drawn",
    "sheet2.planetary.u_1H",
    "sheet2.planetary.z_1",
    "sheet2.planetary.z_2",
    "sheet2.planetary.z_3",
    "sheet3.results.r_min",
    "sheet3.results.alpha_max_rise",
    "sheet3.results.alpha_max_return",
];

/// One variant's outcome, a row of the summary.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub task: String,
    pub variant: u32,
    pub status: Status,
    pub warnings: Vec<String>,
    /// The refusal's kind and its text (or why the variant is incomplete or failed).
    pub refusal: Option<(String, String)>,
    /// For a refusal, the task's note on why the guide's data give it (`None`: unexplained).
    pub explained: Option<String>,
    /// [`KEY_ANSWERS`] in order (`None`: that sheet was not built).
    pub answers: Vec<Option<f64>>,
    /// Per sheet 1–3: texts crossed, text overlaps, items outside (`None`: not built).
    pub layout: [Option<[u64; 4]>; 3],
    pub seconds: f64,
}

/// What every variant's build shares.
pub struct Batch<'a> {
    pub output: &'a Path,
    /// `--sheet`: the sheets to build of each variant that has them (empty: every sheet).
    pub sheets: Vec<u32>,
    pub formats: Vec<Format>,
    /// `--overlay`: each sheet's constructions alone too.
    pub overlay: bool,
    pub lang: Option<Language>,
}

/// Builds every variant of `cat` on `jobs` threads (all cores when `None`); returns the
/// outcomes in catalogue order.
pub fn run(cat: &Catalogue, batch: &Batch, jobs: Option<usize>) -> Result<Vec<Outcome>> {
    let work: Vec<(&Task, u32)> = cat.tasks.iter().flat_map(|t| t.variants().map(move |v| (t, v))).collect();
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(j) = jobs {
        pool = pool.num_threads(j.max(1));
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let progress = Progress::new(work.len());
    let outcomes: Vec<Outcome> = pool.install(|| {
        work.par_iter()
            .map(|&(task, variant)| {
                let o = one(task, variant, batch);
                progress.done(&o);
                o
            })
            .collect()
    });
    progress.finish();
    Ok(outcomes)
}

/// A variant's folder: `task-07/variant-12`.
pub fn folder(task: &Task, variant: u32) -> PathBuf {
    Path::new(&task.folder).join(format!("variant-{variant:02}"))
}

/// Builds one variant, catching a panic so that it cannot stop the batch.
fn one(task: &Task, variant: u32, batch: &Batch) -> Outcome {
    let start = Instant::now();
    let mut o = Outcome {
        task: task.id(),
        variant,
        status: Status::Failed,
        warnings: Vec::new(),
        refusal: None,
        explained: None,
        answers: vec![None; KEY_ANSWERS.len()],
        layout: [None; 3],
        seconds: 0.0,
    };
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| build_variant(task, variant, batch, &mut o)));
    match caught {
        Ok(Ok(())) => {}
        Ok(Err(e)) => {
            o.status = Status::Failed;
            o.refusal = Some(("output".into(), format!("{e:#}")));
        }
        Err(_) => {
            o.status = Status::Failed;
            o.refusal =
                Some(("internal".into(), "the program failed on this variant (a bug: please report it)".into()));
        }
    }
    o.seconds = start.elapsed().as_secs_f64();
    o
}

fn build_variant(task: &Task, variant: u32, batch: &Batch, o: &mut Outcome) -> Result<()> {
    let lang = batch.lang.unwrap_or_default();
    let command = format!("tmm init --task {} --variant {variant}", task.id());
    let mut partial = false;
    let text = match task.project(variant, lang, &command).map_err(|e| anyhow!(e))? {
        Variant::Incomplete { message, .. } => {
            o.status = Status::Incomplete;
            o.refusal = Some(("incomplete".into(), message));
            return Ok(());
        }
        Variant::Project { text, left_out } => {
            if !left_out.is_empty() {
                o.warnings.push(format!("incomplete in the guide: left out {}", left_out.join("; ")));
                partial = true;
            }
            text
        }
    };
    let Some(sheets) = asked_for(&text, &batch.sheets) else {
        o.status = Status::WithoutSheet;
        return Ok(());
    };
    let (project, built) = match load_and_build(&text, batch.lang, &sheets) {
        Ok(done) => done,
        Err(pipeline::Error::Refused(r)) => {
            o.status = Status::Refused;
            o.refusal = Some((r.refusal.kind.key().into(), r.refusal.to_string()));
            o.explained = task.refusal_explained(variant).map(|l| l.why.pick(lang).to_string());
            let others: Vec<u32> = r
                .buildable
                .iter()
                .copied()
                .filter(|n| !r.blocks.contains(n) && (sheets.is_empty() || sheets.contains(n)))
                .collect();
            if others.is_empty() {
                return write_files(batch, task, variant, &text, None);
            }
            // The sheets the refusal does not concern are still built.
            let (project, built) = load_and_build(&text, batch.lang, &others).map_err(|e| anyhow!("{e}"))?;
            record(o, &project, &built, Some(&r.refusal));
            return write_files(batch, task, variant, &text, Some((&project, &built)));
        }
        Err(e) => return Err(anyhow!("{e}")),
    };
    record(o, &project, &built, None);
    o.status = match (partial, o.warnings.is_empty()) {
        (true, _) => Status::BuiltInPart,
        (false, true) => Status::Built,
        (false, false) => Status::BuiltWithWarnings,
    };
    write_files(batch, task, variant, &text, Some((&project, &built)))
}

/// The sheets of `asked` (every sheet when empty) whose sections the variant's project has:
/// `None` when it has none of them.
fn asked_for(text: &str, asked: &[u32]) -> Option<Vec<u32>> {
    if asked.is_empty() {
        return Some(Vec::new());
    }
    let places = crate::project::Places::of(text);
    let has = |n: &u32| COURSE.iter().any(|k| k.number == *n && places.has(k.section));
    let sheets: Vec<u32> = asked.iter().copied().filter(has).collect();
    (!sheets.is_empty()).then_some(sheets)
}

/// Loads a project text and builds its `sheets` (every sheet when empty) in `lang`.
fn load_and_build(
    text: &str,
    lang: Option<Language>,
    sheets: &[u32],
) -> Result<(crate::project::Project, Vec<Built>), pipeline::Error> {
    let mut project = pipeline::load_for(text, sheets)?;
    if let Some(l) = lang {
        project.info.language = l;
    }
    let built = pipeline::build(&project, sheets)?;
    Ok((project, built))
}

/// The warnings, answers and layout measures of a build; the warning that repeats `refused`
/// (loading the sheets it does not concern reports it as one) is the outcome's, not a warning.
fn record(
    o: &mut Outcome,
    project: &crate::project::Project,
    built: &[Built],
    refused: Option<&crate::project::Refusal>,
) {
    let repeats = |w: &crate::project::Warning| {
        refused.is_some_and(|r| (w.line, w.column, w.field.as_str()) == (r.line, r.column, r.path.as_str()))
    };
    o.warnings.extend(project.warnings.iter().filter(|w| !repeats(w)).map(ToString::to_string));
    for b in built {
        o.warnings.extend(b.output.diagnostics.iter().map(|d| format!("sheet {}, {d}", b.output.number)));
        let prefix = format!("sheet{}", b.output.number);
        for a in b.output.tables.iter().flat_map(|t| t.answers(&prefix)) {
            if let Some(i) = KEY_ANSWERS.iter().position(|k| *k == a.id) {
                o.answers[i] = Some(a.value);
            }
        }
        let layout = &b.output.results["layout"];
        let n = |k: &str| layout[k].as_u64().unwrap_or(0);
        if let Some(slot) = o.layout.get_mut(b.output.number as usize - 1) {
            *slot = Some(pipeline::LAYOUT_FAULTS.map(n));
        }
    }
}

/// Writes a variant's project file and, when built, its outputs.
fn write_files(
    batch: &Batch,
    task: &Task,
    variant: u32,
    text: &str,
    built: Option<(&crate::project::Project, &[Built])>,
) -> Result<()> {
    let mut files = vec![("project.yaml".to_string(), text.as_bytes().to_vec())];
    if let Some((project, built)) = built {
        files.extend(pipeline::outputs(project, built, &batch.formats).map_err(|e| anyhow!("{e}"))?);
        if batch.overlay {
            files.extend(pipeline::overlays(built).map_err(|e| anyhow!("{e}"))?);
        }
    }
    write::write_outputs(&batch.output.join(folder(task, variant)), &files)
}

/// The progress a batch shows: a bar on a terminal, a line per variant otherwise.
struct Progress {
    bar: Option<indicatif::ProgressBar>,
}

impl Progress {
    fn new(total: usize) -> Progress {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = indicatif::ProgressBar::new(total as u64);
            if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} variants, {elapsed} {msg}")
            {
                bar.set_style(style);
            }
            bar
        });
        Progress { bar }
    }

    fn done(&self, o: &Outcome) {
        let line = format!("task {} variant {}: {} ({:.2} s)", o.task, o.variant, o.status.key(), o.seconds);
        match &self.bar {
            Some(bar) => {
                bar.set_message(line);
                bar.inc(1);
            }
            None => eprintln!("{line}"),
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
