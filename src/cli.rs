//! The command line: `tmm [build [PROJECT.yaml]] [-o DIR] [--sheet N]…`.
//!
//! Exit codes: 0 built; 1 the project was refused (unreadable, too large, not UTF-8, invalid,
//! or a mechanism that cannot be analysed); 2 a command-line usage error (clap's own, and a
//! sheet number or PNG resolution out of range); 3 the outputs could not be written.

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
}

#[derive(Subcommand)]
enum Command {
    /// Build the sheets of a project file (default: the guide's worked example).
    Build(BuildArgs),
    /// Print the embedded worked example's project file, to start a project from.
    Example,
}

#[derive(Args, Clone)]
struct BuildArgs {
    /// Project file (YAML). Without it, the worked example embedded in the program.
    project: Option<PathBuf>,
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

/// A failure, by whose it is: the input's (exit 1) or the output's (exit 3).
enum Failure {
    Input(anyhow::Error),
    Output(anyhow::Error),
}

pub fn run() -> ExitCode {
    let cli = Cli::parse(); // usage errors exit with 2
    let result = match cli.command {
        Some(Command::Example) => {
            print!("{DEFAULT_PROJECT}");
            Ok(())
        }
        Some(Command::Build(args)) => build(&args),
        None => build(&cli.build),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            eprintln!("error: {e:#}");
            ExitCode::from(1)
        }
        Err(Failure::Output(e)) => {
            eprintln!("error: {e:#}");
            ExitCode::from(3)
        }
    }
}

fn build(args: &BuildArgs) -> Result<(), Failure> {
    let (project, name) = load(args).map_err(Failure::Input)?;
    for w in &project.warnings {
        eprintln!("warning: in {name}: {w}");
    }
    let built = pipeline::build(&project, &args.sheets).map_err(|e| refused(e, &name)).map_err(Failure::Input)?;
    for b in &built {
        for d in &b.output.diagnostics {
            eprintln!("warning: in {name}: sheet {}, {d}", b.output.number);
        }
    }
    let formats = pipeline::formats(!args.no_pdf, (!args.no_png).then_some(args.png_dpi));
    let files = pipeline::outputs(&project, &built, &formats).map_err(|e| Failure::Output(e.into()))?;
    write::write_outputs(&args.output, &files).map_err(Failure::Output)?;
    let numbers: Vec<String> = built.iter().map(|b| b.output.number.to_string()).collect();
    println!("{name}: sheet {} written to {} ({} files)", numbers.join(", "), args.output.display(), files.len());
    Ok(())
}

fn load(args: &BuildArgs) -> Result<(crate::project::Project, String)> {
    let (text, name) = match &args.project {
        Some(p) => (read_project(p)?, p.display().to_string()),
        None => (DEFAULT_PROJECT.to_string(), "the worked example".to_string()),
    };
    let mut project = pipeline::load_for(&text, &args.sheets).map_err(|e| refused(e, &name))?;
    if let Some(l) = args.lang {
        project.info.language = match l {
            Lang::Uz => Language::Uz,
            Lang::Ru => Language::Ru,
            Lang::En => Language::En,
        };
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
