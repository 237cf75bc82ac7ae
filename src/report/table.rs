//! A table of the explanatory note as typed data: every unit, every subscript word and every
//! condition is a key that the sheet translates (no string is matched to decide anything),
//! and every table, row and column has a stable identifier — the answer key that the CSV,
//! the Markdown, `results.json` and the SVG share (`sheet1.velocities.v_B.3`).

use crate::gears::planetary::ConditionKind;
use serde::Serialize;

/// A unit as the note's tables write it; the CSV writes [`Unit::si`], a sheet its own
/// language's word for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Unit {
    /// A ratio, a count, a coefficient.
    None,
    Mm,
    MPerS,
    MPerS2,
    PerS,
    PerS2,
    Kg,
    KgM2,
    N,
    NM,
    Deg,
    Percent,
}

impl Unit {
    /// The unit as the CSV (for programs) writes it, in SI notation.
    pub const fn si(self) -> &'static str {
        match self {
            Unit::None => "",
            Unit::Mm => "mm",
            Unit::MPerS => "m/s",
            Unit::MPerS2 => "m/s²",
            Unit::PerS => "1/s",
            Unit::PerS2 => "1/s²",
            Unit::Kg => "kg",
            Unit::KgM2 => "kg·m²",
            Unit::N => "N",
            Unit::NM => "N·m",
            Unit::Deg => "°",
            Unit::Percent => "%",
        }
    }
}

/// A subscript word that the sheet's language translates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SubWord {
    /// ε measured on the drawing.
    Drawn,
    /// The planetary ratio required.
    Required,
    /// The cam's pitch and working profiles.
    Pitch,
    Work,
    Roller,
    AllowedRise,
    AllowedReturn,
    MaxRise,
    MaxReturn,
}

impl SubWord {
    /// The word's part of an identifier.
    pub const fn key(self) -> &'static str {
        match self {
            SubWord::Drawn => "drawn",
            SubWord::Required => "required",
            SubWord::Pitch => "pitch",
            SubWord::Work => "work",
            SubWord::Roller => "roller",
            SubWord::AllowedRise => "allowed_rise",
            SubWord::AllowedReturn => "allowed_return",
            SubWord::MaxRise => "max_rise",
            SubWord::MaxReturn => "max_return",
        }
    }
}

/// The kind of a force or moment, whose letter is its subscript (P_i, P_ур on a Russian
/// sheet).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ForceKind {
    Inertia,
    Balancing,
    Resistance,
    Gas,
}

impl ForceKind {
    /// The letter the identifiers use (the English sheet's).
    pub const fn key(self) -> &'static str {
        match self {
            ForceKind::Inertia => "i",
            ForceKind::Balancing => "m",
            ForceKind::Resistance => "c",
            ForceKind::Gas => "g",
        }
    }
}

/// A symbol's subscript.
#[derive(Debug, Clone, PartialEq)]
pub enum Sub {
    None,
    /// The same in every language: a point's or relation's name (B, BA, S4), a link or
    /// wheel number (2, 2′), a standard letter (r_b, α_w).
    Name(String),
    Word(SubWord),
    /// A force's letter and the link number after it (P_i2, P_c5; P_m with none).
    Force(ForceKind, String),
}

impl Sub {
    pub fn name(s: impl Into<String>) -> Sub {
        Sub::Name(s.into())
    }

    /// The subscript's part of an identifier.
    pub fn key(&self) -> String {
        match self {
            Sub::None => String::new(),
            Sub::Name(s) => ascii_key(s),
            Sub::Word(w) => w.key().to_string(),
            Sub::Force(k, n) => format!("{}{}", k.key(), ascii_key(n)),
        }
    }
}

/// What a row is: a symbol with its subscript, or a condition by name.
#[derive(Debug, Clone, PartialEq)]
pub enum Quantity {
    /// A symbol as printed in every language ("v", "aⁿ", "ω") and its subscript.
    Symbol(&'static str, Sub),
    /// A planetary stage's condition, named in the sheet's language.
    Condition(ConditionKind),
}

/// One row of a table: its identifier within the table, what it is, its unit, a value per
/// column.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Unique within its table, ASCII: "v_B", "omega_2", "P_m_lever", "neighbours".
    pub key: String,
    pub quantity: Quantity,
    pub unit: Unit,
    pub values: Vec<f64>,
    /// A count (tooth numbers, planets, a condition's sides): printed without decimals when
    /// whole.
    pub count: bool,
    /// Values on a grid of few decimals (the positions' angles): printed with the fewest
    /// decimals that write each exactly, the same in every cell, rather than with four
    /// significant digits.
    pub exact: bool,
    /// The cells whose quantity the column's member does not have (a slider's ε, J_S and
    /// M_i; a link's J_S and M_i where no moment of inertia is given): their value is 0 in
    /// the CSV and the answers, and a table prints "—" there, as the course's tables do, not
    /// a 0 that reads as computed. Empty: every cell is a value.
    pub absent: Vec<bool>,
    /// The decimals this row shares with others of one quantity in its table (see
    /// [`share_decimals`]); `None`: the row's own.
    pub decimals: Option<usize>,
    /// Where the quantity jumps at a column's position (a law's acceleration at the middle
    /// of a uniformly accelerated phase), its value just after it; the cell's value is the
    /// one just before. The tables print both, "before→after" ([`JUMP`](crate::num::digits::JUMP)), as the diagram
    /// draws the jump; the CSV holds the value before, an answer both ([`Answer::after`](crate::report::Answer::after)). Empty: no jumps.
    pub jumps: Vec<Option<f64>>,
}

impl Row {
    /// A row whose key is made from its symbol and subscript ("ω", 2 → "omega_2").
    pub fn new(symbol: &'static str, sub: Sub, unit: Unit, values: Vec<f64>) -> Row {
        let key = match sub.key() {
            s if s.is_empty() => ascii_key(symbol),
            s => format!("{}_{s}", ascii_key(symbol)),
        };
        Row {
            key,
            quantity: Quantity::Symbol(symbol, sub),
            unit,
            values,
            count: false,
            exact: false,
            absent: Vec::new(),
            decimals: None,
            jumps: Vec::new(),
        }
    }

    /// The same row under an explicit key (for symbols a rule would name badly: "P′" →
    /// "P_m_lever").
    pub fn keyed(mut self, key: &str) -> Row {
        self.key = key.to_string();
        self
    }

    /// The same row marked as a count.
    pub fn counted(mut self) -> Row {
        self.count = true;
        self
    }

    /// The same row with the cells `absent` marks printed "—" (see [`Row::absent`]).
    pub fn absent_where(mut self, absent: Vec<bool>) -> Row {
        self.absent = absent;
        self
    }

    /// The same row with the values after its jumps (see [`Row::jumps`]).
    pub fn jumping(mut self, jumps: Vec<Option<f64>>) -> Row {
        self.jumps = jumps;
        self
    }

    /// The values its cells print (the absent ones left out, a jump's value after it
    /// included).
    pub fn present(&self) -> impl Iterator<Item = f64> + '_ {
        let present = (0..self.values.len()).filter(|&c| !self.is_absent(c));
        present.flat_map(|c| std::iter::once(self.values[c]).chain(self.jump_at(c)))
    }

    /// The value just after column `c`'s position where the quantity jumps there.
    pub fn jump_at(&self, c: usize) -> Option<f64> {
        self.jumps.get(c).copied().flatten()
    }

    /// Whether the cell in column `c` has no value (see [`Row::absent`]).
    pub fn is_absent(&self, c: usize) -> bool {
        self.absent.get(c).copied().unwrap_or(false)
    }

    /// The same row marked as exact at few decimals (see [`Row::exact`]).
    pub fn exactly(mut self) -> Row {
        self.exact = true;
        self
    }

    /// The values as a reader gets them (a point and a hyphen-minus): a row of whole
    /// numbers (where `whole` asks for them so; in a count's row each whole value) without decimals, an exact row with its
    /// fewest exact decimals, anything else with the decimals that give the row's largest
    /// value four significant digits — the same decimals in every cell of the row (GOST
    /// 2.105), so a whole 45 beside 47.5 prints 45.00.
    pub fn printed(&self, whole: bool) -> Vec<String> {
        use crate::num::digits;
        // A count's row (a condition's value, limit and 1 for met) is one quantity a cell.
        let whole_value = |v: f64| crate::num::digits::nearly_whole(v) && v.abs() < 1e9;
        // The row's decimals from the cells that hold a value.
        let present: Vec<f64> = self.present().collect();
        let whole = whole && (self.count || present.iter().all(|&v| whole_value(v)));
        let whole = whole && self.decimals.is_none();
        let row = self.decimals_printed();
        let one = |v: f64| digits::at_decimals(v, if whole && whole_value(v) { 0 } else { row });
        (0..self.values.len())
            .map(|c| match self.jump_at(c) {
                _ if self.is_absent(c) => "—".to_string(),
                Some(after) => format!("{}{}{}", one(self.values[c]), digits::JUMP, one(after)),
                None => one(self.values[c]),
            })
            .collect()
    }

    /// The decimals [`Row::printed`] writes the row's values with (a whole row asked for whole
    /// numbers aside): those shared with its table's other rows of one quantity, an exact
    /// row's fewest exact ones, else its largest value's four significant digits'.
    pub fn decimals_printed(&self) -> usize {
        use crate::num::digits;
        let present: Vec<f64> = self.present().collect();
        let decimals =
            if self.exact { self.decimals.or_else(|| digits::exact_decimals(&present)) } else { self.decimals };
        decimals.unwrap_or_else(|| digits::row_decimals(&present))
    }

    /// A condition's row: its value, its limit and 1 when it is met, else 0.
    pub fn condition(kind: ConditionKind, values: Vec<f64>) -> Row {
        Row {
            key: kind.key().to_string(),
            quantity: Quantity::Condition(kind),
            unit: Unit::None,
            values,
            count: true,
            exact: false,
            absent: Vec::new(),
            decimals: None,
            jumps: Vec::new(),
        }
    }
}

/// Gives the rows of one quantity in a table ("every length in mm of the pair's table")
/// one number of decimals, those of their largest value's four significant digits but at
/// least `at_least`, so that a column does not read 64,50 above 127,5 and 90 (GOST 2.105:
/// one quantity, one precision; the course writes a gear's lengths to 0,01 mm, so that a
/// tip's 1,84 mm is not cut to 1,8 beside a 127,5 mm ring). Rows whose values are all whole
/// keep printing without decimals; counts and rows exact at few decimals (given values) keep
/// their own.
pub fn share_decimals<'a>(rows: impl IntoIterator<Item = &'a mut Row>, at_least: usize) {
    share_decimals_within(rows, (at_least, usize::MAX));
}

/// [`share_decimals`] with the decimals kept within `(at_least, at_most)`: a gear's lengths
/// at 0,01 mm exactly, as the course writes them and the mesh's dimensions print them (the
/// table's p = 9,425 beside the drawing's p = 9,42 read as two values).
pub fn share_decimals_within<'a>(rows: impl IntoIterator<Item = &'a mut Row>, (at_least, at_most): (usize, usize)) {
    let mut rows: Vec<&mut Row> = rows.into_iter().filter(|r| !r.count && !r.exact).collect();
    let values: Vec<f64> = rows.iter().flat_map(|r| r.present()).collect();
    if values.iter().all(|&v| crate::num::digits::nearly_whole(v)) {
        return;
    }
    let decimals = crate::num::digits::row_decimals(&values).clamp(at_least, at_most.max(at_least));
    for r in &mut rows {
        r.decimals = Some(decimals);
    }
}

/// Gives exact rows of one quantity (see [`Row::exact`]) the most decimals any of them
/// needs, where each is exact at few: a twin table's 97,5 under the other's 11,25 reads as
/// another precision. Where one is not exact at three, the most any of them takes for its
/// largest value's four significant digits: a rise of 52,5° in eight steps printed 6,56 over
/// the return's 59,1 (task 13 variant 22, a teacher's mark).
pub fn share_exact_decimals<'a>(rows: impl IntoIterator<Item = &'a mut Row>) {
    let mut rows: Vec<&mut Row> = rows.into_iter().filter(|r| r.exact).collect();
    let values = |r: &Row| r.present().collect::<Vec<f64>>();
    let each: Option<Vec<usize>> = rows.iter().map(|r| crate::num::digits::exact_decimals(&values(r))).collect();
    let shared = match each {
        Some(each) => each.into_iter().max(),
        None => rows.iter().map(|r| crate::num::digits::row_decimals(&values(r))).max(),
    };
    if let Some(d) = shared {
        for r in &mut rows {
            r.decimals = Some(d);
        }
    }
}

/// A column: its identifier and its heading as every language writes it (a position label
/// "4′", a link number), or `None` where the sheet names it in its language.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub key: String,
    pub heading: String,
}

impl Column {
    /// A column headed by a label the same in every language ("0", "4′", "2").
    pub fn labelled(heading: &str) -> Column {
        Column { key: ascii_key(heading), heading: heading.to_string() }
    }

    /// A column with a key and a heading of its own ("abs", "|R|").
    pub fn new(key: &str, heading: &str) -> Column {
        Column { key: key.to_string(), heading: heading.to_string() }
    }
}

/// A table of numbers with its identifier.
#[derive(Debug, Clone, PartialEq)]
pub struct NumTable {
    /// The table's identifier within its sheet and its files' stem: "velocities" →
    /// `sheet1-velocities.csv`, answers `sheet1.velocities.…`.
    pub id: &'static str,
    pub columns: Vec<Column>,
    pub rows: Vec<Row>,
}

impl NumTable {
    /// A table of one value per row (its column is keyed "value").
    pub fn single(id: &'static str, rows: Vec<Row>) -> NumTable {
        NumTable { id, columns: vec![Column::new("value", "")], rows }
    }

    /// The identifier of a row's value in column `c` under `prefix` ("sheet1"): the
    /// column's key is left out of a single-column table's.
    pub fn cell_id(&self, prefix: &str, row: &Row, c: usize) -> String {
        let base = format!("{prefix}.{}.{}", self.id, row.key);
        if self.columns.len() == 1 { base } else { format!("{base}.{}", self.columns[c].key) }
    }
}

/// An identifier's ASCII form of a printed symbol or name: Greek letters by their names,
/// modifier letters by their letters, a prime as `p`, other punctuation as `_` (an XML id
/// and a shell word both take it).
pub fn ascii_key(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        let name = match c {
            'α' => "alpha",
            'β' => "beta",
            'γ' => "gamma",
            'δ' => "delta",
            'Δ' => "Delta",
            'ε' => "epsilon",
            'θ' => "theta",
            'μ' => "mu",
            'ρ' => "rho",
            'φ' => "phi",
            'ψ' => "psi",
            'ω' => "omega",
            'π' => "pi",
            'ⁿ' => "n",
            'ᵗ' => "t",
            'ᵏ' => "k",
            'ʳ' => "r",
            '²' => "2",
            '′' => "p",
            '″' => "pp",
            '*' => "star",
            c if c.is_alphanumeric() || c == '_' || c == '-' => {
                out.push(c);
                continue;
            }
            _ => "_",
        };
        out.push_str(name);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_ascii_words() {
        assert_eq!(Row::new("ω", Sub::name("2"), Unit::PerS, vec![]).key, "omega_2");
        assert_eq!(Row::new("aⁿ", Sub::name("BA"), Unit::MPerS2, vec![]).key, "an_BA");
        assert_eq!(Row::new("P", Sub::Force(ForceKind::Resistance, "5".into()), Unit::N, vec![]).key, "P_c5");
        assert_eq!(Row::new("r", Sub::Word(SubWord::Pitch), Unit::Mm, vec![]).key, "r_pitch");
        assert_eq!(Column::labelled("4′").key, "4p");
        assert_eq!(ascii_key("d²s/dφ²"), "d2s_dphi2");
    }

    /// Shared decimals round half up as every other value does (the course's rounding):
    /// 0,625 and 28,125 at two decimals are 0,63 and 28,13, where the formatter's binary
    /// rounding gave 0,62 beside 28,13.
    #[test]
    fn shared_decimals_round_half_up() {
        let mut rows = [Row::new("s", Sub::None, Unit::Mm, vec![0.625, 28.125, 3.125])];
        share_decimals_within(rows.iter_mut(), (2, 2));
        assert_eq!(rows[0].printed(false), ["0.63", "28.13", "3.13"]);
        // Held within the bounds: four significant digits would give three decimals.
        let mut rows = [Row::new("p", Sub::None, Unit::Mm, vec![9.424_778])];
        share_decimals_within(rows.iter_mut(), (2, 2));
        assert_eq!(rows[0].printed(false), ["9.42"]);
    }
}
