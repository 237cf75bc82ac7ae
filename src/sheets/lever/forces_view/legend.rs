//! The texts under and beside the force drawings: force labels, values with a star for a
//! short arrow, rows of items wrapped to a width, the scales.

use super::{ARROW_MIN, ForcesInput, LINE};
use crate::drawing::fmt;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::text::{LabelText, wrap};
use crate::lever::kinetostatics::{FRAME, Kind, Part, Polygon};
use crate::num::math::Norm;
use crate::report::ForceKind;
use crate::report::lever::load_kind;
use kurbo::{Point, Rect};

/// Items in rows no wider than `width`, each followed by `sep` and the last by `last`.
pub(super) fn wrap_items(items: Vec<LabelText>, width: f64, sep: &str, last: &str) -> Vec<Vec<LabelText>> {
    let mut lines: Vec<Vec<LabelText>> = vec![vec![]];
    let mut w = 0.0;
    let n = items.len();
    for (i, t) in items.into_iter().enumerate() {
        let end = if i + 1 == n { last } else { sep };
        let item = LabelText { tail: format!("{}{end}", t.tail), ..t };
        let iw = measure(&item, 3.5).width() + 2.5;
        if w + iw > width && w > 0.0 {
            lines.push(vec![]);
            w = 0.0;
        }
        w += iw;
        lines.last_mut().expect("one line at least").push(item);
    }
    lines.retain(|l| !l.is_empty());
    lines
}

pub(super) fn equation_lines(inp: &ForcesInput, poly: &Polygon, width: f64) -> Vec<Vec<LabelText>> {
    let terms: Vec<LabelText> = poly
        .terms
        .iter()
        .filter(|t| t.force.norm() > 0.0)
        .enumerate()
        .map(|(k, t)| {
            let l = force_label(inp, t.kind, t.on);
            if k == 0 { l } else { LabelText { main: format!("+ {}", l.main), ..l } }
        })
        .collect();
    wrap_items(terms, width, "", " = 0")
}

/// "G₂ = 19,6 N", with a star when the arrow is drawn longer than its scale gives; with
/// `decimals` (its table's, [`decimals_of`]) where given, else four significant digits.
pub(super) fn value_item(
    inp: &ForcesInput,
    label: LabelText,
    (value, decimals): (f64, Option<usize>),
    unit: &str,
    short: bool,
) -> LabelText {
    let star = if short { "*" } else { "" };
    let lang = inp.words.lang;
    let written = match decimals {
        Some(d) => fmt::localise(&crate::num::digits::at_decimals(value, d), lang),
        None => fmt::value(value, lang),
    };
    label.with_tail(format!("{star} = {written} {unit}"))
}

/// The decimals a force of `kind` is written with in a legend: those its table prints it
/// with (table 3's weights and inertia forces, table 4's reactions); none for a load or
/// the balancing force, which table 5 writes with four significant digits as
/// [`fmt::value`] does, nor for a reaction's normal or tangential part, which no table
/// lists (at table 4's whole newtons the worked example's short Rᵗ₁₂ read 5 N for 5,467).
pub(super) fn decimals_of(inp: &ForcesInput, kind: Kind) -> Option<usize> {
    let d = inp.decimals;
    match kind {
        Kind::Weight => Some(d.weight),
        Kind::Inertia => Some(d.inertia),
        Kind::Reaction { part: Part::Whole, .. } => Some(d.reaction),
        Kind::Reaction { .. } | Kind::Load(_) | Kind::Balancing => None,
    }
}

pub(super) fn with_short_note(
    inp: &ForcesInput,
    mut lines: Vec<Vec<LabelText>>,
    short: bool,
    width: f64,
) -> Vec<Vec<LabelText>> {
    if short {
        let note = inp.words.sheet.short_arrow(&format!("{ARROW_MIN}"));
        lines.extend(wrap(&note, 3.5, width).into_iter().map(|l| vec![LabelText::new(l, "")]));
    }
    lines
}

/// The box a label draws (symbol, subscript and tail) when centred on the origin.
pub(super) fn measure(l: &LabelText, h: f64) -> Rect {
    l.draw(&mut Group::new("probe", Rect::ZERO), Point::ZERO, h, Anchor::Middle)
}

/// The label of a force: G₂, Pᵢ₂, P_c5, Rⁿ₁₂, Pₘ.
pub(super) fn force_label(inp: &ForcesInput, kind: Kind, on: usize) -> LabelText {
    let n = |l: usize| if l == FRAME { 0 } else { inp.m.links[l].number };
    match kind {
        Kind::Weight => LabelText::new("G", n(on).to_string()),
        Kind::Inertia => LabelText::new("P", inp.words.sheet.force(ForceKind::Inertia, &n(on).to_string())),
        Kind::Load(i) => {
            LabelText::new("P", inp.words.sheet.force(load_kind(inp.fa.model.loads[i].kind), &n(on).to_string()))
        }
        Kind::Reaction { from, part } => {
            let main = match part {
                Part::Whole => "R",
                Part::Normal => "Rⁿ",
                Part::Tangential => "Rᵗ",
            };
            LabelText::new(main, format!("{}{}", n(from), n(on)))
        }
        Kind::Balancing => LabelText::new("P", inp.words.sheet.sub_balancing()),
    }
}

/// The label of the forces of the couple that replaces link `on`'s inertia moment on the
/// lever.
pub(super) fn couple_label(inp: &ForcesInput, on: usize) -> LabelText {
    LabelText::new("P", format!("M{}", inp.m.links[on].number))
}

pub(super) fn cell_title(g: &mut Group, r: Rect, text: &str) {
    g.text(Text::new(Point::new(r.x0 + 2.0, r.y0 + 5.0), text, 3.5, Anchor::Start));
}

/// Rows of items from `y` down, one row per line; returns the next line's baseline.
pub(super) fn text_rows(g: &mut Group, x0: f64, y: f64, rows: &[Vec<LabelText>]) -> f64 {
    rows_spaced(g, (x0, y), rows, |bb, _| bb.x1 + 2.5)
}

/// A vector equation's rows from `y` down, its terms ("+ Rᵗ₂₄") a word space apart as one
/// line of text sets them (a term's box ends past its sloped subscript: spaced by boxes,
/// "Rⁿ₂₄   + Rᵗ₂₄" read as two groups); returns the next line's baseline.
pub(super) fn equation_rows(g: &mut Group, x0: f64, y: f64, rows: &[Vec<LabelText>]) -> f64 {
    let space = crate::font::metrics().width(" ", crate::font::size_for_cap(3.5));
    rows_spaced(g, (x0, y), rows, |_, (x, item)| x + item.width(3.5) + space)
}

/// Rows of items in 3.5 mm lettering from `(x0, y)` down, each item started where `next`
/// (given the last one's drawn box, its start and itself) says; returns the next baseline.
fn rows_spaced(
    g: &mut Group,
    (x0, mut y): (f64, f64),
    rows: &[Vec<LabelText>],
    next: impl Fn(Rect, (f64, &LabelText)) -> f64,
) -> f64 {
    for line in rows {
        let mut x = x0;
        for item in line {
            let bb = item.draw(g, Point::new(x, y), 3.5, Anchor::Start);
            x = next(bb, (x, item));
        }
        y += LINE;
    }
    y
}

pub(super) fn scale_item(inp: &ForcesInput, sub: &str, mu: f64, unit: &str) -> LabelText {
    LabelText::new("μ", sub).with_tail(format!(" = {} {unit}", fmt::localise(&scale::format(mu), inp.words.lang)))
}

pub(super) fn with_semicolon(mut l: LabelText) -> LabelText {
    l.tail.push(';');
    l
}
