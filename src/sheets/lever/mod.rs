//! Sheet 1: the lever mechanism. Analyses the mechanism (positions, plans, and with a
//! `forces` section the kinetostatics at φ1), builds the note's tables and composes the
//! sheet; the composition itself lives in [`compose`] and the views it places.

pub mod compose;
pub mod forces_view;
pub mod labels;
mod mechanism_view;
mod plans_view;
pub mod results;

use super::{COURSE, Context, Sheet, SheetError, SheetKind, SheetOutput};
use crate::drawing::labels::{Common, Language};
use crate::lever::analysis::{self, ForceAnalysis, Kinematics};
use crate::project::{LeverProject, Project};
use crate::report::lever::{ForceTables, KinematicTables, force_tables, kinematic_tables};
use crate::report::{NoteTable, NumTable};
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
    let input = compose::Input {
        info: ctx.info,
        project: p,
        tables: &tables,
        forces: forces.as_ref(),
        sheet_no: KIND.number,
        sheet_count: ctx.sheet_count,
    };
    let composed = compose::compose(&input, &kinematics)?;
    Ok(LeverBuild { kinematics, forces, tables, composed })
}

impl LeverBuild {
    /// The note's tables with their titles, headings and units in the sheet's language.
    pub fn note_tables(&self, lang: Language) -> Vec<NoteTable> {
        let (l, c) = (LeverLabels::get(lang), Common::get(lang));
        let note = |stem: &'static str, title: &str, table: &NumTable| NoteTable {
            stem,
            title: title.into(),
            headings: [c.quantity().into(), c.unit().into()],
            units: table.rows.iter().map(|r| c.si_unit(&r.unit).to_string()).collect(),
            // Force symbols' subscripts in the sheet's language (P_и on a Russian sheet).
            table: NumTable {
                rows: table
                    .rows
                    .iter()
                    .map(|r| crate::report::Row { sub: l.force_sub(&r.symbol, &r.sub), ..r.clone() })
                    .collect(),
                ..table.clone()
            },
            decimal_comma: lang != Language::En,
            column_titles: Vec::new(),
            whole_numbers: false,
        };
        let mut out = vec![
            note("velocities", l.velocity_table(), &self.tables.velocities),
            note("accelerations", l.acceleration_table(), &self.tables.accelerations),
        ];
        if let Some((_, t)) = &self.forces {
            out.extend([
                note("inertia", l.inertia_table(), &t.inertia),
                note("reactions", l.reaction_table(), &t.reactions),
                note("balancing", l.balance_table(), &t.balance),
            ]);
        }
        out
    }

    /// The sheet's section of `results.json`.
    pub fn results(&self, p: &LeverProject) -> serde_json::Value {
        results::section(&p.mechanism, &self.kinematics, &self.composed, self.forces.as_ref().map(|f| &f.0))
    }
}

impl Sheet for LeverSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn build(&self, ctx: &Context) -> Result<SheetOutput, SheetError> {
        let b = build(ctx, self.project)?;
        let mut diagnostics: Vec<String> = Vec::new();
        let motion = &b.kinematics.motion;
        if motion.extremes.len() > 2 {
            let angles: Vec<String> = motion
                .extremes
                .iter()
                .map(|&t| {
                    let phi = (motion.sense * (t - motion.theta0)).rem_euclid(std::f64::consts::TAU);
                    format!("θ = {:.1}° (φ = {:.1}°)", t.to_degrees(), phi.to_degrees())
                })
                .collect();
            diagnostics.push(format!(
                "the output ({}) has {} extreme positions per crank turn, at {}: a slider or rocker driven as the course assumes has two, so the scheme is almost surely not the one meant (check the lengths, the guide and the branches)",
                crate::lever::motion::output_name(&self.project.mechanism),
                motion.extremes.len(),
                angles.join(", ")
            ));
        }
        diagnostics.extend(b.composed.layout.problems.iter().map(|p| format!("layout: {p}")));
        Ok(SheetOutput {
            number: self.kind().number,
            tables: b.note_tables(ctx.info.language),
            results: b.results(self.project),
            scene: b.composed.scene,
            diagnostics,
        })
    }
}
