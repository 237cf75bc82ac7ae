//! The command line: `tmm [build [PROJECT.yaml | --task T --variant V | --all]] [-o DIR]
//! [--sheet N]…`, `tmm list [--task T]`, `tmm init --task T --variant V`, `tmm check [PROJECT]
//! VALUES.csv` (its own exit codes: `cli/check.rs`).
//!
//! Exit codes: 0 built; 1 the project was refused (unreadable, too large, not UTF-8, invalid,
//! or a mechanism that cannot be analysed; a catalogue variant incomplete in the guide; in a
//! batch, any variant refused); 2 a command-line usage error (clap's own, a sheet number or
//! PNG resolution out of range, a task or variant the catalogue does not have); 3 the outputs
//! could not be written.

mod batch;
mod catalogue;
mod check;
mod summary;
pub mod write;

use crate::drawing::labels::Language;
use crate::pipeline::{self, DEFAULT_PROJECT};
use anyhow::{Context, Result, bail};
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

pub use write::MANIFEST;

#[derive(Parser)]
#[command(name = "tmm", version, about = "Drawing sheets of the TMM course project, computed exactly")]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    build: BuildArgs,
    /// A catalogue folder to read instead of the one built in (the same form as the
    /// repository's `catalogue/`).
    #[arg(long, global = true, value_name = "DIR")]
    catalogue: Option<PathBuf>,
}

#[derive(Subcommand)]
enum Command {
    /// Build the sheets of a project file (default: the guide's worked example).
    Build(BuildArgs),
    /// Print the embedded worked example's project file, to start a project from.
    Example,
    /// List the guide's tasks (with `--task`, one task's variants).
    List(ListArgs),
    /// Write the project file of a task's variant, every value commented with its source.
    Init(InitArgs),
    /// Check a student's values (CSV) against the exact answers: exit 0 when all pass, 1
    /// when any fails, 2 when the file cannot be used.
    Check(check::CheckArgs),
    /// Measure on this machine each trade-off's time against the error it buys, and whole
    /// builds, on the worked example (Markdown tables on stdout).
    Bench(BenchArgs),
}

#[derive(Args)]
struct BenchArgs {
    /// A few repetitions of each measurement (under 30 s) instead of ~0.4 s each.
    #[arg(long)]
    quick: bool,
}

#[derive(Args)]
struct ListArgs {
    /// A task's number (1–15) or practice set (P1–P3): list its variants.
    #[arg(long)]
    task: Option<String>,
    /// Language of the listing (default Uzbek).
    #[arg(long, value_enum)]
    lang: Option<Lang>,
}

#[derive(Args)]
struct InitArgs {
    /// The task's number (1–15) or practice set (P1–P3).
    #[arg(long)]
    task: String,
    /// The variant's number.
    #[arg(long)]
    variant: u32,
    /// The file to write (default: print to stdout).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Replace the file if it exists.
    #[arg(long)]
    force: bool,
    /// Language of the comments and of the sheets (default Uzbek).
    #[arg(long, value_enum)]
    lang: Option<Lang>,
}

#[derive(Args, Clone)]
struct BuildArgs {
    /// Project file (YAML). Without it, the worked example embedded in the program.
    #[arg(conflicts_with_all = ["task", "all"])]
    project: Option<PathBuf>,
    /// Build a variant of the guide's task from the catalogue (with `--variant`).
    #[arg(long, requires = "variant", conflicts_with = "all")]
    task: Option<String>,
    /// The variant of `--task`.
    #[arg(long, requires = "task")]
    variant: Option<u32>,
    /// Build every variant of every task into DIR/task-NN/variant-NN/, with summary.csv and
    /// summary.md.
    #[arg(long)]
    all: bool,
    /// Threads for `--all` (default: every core).
    #[arg(short, long, requires = "all")]
    jobs: Option<usize>,
    /// Output directory.
    #[arg(short, long, default_value = "out")]
    output: PathBuf,
    /// Sheets to build, by number, comma-separated (default: every sheet the project has a
    /// section for).
    #[arg(long = "sheet", value_delimiter = ',', value_parser = parse_sheet)]
    sheets: Vec<u32>,
    /// Label language, overriding the project file's.
    #[arg(long, value_enum)]
    lang: Option<Lang>,
    /// Resolution of the PNG preview, dots per inch (10–600).
    #[arg(long, default_value_t = 100.0, value_parser = parse_png_dpi)]
    png_dpi: f64,
    /// Skip the PNG preview.
    #[arg(long)]
    no_png: bool,
    /// Skip the PDF.
    #[arg(long)]
    no_pdf: bool,
    /// Also write each sheet as DXF for AutoCAD, KOMPAS or LibreCAD (sheetN.dxf).
    #[arg(long)]
    dxf: bool,
    /// The DXF's version: r2000 (AC1015, what current AutoCAD opens; the default) or r12
    /// (AC1009, for old programs). Implies `--dxf`.
    #[arg(long, value_enum, value_name = "VERSION")]
    dxf_version: Option<Dxf>,
    /// Also write each sheet's constructions alone, in red at their places on A1, to print
    /// on film and lay over a hand drawing: sheetN-overlay.svg and sheetN-overlay.pdf.
    #[arg(long)]
    overlay: bool,
}

#[derive(Clone, Copy, ValueEnum)]
enum Dxf {
    R2000,
    R12,
}

impl BuildArgs {
    /// The formats the options ask for.
    fn formats(&self) -> Vec<pipeline::Format> {
        let dxf = match (self.dxf, self.dxf_version) {
            (_, Some(Dxf::R12)) => Some(pipeline::DxfVersion::R12),
            (true, _) | (_, Some(Dxf::R2000)) => Some(pipeline::DxfVersion::R2000),
            (false, None) => None,
        };
        pipeline::formats(!self.no_pdf, (!self.no_png).then_some(self.png_dpi), dxf)
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum Lang {
    Uz,
    Ru,
    En,
}

/// The PNG preview's resolutions accepted, dots per inch.
const PNG_DPI: std::ops::RangeInclusive<f64> = 10.0..=600.0;

/// The largest project file read. A course project is a few kilobytes; the limit keeps a
/// wrong path (`/dev/zero`, a video) from filling the memory before the parser refuses it.
const PROJECT_LIMIT: u64 = 16 * 1024 * 1024;

/// A failure, by whose it is: the input's (exit 1), the command line's (exit 2) or the
/// output's (exit 3).
enum Failure {
    Input(anyhow::Error),
    Usage(anyhow::Error),
    Output(anyhow::Error),
}

pub fn run() -> ExitCode {
    let cli = Cli::parse(); // usage errors exit with 2
    let dir = cli.catalogue.as_deref();
    if let (Some(_), Some(project)) = (&cli.command, &cli.build.project) {
        // `tmm FILE check …` would otherwise check (or build) the worked example.
        eprintln!(
            "error: {} comes before the subcommand: write it after (`tmm build {0}`, `tmm check {0} VALUES.csv`)",
            project.display()
        );
        return ExitCode::from(2);
    }
    let result = match cli.command {
        Some(Command::Example) => {
            print!("{DEFAULT_PROJECT}");
            Ok(())
        }
        Some(Command::List(args)) => list(&args, dir),
        Some(Command::Init(args)) => init(&args, dir),
        Some(Command::Check(args)) => return check::run(&args, dir),
        Some(Command::Bench(args)) => bench(&args),
        Some(Command::Build(args)) => build(&args, dir),
        None => build(&cli.build, dir),
    };
    let (e, code) = match result {
        Ok(()) => return ExitCode::SUCCESS,
        Err(Failure::Input(e)) => (e, 1),
        Err(Failure::Usage(e)) => (e, 2),
        Err(Failure::Output(e)) => (e, 3),
    };
    eprintln!("error: {e:#}");
    ExitCode::from(code)
}

fn bench(args: &BenchArgs) -> Result<(), Failure> {
    let clock = if args.quick { crate::bench::Clock::QUICK } else { crate::bench::Clock::FULL };
    let start = std::time::Instant::now();
    let tables = crate::bench::run(clock).map_err(|e| Failure::Input(anyhow::anyhow!(e)))?;
    println!(
        "# tmm bench{}: the worked example, on this machine ({} threads), medians\n",
        if args.quick { " --quick" } else { "" },
        rayon::current_num_threads()
    );
    for t in &tables {
        println!("{}", t.markdown());
    }
    println!("Measured in {:.1} s.", start.elapsed().as_secs_f64());
    Ok(())
}

fn language(lang: Option<Lang>) -> Option<Language> {
    lang.map(|l| match l {
        Lang::Uz => Language::Uz,
        Lang::Ru => Language::Ru,
        Lang::En => Language::En,
    })
}

fn list(args: &ListArgs, dir: Option<&Path>) -> Result<(), Failure> {
    let cat = catalogue::load(dir).map_err(Failure::Input)?;
    let lang = language(args.lang).unwrap_or_default();
    let text = match &args.task {
        Some(t) => catalogue::list_task(cat.task(t).map_err(|e| Failure::Usage(anyhow::anyhow!(e)))?, lang),
        None => catalogue::list(&cat, lang),
    };
    print!("{}", text.map_err(Failure::Input)?);
    Ok(())
}

/// A catalogue variant's project text and the name messages call it by.
fn variant_text(dir: Option<&Path>, task: &str, variant: u32, lang: Language) -> Result<(String, String), Failure> {
    let cat = catalogue::load(dir).map_err(Failure::Input)?;
    let t = cat.task(task).map_err(|e| Failure::Usage(anyhow::anyhow!(e)))?;
    t.row(variant).map_err(|e| Failure::Usage(anyhow::anyhow!(e)))?;
    let command = format!("tmm init --task {} --variant {variant}", t.id());
    match t.project(variant, lang, &command).map_err(|e| Failure::Input(anyhow::anyhow!(e)))? {
        crate::catalogue::Variant::Project { text, left_out } => {
            if !left_out.is_empty() {
                eprintln!(
                    "warning: task {} variant {variant} is incomplete in the guide: left out {}",
                    t.id(),
                    left_out.join("; ")
                );
            }
            Ok((text, format!("task {} variant {variant}", t.id())))
        }
        crate::catalogue::Variant::Incomplete { message, .. } => Err(Failure::Input(anyhow::anyhow!(message))),
    }
}

fn init(args: &InitArgs, dir: Option<&Path>) -> Result<(), Failure> {
    let (text, name) = variant_text(dir, &args.task, args.variant, language(args.lang).unwrap_or_default())?;
    // The variant as the program reads it: a refusal is the student's to know before editing.
    if let Err(e) = pipeline::load(&text) {
        eprintln!("warning: {}", refused(e, &name));
    }
    let Some(path) = &args.output else {
        print!("{text}");
        return Ok(());
    };
    if path.exists() && !args.force {
        return Err(Failure::Output(anyhow::anyhow!(
            "{} exists: a project file may hold your edits; `--force` replaces it",
            path.display()
        )));
    }
    std::fs::write(path, &text).with_context(|| format!("cannot write {}", path.display())).map_err(Failure::Output)?;
    println!("{name}: written to {}", path.display());
    Ok(())
}

/// `tmm build --all`: every variant, the summary, exit 1 when any was refused.
fn build_all(args: &BuildArgs, dir: Option<&Path>) -> Result<(), Failure> {
    let cat = catalogue::load(dir).map_err(Failure::Input)?;
    let formats = args.formats();
    let lang = language(args.lang);
    let run = batch::Batch { output: &args.output, sheets: args.sheets.clone(), formats, overlay: args.overlay, lang };
    let start = std::time::Instant::now();
    let outcomes = batch::run(&cat, &run, args.jobs).map_err(Failure::Output)?;
    let seconds = start.elapsed().as_secs_f64();
    let jobs = args.jobs.unwrap_or_else(rayon::current_num_threads);
    let files = [
        ("summary.csv".to_string(), summary::csv(&outcomes).into_bytes()),
        ("summary.md".to_string(), summary::markdown(&outcomes, seconds, jobs).into_bytes()),
    ];
    write::write_outputs(&args.output, &files).map_err(Failure::Output)?;
    let (status, _) = summary::counts(&outcomes);
    let counts: Vec<String> = status.iter().map(|(s, n)| format!("{n} {}", s.key())).collect();
    println!(
        "{} variants in {seconds:.1} s: {}; summary in {}",
        outcomes.len(),
        counts.join(", "),
        args.output.join("summary.md").display()
    );
    if status.contains_key(&batch::Status::Failed) {
        return Err(Failure::Output(anyhow::anyhow!(
            "some variants' files could not be written (summary.md names them)"
        )));
    }
    if status.contains_key(&batch::Status::Refused) {
        return Err(Failure::Input(anyhow::anyhow!("some variants were refused (summary.md names them and why)")));
    }
    Ok(())
}

fn build(args: &BuildArgs, dir: Option<&Path>) -> Result<(), Failure> {
    if args.all {
        return build_all(args, dir);
    }
    let (project, name) = load(args, dir)?;
    for w in &project.warnings {
        eprintln!("warning: in {name}: {w}");
    }
    let built = pipeline::build(&project, &args.sheets).map_err(|e| refused(e, &name)).map_err(Failure::Input)?;
    for b in &built {
        for d in &b.output.diagnostics {
            eprintln!("warning: in {name}: sheet {}, {d}", b.output.number);
        }
    }
    let formats = args.formats();
    let mut files = pipeline::outputs(&project, &built, &formats).map_err(|e| Failure::Output(e.into()))?;
    if args.overlay {
        files.extend(pipeline::overlays(&built).map_err(|e| Failure::Output(e.into()))?);
    }
    write::write_outputs(&args.output, &files).map_err(Failure::Output)?;
    let numbers: Vec<String> = built.iter().map(|b| b.output.number.to_string()).collect();
    println!("{name}: sheet {} written to {} ({} files)", numbers.join(", "), args.output.display(), files.len());
    Ok(())
}

fn load(args: &BuildArgs, dir: Option<&Path>) -> Result<(crate::project::Project, String), Failure> {
    let (text, name) = match (&args.project, &args.task, args.variant) {
        (Some(p), _, _) => (read_project(p).map_err(Failure::Input)?, p.display().to_string()),
        (None, Some(t), Some(v)) => variant_text(dir, t, v, language(args.lang).unwrap_or_default())?,
        _ => (DEFAULT_PROJECT.to_string(), "the worked example".to_string()),
    };
    let mut project = pipeline::load_for(&text, &args.sheets).map_err(|e| Failure::Input(refused(e, &name)))?;
    if let Some(l) = language(args.lang) {
        project.info.language = l;
    }
    Ok((project, name))
}

/// A refusal as the user reads it: where (file, line, column), the field and the cause, and
/// when it refuses some sheets only, how to build the others.
fn refused(e: pipeline::Error, name: &str) -> anyhow::Error {
    let pipeline::Error::Refused(r) = &e else { return anyhow::Error::from(e) };
    let pipeline::Refused { refusal, blocks, buildable } = &**r;
    let mut text = format!("in {name}: {refusal}");
    let others: Vec<String> = buildable.iter().filter(|n| !blocks.contains(n)).map(u32::to_string).collect();
    if !others.is_empty() {
        let blocked: Vec<String> = blocks.iter().map(u32::to_string).collect();
        text.push_str(&format!(
            "\n  (this refuses sheet {} only: `--sheet {}` builds the others)",
            blocked.join(", "),
            others.join(",")
        ));
    }
    anyhow::anyhow!(text)
}

/// A `--sheet` value: the number of one of the course's sheets. A sheet of the course that
/// the project has no section for is the project's error (exit 1), found when building.
fn parse_sheet(value: &str) -> Result<u32, String> {
    let numbers = pipeline::sheet_numbers;
    let (first, last) = (numbers().min().unwrap_or(0), numbers().max().unwrap_or(0));
    let range = format!("the course project has sheets {first} to {last}");
    match value.trim().parse::<u32>() {
        Ok(n) if numbers().any(|k| k == n) => Ok(n),
        Ok(n) => Err(format!("there is no sheet {n}: {range}")),
        Err(_) => Err(format!("not a sheet number: {range}")),
    }
}

/// A `--png-dpi` value: a finite number of dots per inch within [`PNG_DPI`].
fn parse_png_dpi(value: &str) -> Result<f64, String> {
    match value.trim().parse::<f64>() {
        Ok(dpi) if dpi.is_finite() && PNG_DPI.contains(&dpi) => Ok(dpi),
        _ => Err(format!(
            "the PNG resolution must be a number of dots per inch from {} to {}",
            PNG_DPI.start(),
            PNG_DPI.end()
        )),
    }
}

/// The project file's text: at most [`PROJECT_LIMIT`] bytes (read through a limit, since a
/// device or a pipe reports no size), in UTF-8.
fn read_project(path: &Path) -> Result<String> {
    let cannot = || format!("cannot read {}", path.display());
    let file = std::fs::File::open(path).with_context(cannot)?;
    let mut bytes = Vec::new();
    file.take(PROJECT_LIMIT + 1).read_to_end(&mut bytes).with_context(cannot)?;
    if bytes.len() as u64 > PROJECT_LIMIT {
        bail!("cannot read {}: larger than {} MiB, the limit for a project file", path.display(), PROJECT_LIMIT >> 20);
    }
    String::from_utf8(bytes).map_err(|e| not_utf8(path, &e))
}

/// Names the first byte that is not UTF-8, by offset and line, so that the user can find the
/// character their editor saved in a legacy code page.
fn not_utf8(path: &Path, e: &std::string::FromUtf8Error) -> anyhow::Error {
    let at = e.utf8_error().valid_up_to();
    let line = e.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count() + 1;
    anyhow::anyhow!(
        "cannot read {}: not UTF-8 text (an invalid byte 0x{:02X} at byte offset {at}, line {line}); save it as UTF-8",
        path.display(),
        e.as_bytes()[at]
    )
}
