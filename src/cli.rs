//! The command line: `tmm [build [PROJECT.yaml]] [-o DIR] [--sheet N]…`.
//!
//! Exit codes: 0 built; 1 the project was refused (unreadable, invalid, or a mechanism that
//! cannot be analysed); 2 a command-line usage error; 3 the outputs could not be written.

use crate::drawing::labels::Language;
use crate::pipeline::{self, DEFAULT_PROJECT};
use anyhow::{Context, Result, bail};
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
    #[arg(long = "sheet", value_delimiter = ',')]
    sheets: Vec<u32>,
    /// Label language, overriding the project file's.
    #[arg(long, value_enum)]
    lang: Option<Lang>,
    /// Resolution of the PNG preview, dots per inch (10–600).
    #[arg(long, default_value_t = 100.0)]
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

/// The file in the output directory that lists what the last build wrote, so that the next
/// build removes what it no longer writes (and nothing else).
pub const MANIFEST: &str = ".tmm-outputs";

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
    let built =
        pipeline::build(&project, &args.sheets).with_context(|| format!("in {name}")).map_err(Failure::Input)?;
    for b in &built {
        for d in &b.output.diagnostics {
            eprintln!("warning: sheet {}: {d}", b.output.number);
        }
    }
    let formats = pipeline::formats(!args.no_pdf, (!args.no_png).then_some(args.png_dpi));
    let files = pipeline::outputs(&project, &built, &formats).map_err(|e| Failure::Output(e.into()))?;
    write_all(&args.output, &files).map_err(Failure::Output)?;
    let numbers: Vec<String> = built.iter().map(|b| b.output.number.to_string()).collect();
    println!("{name}: sheet {} written to {} ({} files)", numbers.join(", "), args.output.display(), files.len());
    Ok(())
}

fn load(args: &BuildArgs) -> Result<(crate::project::Project, String)> {
    if !(10.0..=600.0).contains(&args.png_dpi) {
        bail!("--png-dpi must lie between 10 and 600, got {}", args.png_dpi);
    }
    let (text, name) = match &args.project {
        Some(p) => (
            std::fs::read_to_string(p).with_context(|| format!("cannot read {}", p.display()))?,
            p.display().to_string(),
        ),
        None => (DEFAULT_PROJECT.to_string(), "the worked example".to_string()),
    };
    let mut project = pipeline::load(&text).with_context(|| format!("in {name}"))?;
    if let Some(l) = args.lang {
        project.info.language = match l {
            Lang::Uz => Language::Uz,
            Lang::Ru => Language::Ru,
            Lang::En => Language::En,
        };
    }
    Ok((project, name))
}

/// Writes the files, removes those the previous build listed and this one did not write,
/// and records the new list.
fn write_all(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let previous = read_manifest(dir);
    for (name, bytes) in files {
        let p = dir.join(name);
        std::fs::write(&p, bytes).with_context(|| format!("cannot write {}", p.display()))?;
    }
    let now: BTreeSet<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    for stale in previous.iter().filter(|n| !now.contains(n.as_str())) {
        let p = dir.join(stale);
        if p.is_file() {
            std::fs::remove_file(&p).with_context(|| format!("cannot remove the stale output {}", p.display()))?;
        }
    }
    let list: String = now.iter().map(|n| format!("{n}\n")).collect();
    let p = dir.join(MANIFEST);
    std::fs::write(&p, list).with_context(|| format!("cannot write {}", p.display()))
}

/// The names the previous build wrote; only plain file names are trusted (a hand-edited
/// manifest cannot make a build delete anything outside the directory).
fn read_manifest(dir: &Path) -> Vec<String> {
    let Ok(text) = std::fs::read_to_string(dir.join(MANIFEST)) else { return Vec::new() };
    let plain = |n: &&str| !n.is_empty() && !n.starts_with('.') && !n.contains(['/', '\\']) && *n != MANIFEST;
    text.lines().map(str::trim).filter(plain).map(str::to_string).collect()
}
