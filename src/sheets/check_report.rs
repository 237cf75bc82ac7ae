//! `tmm check`'s report to hand back: the verdicts as a ruled table on A4 landscape pages in
//! the project's language — what the student's value was matched to, the exact value, the
//! student's, the deviation and what was allowed, and the result, failures marked in the
//! margin — with the summary, the rule of the tolerances, the page number and a line for
//! the teacher's signature.

use crate::check::{Rule, Verdict, write};
use crate::drawing::fmt;
use crate::drawing::labels::{Common, Language};
use crate::drawing::scene::{Anchor, Group, Ink, MAIN, Scene, THIN, Text};
use crate::drawing::text::wrap;
use kurbo::{Point, Rect};

crate::label_set! {
    /// The report's words (`templates/labels/check.yaml`).
    pub struct CheckLabels = "check.yaml" {
        title,
        against(project, values),
        summary(passed, total),
        rules,
        page(n, total),
        teacher,
        col_line,
        col_quantity,
        col_exact,
        col_student,
        col_unit,
        col_deviation,
        col_allowed,
        col_result,
        pass,
        fail,
        rule_given,
        rule_course,
        rule_point,
        rule_paper,
        rule_relative,
        rule_row,
    }
}

/// A4 landscape, mm.
const PAGE: (f64, f64) = (297.0, 210.0);
/// The frame: 20 mm on the left for binding, 5 mm elsewhere (as the sheets').
const FRAME: Rect = Rect { x0: 20.0, y0: 5.0, x1: 292.0, y1: 205.0 };
/// The table's first row's top, its rows' height, and the footer's top, mm.
const TABLE_TOP: f64 = 38.0;
const ROW_H: f64 = 5.5;
const FOOTER_TOP: f64 = 190.0;
/// Lettering, mm.
const TEXT: f64 = 2.5;
/// The columns' widths, mm: line, quantity, exact, student, unit, deviation, allowed, result.
const WIDTHS: [f64; 8] = [13.0, 84.0, 24.0, 24.0, 16.0, 34.0, 42.0, 22.0];

/// Rows a page holds.
fn rows_per_page() -> usize {
    ((FOOTER_TOP - TABLE_TOP - ROW_H) / ROW_H).floor() as usize
}

/// Who is checked against what: the project's and the values' names as the report states them.
pub struct Names<'a> {
    pub project: &'a str,
    pub values: &'a str,
}

/// The report's pages: at least one (an empty check still states its summary).
pub fn pages(verdicts: &[Verdict], names: &Names, lang: Language) -> Vec<Scene> {
    let l = CheckLabels::get(lang);
    let chunks: Vec<&[Verdict]> =
        if verdicts.is_empty() { vec![&[]] } else { verdicts.chunks(rows_per_page()).collect() };
    let total = chunks.len();
    chunks.iter().enumerate().map(|(i, rows)| page(rows, names, lang, l, (i + 1, total), verdicts)).collect()
}

fn page(
    rows: &[Verdict],
    names: &Names,
    lang: Language,
    l: &CheckLabels,
    (n, total): (usize, usize),
    all: &[Verdict],
) -> Scene {
    let mut g = Group::new("report", Rect::new(0.0, 0.0, PAGE.0, PAGE.1));
    g.path(
        vec![
            Point::new(FRAME.x0, FRAME.y0),
            Point::new(FRAME.x1, FRAME.y0),
            Point::new(FRAME.x1, FRAME.y1),
            Point::new(FRAME.x0, FRAME.y1),
        ],
        true,
        MAIN,
    );
    let left = FRAME.x0 + 5.0;
    let width = FRAME.width() - 10.0;
    g.text(Text::new(Point::new(left, 14.0), l.title(), 5.0, Anchor::Start));
    // The names may be long paths: the line is wrapped, then cut to two lines.
    let against = wrap(&l.against(names.project, names.values), TEXT, width);
    for (k, line) in against.iter().take(2).enumerate() {
        g.text(Text::new(Point::new(left, 21.0 + k as f64 * 4.0), line.as_str(), TEXT, Anchor::Start));
    }
    let passed = all.iter().filter(|v| v.pass).count();
    let summary = l.summary(&passed.to_string(), &all.len().to_string());
    g.text(Text::new(Point::new(left, 31.5), summary, 3.5, Anchor::Start));
    table(&mut g, rows, lang, l, left);
    let rules = wrap(l.rules(), TEXT, width);
    for (k, line) in rules.iter().take(2).enumerate() {
        g.text(Text::new(Point::new(left, FOOTER_TOP + 4.0 + k as f64 * 4.0), line.as_str(), TEXT, Anchor::Start));
    }
    let footer = FRAME.y1 - 3.0;
    g.text(Text::new(Point::new(left, footer), l.teacher(), 3.5, Anchor::Start));
    let page_no = l.page(&n.to_string(), &total.to_string());
    g.text(Text::new(Point::new(FRAME.x1 - 5.0, footer), page_no, TEXT, Anchor::End));
    Scene {
        ink: Ink::Black,
        name: "check".into(),
        width: PAGE.0,
        height: PAGE.1,
        title: format!("{} — {}", l.title(), names.project),
        groups: vec![g],
    }
}

/// The ruled table: a header row and a row per verdict; a failure gets a thick mark in the
/// margin left of its row, so that the teacher's eye finds it.
fn table(g: &mut Group, rows: &[Verdict], lang: Language, l: &CheckLabels, left: f64) {
    let head = [
        l.col_line(),
        l.col_quantity(),
        l.col_exact(),
        l.col_student(),
        l.col_unit(),
        l.col_deviation(),
        l.col_allowed(),
        l.col_result(),
    ];
    let right = left + WIDTHS.iter().sum::<f64>();
    let bottom = TABLE_TOP + ROW_H * (rows.len() + 1) as f64;
    for k in 0..=rows.len() + 1 {
        let y = TABLE_TOP + ROW_H * k as f64;
        g.line(Point::new(left, y), Point::new(right, y), if k <= 1 { MAIN } else { THIN });
    }
    let mut x = left;
    for (c, w) in WIDTHS.iter().enumerate() {
        g.line(Point::new(x, TABLE_TOP), Point::new(x, bottom), if c == 0 { MAIN } else { THIN });
        x += w;
    }
    g.line(Point::new(right, TABLE_TOP), Point::new(right, bottom), MAIN);
    cells(g, left, TABLE_TOP, &head.map(String::from));
    for (k, v) in rows.iter().enumerate() {
        let top = TABLE_TOP + ROW_H * (k + 1) as f64;
        cells(g, left, top, &row(v, lang, l));
        if !v.pass {
            g.line(Point::new(left - 3.0, top + 1.0), Point::new(left - 3.0, top + ROW_H - 1.0), MAIN);
        }
    }
}

/// One row's texts, each narrowed (never cut) to its column.
fn cells(g: &mut Group, left: f64, top: f64, texts: &[String; 8]) {
    let mut x = left;
    for (text, w) in texts.iter().zip(WIDTHS) {
        let t = Text::new(Point::new(x + 1.2, top + ROW_H - 1.5), text.as_str(), TEXT, Anchor::Start);
        let room = w - 2.4;
        let natural = t.bbox().width();
        g.text(if natural > room { t.with_stretch(room / natural) } else { t });
        x += w;
    }
}

/// A verdict's cells as the terminal's report writes them, in the report's language.
fn row(v: &Verdict, lang: Language, l: &CheckLabels) -> [String; 8] {
    let num = |x: f64| fmt::localise(&write::number(x), lang);
    let rule = match v.rule {
        Rule::Given => l.rule_given(),
        Rule::Course => l.rule_course(),
        Rule::PercentPoint => l.rule_point(),
        Rule::Paper => l.rule_paper(),
        Rule::Relative => l.rule_relative(),
        Rule::RowRelative => l.rule_row(),
    };
    [
        v.line.to_string(),
        write::quantity(v),
        num(v.exact),
        num(v.student),
        Common::get(lang).si_unit(&v.unit).to_string(),
        fmt::localise(&write::deviation(v), lang),
        format!("±{} ({rule})", num(v.tolerance)),
        if v.pass { l.pass() } else { l.fail() }.to_string(),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_report_set_loads_in_every_language() {
        for lang in Language::ALL {
            CheckLabels::load(lang).unwrap();
        }
        assert_eq!(CheckLabels::get(Language::Ru).page("1", "2"), "Лист 1 из 2");
    }

    #[test]
    fn a_page_holds_its_rows_above_the_footer() {
        let bottom = TABLE_TOP + ROW_H * (rows_per_page() + 1) as f64;
        assert!(bottom <= FOOTER_TOP && bottom + ROW_H > FOOTER_TOP, "{bottom}");
        assert!(FRAME.x0 + 5.0 + WIDTHS.iter().sum::<f64>() <= FRAME.x1, "the table fits the frame");
    }
}
