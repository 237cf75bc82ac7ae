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

/// Variants, each with a text.
type ByVariant = Vec<(u32, String)>;

/// The variants of a task the guide leaves incomplete, with the values lost, and those it
/// leaves incomplete in part (some sheets' values lost), with the sections left out.
fn incomplete(task: &Task, lang: Language) -> Result<(ByVariant, ByVariant)> {
    let (mut whole, mut part) = (Vec::new(), Vec::new());
    for v in task.variants() {
        match task.project(v, lang, "").map_err(|e| anyhow!(e))? {
            Variant::Incomplete { lost, .. } => whole.push((v, lost)),
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

/// A range note's variants as the listing writes them: "1–15, 31".
fn shown_range(text: &str) -> String {
    crate::catalogue::variant_range(text).map_or(text.to_string(), |v| ranges(&v))
}

/// Lines that say the same for several variants, said once with the variants' ranges:
/// (variants, text) in order of first appearance.
fn grouped(items: impl IntoIterator<Item = (u32, String)>) -> Vec<(String, String)> {
    let mut groups: Vec<(Vec<u32>, String)> = Vec::new();
    for (v, text) in items {
        match groups.iter_mut().find(|(_, t)| *t == text) {
            Some((vs, _)) => vs.push(v),
            None => groups.push((vec![v], text)),
        }
    }
    groups.into_iter().map(|(vs, t)| (ranges(&vs), t)).collect()
}

/// `tmm list`: the tasks, their machines, variants, the incomplete ones and those the
/// program refuses as printed, with why.
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
            w.refused_as_printed().into(),
        ]];
        let mut why = Vec::new();
        for t in cat.tasks.iter().filter(|t| t.is_practice() == practice) {
            let all: Vec<u32> = t.variants().collect();
            let (missing, part) = incomplete(t, lang)?;
            let shown = |numbers: Vec<u32>| if numbers.is_empty() { w.none().to_string() } else { ranges(&numbers) };
            let refused: Vec<u32> = all.iter().copied().filter(|&v| t.refusal_explained(v).is_some()).collect();
            rows.push(vec![
                t.id(),
                t.name(lang).into(),
                t.kind(lang).into(),
                ranges(&all),
                shown(missing.iter().map(|m| m.0).collect()),
                shown(part.iter().map(|m| m.0).collect()),
                shown(refused),
            ]);
            let mut reasons: Vec<String> =
                t.lost().iter().map(|l| format!("{}: {}", shown_range(&l.variants), l.why.pick(lang))).collect();
            if reasons.is_empty() {
                reasons.extend(grouped(missing).into_iter().map(|(v, m)| format!("{v}: {}: {m}", w.col_incomplete())));
            }
            reasons.extend(
                t.refused()
                    .iter()
                    .map(|l| format!("{}: {}: {}", shown_range(&l.variants), w.refused_as_printed(), l.why.pick(lang))),
            );
            why.extend(reasons.into_iter().map(|r| format!("  {} {}, {r}", w.col_task(), t.id())));
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

/// `tmm list --task T`: the task's constants, each variant's key data and status, the
/// corrections, and why variants are incomplete or refused.
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
    head.push(w.col_status().to_string());
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
            w.col_incomplete()
        } else if part.iter().any(|m| m.0 == r.variant) {
            w.col_partial()
        } else if task.refusal_explained(r.variant).is_some() {
            w.refused_as_printed()
        } else {
            ""
        };
        row.push(status.to_string());
        rows.push(row);
    }
    out.push_str(&aligned(&rows));
    let p = |s: &Option<String>| s.as_deref().map_or("—".into(), |s| crate::catalogue::printed_cell(s, lang));
    let errata = task.errata.iter().map(|e| {
        let name = task.columns().iter().find(|c| c.key == e.column).map_or(e.column.as_str(), |c| c.printed.as_str());
        (e.variant, format!("{name}: {} → {}\n    {}", p(&e.printed), p(&e.corrected), e.reason.pick(lang)))
    });
    for (v, text) in grouped(errata) {
        writeln!(out, "* {} {v}, {text}", w.col_variant()).ok();
    }
    for (v, m) in grouped(missing) {
        writeln!(out, "{v}: {}: {m}", w.col_incomplete()).ok();
    }
    for l in task.lost() {
        writeln!(out, "{}: {}", shown_range(&l.variants), l.why.pick(lang)).ok();
    }
    for (v, m) in grouped(part) {
        writeln!(out, "{v}: {}: {m}", w.col_partial()).ok();
    }
    for l in task.refused() {
        writeln!(out, "{}: {}: {}", shown_range(&l.variants), w.refused_as_printed(), l.why.pick(lang)).ok();
    }
    Ok(out)
}
