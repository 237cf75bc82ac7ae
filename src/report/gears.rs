//! Sheet 2's tables for the note: the wheels and the pair (lengths in mm, as the course
//! writes gears), the planetary stage and its conditions with their numbers.

use super::{NumTable, row};
use crate::gears::pair::Pair;
use crate::gears::planetary::Stage;

/// Millimetres per metre: the gear tables are in mm.
const MM: f64 = 1e3;

/// Table of the two wheels: one column per wheel.
pub fn wheels(p: &Pair) -> NumTable {
    let col = |f: &dyn Fn(usize) -> f64| vec![f(0), f(1)];
    let w = &p.wheels;
    NumTable {
        name: "wheels".into(),
        columns: vec!["1".into(), "2".into()],
        rows: vec![
            row("z", "", "", col(&|i| f64::from(w[i].z))),
            row("x", "", "", col(&|i| w[i].shift)),
            row("x", "min", "", col(&|i| w[i].x_min)),
            row("r", "", "mm", col(&|i| w[i].pitch * MM)),
            row("r", "b", "mm", col(&|i| w[i].base * MM)),
            row("r", "a", "mm", col(&|i| w[i].tip * MM)),
            row("r", "f", "mm", col(&|i| w[i].root * MM)),
            row("r", "w", "mm", col(&|i| w[i].working * MM)),
            row("s", "", "mm", col(&|i| w[i].tooth_thickness * MM)),
            row("s", "a", "mm", col(&|i| w[i].tip_thickness * MM)),
        ],
    }
}

/// Table of what the pair shares; `eps_drawn` is the contact ratio measured on the drawing.
pub fn pair(p: &Pair, eps_drawn: f64) -> NumTable {
    let s = &p.spec;
    let one = |x: f64| vec![x];
    NumTable {
        name: "pair".into(),
        columns: vec!["".into()],
        rows: vec![
            row("m", "", "mm", one(s.module * MM)),
            row("α", "", "°", one(s.pressure_angle.to_degrees())),
            row("h", "a*", "", one(s.addendum)),
            row("c*", "", "", one(s.clearance)),
            row("u", "12", "", one(p.ratio)),
            row("α", "w", "°", one(p.working_pressure_angle.to_degrees())),
            row("a", "", "mm", one(p.reference_centre_distance * MM)),
            row("a", "w", "mm", one(p.centre_distance * MM)),
            row("y", "", "", one(p.y)),
            row("Δy", "", "", one(p.delta_y)),
            row("h", "", "mm", one(p.tooth_height * MM)),
            row("p", "", "mm", one(p.pitch * MM)),
            row("p", "b", "mm", one(p.base_pitch * MM)),
            row("g", "α", "mm", one(p.active_length * MM)),
            row("ε", "", "", one(p.contact_ratio)),
            row("ε", "drawn", "", one(eps_drawn)),
        ],
    }
}

/// The planetary stage: tooth numbers, planets, ratios, pitch radii and the carrier's radius.
pub fn stage(s: &Stage, module: f64) -> NumTable {
    let names: &[&str] = if s.z.len() == 4 { &["1", "2", "2′", "3"] } else { &["1", "2", "3"] };
    let mut rows = vec![row("m", "", "mm", vec![module * MM])];
    rows.extend(names.iter().zip(&s.z).map(|(n, &z)| row("z", *n, "", vec![f64::from(z)])));
    rows.push(row("K", "", "", vec![f64::from(s.planets)]));
    rows.push(row("u", "1H", "", vec![s.ratio]));
    rows.push(row("u", "required", "", vec![s.ratio_required]));
    rows.extend(names.iter().zip(&s.z).map(|(n, &z)| row("r", *n, "mm", vec![module * f64::from(z) / 2.0 * MM])));
    rows.push(row("a", "H", "mm", vec![module * f64::from(s.z[0] + s.z[1]) / 2.0 * MM]));
    NumTable { name: "stage".into(), columns: vec!["".into()], rows }
}

/// Every condition with its value, limit and whether it is met (1) or not (0).
pub fn conditions(s: &Stage) -> NumTable {
    NumTable {
        name: "conditions".into(),
        columns: vec!["value".into(), "limit".into(), "met".into()],
        rows: s
            .conditions
            .iter()
            .map(|c| row(c.name, "", "", vec![c.value, c.limit, if c.ok { 1.0 } else { 0.0 }]))
            .collect(),
    }
}
