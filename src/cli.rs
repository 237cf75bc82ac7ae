//! The command line: `tmm [build [PROJECT.yaml]] [-o DIR] [--sheet N]…`.

use crate::model::Language;
use crate::pipeline::{self, DEFAULT_PROJECT};
use crate::report;
use anyhow::{bail, Context, Result};
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::{Path, PathBuf};

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
    /// Sheets to build (1; sheets 2 and 3 are not implemented yet).
    #[arg(long = "sheet", value_delimiter = ',', default_values_t = vec![1])]
    sheets: Vec<u32>,
    /// Label language, overriding the project file's.
    #[arg(long, value_enum)]
    lang: Option<Lang>,
    /// Resolution of the PNG preview, dots per inch.
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

pub fn run() -> Result<()> {
    let cli = Cli::parse();
    match cli.command {
        Some(Command::Example) => {
            print!("{DEFAULT_PROJECT}");
            Ok(())
        }
        Some(Command::Build(args)) => build(&args),
        None => build(&cli.build),
    }
}

fn build(args: &BuildArgs) -> Result<()> {
    if let Some(&s) = args.sheets.iter().find(|&&s| s != 1) {
        bail!("sheet {s} is not available yet: this version draws sheet 1 (the lever mechanism)");
    }
    if !(10.0..=600.0).contains(&args.png_dpi) {
        bail!("--png-dpi must lie between 10 and 600, got {}", args.png_dpi);
    }
    let (text, name) = match &args.project {
        Some(p) => (std::fs::read_to_string(p).with_context(|| format!("cannot read {}", p.display()))?, p.display().to_string()),
        None => (DEFAULT_PROJECT.to_string(), "the worked example".to_string()),
    };
    let mut project = pipeline::load(&text).with_context(|| format!("in {name}"))?;
    if let Some(l) = args.lang {
        project.file.project.language = match l {
            Lang::Uz => Language::Uz,
            Lang::Ru => Language::Ru,
            Lang::En => Language::En,
        };
    }
    let s1 = pipeline::sheet1(&project).with_context(|| format!("in {name}"))?;
    let out = &args.output;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    write(out, "sheet1.svg", s1.svg.as_bytes())?;
    if !(args.no_pdf && args.no_png) {
        let dpi = (!args.no_png).then_some(args.png_dpi);
        let (pdf, png) = pipeline::pdf_and_png(&s1.svg, &s1.scene, dpi)?;
        if !args.no_pdf {
            write(out, "sheet1.pdf", &pdf)?;
        }
        if let Some(png) = png {
            write(out, "sheet1.png", &png)?;
        }
    }
    let (vt, at) = &s1.tables;
    write(out, "sheet1-velocities.csv", report::csv(vt).as_bytes())?;
    write(out, "sheet1-accelerations.csv", report::csv(at).as_bytes())?;
    let mut md = format!("{}\n{}", report::markdown(vt, "Table 1. Velocities and angular velocities"), report::markdown(at, "Table 2. Accelerations and angular accelerations"));
    if let Some((_, (t3, t4, t5))) = &s1.forces {
        for (t, file, title) in [
            (t3, "sheet1-inertia.csv", "Table 3. Inertia forces and moments (per link)"),
            (t4, "sheet1-reactions.csv", "Table 4. Reactions in the kinematic pairs (R_ij: link i on link j, 0 = frame)"),
            (t5, "sheet1-balancing.csv", "Table 5. Balancing force: kinetostatics, Zhukovsky lever, power balance"),
        ] {
            write(out, file, report::csv(t).as_bytes())?;
            md.push('\n');
            md.push_str(&report::markdown(t, title));
        }
    }
    write(out, "sheet1-tables.md", md.as_bytes())?;
    let json = s1.json(&project);
    write(out, "results.json", json.as_bytes())?;
    eprintln!("sheet 1 of {name} written to {}", out.display());
    Ok(())
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> Result<()> {
    let p = dir.join(name);
    std::fs::write(&p, bytes).with_context(|| format!("cannot write {}", p.display()))
}
