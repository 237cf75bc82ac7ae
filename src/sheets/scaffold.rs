//! What every sheet shares, done once: a sheet module composes its drawings, note tables and
//! results ([`Composition`]); [`finish`] adds the frame and the title block, measures the
//! layout, gathers the diagnostics and the `layout` block of the results. The note tables'
//! keys become words here ([`note`], [`drawn_rows`]).

use super::{Context, SheetError, SheetKind, SheetOutput, words};
use crate::drawing::fmt;
use crate::drawing::frame::{self, A1_H, A1_W};
use crate::drawing::labels::{Common, Language};
use crate::drawing::layout::{self, Layout};
use crate::drawing::scale;
use crate::drawing::scene::{Group, Ink, Item, Scene};
use crate::drawing::table;
use crate::drawing::text::{LabelText, TooLong};
use crate::report::{NoteTable, NumTable, Segment};
use kurbo::Rect;

/// A sheet as its module composes it: everything but the frame and the title block.
pub struct Composition {
    /// The sheet's name, in the title block and the document's title.
    pub name: String,
    /// The scale the title block states: the main view's μ_l, m/mm.
    pub mu_l: f64,
    /// The drawings, tables and notes, in drawing order.
    pub groups: Vec<Group>,
    /// The note's tables, in order.
    pub tables: Vec<NoteTable>,
    /// The sheet's section of `results.json`, from its typed results; [`finish`] adds the
    /// `layout` block.
    pub results: serde_json::Value,
    /// What the user should know about this sheet besides its layout.
    pub diagnostics: Vec<String>,
    /// The longer side of the smallest velocity or acceleration plan, mm (sheet 1).
    pub smallest_plan_mm: Option<f64>,
    /// The segments a student measures on its drawings, in drawing order.
    pub segments: Vec<Segment>,
    /// The whole sheet as [`scene`] makes it from this composition and its [`measure`], when
    /// the sheet module already has them (sheet 1 measures each layout it tries): [`finish`]
    /// takes them rather than measuring the same scene again.
    pub measured: Option<(Scene, Layout)>,
}

/// The whole sheet: the frame, the composition's groups, the title block.
pub fn scene(ctx: &Context, kind: SheetKind, c: &Composition) -> Result<Scene, TooLong> {
    let lang = ctx.info.language;
    let mut fr = Group::new(frame::FRAME, Rect::new(0.0, 0.0, A1_W, A1_H));
    frame::frame(&mut fr);
    let tb = ctx.title_block(Common::get(lang), &c.name, &fmt::localise(&scale::ratio(c.mu_l), lang))?;
    let mut groups = Vec::with_capacity(c.groups.len() + 3);
    groups.push(fr);
    groups.extend(c.groups.iter().cloned());
    groups.push(tb);
    groups.push(frame::designation_box_group(ctx.info.designation())?);
    Ok(Scene {
        ink: Default::default(),
        name: format!("sheet{}", kind.number),
        width: A1_W,
        height: A1_H,
        title: format!("{} — {}", ctx.info.title(), c.name),
        groups,
    })
}

pub use crate::drawing::frame::TITLE_BLOCK;

/// The sheet's constructions alone, in the overlay's ink at their places on the sheet: the
/// frame (to register the film on a hand drawing's frame), every drawing's lines, circles
/// and arrowheads; no letters, no tables, no title block — what a student draws with
/// instruments, not what they write.
pub fn overlay(scene: &Scene) -> Scene {
    let groups = scene
        .groups
        .iter()
        .filter(|g| g.id != TITLE_BLOCK && g.id != frame::DESIGNATION_BOX)
        .map(constructions)
        .collect();
    Scene { ink: Ink::Overlay, groups, ..scene.clone() }
}

/// A group without its texts, the lines of its writing (leaders, legend samples) and its
/// tables, its other parts kept around what is left of them.
fn constructions(g: &Group) -> Group {
    let in_table = |i: usize| g.parts.iter().any(|p| p.id.starts_with(table::PART) && p.items.contains(&i));
    let mut out = Group::new(g.id.clone(), g.region);
    let mut parts = g.parts.iter().filter(|p| !p.id.starts_with(table::PART)).peekable();
    let mut start = None;
    for (i, item) in g.items.iter().enumerate() {
        if parts.peek().is_some_and(|p| p.items.start == i) {
            start = Some(out.mark());
        }
        if !matches!(item, Item::Text(_)) && !in_table(i) && !g.writing.contains(&i) {
            out.items.push(item.clone());
        }
        if let Some(p) = parts.next_if(|p| p.items.end == i + 1) {
            out.part_from(p.id.clone(), start.take().unwrap_or(out.mark()));
        }
    }
    out
}

/// The layout measurement of the whole sheet (see [`layout::measure`]).
pub fn measure(scene: &Scene, c: &Composition) -> Layout {
    measure_with_share(scene, c).0
}

/// [`measure`], and the share of empty cells unrounded (sheet 3 compares its variants'
/// shares to the thousandth).
pub fn measure_with_share(scene: &Scene, c: &Composition) -> (Layout, f64) {
    // The drawing field: inside the frame, the title block left out.
    let (mut layout, share) = layout::measure_with_share(
        scene,
        frame::inner(),
        frame::title_block_rect(),
        &["frame", TITLE_BLOCK, frame::DESIGNATION_BOX],
    );
    layout.smallest_plan_mm = c.smallest_plan_mm;
    // Three decimals: the same bytes on every machine.
    layout.empty_share = Some((share * 1e3).round() / 1e3);
    (layout, share)
}

/// The finished sheet: the scene with its frame and title block, the layout measured and
/// reported (in the results and as diagnostics).
pub fn finish(ctx: &Context, kind: SheetKind, mut c: Composition) -> Result<SheetOutput, SheetError> {
    let (scene, layout) = match c.measured.take() {
        Some(measured) => measured,
        None => {
            let scene = scene(ctx, kind, &c)?;
            let layout = measure(&scene, &c);
            (scene, layout)
        }
    };
    let Composition { tables, mut results, mut diagnostics, segments, .. } = c;
    diagnostics.extend(layout.problems.iter().map(|p| format!("layout: {p}")));
    if let serde_json::Value::Object(map) = &mut results {
        map.insert("layout".into(), serde_json::to_value(&layout).expect("the layout serialises"));
    }
    Ok(SheetOutput { number: kind.number, scene, tables, results, diagnostics, segments })
}

/// A table of the note in `lang`: titled `title`, its value columns headed `column_titles`
/// (the table's own headings when empty), its rows' symbols, subscripts and units in words.
pub fn note(
    lang: Language,
    table: NumTable,
    title: &str,
    column_titles: Vec<String>,
    whole_numbers: bool,
) -> NoteTable {
    let c = Common::get(lang);
    let printed = table.rows.iter().map(|r| words::quantity(lang, &r.quantity)).collect();
    let units = table.rows.iter().map(|r| words::unit(lang, r.unit).to_string()).collect();
    let column_titles = if column_titles.is_empty() {
        table.columns.iter().map(|c| c.heading.clone()).collect()
    } else {
        column_titles
    };
    NoteTable {
        title: title.to_string(),
        headings: [c.quantity().into(), c.unit().into()],
        printed,
        units,
        column_titles,
        decimal_comma: lang != Language::En,
        whole_numbers,
        table,
    }
}

/// The rows of a drawn table: each quantity as a label (with ", unit" after it when
/// `unit_tails` and the row has a unit), its values as the note prints them
/// ([`NoteTable::printed_values`]).
pub fn drawn_rows(n: &NoteTable, lang: Language, unit_tails: bool) -> Vec<(LabelText, Vec<String>)> {
    n.table
        .rows
        .iter()
        .zip(n.printed.iter().zip(&n.units))
        .map(|(r, ((symbol, sub), unit))| {
            // A coefficient's star follows its subscript at full size (h with a, then *: hₐ*,
            // as c*), not set small inside it.
            let (sub, star) = match sub.strip_suffix('*') {
                Some(bare) => (bare.to_string(), "*"),
                None => (sub.clone(), ""),
            };
            let mut label = LabelText::new(symbol.clone(), sub);
            label.tail = star.to_string();
            if unit_tails && !unit.is_empty() {
                label.tail.push_str(&format!(", {unit}"));
            }
            (label, n.printed_values(r).iter().map(|v| fmt::localise(v, lang)).collect())
        })
        .collect()
}
