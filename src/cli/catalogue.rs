//! `tmm list` and `tmm init`: the catalogue for a student choosing their assignment, and a
//! variant's project file to start from.

use crate::catalogue::{Catalogue, CatalogueWords, Task, Variant};
use crate::drawing::labels::Language;
use anyhow::{Context, Result, anyhow, bail};
use std::fmt::Write as _;
use std::io::Read;
use std::path::Path;

/// The largest file of a catalogue folder read.
const FILE_LIMIT: u64 = 4 * 1024 * 1024;

/// The embedded catalogue, or the folder `dir` in the same form.
pub fn load(dir: Option<&Path>) -> Result<Catalogue> {
    let Some(dir) = dir else { return Catalogue::embedded().map_err(|e| anyhow!("the embedded {e}")) };
    let mut folders: Vec<String> = std::fs::read_dir(dir)
        .with_context(|| format!("cannot read the catalogue folder {}", dir.display()))?
        .filter_map(Result::ok)
        .filter(|e| e.path().join("task.yaml").is_file())
        .filter_map(|e| e.file_name().into_string().ok())
        .collect();
    folders.sort();
    if folders.is_empty() {
        bail!("{} holds no catalogue folder (a folder with a task.yaml)", dir.display());
    }
    let texts = folders
        .iter()
        .map(|f| {
            let read = |name: &str| read_small(&dir.join(f).join(name));
            Ok((f.clone(), read("task.yaml")?, read("variants.csv")?, read("errata.csv")?))
        })
        .collect::<Result<Vec<_>>>()?;
    let sources: Vec<_> = texts.iter().map(|(f, t, v, e)| (f.clone(), t.as_str(), v.as_str(), e.as_str())).collect();
    Catalogue::parse(&sources).map_err(|e| anyhow!("in {}: {e}", dir.display()))
}

/// A catalogue file's text; a missing file reads as empty.
fn read_small(path: &Path) -> Result<String> {
    let Ok(file) = std::fs::File::open(path) else { return Ok(String::new()) };
    let mut text = String::new();
    file.take(FILE_LIMIT).read_to_string(&mut text).with_context(|| format!("cannot read {}", path.display()))?;
    Ok(text)
}

/// Consecutive numbers as ranges: 1–15, 31, 33–45.
pub fn ranges(numbers: &[u32]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < numbers.len() {
        let mut j = i;
        while j + 1 < numbers.len() && numbers[j + 1] == numbers[j] + 1 {
            j += 1;
        }
        out.push(if i == j { numbers[i].to_string() } else { format!("{}–{}", numbers[i], numbers[j]) });
        i = j + 1;
    }
    out.join(", ")
}

/// The variants of a task the guide leaves incomplete, with why, and those it leaves
/// incomplete in part (some sheets' values lost), with the sections left out.
fn incomplete(task: &Task, lang: Language) -> Result<(Vec<(u32, String)>, Vec<(u32, String)>)> {
    let (mut whole, mut part) = (Vec::new(), Vec::new());
    for v in task.variants() {
        match task.project(v, lang, "").map_err(|e| anyhow!(e))? {
            Variant::Incomplete { message } => whole.push((v, message)),
            Variant::Project { left_out, .. } if !left_out.is_empty() => part.push((v, left_out.join("; "))),
            Variant::Project { .. } => {}
        }
    }
    Ok((whole, part))
}

/// Pads `s` to `width` characters.
fn pad(s: &str, width: usize) -> String {
    let n = s.chars().count();
    format!("{s}{}", " ".repeat(width.saturating_sub(n)))
}

/// Lines of aligned columns, two spaces apart.
fn aligned(rows: &[Vec<String>]) -> String {
    let cols = rows.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> =
        (0..cols).map(|c| rows.iter().filter_map(|r| r.get(c)).map(|s| s.chars().count()).max().unwrap_or(0)).collect();
    let mut out = String::new();
    for r in rows {
        let cells: Vec<String> = r.iter().enumerate().map(|(c, s)| pad(s, widths[c])).collect();
        out.push_str(cells.join("  ").trim_end());
        out.push('\n');
    }
    out
}

/// `tmm list`: the tasks, their machines, variants and the incomplete ones.
pub fn list(cat: &Catalogue, lang: Language) -> Result<String> {
    let w = CatalogueWords::get(lang);
    let mut out = String::new();
    for practice in [false, true] {
        let heading = if practice { w.list_practice() } else { w.list_heading() };
        let source = if practice { w.manual() } else { w.guide() };
        writeln!(out, "{heading} ({source})\n").ok();
        let mut rows = vec![vec![
            w.col_task().to_string(),
            w.col_machine().into(),
            w.col_kind().into(),
            w.col_variants().into(),
            w.col_incomplete().into(),
            w.col_partial().into(),
        ]];
        let mut why = Vec::new();
        for t in cat.tasks.iter().filter(|t| t.is_practice() == practice) {
            let all: Vec<u32> = t.variants().collect();
            let (missing, part) = incomplete(t, lang)?;
            let shown = |list: &[(u32, String)]| {
                let numbers: Vec<u32> = list.iter().map(|m| m.0).collect();
                if numbers.is_empty() { w.none().to_string() } else { ranges(&numbers) }
            };
            rows.push(vec![
                t.id(),
                t.name(lang).into(),
                t.kind(lang).into(),
                ranges(&all),
                shown(&missing),
                shown(&part),
            ]);
            let mut reasons: Vec<String> =
                t.lost().iter().map(|l| format!("{}: {}", l.variants, l.why.pick(lang))).collect();
            if reasons.is_empty() {
                reasons.extend(missing.iter().map(|(_, m)| m.clone()));
            }
            why.extend(reasons.into_iter().map(|r| format!("  {}: {r}", t.id())));
        }
        out.push_str(&aligned(&rows));
        for line in why {
            writeln!(out, "{line}").ok();
        }
        out.push('\n');
    }
    out.push_str(w.list_hint());
    out.push('\n');
    Ok(out)
}

/// `tmm list --task T`: the task's constants, and each variant's key data and status.
pub fn list_task(task: &Task, lang: Language) -> Result<String> {
    let w = CatalogueWords::get(lang);
    let mut out = format!("{} {} — {} ({})\n", w.col_task(), task.id(), task.name(lang), task.kind(lang));
    if !task.constants().is_empty() {
        writeln!(out, "{}:", w.constants()).ok();
        for c in task.constants() {
            let c_text = crate::catalogue::constant(c, lang);
            writeln!(out, "  {c_text} — {} ({})", c.what.pick(lang), c.source.pick(lang)).ok();
        }
    }
    out.push('\n');
    let keys: Vec<_> = task.key_columns().collect();
    let mut head = vec![w.col_variant().to_string(), w.col_table().to_string()];
    head.extend(keys.iter().map(|(_, c)| crate::catalogue::heading(c, lang)));
    head.push(String::new());
    let mut rows = vec![head];
    let (missing, part) = incomplete(task, lang)?;
    for r in &task.rows {
        let mut row = vec![r.variant.to_string(), r.table.clone()];
        for (i, _) in &keys {
            let (value, erratum) = task.cell(r, *i);
            let shown = value.map_or("—".into(), |v| crate::catalogue::printed_cell(&v, lang));
            row.push(if erratum.is_some() { format!("{shown}*") } else { shown });
        }
        let status = if missing.iter().any(|m| m.0 == r.variant) {
            w.col_incomplete().to_string()
        } else if part.iter().any(|m| m.0 == r.variant) {
            w.col_partial().to_string()
        } else {
            String::new()
        };
        row.push(status);
        rows.push(row);
    }
    out.push_str(&aligned(&rows));
    for e in &task.errata {
        let name = task.columns().iter().find(|c| c.key == e.column).map_or(e.column.as_str(), |c| c.printed.as_str());
        let p = |s: &Option<String>| s.as_deref().map_or("—".into(), |s| crate::catalogue::printed_cell(s, lang));
        writeln!(out, "* {} {}, {name}: {} → {}", w.col_variant(), e.variant, p(&e.printed), p(&e.corrected)).ok();
        writeln!(out, "    {}", e.reason.pick(lang)).ok();
    }
    for (v, m) in &missing {
        writeln!(out, "{v}: {m}").ok();
    }
    for (v, m) in &part {
        writeln!(out, "{v}: {}: {m}", w.col_partial()).ok();
    }
    Ok(out)
}
