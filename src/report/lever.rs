//! The lever sheet's tables of the explanatory note as numbers: 1-jadval (velocities),
//! 2-jadval (accelerations) and, with a force analysis, tables 3–5.

use super::{Column, ForceKind, NumTable, Row, Sub, Unit, share_decimals};
use crate::lever::analysis::{ForceAnalysis, Kinematics, Position};
use crate::lever::kinetostatics::{FRAME, Forces, InertiaLoad, Kind, Part};
use crate::lever::linkage::{LinkKind, Mechanism};
use crate::lever::load::LoadKind;
use crate::lever::plans::{RelationValues, relation_values};
use crate::lever::{Kin, LinkKin};
use crate::num::math::Norm;

/// Points that move, without kulisa images: a kulisa image moves like the block's pin only
/// in position; its speed is tabulated through the relation rows instead.
fn moving_points(m: &Mechanism) -> Vec<usize> {
    (0..m.point_names.len()).filter(|&id| !m.is_frame(id) && !m.is_kulisa_image(id)).collect()
}

fn turning_links(m: &Mechanism) -> Vec<usize> {
    (0..m.links.len()).filter(|&l| m.links[l].kind != LinkKind::Slider).collect()
}

/// One row per moving point, one column per position.
fn point_rows(
    m: &Mechanism,
    positions: &[&Position],
    symbol: &'static str,
    unit: Unit,
    of: impl Fn(&Kin) -> f64,
) -> Vec<Row> {
    moving_points(m)
        .into_iter()
        .map(|id| {
            Row::new(symbol, Sub::name(m.name(id)), unit, positions.iter().map(|p| of(&p.state.points[id])).collect())
        })
        .collect()
}

/// One row per turning link (not the kulisa's block, which turns with its kulisa).
fn link_rows(
    m: &Mechanism,
    positions: &[&Position],
    symbol: &'static str,
    unit: Unit,
    skip_crank: bool,
    of: impl Fn(&LinkKin) -> f64,
) -> Vec<Row> {
    turning_links(m)
        .into_iter()
        .filter(|&l| m.links[l].kind != LinkKind::Block && !(skip_crank && m.links[l].kind == LinkKind::Crank))
        .map(|l| {
            let values = positions.iter().map(|p| of(&p.state.links[l])).collect();
            Row::new(symbol, Sub::Name(m.links[l].number.to_string()), unit, values)
        })
        .collect()
}

/// Relative motions of every position, transposed: one entry per relation.
fn relation_columns(m: &Mechanism, positions: &[&Position]) -> Vec<Vec<RelationValues>> {
    let per_position: Vec<_> = positions.iter().map(|p| relation_values(m, &p.state)).collect();
    let n = per_position.first().map_or(0, Vec::len);
    (0..n).map(|i| per_position.iter().map(|x| x[i].clone()).collect()).collect()
}

fn table(id: &'static str, positions: &[&Position], rows: Vec<Row>) -> NumTable {
    NumTable { id, columns: positions.iter().map(|p| Column::labelled(&p.label)).collect(), rows }
}

/// Table 1: speeds of points, relative speeds and angular velocities, all positions.
pub fn velocity_table(m: &Mechanism, positions: &[&Position]) -> NumTable {
    let mut rows = point_rows(m, positions, "v", Unit::MPerS, |k| k.v.norm());
    for rel in relation_columns(m, positions) {
        rows.push(Row::new("v", Sub::name(rel[0].name.clone()), Unit::MPerS, rel.iter().map(|x| x.v).collect()));
    }
    rows.extend(link_rows(m, positions, "ω", Unit::PerS, false, |l| l.omega.abs()));
    table("velocities", positions, rows)
}

/// Table 2: accelerations of points, their normal and tangential (Coriolis and relative)
/// components and angular accelerations, at the plan positions. The crank turns
/// uniformly (ε1 = 0), so it has no ε row.
pub fn acceleration_table(m: &Mechanism, positions: &[&Position]) -> NumTable {
    let mut rows = point_rows(m, positions, "a", Unit::MPerS2, |k| k.a.norm());
    for rel in relation_columns(m, positions) {
        let (s1, s2) = if rel[0].sliding { ("aᵏ", "aʳ") } else { ("aⁿ", "aᵗ") };
        let sub = || Sub::name(rel[0].name.clone());
        rows.push(Row::new(s1, sub(), Unit::MPerS2, rel.iter().map(|x| x.a_n).collect()));
        rows.push(Row::new(s2, sub(), Unit::MPerS2, rel.iter().map(|x| x.a_t).collect()));
    }
    rows.extend(link_rows(m, positions, "ε", Unit::PerS2, true, |l| l.eps.abs()));
    table("accelerations", positions, rows)
}

/// Tables 1 and 2 of the kinematic analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct KinematicTables {
    pub velocities: NumTable,
    pub accelerations: NumTable,
}

/// Tables 3–5 of the force analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceTables {
    pub inertia: NumTable,
    pub reactions: NumTable,
    pub balance: NumTable,
}

/// Tables 1 and 2: every position's velocities, the plan positions' accelerations.
pub fn kinematic_tables(m: &Mechanism, k: &Kinematics) -> KinematicTables {
    let all: Vec<&Position> = k.positions.iter().collect();
    let acc: Vec<&Position> = k.acceleration.iter().map(|&i| &k.positions[i]).collect();
    KinematicTables { velocities: velocity_table(m, &all), accelerations: acceleration_table(m, &acc) }
}

/// The reactions of the note, one per pair: R_ij is the force of link i on link j (0: frame).
pub fn reactions(m: &Mechanism, f: &Forces) -> Vec<(String, kurbo::Vec2)> {
    let mut seen: Vec<(usize, usize)> = Vec::new();
    let mut out = Vec::new();
    for a in &f.applied {
        let Kind::Reaction { from, part: Part::Whole } = a.kind else { continue };
        if seen.contains(&(a.on, from)) {
            continue;
        }
        seen.push((from, a.on));
        let num = |l: usize| if l == FRAME { 0 } else { m.links[l].number };
        out.push((format!("{}{}", num(from), num(a.on)), a.force));
    }
    out
}

/// The decimals tables 3 and 4 print the force drawings' quantities with, for their legends
/// to write the same digits: a group's legend read P_i2 = 111,7 N and G2 = 206,0 N over
/// table 3's 112 and 206 (a teacher's review). Whole reactions take table 4's; their
/// normal and tangential parts, in no table, keep four significant digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegendDecimals {
    pub weight: usize,
    pub inertia: usize,
    pub moment: usize,
    pub reaction: usize,
}

impl LegendDecimals {
    /// Read off the tables' rows: table 3's G, P_i and M_i, table 4's reactions.
    pub fn of(t: &ForceTables) -> LegendDecimals {
        let row =
            |table: &NumTable, key: &str| table.rows.iter().find(|r| r.key == key).map_or(0, Row::decimals_printed);
        let reaction = t.reactions.rows.iter().map(Row::decimals_printed).max().unwrap_or(0);
        LegendDecimals {
            weight: row(&t.inertia, INERTIA_KEYS[0]),
            inertia: row(&t.inertia, INERTIA_KEYS[1]),
            moment: row(&t.inertia, INERTIA_KEYS[2]),
            reaction,
        }
    }
}

/// The keys of table 3's rows of weights, inertia forces and inertia moments.
const INERTIA_KEYS: [&str; 3] = ["G", "P_i", "M_i"];

/// Tables 3–5 of the force analysis: inertia loads per link, reactions per pair, and the
/// balancing force found three ways.
pub fn force_tables(m: &Mechanism, fa: &ForceAnalysis) -> ForceTables {
    let f = &fa.forces;
    let columns = f.inertia.iter().map(|i| Column::labelled(&m.links[i.link].number.to_string())).collect();
    let per = |sym: &'static str, sub: Sub, unit: Unit, of: &dyn Fn(&InertiaLoad) -> f64| {
        Row::new(sym, sub, unit, f.inertia.iter().map(of).collect())
    };
    // A slider does not turn: it has no ε, J_S or M_i; a link given no moment of inertia
    // has no J_S or M_i.
    let translating: Vec<bool> = f.inertia.iter().map(|i| m.links[i.link].kind == LinkKind::Slider).collect();
    let no_moment: Vec<bool> = f.inertia.iter().zip(&translating).map(|(i, &t)| t || i.j == 0.0).collect();
    let inertia = NumTable {
        id: "inertia",
        columns,
        rows: vec![
            // Given: printed as given (21 and 500 kg, not 21,0 and 500,0).
            per("m", Sub::None, Unit::Kg, &|i| i.mass).exactly(),
            per("G", Sub::None, Unit::N, &|i| i.weight),
            per("a", Sub::name("S"), Unit::MPerS2, &|i| i.a_s.norm()),
            per("P", Sub::Force(ForceKind::Inertia, String::new()), Unit::N, &|i| i.force.norm()),
            per("ε", Sub::None, Unit::PerS2, &|i| i.eps.abs()).absent_where(translating.clone()),
            per("J", Sub::name("S"), Unit::KgM2, &|i| i.j).exactly().absent_where(no_moment.clone()),
            per("M", Sub::Force(ForceKind::Inertia, String::new()), Unit::NM, &|i| i.moment.abs())
                .absent_where(no_moment),
        ],
    };
    let mut reactions = NumTable {
        id: "reactions",
        columns: vec![Column::new("x", "x"), Column::new("y", "y"), Column::new("abs", "|R|")],
        rows: reactions(m, f)
            .into_iter()
            .map(|(sub, r)| Row::new("R", Sub::Name(sub), Unit::N, vec![r.x, r.y, r.norm()]))
            .collect(),
    };
    // One quantity, one precision (GOST 2.105): a column read −978,1 under 1394 and over
    // −978 (a teacher's mark on task 1 variant 5).
    share_decimals(reactions.rows.iter_mut(), 0);
    let balancing = Sub::Force(ForceKind::Balancing, String::new());
    let mut rows = vec![];
    for (load, v) in fa.model.loads.iter().zip(&f.loads) {
        let n = m.links[load.link].number.to_string();
        rows.push(Row::new("S/H", Sub::Name(n.clone()), Unit::None, vec![v.s]).keyed(&format!("S_H_{n}")));
        rows.push(Row::new("P", Sub::Force(load_kind(load.kind), n), Unit::N, vec![v.force.norm()]));
    }
    rows.extend([
        Row::new("P", balancing.clone(), Unit::N, vec![f.p_m]),
        Row::new("M", balancing.clone(), Unit::NM, vec![f.m_m]),
        Row::new("P′", balancing.clone(), Unit::N, vec![f.p_m_lever]).keyed("P_m_lever"),
        Row::new("Δ", Sub::None, Unit::Percent, vec![f.difference_percent()]).keyed("delta"),
        Row::new("P″", balancing, Unit::N, vec![f.p_m_power]).keyed("P_m_power"),
    ]);
    let balance = NumTable::single("balancing", rows);
    ForceTables { inertia, reactions, balance }
}

/// The kind of a load's force: a resistance or a gas force.
pub fn load_kind(kind: LoadKind) -> ForceKind {
    match kind {
        LoadKind::Resistance => ForceKind::Resistance,
        LoadKind::Gas => ForceKind::Gas,
    }
}
