//! Sheet 1: the lever mechanism. Analyses the mechanism (positions, plans, and with a
//! `forces` section the kinetostatics at φ1), builds the note's tables and composes the
//! sheet; the composition itself lives in [`compose`] and the views it places.

mod choice;
pub mod compose;
mod drawn_once;
pub mod forces_view;
pub mod labels;
mod mechanism_place;
mod mechanism_view;
mod note_tables;
mod plan_regions;
mod plans_view;
pub mod results;
mod segments;

use super::scaffold::{self, Composition};
use super::{COURSE, Context, Sheet, SheetError, SheetKind};
use crate::drawing::labels::Language;
use crate::lever::analysis::{self, ForceAnalysis, Kinematics};
use crate::project::{LeverProject, Project};
use crate::report::NoteTable;
use crate::report::lever::{ForceTables, KinematicTables, force_tables, kinematic_tables};
use compose::Composed;
use labels::LeverLabels;

/// This sheet's place in the course.
pub const KIND: SheetKind = COURSE[0];

/// Sheet 1 of a project with a `mechanism` section.
pub struct LeverSheet<'a> {
    pub project: &'a LeverProject,
}

impl LeverSheet<'_> {
    pub fn of(project: &Project) -> Option<Box<dyn Sheet + '_>> {
        project.lever.as_ref().map(|p| Box::new(LeverSheet { project: p }) as Box<dyn Sheet>)
    }
}

/// Everything computed for sheet 1.
pub struct LeverBuild {
    pub kinematics: Kinematics,
    /// The force analysis at φ1 with tables 3–5, when the project asks for one.
    pub forces: Option<(ForceAnalysis, ForceTables)>,
    pub tables: KinematicTables,
    /// The note's tables 1–5 in the sheet's language.
    pub notes: Vec<NoteTable>,
    pub composed: Composed,
}

/// Analyses and composes sheet 1.
pub fn build(ctx: &Context, p: &LeverProject) -> Result<LeverBuild, SheetError> {
    let m = &p.mechanism;
    let kinematics = analysis::kinematics(m, &p.settings)?;
    let tables = kinematic_tables(m, &kinematics);
    let forces = match &p.forces {
        Some(model) => {
            let fa = analysis::forces(m, &kinematics, model)?;
            let t = force_tables(m, &fa);
            Some((fa, t))
        }
        None => None,
    };
    let notes = note_tables(ctx.info.language, &tables, forces.as_ref().map(|f| &f.1), ctx.first_table);
    let input = compose::Input { ctx, kind: KIND, project: p, notes: &notes, forces: forces.as_ref() };
    let composed = compose::compose(&input, &kinematics)?;
    Ok(LeverBuild { kinematics, forces, tables, notes, composed })
}

/// The note's tables with their titles in the sheet's language, numbered from `first`:
/// the velocities and the accelerations, and three more with a force analysis.
fn note_tables(lang: Language, k: &KinematicTables, f: Option<&ForceTables>, first: u32) -> Vec<NoteTable> {
    let l = LeverLabels::get(lang);
    let note =
        |table: &crate::report::NumTable, title: String| scaffold::note(lang, table.clone(), &title, vec![], false);
    let n = |k: u32| (first + k).to_string();
    let mut out =
        vec![note(&k.velocities, l.velocity_table(&n(0))), note(&k.accelerations, l.acceleration_table(&n(1)))];
    if let Some(t) = f {
        // A balancing value printed negative: the title says what the sign means (as
        // printed — a value that rounds to zero is written without its sign).
        let balancing = ["P_m", "M_m", "P_m_lever", "P_m_power"];
        let rows = t.balance.rows.iter().filter(|r| balancing.contains(&r.key.as_str()));
        let signed = rows.flat_map(|r| r.printed(false)).any(|v| v.starts_with('-'));
        let balance = if signed { l.balance_table_signed(&n(4)) } else { l.balance_table(&n(4)) };
        out.extend([
            note(&t.inertia, l.inertia_table(&n(2))),
            note(&t.reactions, l.reaction_table(&n(3))),
            note(&t.balance, balance),
        ]);
    }
    out
}

/// How many tables the note gets from sheet 1 (see `note_tables`).
pub fn table_count(p: &LeverProject) -> u32 {
    if p.forces.is_some() { 5 } else { 2 }
}

impl LeverBuild {
    /// The sheet's section of `results.json`.
    pub fn results(&self, p: &LeverProject) -> serde_json::Value {
        results::section(&p.mechanism, &self.kinematics, &self.composed, self.forces.as_ref().map(|f| &f.0))
    }

    /// What the user should know: an output with more extreme positions than the course's
    /// two.
    fn diagnostics(&self, p: &LeverProject) -> Vec<String> {
        let motion = &self.kinematics.motion;
        if motion.extremes.len() <= 2 {
            return Vec::new();
        }
        let angles: Vec<String> = motion
            .extremes
            .iter()
            .map(|&t| {
                let phi = (motion.sense.sign() * (t - motion.theta0)).rem_euclid(std::f64::consts::TAU);
                format!("θ = {:.1}° (φ = {:.1}°)", t.to_degrees(), phi.to_degrees())
            })
            .collect();
        vec![format!(
            "the output ({}) has {} extreme positions per crank turn, at {}: a slider or rocker driven as the course assumes has two, so the scheme is almost surely not the one meant (check the lengths, the guide and the branches)",
            crate::lever::motion::output_name(&p.mechanism),
            motion.extremes.len(),
            angles.join(", ")
        )]
    }
}

impl Sheet for LeverSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn table_count(&self) -> u32 {
        table_count(self.project)
    }

    fn name(&self, lang: crate::drawing::labels::Language) -> String {
        let l = labels::LeverLabels::get(lang);
        if self.project.forces.is_some() { l.sheet_name_forces() } else { l.sheet_name() }.to_string()
    }

    fn compose(&self, ctx: &Context) -> Result<Composition, SheetError> {
        let b = build(ctx, self.project)?;
        let results = b.results(self.project);
        let diagnostics = b.diagnostics(self.project);
        let c = b.composed.composition;
        // The scene finish would make of `c` is the one composed and measured.
        let measured = Some((b.composed.scene, b.composed.layout));
        Ok(Composition { results, diagnostics, tables: b.notes, measured, ..c })
    }
}
