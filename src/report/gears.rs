//! Sheet 2's tables for the note: the wheels and the pair (lengths in mm, as the course
//! writes gears), the planetary stage and its conditions with their numbers.

use super::{Column, NumTable, Row, Sub, SubWord, Unit, share_decimals_within};
use crate::gears::pair::Pair;
use crate::gears::planetary::Stage;
use crate::num::units::mm;

fn named(symbol: &'static str, sub: &str, unit: Unit, values: Vec<f64>) -> Row {
    Row::new(symbol, if sub.is_empty() { Sub::None } else { Sub::name(sub) }, unit, values)
}

/// The rows of one kind share their decimals (see [`share_decimals_within`]): each group of
/// keys (a wheel's radii; the pair's lengths; u_1H and u_req; ε and ε_drawn) within its
/// bounds — lengths at 0,01 mm ([`LENGTHS`]). Rows of different quantities keep their own
/// four significant digits.
fn with_shared_decimals(mut rows: Vec<Row>, groups: &[(&[&str], (usize, usize))]) -> Vec<Row> {
    for &(keys, bounds) in groups {
        share_decimals_within(rows.iter_mut().filter(|r| keys.contains(&r.key.as_str())), bounds);
    }
    rows
}

/// A gear's lengths in its tables: to 0,01 mm, as the course writes them and the mesh's
/// dimensions print them.
const LENGTHS: (usize, usize) = (2, 2);

/// Decimals for four significant digits, however many.
const ANY: (usize, usize) = (0, usize::MAX);

/// Table of the two wheels: one column per wheel.
pub fn wheels(p: &Pair) -> NumTable {
    let col = |f: &dyn Fn(usize) -> f64| vec![f(0), f(1)];
    let w = &p.wheels;
    // The radii share their decimals, and the thicknesses theirs: r = 18 over r_b = 16,91
    // read as two precisions (the KHK pair).
    let rows = with_shared_decimals(
        vec![
            named("z", "", Unit::None, col(&|i| f64::from(w[i].z))).counted(),
            // Given shifts as given (0,6 and 0,36); chosen ones at four significant digits.
            named("x", "", Unit::None, col(&|i| w[i].shift)).exactly(),
            // The course's least shift, (17 − z)/17 for α = 20°, h_a* = 1.
            named("x", "min", Unit::None, col(&|i| w[i].x_min_course)),
            named("r", "", Unit::Mm, col(&|i| mm(w[i].pitch))),
            named("r", "b", Unit::Mm, col(&|i| mm(w[i].base))),
            named("r", "a", Unit::Mm, col(&|i| mm(w[i].tip))),
            named("r", "f", Unit::Mm, col(&|i| mm(w[i].root))),
            named("r", "w", Unit::Mm, col(&|i| mm(w[i].working))),
            named("s", "", Unit::Mm, col(&|i| mm(w[i].tooth_thickness))),
            named("s", "a", Unit::Mm, col(&|i| mm(w[i].tip_thickness))),
        ],
        &[(&["r", "r_b", "r_a", "r_f", "r_w"], LENGTHS), (&["s", "s_a"], LENGTHS)],
    );
    NumTable { id: "wheels", columns: vec![Column::labelled("1"), Column::labelled("2")], rows }
}

/// Table of what the pair shares; `eps_drawn` is the contact ratio measured on the drawing.
pub fn pair(p: &Pair, eps_drawn: f64) -> NumTable {
    let s = &p.spec;
    let one = |x: f64| vec![x];
    NumTable::single(
        "pair",
        with_shared_decimals(
            vec![
                // The given values as given: m = 2.5, c* = 0.25, not 2.500 and 0.2500.
                named("m", "", Unit::Mm, one(mm(s.module))).exactly(),
                named("α", "", Unit::Deg, one(s.pressure_angle.to_degrees())).exactly(),
                named("h", "a*", Unit::None, one(s.addendum)).keyed("h_a_star").exactly(),
                named("c*", "", Unit::None, one(s.clearance)).keyed("c_star").exactly(),
                named("u", "12", Unit::None, one(p.ratio)),
                named("α", "w", Unit::Deg, one(p.working_pressure_angle.to_degrees())),
                named("a", "", Unit::Mm, one(mm(p.reference_centre_distance))),
                named("a", "w", Unit::Mm, one(mm(p.centre_distance))),
                named("y", "", Unit::None, one(p.y)),
                named("Δy", "", Unit::None, one(p.delta_y)).keyed("delta_y"),
                named("h", "", Unit::Mm, one(mm(p.tooth_height))),
                named("p", "", Unit::Mm, one(mm(p.pitch))),
                named("p", "b", Unit::Mm, one(mm(p.base_pitch))),
                named("g", "α", Unit::Mm, one(mm(p.active_length))),
                named("ε", "", Unit::None, one(p.contact_ratio)),
                Row::new("ε", Sub::Word(SubWord::Drawn), Unit::None, one(eps_drawn)),
            ],
            // The centre distances apart: whole where both are (a = a_w = 90, not 90,00).
            &[(&["a", "a_w"], LENGTHS), (&["h", "p", "p_b", "g_alpha"], LENGTHS), (&["epsilon", "epsilon_drawn"], ANY)],
        ),
    )
}

/// The planetary stage: tooth numbers, planets, ratios, pitch radii and the carrier's radius.
pub fn stage(s: &Stage, module: f64) -> NumTable {
    let names: &[&str] = if s.z.len() == 4 { &["1", "2", "2′", "3"] } else { &["1", "2", "3"] };
    let mut rows = vec![named("m", "", Unit::Mm, vec![mm(module)]).exactly()];
    rows.extend(names.iter().zip(&s.z).map(|(n, &z)| named("z", n, Unit::None, vec![f64::from(z)]).counted()));
    rows.push(named("K", "", Unit::None, vec![f64::from(s.planets)]).counted());
    rows.push(named("u", "1H", Unit::None, vec![s.ratio]));
    rows.push(Row::new("u", Sub::Word(SubWord::Required), Unit::None, vec![s.ratio_required]));
    rows.extend(names.iter().zip(&s.z).map(|(n, &z)| named("r", n, Unit::Mm, vec![mm(module * f64::from(z) / 2.0)])));
    rows.push(named("a", "H", Unit::Mm, vec![mm(module * f64::from(s.z[0] + s.z[1]) / 2.0)]));
    let radii = ["r_1", "r_2", "r_2p", "r_3", "a_H"];
    NumTable::single("planetary", with_shared_decimals(rows, &[(&radii, LENGTHS), (&["u_1H", "u_required"], ANY)]))
}

/// Every condition with its value, limit and whether it is met (1) or not (0).
pub fn conditions(s: &Stage) -> NumTable {
    NumTable {
        id: "conditions",
        columns: vec![Column::new("value", "value"), Column::new("limit", "limit"), Column::new("met", "met")],
        rows: s
            .conditions
            .iter()
            .map(|c| Row::condition(c.name, vec![c.value, c.limit, f64::from(u8::from(c.ok))]))
            .collect(),
    }
}
