//! `tmm check [PROJECT] MEASURED.csv`: a student's values against the exact answers of the
//! project's sheets (the worked example when no project is named, or `--task`/`--variant`).
//!
//! Exit codes: 0 every value passes; 1 some value fails; 2 the values or the project cannot
//! be used (unreadable, empty, an unknown name, a unit of another quantity, a project
//! refused); 3 the report could not be written.

use super::write;
use crate::check::{self, Tolerance, read};
use crate::pipeline::ReportNames as Names;
use crate::pipeline::{self, DEFAULT_PROJECT};
use anyhow::anyhow;
use clap::Args;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Args)]
pub struct CheckArgs {
    /// The project file and the student's values (CSV), or the values alone: then they are
    /// checked against the worked example, or the variant of `--task` and `--variant`.
    #[arg(required = true, num_args = 1..=2, value_name = "FILES")]
    files: Vec<PathBuf>,
    /// Check against the guide's task (with `--variant`).
    #[arg(long, requires = "variant")]
    task: Option<String>,
    /// The variant of `--task`.
    #[arg(long, requires = "task")]
    variant: Option<u32>,
    /// The tolerance of every value not given its own: percent of the exact value ("5" or
    /// "5%"), instead of the course's rule.
    #[arg(long, value_parser = parse_percent)]
    tolerance: Option<f64>,
    /// Also write the verdicts to this file: Markdown (.md), CSV (.csv), or PDF (.pdf: A4
    /// pages to hand back, in the project's language or `--lang`'s).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// The PDF report's language, overriding the project file's.
    #[arg(long, value_enum)]
    lang: Option<super::Lang>,
}

fn parse_percent(s: &str) -> Result<f64, String> {
    match read::parse_tolerance(s.trim_end_matches('%')) {
        Some(Tolerance::Absolute(p)) => Ok(p / 100.0),
        _ => Err(format!("'{s}' is not a percentage (such as 5 or 5%)")),
    }
}

/// Runs the check and prints the verdicts; the exit code says how it went.
pub fn run(args: &CheckArgs, dir: Option<&Path>) -> ExitCode {
    match checked(args, dir) {
        Ok(all_pass) => ExitCode::from(u8::from(!all_pass)),
        Err((e, code)) => {
            eprintln!("error: {e:#}");
            ExitCode::from(code)
        }
    }
}

fn checked(args: &CheckArgs, dir: Option<&Path>) -> Result<bool, (anyhow::Error, u8)> {
    let unusable = |e: anyhow::Error| (e, 2);
    let (project_text, name) = match (args.files.as_slice(), &args.task, args.variant) {
        ([project, _], None, _) => (super::read_project(project).map_err(unusable)?, project.display().to_string()),
        ([_], Some(t), Some(v)) => super::variant_text(dir, t, v, Default::default()).map_err(|f| match f {
            super::Failure::Input(e) | super::Failure::Usage(e) | super::Failure::Output(e) => (e, 2),
        })?,
        ([_], None, _) => (DEFAULT_PROJECT.to_string(), "the worked example".to_string()),
        _ => return Err((anyhow!("name either a project file or --task and --variant, not both"), 2)),
    };
    let values = args.files.last().expect("clap requires one file");
    if args.files.len() == 1 && values.extension().is_some_and(|x| x == "yaml" || x == "yml") {
        return Err((
            anyhow!("{} is a project file: give the student's values too (tmm check {0} VALUES.csv)", values.display()),
            2,
        ));
    }
    if let Some(out) = &args.output
        && std::fs::canonicalize(out).ok().is_some_and(|o| std::fs::canonicalize(values).ok() == Some(o))
    {
        return Err((anyhow!("-o {} would replace the student's values with the report", out.display()), 2));
    }
    let mut project = pipeline::load(&project_text).map_err(|e| unusable(anyhow!(super::refused(e, &name))))?;
    if let Some(l) = super::language(args.lang) {
        project.info.language = l;
    }
    let reference = pipeline::reference(&project).map_err(|e| unusable(anyhow!(super::refused(e, &name))))?;
    let bytes = std::fs::read(values).map_err(|e| unusable(anyhow!("cannot read {}: {e}", values.display())))?;
    let (text, code_page) = read::decode(&bytes);
    if let Some(page) = code_page {
        eprintln!("note: {} is not UTF-8: read as {page}", values.display());
    }
    let (rows, skipped) = read::measured(&text).map_err(|e| unusable(anyhow!("in {}: {e}", values.display())))?;
    for line in skipped {
        eprintln!("warning: in {}: line {line}: no value and no length in mm: not checked", values.display());
    }
    let verdicts = check::check(&reference, &rows, args.tolerance.map(Tolerance::Relative)).map_err(|e| {
        let each: Vec<String> = e.0.iter().map(|x| format!("in {}: {x}", values.display())).collect();
        unusable(anyhow!(each.join("\nerror: ")))
    })?;
    // The same quantity twice is almost surely a slip (a position mistyped): both are judged.
    for (k, v) in verdicts.iter().enumerate() {
        if let Some(first) = verdicts[..k].iter().find(|w| w.id == v.id) {
            eprintln!(
                "warning: in {}: line {}: {} is given on line {} too",
                values.display(),
                v.line,
                v.id,
                first.line
            );
        }
    }
    print!("{}", check::write::text(&verdicts));
    if let Some(out) = &args.output {
        let body = match out.extension().and_then(|x| x.to_str()) {
            Some("csv") => check::write::csv(&verdicts).into_bytes(),
            Some("md") => check::write::markdown(&verdicts).into_bytes(),
            Some("pdf") => {
                // The worked example (or a variant) by its title, a file by its path.
                let project_name = if args.files.len() == 2 { name.clone() } else { project.info.title().to_string() };
                let names = Names { project: &project_name, values: &values.display().to_string() };
                pipeline::check_report_pdf(&project, &verdicts, &names).map_err(|e| (anyhow!(e), 3))?
            }
            _ => return Err((anyhow!("{}: the report is written as .md, .csv or .pdf", out.display()), 2)),
        };
        write::write_file(out, &body).map_err(|e| (e, 3))?;
    }
    Ok(verdicts.iter().all(|v| v.pass))
}
