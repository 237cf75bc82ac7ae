//! The guide's assignments as data: every task's variant tables exactly as printed, their
//! corrections, and a template that turns a variant into a project file (catalogue/README.md
//! describes the folder). Pure: the texts come embedded or from the caller; [`Task::project`]
//! writes a project file's text, which the project layer then reads like any other.

mod data;
mod template;
mod words;

pub use data::{Column, Constant, Derived, Erratum, Row, VariantNote};
pub use template::Unfilled;
pub use words::CatalogueWords;

use crate::drawing::labels::Language;
use data::Meta;
use std::collections::BTreeMap;
use template::Known;

/// The catalogue's folders embedded at build time (build.rs): (folder, task.yaml,
/// variants.csv, errata.csv).
const EMBEDDED: &[(&str, &str, &str, &str)] = include!(concat!(env!("OUT_DIR"), "/catalogue.rs"));

/// One task of the guide (or a practice set of the kinematics manual).
#[derive(Debug, Clone)]
pub struct Task {
    pub folder: String,
    meta: Meta,
    pub rows: Vec<Row>,
    pub errata: Vec<Erratum>,
}

/// Every task, in folder order (tasks 1–15, then the practice sets).
#[derive(Debug, Clone)]
pub struct Catalogue {
    pub tasks: Vec<Task>,
}

/// What a variant gives: a project file, or why it cannot.
#[derive(Debug, Clone, PartialEq)]
pub enum Variant {
    /// The project file's text, and the sections left out because the guide lost their
    /// values (each "cam (φ_b)"), empty when the variant is complete.
    Project { text: String, left_out: Vec<String> },
    /// The guide lost values the template needs: their printed names and why (the task's
    /// `lost` notes for this variant).
    Incomplete {
        message: String,
        /// The lost values' printed names, comma-separated.
        lost: String,
    },
}

impl Catalogue {
    /// The catalogue built into the program.
    pub fn embedded() -> Result<Catalogue, String> {
        let sources: Vec<_> = EMBEDDED.iter().map(|&(f, t, v, e)| (f.to_string(), t, v, e)).collect();
        Catalogue::parse(&sources)
    }

    /// Reads folders given as (name, task.yaml, variants.csv, errata.csv) texts.
    pub fn parse(sources: &[(String, &str, &str, &str)]) -> Result<Catalogue, String> {
        let tasks = sources
            .iter()
            .map(|(folder, t, v, e)| Task::parse(folder, t, v, e).map_err(|why| format!("catalogue/{folder}/{why}")))
            .collect::<Result<Vec<Task>, _>>()?;
        let mut tasks = tasks;
        // The guide's tasks by number, then the practice sets.
        tasks.sort_by_key(|t| {
            (t.is_practice(), t.id().trim_start_matches('P').parse::<u32>().unwrap_or(u32::MAX), t.id())
        });
        Ok(Catalogue { tasks })
    }

    /// A task by the number the user typed: `7`, `07`, `P1`, `p1`.
    pub fn task(&self, id: &str) -> Result<&Task, String> {
        let want = id.trim().trim_start_matches('0').to_ascii_uppercase();
        self.tasks.iter().find(|t| t.id().to_ascii_uppercase() == want).ok_or_else(|| {
            let ids: Vec<String> = self.tasks.iter().map(Task::id).collect();
            format!("there is no task `{id}` in the catalogue (tasks: {})", ids.join(", "))
        })
    }
}

impl Task {
    fn parse(folder: &str, task: &str, variants: &str, errata: &str) -> Result<Task, String> {
        let meta = data::meta(task)?;
        let rows = data::rows(variants, &meta.columns)?;
        let errata = data::errata(errata)?;
        let t = Task { folder: folder.to_string(), meta, rows, errata };
        t.check().map_err(|why| format!("task.yaml: {why}"))?;
        Ok(t)
    }

    /// The task's identifier: "7", "P1".
    pub fn id(&self) -> String {
        self.meta.id()
    }

    /// A practice set of the kinematics manual (no forces, gears or cam).
    pub fn is_practice(&self) -> bool {
        self.id().starts_with('P')
    }

    pub fn name(&self, lang: Language) -> &str {
        self.meta.name.pick(lang)
    }

    pub fn kind(&self, lang: Language) -> &str {
        self.meta.kind.pick(lang)
    }

    pub fn columns(&self) -> &[Column] {
        &self.meta.columns
    }

    pub fn key_columns(&self) -> impl Iterator<Item = (usize, &Column)> {
        self.meta.key_columns.iter().filter_map(|k| self.meta.columns.iter().enumerate().find(|(_, c)| &c.key == k))
    }

    pub fn constants(&self) -> &[Constant] {
        &self.meta.constants
    }

    pub fn lost(&self) -> &[VariantNote] {
        &self.meta.lost
    }

    /// The task's notes on why the program refuses some variants as printed.
    pub fn refused(&self) -> &[VariantNote] {
        &self.meta.refused
    }

    /// Why the guide's data make the program refuse `variant`, if the task says so.
    pub fn refusal_explained(&self, variant: u32) -> Option<&VariantNote> {
        self.meta.refused.iter().find(|l| data::range(&l.variants).is_some_and(|r| r.contains(&variant)))
    }

    pub fn variants(&self) -> impl Iterator<Item = u32> + '_ {
        self.rows.iter().map(|r| r.variant)
    }

    /// A variant's row.
    pub fn row(&self, variant: u32) -> Result<&Row, String> {
        self.rows.iter().find(|r| r.variant == variant).ok_or_else(|| {
            let (first, last) = (self.rows.first().map_or(0, |r| r.variant), self.rows.last().map_or(0, |r| r.variant));
            format!("task {} has no variant {variant} (its variants are {first}–{last})", self.id())
        })
    }

    /// The corrections of a variant's cells.
    pub fn errata_of(&self, variant: u32) -> impl Iterator<Item = &Erratum> {
        self.errata.iter().filter(move |e| e.variant == variant)
    }

    /// A cell's value after the errata: (the text used, its erratum).
    pub fn cell(&self, row: &Row, column: usize) -> (Option<String>, Option<&Erratum>) {
        let key = &self.meta.columns[column].key;
        match self.errata.iter().find(|e| e.variant == row.variant && &e.column == key) {
            Some(e) => (e.corrected.clone(), Some(e)),
            None => (row.cells[column].clone(), None),
        }
    }

    /// The project file of a variant, commented in `lang`, or why the guide cannot give it.
    pub fn project(&self, variant: u32, lang: Language, command: &str) -> Result<Variant, String> {
        let row = self.row(variant)?;
        let w = CatalogueWords::get(lang);
        let known = self.known(row, lang);
        let computed = |e: &str, v: &str| w.computed(e, &data::printed(v, lang));
        let filled = template::fill(&template_in(&self.meta.template, lang), &known, &computed);
        let filled = filled.map(|sections| {
            let expand = |keys: Vec<String>| self.lost_columns(keys, &known);
            sections.into_iter().map(|s| template::Section { key: s.key, filled: s.filled.map_err(expand) }).collect()
        });
        match filled.map_err(|e| match e {
            Unfilled::Missing(keys) => Unfilled::Missing(self.lost_columns(keys, &known)),
            other => other,
        }) {
            Ok(sections) => Ok(self.assemble(row, sections, lang, command)),
            Err(Unfilled::Missing(keys)) => {
                Ok(Variant::Incomplete { message: self.incomplete(row, &keys, lang), lost: self.printed_names(&keys) })
            }
            Err(Unfilled::Invalid { line, expression, reason }) => {
                Err(format!("catalogue/{}/task.yaml: template line {line}: `${{{expression}}}`: {reason}", self.folder))
            }
        }
    }

    /// The project file from its filled sections: a section the guide's data cannot fill is
    /// a comment naming the values lost, and the variant says which sheets it lacks.
    fn assemble(&self, row: &Row, sections: Vec<template::Section>, lang: Language, command: &str) -> Variant {
        let mut body = String::new();
        let mut left_out = Vec::new();
        for s in sections {
            match s.filled {
                Ok(text) => body.push_str(&text),
                Err(keys) => {
                    let names = self.printed_names(&keys);
                    let w = CatalogueWords::get(lang);
                    let (why, said) = if names.is_empty() {
                        (s.key.clone(), w.left_out_with_mechanism().to_string())
                    } else {
                        (format!("{} ({names})", s.key), w.left_out(&names))
                    };
                    body.push_str(&format!("# {}: {said}\n\n", s.key));
                    left_out.push(why);
                }
            }
        }
        let body: String = body.lines().filter(|l| *l != DROPPED).map(|l| format!("{l}\n")).collect();
        let body = with_language(&body, lang);
        let mut header = self.header(row, lang, command);
        if !left_out.is_empty() {
            header.push_str(&format!("# {}\n", CatalogueWords::get(lang).partial(&left_out.join("; "))));
        }
        Variant::Project { text: format!("{header}{body}"), left_out }
    }

    /// Lost keys as the lost columns behind them: a derived value by the lost columns it is
    /// computed from.
    fn lost_columns(&self, keys: Vec<String>, known: &BTreeMap<String, Known>) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        let mut todo = keys;
        todo.reverse();
        while let Some(k) = todo.pop() {
            if let Some(d) = self.meta.derived.iter().find(|d| d.key == k) {
                let mut inputs = template::keys_of(&d.expression).unwrap_or_default();
                inputs.reverse();
                todo.extend(inputs);
            } else if known.get(&k).is_some_and(|n| n.value.is_none()) && !out.contains(&k) {
                out.push(k);
            }
        }
        out
    }

    /// Keys by their printed names, comma-separated.
    fn printed_names(&self, keys: &[String]) -> String {
        let names: Vec<&str> = keys
            .iter()
            .map(|k| self.meta.columns.iter().find(|c| &c.key == k).map_or(k.as_str(), |c| c.printed.as_str()))
            .collect();
        names.join(", ")
    }

    /// Every value the template may use: the columns (after the errata) and the constants.
    fn known(&self, row: &Row, lang: Language) -> BTreeMap<String, Known> {
        let w = CatalogueWords::get(lang);
        let mut out = BTreeMap::new();
        for (i, c) in self.meta.columns.iter().enumerate() {
            let (text, erratum) = self.cell(row, i);
            let value = text.as_deref().and_then(data::number);
            let shown = text.as_deref().map_or("—".to_string(), |t| data::printed(t, lang));
            let source = w.cell_source(&row.table, &row.variant.to_string());
            let mut note =
                format!("{} = {shown} {} ({}): {source}", c.printed, words::unit(&c.unit, lang), c.what.pick(lang));
            if let Some(e) = erratum {
                let reason = e.reason.pick(lang);
                note.push_str("; ");
                note.push_str(&match &e.printed {
                    Some(p) => w.corrected(&data::printed(p, lang), reason),
                    None => w.restored(reason),
                });
            }
            out.insert(c.key.clone(), Known { value, note: tidy(&note) });
        }
        let note = format!("{}: {}", w.col_variant(), row.variant);
        out.insert("variant".into(), Known { value: Some(f64::from(row.variant)), note });
        for c in &self.meta.constants {
            let note = format!("{} ({}): {}", constant(c, lang), c.what.pick(lang), c.source.pick(lang));
            out.insert(c.key.clone(), Known { value: Some(c.value), note: tidy(&note) });
        }
        for d in &self.meta.derived {
            // Checked when the catalogue is read: the expression parses and names known keys.
            let value = template::evaluate(&d.expression, &out, &mut Vec::new()).ok().flatten().map(|(x, _)| x);
            let shown = value.map_or("—".to_string(), |x| printed_number(x, lang));
            let unit = words::unit(&d.unit, lang);
            let computed = w.computed(&d.expression, &shown);
            // The values it is computed from are named too, each on its own comment line.
            let mut lines: Vec<String> = Vec::new();
            for k in template::keys_of(&d.expression).unwrap_or_default() {
                for l in out.get(&k).map_or("", |n| n.note.as_str()).lines() {
                    if !lines.iter().any(|x| x == l) {
                        lines.push(l.to_string());
                    }
                }
            }
            lines.push(tidy(&format!("{} = {shown} {unit} ({}): {computed}", d.key, d.what.pick(lang))));
            out.insert(d.key.clone(), Known { value, note: lines.join("\n") });
        }
        out
    }

    /// The generated file's opening comment: the source, how it was written, the errata.
    fn header(&self, row: &Row, lang: Language, command: &str) -> String {
        let w = CatalogueWords::get(lang);
        let v = row.variant.to_string();
        let first = if self.is_practice() {
            w.header_practice(w.manual(), &row.table, &v, self.name(lang))
        } else {
            w.header_task(w.guide(), &self.id(), &v, self.name(lang))
        };
        let mut out = format!("# {first}\n# {}\n", w.header_written(command));
        let errata: Vec<&Erratum> = self.errata_of(row.variant).collect();
        if !errata.is_empty() {
            out.push_str(&format!("# {}\n", w.header_errata()));
            for e in errata {
                let name =
                    self.meta.columns.iter().find(|c| c.key == e.column).map_or(e.column.as_str(), |c| &c.printed);
                let printed = e.printed.as_deref().map_or("—".into(), |p| data::printed(p, lang));
                let corrected = e.corrected.as_deref().map_or("—".into(), |p| data::printed(p, lang));
                out.push_str(&format!("#   {name}: {printed} → {corrected}: {}\n", e.reason.pick(lang)));
            }
        }
        out
    }

    /// Why a variant is incomplete: the lost values by their printed names, and the task's
    /// note on why they are lost.
    fn incomplete(&self, row: &Row, keys: &[String], lang: Language) -> String {
        let w = CatalogueWords::get(lang);
        let mut text = w.incomplete(&self.id(), &row.variant.to_string(), &self.printed_names(keys));
        for l in self.lost_notes(row.variant) {
            text.push_str(" (");
            text.push_str(l.why.pick(lang));
            text.push(')');
        }
        text
    }

    /// The task's notes on lost values that concern `variant`.
    pub fn lost_notes(&self, variant: u32) -> impl Iterator<Item = &VariantNote> {
        self.meta.lost.iter().filter(move |l| data::range(&l.variants).is_some_and(|r| r.contains(&variant)))
    }

    /// The task's own consistency: unique keys, known key columns and errata cells, readable
    /// ranges, variants in order, template expressions that parse and name known keys.
    fn check(&self) -> Result<(), String> {
        let m = &self.meta;
        let mut keys: Vec<&str> =
            m.columns.iter().map(|c| c.key.as_str()).chain(m.constants.iter().map(|c| c.key.as_str())).collect();
        keys.push("variant");
        for d in &m.derived {
            let names = template::keys_of(&d.expression).map_err(|why| format!("derived `{}`: {why}", d.key))?;
            if let Some(n) = names.iter().find(|n| !keys.contains(&n.as_str())) {
                return Err(format!(
                    "derived `{}`: `{n}` is not a column, a constant or an earlier derived value",
                    d.key
                ));
            }
            keys.push(&d.key);
        }
        keys.sort_unstable();
        if let Some(w) = keys.windows(2).find(|w| w[0] == w[1]) {
            return Err(format!("the key `{}` is defined twice", w[0]));
        }
        if let Some(k) = m.key_columns.iter().find(|k| !keys.contains(&k.as_str())) {
            return Err(format!("key_columns: `{k}` is not a column"));
        }
        for (table, r) in &m.tables {
            data::range(r).ok_or_else(|| format!("tables: `{table}: {r}` is not a range of variants"))?;
        }
        for l in m.lost.iter().chain(&m.refused) {
            data::range(&l.variants)
                .ok_or_else(|| format!("lost, refused: `{}` is not a range of variants", l.variants))?;
        }
        if let Some(w) = self.rows.windows(2).find(|w| w[1].variant <= w[0].variant) {
            return Err(format!(
                "variants.csv: variant {} follows {}: one row per variant, in order",
                w[1].variant, w[0].variant
            ));
        }
        for e in &self.errata {
            let row = self.row(e.variant).map_err(|why| format!("errata.csv: {why}"))?;
            let i = m
                .columns
                .iter()
                .position(|c| c.key == e.column)
                .ok_or_else(|| format!("errata.csv: no column `{}`", e.column))?;
            if row.cells[i].as_deref().and_then(data::number) != e.printed.as_deref().and_then(data::number) {
                return Err(format!(
                    "errata.csv: variant {} {}: printed `{}` but variants.csv has `{}`",
                    e.variant,
                    e.column,
                    e.printed.as_deref().unwrap_or(""),
                    row.cells[i].as_deref().unwrap_or("")
                ));
            }
        }
        for (line, e) in template::all_expressions(&m.template) {
            let names = template::keys_of(&e).map_err(|why| format!("template line {line}: `${{{e}}}`: {why}"))?;
            if let Some(n) = names.iter().find(|n| !keys.contains(&n.as_str())) {
                return Err(format!("template line {line}: `${{{e}}}`: `{n}` is neither a column nor a constant"));
            }
        }
        Ok(())
    }
}

/// The template for a file in `lang`: its own comments are written in English (they document
/// the preset; everything they tell a student is in the uz/ru/en assumptions), so in Uzbek or
/// Russian each becomes a [`DROPPED`] line — dropped after filling, the template's line
/// numbers kept for its messages.
fn template_in(template: &str, lang: Language) -> String {
    if lang == Language::En {
        return template.to_string();
    }
    template
        .lines()
        .map(|l| if l.trim_start().starts_with('#') { DROPPED } else { l })
        .map(|l| format!("{l}\n"))
        .collect()
}

/// A template line left out of the file (see [`template_in`]).
const DROPPED: &str = "\u{1}";

/// The project file with `project.language` set to `lang`: the language the student chose
/// for the comments is the sheets' too.
fn with_language(body: &str, lang: Language) -> String {
    let mut out = String::new();
    let (mut in_project, mut written) = (false, false);
    for line in body.lines() {
        if !line.starts_with([' ', '#']) && !line.trim().is_empty() {
            if in_project && !written {
                out.push_str(&format!("  language: {}\n", lang.key()));
                written = true;
            }
            in_project = line.starts_with("project:");
        }
        if in_project
            && line.trim_start().starts_with("language:")
            && line.starts_with("  ")
            && !line.starts_with("   ")
        {
            out.push_str(&format!("  language: {}\n", lang.key()));
            written = true;
            continue;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// A constant as `symbol = value unit` in `lang`.
pub fn constant(c: &Constant, lang: Language) -> String {
    let symbol = c.printed.as_deref().unwrap_or(&c.key);
    tidy(&format!("{symbol} = {} {}", printed_number(c.value, lang), words::unit(&c.unit, lang))).trim_end().to_string()
}

/// A column's heading with its unit in `lang`: "L_O1A, м".
pub fn heading(c: &Column, lang: Language) -> String {
    if c.unit.is_empty() { c.printed.clone() } else { format!("{}, {}", c.printed, words::unit(&c.unit, lang)) }
}

/// A note's spacing: no space before a degree sign, none left by an empty unit.
fn tidy(note: &str) -> String {
    note.replace(" °", "°").replace(" ,", ",").replace("  (", " (")
}

/// A number as the catalogue prints it for a reader: a decimal comma in Uzbek and Russian.
pub fn printed_number(x: f64, lang: Language) -> String {
    data::printed(&template::number(x), lang)
}

/// The variants a range text names ("1-15, 31"), as a task's notes write them.
pub fn variant_range(text: &str) -> Option<Vec<u32>> {
    data::range(text)
}

/// A cell's text as the guide prints it in `lang`.
pub fn printed_cell(cell: &str, lang: Language) -> String {
    data::printed(cell, lang)
}
