//! Sheet 2: the gears. The external pair's mesh on the left half (three exact teeth per
//! wheel at a GOST scale making the tooth taller than 50 mm), the planetary stage's two
//! views and the tables on the right, the notes and the title block.

mod clip;
mod generation_view;
pub mod labels;
mod mesh_dimensions;
mod mesh_view;
mod planetary_view;
mod results;
mod room;
mod segments;
mod sliding_view;
mod stage_layout;
mod stage_velocities;
mod tables;
mod teeth_view;

pub use mesh_view::MeshDrawn;
pub use stage_velocities::{READ_TO_MM, Reading};
pub use teeth_view::INVOLUTE_PIECES;

use super::notes::Room;
use super::scaffold::Composition;
use super::{COURSE, Context, Sheet, SheetError, SheetKind};
use crate::drawing::columns::{self, Para};
use crate::drawing::fmt;
use crate::drawing::frame;
use crate::drawing::labels::Language;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::table::{self, CELL_TEXT};
use crate::drawing::text::TooLong;
use crate::gears::pair::PairWarning;
use crate::gears::sliding::Sliding;
use crate::num::units::mm;
use crate::project::{GearsProject, Project};
use crate::report::AnswerKeys;
use kurbo::{Point, Rect};
use labels::GearWords;
use mesh_view::{MeshInput, draw_mesh};

/// This sheet's place in the course.
pub const KIND: SheetKind = COURSE[1];

/// Sheet 2 of a project with a `gears` section.
pub struct GearsSheet<'a> {
    pub project: &'a GearsProject,
}

impl GearsSheet<'_> {
    pub fn of(project: &Project) -> Option<Box<dyn Sheet + '_>> {
        project.gears.as_ref().map(|p| Box::new(GearsSheet { project: p }) as Box<dyn Sheet>)
    }
}

/// Everything built for sheet 2.
pub struct GearsBuild {
    pub composition: Composition,
    pub mesh: MeshDrawn,
    /// μ_l of the planetary views, m/mm.
    pub planetary_mu: Option<f64>,
    /// The ratio read off the plan of angular velocities.
    pub planetary_reading: Option<Reading>,
    /// The specific sliding's diagram, where the mesh left it room.
    pub sliding: Option<sliding_view::SlidingDrawn>,
}

/// The parts of the mesh's and the planetary stage's drawings (their ids in the SVG, and
/// the start of their segments' ids).
const MESH_PART: &str = "mesh.drawing";
const PLANETARY_PART: &str = "planetary.views";

/// Left half: the mesh (without a planetary stage, as far right as the tables leave).
const MESH: Rect = Rect { x0: 24.0, y0: 9.0, x1: 440.0, y1: 585.0 };
/// Right half, above the title block's column.
const RIGHT_X0: f64 = 448.0;

/// Builds sheet 2.
pub fn build(ctx: &Context, p: &GearsProject) -> Result<GearsBuild, SheetError> {
    let words = GearWords::new(ctx.info.language);
    let l = words.sheet;
    let tolerance = p.planetary.as_ref().map(|pl| pl.stage.tolerance);
    let inner = frame::inner();
    let right_of = |x0: f64| Rect::new(x0, inner.y0 + 4.0, inner.x1 - 4.0, frame::title_block_rect().y0 - 4.0);
    // Without a planetary stage the mesh takes the width the tables leave: the widest they
    // take in any language (measured on the exact contact ratio, the drawn one's digits
    // being as many), so that the drawing, and what is measured on it, is the same in all.
    let region = match p.planetary {
        Some(_) => MESH,
        None => {
            let w = Language::ALL
                .into_iter()
                .map(|lang| {
                    let words = GearWords::new(lang);
                    let sized = tables::notes(p, p.pair.contact_ratio, &words, ctx.first_table);
                    let height = right_of(RIGHT_X0).height();
                    let largest = tables::largest_sizes(&sized, tolerance, &words);
                    let one_column = largest.iter().map(|s| s.0).fold(0.0, f64::max);
                    match table::flow_width(&largest, height, tables::GAP) {
                        w if w <= one_column + 1e-9 => w,
                        _ => table::flow_width(&tables::large_sizes(&sized, tolerance, &words), height, tables::GAP),
                    }
                })
                .fold(0.0, f64::max);
            // 5 mm lettering where the tables stand in one column so, else 3.5 mm.
            // Over the title block's column too: the circles' arcs stop short of the block.
            Rect { x1: (right_of(0.0).x1 - w - 8.0).max(MESH.x1), ..MESH }
        }
    };
    let (mesh, drawn, sliding) = mesh_group(p, region, &words)?;
    let notes = tables::notes(p, drawn.contact_ratio_drawn, &words, ctx.first_table);
    let answers = AnswerKeys::of(&format!("sheet{}", KIND.number), &notes);
    let mut measured = segments::mesh(&p.pair, drawn.mu, MESH_PART, &answers);

    // The right half: the planetary views on top, the tables below; the rack generation of
    // each wheel in the largest room the rest leaves on the sheet.
    let right = right_of(region.x1 + 8.0);
    let tables_in = |y0: f64| tables::group(&notes, Rect::new(right.x0, y0, right.x1, right.y1), tolerance, &words);
    let mut planetary = None;
    let groups = match &p.planetary {
        None => {
            let mut groups = vec![mesh, tables_in(right.y0)];
            groups.extend(generations(&groups, p, &words));
            groups
        }
        Some(pl) => {
            let sizes =
                [tables::largest_sizes(&notes, tolerance, &words), tables::large_sizes(&notes, tolerance, &words)];
            let choices = stage_layout::choices(pl, right, &sizes, &words);
            // Of the plan's rooms, the first that leaves the rack generation pictures as
            // many rooms as any (a strip moves the tables down into theirs).
            let mut best: Option<(stage_layout::PlanetaryDrawn, Vec<Group>)> = None;
            for plan in choices.plans {
                let drawn = stage_layout::draw(pl, right, choices.share, plan, &words);
                let mut rest = vec![tables_in(drawn.bottom + 4.0)];
                let pictures = generations(&[&mesh, &drawn.group, &rest[0]], p, &words);
                rest.extend(pictures);
                if best.as_ref().is_none_or(|(_, b)| rest.len() > b.len()) {
                    best = Some((drawn, rest));
                }
                if best.as_ref().is_some_and(|(_, b)| b.len() == 3) {
                    break;
                }
            }
            let (drawn, rest) = best.expect("at least one room for the plan");
            measured.extend(segments::planetary(&pl.stage, pl.module, drawn.mu, PLANETARY_PART, &answers));
            planetary = Some((drawn.mu, drawn.reading));
            let mut groups = vec![mesh, drawn.group];
            groups.extend(rest);
            groups
        }
    };
    let name = if p.planetary.is_some() { l.sheet_name() } else { l.sheet_name_pair() };
    let composition = Composition {
        name: name.to_string(),
        mu_l: drawn.mu,
        groups,
        tables: notes,
        results: serde_json::Value::Null,
        diagnostics: Vec::new(),
        smallest_plan_mm: None,
        segments: measured,
        measured: None,
    };
    let (planetary_mu, planetary_reading) = (planetary.map(|p| p.0), planetary.map(|p| p.1));
    Ok(GearsBuild { composition, mesh: drawn, planetary_mu, planetary_reading, sliding })
}

/// The rack generation of each wheel in the largest room `drawn` leaves on the sheet, wheel
/// 1 first (the pinion, the shift chosen against its undercut).
fn generations<G: std::borrow::Borrow<Group>>(drawn: &[G], p: &GearsProject, words: &GearWords) -> Vec<Group> {
    let mut out: Vec<Group> = Vec::new();
    for wheel in 0..2 {
        let items = drawn.iter().map(|g| g.borrow()).chain(&out).flat_map(|g| g.items.iter());
        let drawn_items = Obstacles::of_items(items);
        let outline = &p.pair.outlines[wheel];
        out.extend(generation_view::draw(&drawn_items, frame::inner().inset(-4.0), (&p.pair, wheel), outline, words));
    }
    out
}

/// The notes under the mesh (its results, the sheet's notes and the assumptions) may take
/// this much height, mm: the mesh keeps the rest of the half; its teeth, drawn at a fixed
/// scale, are not shrunk to make room.
const NOTES_MAX_H: f64 = 100.0;

/// The mesh on the left half: title on top, notes at the bottom, the drawing between;
/// refuses assumptions that would make the notes taller than [`NOTES_MAX_H`].
fn mesh_group(
    p: &GearsProject,
    region: Rect,
    words: &GearWords,
) -> Result<(Group, MeshDrawn, Option<sliding_view::SlidingDrawn>), TooLong> {
    let (l, lang) = (words.sheet, words.lang);
    let notes = mesh_notes(p, words);
    // Left of the title block where the region reaches down beside it (set across the
    // region, the notes' last column ran into it).
    let title_block = frame::title_block_rect();
    let notes_w = if region.y1 > title_block.y0 && region.x1 > title_block.x0 {
        (title_block.x0 - 4.0 - (region.x0 + 2.0)).min(region.width() - 4.0)
    } else {
        region.width() - 4.0
    };
    // The notes' height: four lines of results (their numbers come from the drawing, not
    // drawn yet: set here with numbers at least as wide as the drawing's will be, so that
    // the lines wrap no less than the real ones) and the notes, in columns.
    let exact = fmt::value(p.pair.contact_ratio, lang);
    let head_like = [
        l.scale(&fmt::localise("2.5:1", lang)),
        l.contact_ratio_exact(&exact),
        l.contact_ratio_drawn(&exact, &fmt::percent_difference(-9.99, lang)),
        l.involute_note(&fmt::bound_above(99.9, lang)),
    ];
    let mut notes_h = columns::set(&note_paras(&head_like, &notes), CELL_TEXT, notes_w).height + 6.0;
    let assumptions: Vec<String> = p.assumptions.iter().map(|a| a.get(lang).to_string()).collect();
    let room = Room { field: "gears.assumptions", place: "notes under the mesh", size: (notes_w, NOTES_MAX_H) };
    // The real numbers may still set the notes taller (a column ending elsewhere: a pair of
    // 133/133 teeth had its notes in three columns with the stand-ins, in one with its own
    // and 22 mm taller, off the page): then the mesh is drawn again above that height.
    for tries in 1.. {
        room.check(&assumptions, notes_h)?;
        let (mesh, real_h) = mesh_over_notes(p, region, (&notes, notes_w, notes_h), words);
        if real_h <= notes_h + 1e-9 || tries == 3 {
            return Ok(mesh);
        }
        notes_h = real_h;
    }
    unreachable!("the tries end at the third")
}

/// The mesh's group in `region` with the notes (`notes`, set `notes_w` wide) under its
/// drawing, which ends `notes_h` mm above the region's foot; with the notes' real height.
fn mesh_over_notes(
    p: &GearsProject,
    region: Rect,
    (notes, notes_w, notes_h): (&[String], f64, f64),
    words: &GearWords,
) -> ((Group, MeshDrawn, Option<sliding_view::SlidingDrawn>), f64) {
    let (l, lang) = (words.sheet, words.lang);
    let mut mesh = Group::new("mesh", region);
    let mut labels = Labels::new();
    let title = l.mesh_title(
        &fmt::trimmed(mm(p.pair.spec.module), lang),
        &p.pair.wheels[0].z.to_string(),
        &p.pair.wheels[1].z.to_string(),
    );
    let at = crate::drawing::frame::clear_of_designation_box(Point::new(region.x0 + 2.0, region.y0 + 6.0), 5.0);
    mesh.text(Text::new(at, title, 5.0, Anchor::Start));
    let area = Rect::new(region.x0 + 2.0, region.y0 + 10.0, region.x1 - 2.0, region.y1 - notes_h);
    let start = mesh.mark();
    let drawn = draw_mesh(
        &mut mesh,
        area,
        &MeshInput { pair: &p.pair, outlines: [&p.pair.outlines[0], &p.pair.outlines[1]], lang },
        &mut labels,
    );
    // Its labels stay inside the drawing's area, clear of the notes below it.
    labels.place(&mut mesh, area);
    mesh.part_from(MESH_PART, start);
    let start = mesh.mark();
    let sliding = sliding_view::draw(&mut mesh, area, &Sliding::of(&p.pair), l.sliding_title(), words);
    if sliding.is_some() {
        mesh.part_from("mesh.sliding", start);
    }
    let start = mesh.mark();
    let eps = &fmt::value;
    let diff = (drawn.contact_ratio_drawn - p.pair.contact_ratio) / p.pair.contact_ratio * 100.0;
    let head = [
        l.scale(&fmt::localise(&scale::ratio(drawn.mu), lang)),
        l.contact_ratio_exact(&eps(p.pair.contact_ratio, lang)),
        l.contact_ratio_drawn(&eps(drawn.contact_ratio_drawn, lang), &fmt::percent_difference(diff, lang)),
        l.involute_note(&fmt::bound_above(drawn.involute_deviation * 1e6, lang)),
    ];
    let set = columns::set(&note_paras(&head, notes), CELL_TEXT, notes_w);
    columns::draw(&mut mesh, Point::new(region.x0 + 2.0, area.y1 + 5.0), &set, CELL_TEXT);
    mesh.part_from("mesh.notes", start);
    ((mesh, drawn, sliding), set.height + 6.0)
}

/// The results under the mesh and its notes, as paragraphs. The head's second line, the
/// analytic ε, and its third, the drawn one with their difference ("измеренный на чертеже
/// …"), are one statement: kept in one column.
fn note_paras(head: &[String], notes: &[String]) -> Vec<Para> {
    let mut paras: Vec<Para> = head.iter().chain(notes).map(|n| Para::new(n.clone(), 0.5)).collect();
    if let Some(exact) = paras.get_mut(1) {
        exact.keep_with_next = true;
    }
    paras
}

/// The notes under the mesh: shifts chosen, warnings, the user's assumptions.
fn mesh_notes(p: &GearsProject, words: &GearWords) -> Vec<String> {
    let (l, lang) = (words.sheet, words.lang);
    let v = |x: f64| fmt::value(x, lang);
    let mut out = vec![l.active_note().to_string()];
    for (i, w) in p.pair.wheels.iter().enumerate() {
        if p.auto_shift[i] {
            // The shift as chosen (to 0.001, as the wheels' table gives it), the limit as the
            // table gives it.
            let x = fmt::trimmed(w.shift, lang);
            out.push(l.auto_shift_note(&(i + 1).to_string(), &x, &v(w.x_min_course)));
        }
    }
    for w in &p.warnings {
        out.push(match w {
            PairWarning::Undercut { wheel, x, x_min, .. } => {
                let (x, x_min) = fmt::values_apart(*x, *x_min, lang);
                l.undercut_note(&wheel.to_string(), &x, &x_min)
            }
            PairWarning::ThinTip { wheel, s_a, .. } => l.thin_tip_note(&wheel.to_string(), &v(mm(*s_a))),
            PairWarning::LowContactRatio { eps } => l.low_ratio_note(&v(*eps)),
            PairWarning::Interference { wheel } => {
                let other = 3 - wheel;
                l.interference_note(&wheel.to_string(), &other.to_string(), ["₁", "₂"][other - 1])
            }
        });
    }
    out.extend(p.assumptions.iter().map(|a| a.get(lang).to_string()));
    out
}

impl Sheet for GearsSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn table_count(&self) -> u32 {
        tables::table_count(self.project)
    }

    fn name(&self, lang: crate::drawing::labels::Language) -> String {
        let l = labels::GearLabels::get(lang);
        if self.project.planetary.is_some() { l.sheet_name() } else { l.sheet_name_pair() }.to_string()
    }

    fn compose(&self, ctx: &Context) -> Result<Composition, SheetError> {
        let b = build(ctx, self.project)?;
        let results = results::section(self.project, &b);
        Ok(Composition { results, diagnostics: diagnostics(self.project), ..b.composition })
    }
}

/// The pair's warnings that the sheet's notes do not already state.
fn diagnostics(p: &GearsProject) -> Vec<String> {
    p.warnings
        .iter()
        .filter_map(|w| match w {
            PairWarning::ThinTip { wheel, s_a, limit } => {
                Some(format!("wheel {wheel}'s tip is thin: s_a = {:.3} mm < 0.25·m = {:.3} mm", mm(*s_a), mm(*limit)))
            }
            PairWarning::LowContactRatio { eps } => Some(format!("the contact ratio {eps:.3} is below 1.2")),
            PairWarning::Interference { wheel } => {
                Some(format!("wheel {wheel}'s tip passes the other wheel's N: the contact ends at N (undercut root)"))
            }
            PairWarning::Undercut { .. } => None,
        })
        .collect()
}
