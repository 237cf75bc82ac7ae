//! The tables of the explanatory note ("1-jadval", "2-jadval") as numbers, written as
//! CSV and Markdown, and every computed quantity as JSON (SI units).

use crate::analysis::{Kinematics, Position};
use crate::mechanics::linkage::{LinkKind, Mechanism};
use crate::mechanics::plans::relation_values;
use serde::Serialize;
use std::fmt::Write;

/// One row of a table: a symbol with a subscript, its unit and a value per column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub symbol: String,
    pub sub: String,
    pub unit: String,
    pub values: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NumTable {
    pub name: String,
    /// Position labels, one per column.
    pub columns: Vec<String>,
    pub rows: Vec<Row>,
}

fn moving_points(m: &Mechanism) -> Vec<usize> {
    (0..m.point_names.len())
        .filter(|&id| !m.frame.iter().any(|&(f, _)| f == id))
        .filter(|&id| !is_kulisa_image(m, id))
        .collect()
}

/// The kulisa point under a block moves like the block's pin only in position; its
/// speed is tabulated through the relation rows instead.
fn is_kulisa_image(m: &Mechanism, id: usize) -> bool {
    m.steps.iter().any(|s| matches!(*s, crate::mechanics::Step::Rpr { a3, .. } if a3 == id))
}

fn turning_links(m: &Mechanism) -> Vec<usize> {
    (0..m.links.len()).filter(|&l| m.links[l].kind != LinkKind::Slider).collect()
}

fn row(symbol: &str, sub: impl Into<String>, unit: &str, values: Vec<f64>) -> Row {
    Row { symbol: symbol.into(), sub: sub.into(), unit: unit.into(), values }
}

/// Table 1: speeds of points, relative speeds and angular velocities, all positions.
pub fn velocity_table(m: &Mechanism, positions: &[&Position]) -> NumTable {
    let mut rows = Vec::new();
    for id in moving_points(m) {
        rows.push(row("v", m.name(id), "m/s", positions.iter().map(|p| p.state.points[id].v.hypot()).collect()));
    }
    let rel: Vec<_> = positions.iter().map(|p| relation_values(m, &p.state)).collect();
    for (i, r) in rel.first().map(|r| r.as_slice()).unwrap_or(&[]).iter().enumerate() {
        rows.push(row("v", r.name.clone(), "m/s", rel.iter().map(|x| x[i].v).collect()));
    }
    for l in turning_links(m) {
        if m.links[l].kind == LinkKind::Block {
            continue; // turns with its kulisa
        }
        let n = m.links[l].number;
        rows.push(row("ω", n.to_string(), "1/s", positions.iter().map(|p| p.state.links[l].omega.abs()).collect()));
    }
    NumTable { name: "velocities".into(), columns: positions.iter().map(|p| p.label.clone()).collect(), rows }
}

/// Table 2: accelerations of points, their normal and tangential (Coriolis and relative)
/// components and angular accelerations, at the plan positions.
pub fn acceleration_table(m: &Mechanism, positions: &[&Position]) -> NumTable {
    let mut rows = Vec::new();
    for id in moving_points(m) {
        rows.push(row("a", m.name(id), "m/s²", positions.iter().map(|p| p.state.points[id].a.hypot()).collect()));
    }
    let rel: Vec<_> = positions.iter().map(|p| relation_values(m, &p.state)).collect();
    for (i, r) in rel.first().map(|r| r.as_slice()).unwrap_or(&[]).iter().enumerate() {
        let (s1, s2) = if r.sliding { ("aᵏ", "aʳ") } else { ("aⁿ", "aᵗ") };
        rows.push(row(s1, r.name.clone(), "m/s²", rel.iter().map(|x| x[i].a_n).collect()));
        rows.push(row(s2, r.name.clone(), "m/s²", rel.iter().map(|x| x[i].a_t).collect()));
    }
    for l in turning_links(m) {
        let link = &m.links[l];
        if link.kind == LinkKind::Block || link.kind == LinkKind::Crank {
            continue; // the block turns with its kulisa; the crank turns uniformly (ε1 = 0)
        }
        rows.push(row("ε", link.number.to_string(), "1/s²", positions.iter().map(|p| p.state.links[l].eps.abs()).collect()));
    }
    NumTable { name: "accelerations".into(), columns: positions.iter().map(|p| p.label.clone()).collect(), rows }
}

/// The two tables of sheet 1 for a kinematic analysis.
pub fn sheet1_tables(m: &Mechanism, k: &Kinematics) -> (NumTable, NumTable) {
    let all: Vec<&Position> = k.positions.iter().collect();
    let acc: Vec<&Position> = k.acceleration.iter().map(|&i| &k.positions[i]).collect();
    (velocity_table(m, &all), acceleration_table(m, &acc))
}

/// Full-precision numbers: the CSV is for programs, the sheet rounds.
pub fn csv(t: &NumTable) -> String {
    let mut s = String::from("quantity,unit");
    for c in &t.columns {
        let _ = write!(s, ",{c}");
    }
    s.push('\n');
    for r in &t.rows {
        let _ = write!(s, "{}_{},{}", r.symbol, r.sub, r.unit);
        for v in &r.values {
            let _ = write!(s, ",{v:.9}");
        }
        s.push('\n');
    }
    s
}

pub fn markdown(t: &NumTable, title: &str) -> String {
    let mut s = format!("### {title}\n\n| quantity | unit |");
    for c in &t.columns {
        let _ = write!(s, " {c} |");
    }
    s.push_str("\n|---|---|");
    s.push_str(&"---:|".repeat(t.columns.len()));
    s.push('\n');
    for r in &t.rows {
        let _ = write!(s, "| {}<sub>{}</sub> | {} |", r.symbol, r.sub, r.unit);
        for v in &r.values {
            let _ = write!(s, " {v:.4} |");
        }
        s.push('\n');
    }
    s
}
