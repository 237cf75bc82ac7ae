//! Sheet 3's tables: the law and the profiles' polar coordinates at the numbered positions
//! (each phase its own table) and the results, as the note writes them and as the sheet
//! draws them.

use super::DIVISIONS;
use super::labels::CamLabels;
use crate::cams::Design;
use crate::drawing::labels::{Common, Language};
use crate::drawing::table::{CELL_TEXT, Table};
use crate::report::{self, NoteTable};
use crate::sheets::scaffold;

/// The note's tables in the sheet's language, at the positions' cam angles `phis`;
/// `errors` are the integration's, percent of the lift and of the largest analog.
/// The tables are numbered from `first`.
pub fn notes(d: &Design, phis: &[f64], errors: (f64, f64), lang: Language, first: u32) -> Vec<NoteTable> {
    let (l, c) = (CamLabels::get(lang), Common::get(lang));
    let n = DIVISIONS + 1;
    let (rise, ret) = phis.split_at(n);
    let note = |t, title: String, columns| scaffold::note(lang, t, &title, columns, false);
    let k = |i: u32| (first + i).to_string();
    let (up, back) = (l.phase_rise(), l.phase_return());
    let twins = |mut a: report::NumTable, mut b: report::NumTable| {
        report::cam::share_twin_decimals(&mut a, &mut b);
        (a, b)
    };
    let (law_up, law_back) = twins(report::cam::law(d, "law-rise", 0, rise), report::cam::law(d, "law-return", n, ret));
    let (profile_up, profile_back) =
        twins(report::cam::profile(d, "profile-rise", 0, rise), report::cam::profile(d, "profile-return", n, ret));
    vec![
        note(law_up, l.law_table(&k(0), up), vec![]),
        note(law_back, l.law_table(&k(1), back), vec![]),
        note(profile_up, l.profile_table(&k(2), up), vec![]),
        note(profile_back, l.profile_table(&k(3), back), vec![]),
        note(report::cam::results(d, errors), l.results_table(&k(4)), vec![c.value().into()]),
    ]
}

/// How many tables the note gets from sheet 3 (see [`notes`]).
pub const TABLE_COUNT: u32 = 5;

/// Whether a table is one of the law's (drawn under the diagrams when they fit).
pub fn is_law(n: &NoteTable) -> bool {
    n.table.id.starts_with("law")
}

/// A table as sheet 3 draws it: units after the symbols (each phase's table has its own
/// number and its phase in the title, wherever the columns put it).
pub fn sheet_table(n: &NoteTable, lang: Language) -> Table {
    let c = Common::get(lang);
    let rows = scaffold::drawn_rows(n, lang, true);
    let label_w = rows.iter().map(|(x, _)| x.width(CELL_TEXT) + 4.0).fold(14.0, f64::max);
    let results = n.table.id == "results";
    Table {
        id: format!("{}{}", crate::drawing::table::PART, n.table.id),
        title: n.title.clone(),
        header: n.column_titles.clone(),
        rows,
        label_w,
        cell_w: 12.0,
        corner: if results { c.quantity().into() } else { c.position_col().into() },
        text_h: crate::drawing::table::CELL_TEXT,
        least_columns: Vec::new(),
    }
}
