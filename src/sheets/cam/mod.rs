//! Sheet 3: the cam. The law's three diagrams by graphical integration on the left with the
//! notes under them, the nomogram of the minimum radius and the profile arranged where each
//! comes out largest (`regions.rs`), the tables in a strip left of the title block.

mod choice;
mod diagrams;
pub mod labels;
mod nomogram;
mod notes;
mod pressure_view;
mod profile_view;
mod regions;
mod results;
mod segments;
mod tables;
mod view_heading;

pub use diagrams::Scales;
pub use profile_view::{MAX_PIECES, PROFILE_TOL};

use super::notes::Room;
use super::scaffold::Composition;
use super::{COURSE, Context, Sheet, SheetError, SheetKind};
use crate::cams::integrate::{self, Integrated};
use crate::drawing::columns::{self, Para};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group};
use crate::drawing::table::{self, CELL_TEXT, Table};
use crate::drawing::text::{LINE_PITCH, TooLong, paragraph, wrap};
use crate::project::{CamProject, Project};
use crate::report::{AnswerKeys, NoteTable};
use kurbo::{Point, Rect, Vec2};
use labels::CamWords;
use nomogram::Placement;
use regions::{COLUMN_WIDTHS, ColumnWidth, Content, Regions, SHEET, TABLE_GAP, ViewSize, view_area};
use view_heading::{TITLE_H, heading_w, scale_note, view_group};

/// This sheet's place in the course.
pub const KIND: SheetKind = COURSE[2];

/// Divisions of each phase: the numbered positions and the chord integration.
pub use crate::cams::integrate::DIVISIONS;

/// Sheet 3 of a project with a `cam` section.
pub struct CamSheet<'a> {
    pub project: &'a CamProject,
}

impl CamSheet<'_> {
    pub fn of(project: &Project) -> Option<Box<dyn Sheet + '_>> {
        project.cam.as_ref().map(|p| Box::new(CamSheet { project: p }) as Box<dyn Sheet>)
    }
}

/// Everything built for sheet 3.
pub struct CamBuild {
    pub composition: Composition,
    pub scales: Scales,
    pub integrated: [Integrated; 2],
    /// The integration's errors, percent of the lift and of the largest ds/dφ.
    pub errors: (f64, f64),
    pub nomogram_mu: f64,
    pub profile_mu: f64,
    pub profile_pieces: usize,
    pub profile_deviation: f64,
    /// The pressure angle's diagram's scales, where the sheet had room for it.
    pub pressure: Option<pressure_view::PressureScales>,
    /// Lettered by the rule in the smaller lettering where the larger one fits too: a build
    /// in [`Lettering::Large`] would differ.
    large_differs: bool,
}

/// Of columns planned shorter and shorter with the regions they leave, the one with the
/// largest profile, and of those the one that keeps the nomogram and the diagrams nearest
/// their largest (the larger of their two shrinkings the least: a taller column can leave
/// the nomogram no room under it, a shorter one draws smaller diagrams).
fn balanced(tried: Vec<(diagrams::Plan, Regions)>) -> Option<(diagrams::Plan, Regions)> {
    let profile = tried.iter().map(|t| t.1.profile_mu).fold(f64::INFINITY, f64::min);
    let nomogram = tried.iter().map(|t| t.1.nomogram_mu).fold(f64::INFINITY, f64::min);
    let height = tried.iter().map(|t| t.0.height).fold(0.0, f64::max);
    let kept = |t: &(diagrams::Plan, Regions)| (nomogram / t.1.nomogram_mu).min(t.0.height / height);
    let largest_profile = |t: &(diagrams::Plan, Regions)| t.1.profile_mu <= profile * 1.001;
    // The law's tables under the diagrams where a column nearly as tall leaves them room:
    // else they take the right side's middle from the pressure angle's diagram.
    let under = |t: &(diagrams::Plan, Regions)| t.1.law_tables.is_some();
    let room_under = tried.iter().any(|t| largest_profile(t) && under(t) && t.0.height >= TABLES_UNDER * height);
    // The first (tallest) wins a tie.
    tried
        .into_iter()
        .filter(|t| largest_profile(t) && (under(t) || !room_under))
        .reduce(|best, t| if kept(&t) > kept(&best) * 1.001 { t } else { best })
}

/// The share of the tallest column's height a column keeps to leave the law's tables room
/// under it.
const TABLES_UNDER: f64 = 0.85;

/// The diagrams' column is planned this much shorter than its room, mm: the first as tall
/// as it goes.
const SHORTER: [f64; 5] = [0.0, 50.0, 100.0, 175.0, 250.0];

/// The tables' larger lettering, mm: one GOST size above [`CELL_TEXT`].
const LARGE_TEXT: f64 = 3.5;

/// The share of their height the diagrams keep at least for the tables' larger lettering.
const LARGE_KEEPS: f64 = 0.8;

/// The two views' sizes, what the regions are chosen for besides the column and the tables.
struct Views {
    nomogram: ViewSize,
    profile: ViewSize,
}

impl Views {
    fn content<'a>(
        &self,
        (plan, text_h): (&'a diagrams::Plan, f64),
        law: &'a [regions::Size],
        rest: &'a [regions::Size],
    ) -> Content<'a> {
        Content { nomogram: self.nomogram.clone(), profile: self.profile.clone(), plan, text_h, law, rest }
    }
}

/// The diagrams' column as planned: its title, notes, plan and the height of its texts.
struct Column {
    title: String,
    notes: Vec<String>,
    plan: diagrams::Plan,
    /// The title's and the notes' height in a column of the plan's width, mm.
    text_h: f64,
    /// The height the texts leave the diagrams, mm.
    room: f64,
    width: ColumnWidth,
}

/// The notes under the diagrams (the sheet's and the assumptions) may take this much
/// height, mm: the diagrams keep the rest of the column at the course's scales.
const NOTES_MAX_H: f64 = 80.0;

/// Plans the column: the diagrams as large as the column leaves them after the texts (μ_φ,
/// hence the plan's width and the notes' wrapping, depend on the width alone: a plan made
/// shorter with [`shorter_plan`] keeps them); refuses assumptions that would make the notes
/// taller than [`NOTES_MAX_H`].
fn plan_column(
    p: &CamProject,
    errors: ((f64, f64), usize),
    deviation: f64,
    words: &CamWords,
    width: ColumnWidth,
) -> Result<Column, TooLong> {
    let title = notes::laws_title(p, words);
    let notes = notes::sheet_notes(p, errors, deviation, words);
    let wide = head_h(&title, width.left - 4.0) + notes_h(&notes, width.left - 4.0);
    let mut room = SHEET.height() - wide - 8.0;
    let mut plan = diagrams::plan(&p.design, (width.left - 4.0, width.phi), room);
    // The title and the notes are set as wide as the diagrams (the column's region narrows
    // to them): in more lines than the column's width gave, where those leave the diagrams
    // no room the plan is made again in what is left (its width does not change with its
    // height). A roller's note and a title in two lines put a column 5 mm past the frame.
    let (head, drawn_h) = (head_h(&title, plan.width), notes_h(&notes, plan.width));
    let excess = head + drawn_h - wide;
    if excess > 0.0 && plan.height > room - excess {
        room -= excess;
        plan = diagrams::plan(&p.design, (width.left - 4.0, width.phi), room);
    }
    let assumptions: Vec<String> = p.assumptions.iter().map(|a| a.get(words.lang).to_string()).collect();
    let notes_room =
        Room { field: "cam.assumptions", place: "notes under the diagrams", size: (plan.width, NOTES_MAX_H) };
    notes_room.check(&assumptions, drawn_h)?;
    Ok(Column { title, notes, plan, text_h: head + drawn_h, room, width })
}

/// The column's diagrams planned `shorter` mm lower than its room (leaving the nomogram room
/// under them).
fn shorter_plan(p: &CamProject, column: &Column, shorter: f64) -> diagrams::Plan {
    diagrams::plan(&p.design, (column.width.left - 4.0, column.width.phi), column.room - shorter)
}

/// The notes set `w` wide in GOST 2.316's columns (at most 185 mm each), 1 mm after each
/// note.
fn notes_set(notes: &[String], w: f64) -> columns::Set {
    let paras: Vec<Para> = notes.iter().map(|n| Para::new(n.as_str(), 1.0)).collect();
    columns::set(&paras, CELL_TEXT, w)
}

/// The notes' height set `w` wide as `diagrams_group` sets them.
fn notes_h(notes: &[String], w: f64) -> f64 {
    notes_set(notes, w).height
}

/// The height of the column's title set `w` wide, with its margins, mm.
fn head_h(title: &str, w: f64) -> f64 {
    6.0 + title_lines(title, Rect::new(SHEET.x0, SHEET.y0, SHEET.x0 + w + 4.0, SHEET.y1)).1.len() as f64
        * LINE_PITCH
        * TITLE_H
        + 2.0
}

/// Where the column's title starts in the diagrams' region `r` (right of box 26) and its
/// lines there, as wide as the region leaves them (set as wide as the region, the English
/// title took a line more than [`head_h`] counted and ran into the nomogram under it).
fn title_lines(title: &str, r: Rect) -> (Point, Vec<String>) {
    let at = crate::drawing::frame::clear_of_designation_box(Point::new(r.x0 + 2.0, r.y0 + 6.0), TITLE_H);
    (at, wrap(title, TITLE_H, r.width() - 4.0 - (at.x - r.x0 - 2.0)))
}

/// Builds sheet 3 with the diagrams' column at each of the widths `regions.rs` tries, the
/// tables lettered by the rule and, where that differs, in the larger lettering wherever
/// they fit, and keeps the one that leaves the least of the sheet empty (the usual width by
/// the rule on a tie) among those whose layout is no less clean: a column
/// too narrow for its views' room leaves a band across the sheet's middle; one too wide
/// shrinks the views; larger tables can leave the pressure angle's diagram room beside them
/// (`choice.rs`: a smaller profile only for a clearly emptier sheet).
pub fn build(ctx: &Context, p: &CamProject) -> Result<CamBuild, SheetError> {
    use rayon::prelude::*;
    let prepared = Prepared::new(ctx, p);
    // A width by the rule, and in the larger lettering where that differs.
    let at_width = |w: ColumnWidth| -> Result<(CamBuild, Option<CamBuild>), SheetError> {
        let rule = build_at(ctx, p, &prepared, w, Lettering::ByRule)?;
        let large = if rule.large_differs { build_at(ctx, p, &prepared, w, Lettering::Large).ok() } else { None };
        Ok((rule, large))
    };
    // The usual width by the rule refuses what the sheet refuses; the other variants are
    // only tried, each composed on rayon's pool.
    let (usual, others) = rayon::join(
        || at_width(COLUMN_WIDTHS[0]),
        || COLUMN_WIDTHS[1..].par_iter().filter_map(|&w| at_width(w).ok()).collect::<Vec<_>>(),
    );
    let (usual, usual_large) = usual?;
    let rest =
        usual_large.into_iter().chain(others.into_iter().flat_map(|(rule, large)| [Some(rule), large]).flatten());
    Ok(choice::kept(ctx, usual, rest))
}

/// How the tables are lettered.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Lettering {
    /// In [`LARGE_TEXT`] where the views keep their scales beside them and the diagrams most
    /// of their height, else in [`CELL_TEXT`].
    ByRule,
    /// In [`LARGE_TEXT`] wherever they fit.
    Large,
}

/// What sheet 3 draws whatever its column's width: the integration, the positions, the
/// notes' tables in both letterings, the fitted profiles and the views' extents, computed
/// once for the widths tried.
struct Prepared {
    integrated: [Integrated; 2],
    errors: (f64, f64),
    phis: Vec<f64>,
    notes: Vec<NoteTable>,
    fitted: profile_view::Pieces,
    /// The notes' tables in [`CELL_TEXT`] and in [`LARGE_TEXT`] lettering.
    small: Lettered,
    large: Lettered,
    nomogram_extent: regions::Extent,
    nomogram_reach: Vec<(Vec2, Vec2)>,
    profile_extent: regions::Extent,
    boundary: nomogram::BoundaryMemo,
}

impl Prepared {
    fn new(ctx: &Context, p: &CamProject) -> Self {
        let lang = ctx.info.language;
        let d = &p.design;
        let integrated = integrate::turn_within(&d.spec.program, DIVISIONS);
        let errors = diagrams::error_percent(d, &integrated);
        let phis = nomogram::positions(d, DIVISIONS);
        let notes = tables::notes(d, &phis, errors, lang, ctx.first_table);
        let (law, rest): (Vec<_>, Vec<_>) = notes.iter().partition(|n| tables::is_law(n));
        // The rise's table and the return's line up (the law's, the profiles').
        let drawn = |ns: &[&NoteTable], h: f64| -> Vec<Table> {
            let mut ts: Vec<Table> = ns.iter().map(|n| Table { text_h: h, ..tables::sheet_table(n, lang) }).collect();
            Table::line_up(&mut ts[..2.min(ns.len())]);
            ts
        };
        let small = Lettered::new(drawn(&law, CELL_TEXT), drawn(&rest, CELL_TEXT));
        let large = Lettered::new(drawn(&law, LARGE_TEXT), drawn(&rest, LARGE_TEXT));
        Prepared {
            nomogram_extent: nomogram::extent(d, &phis),
            nomogram_reach: nomogram::reach(d),
            profile_extent: profile_view::extent(d),
            boundary: nomogram::BoundaryMemo::default(),
            fitted: profile_view::fit(d),
            integrated,
            errors,
            phis,
            notes,
            small,
            large,
        }
    }
}

/// The law's tables and the rest in one lettering, with their sizes measured once.
struct Lettered {
    law: Vec<Table>,
    rest: Vec<Table>,
    law_sizes: Vec<regions::Size>,
    rest_sizes: Vec<regions::Size>,
}

impl Lettered {
    fn new(law: Vec<Table>, rest: Vec<Table>) -> Self {
        Lettered { law_sizes: regions::sizes(&law), rest_sizes: regions::sizes(&rest), law, rest }
    }
}

/// Builds sheet 3 with the diagrams' column at most `width` wide.
fn build_at(
    ctx: &Context,
    p: &CamProject,
    prepared: &Prepared,
    width: ColumnWidth,
    lettering: Lettering,
) -> Result<CamBuild, SheetError> {
    let words = CamWords::new(ctx.info.language);
    let l = words.sheet;
    let d = &p.design;
    let Prepared { integrated, errors, phis, notes, fitted, small, large, .. } = prepared;
    let (integrated, errors, phis) = (integrated.clone(), *errors, phis.as_slice());
    let mut column = plan_column(p, (errors, integrated[0].chords), fitted.deviation, &words, width)?;
    // Besides the steps, the diagrams exactly as tall as leaves the law's tables room under
    // them in either lettering (a step short of that leaves a band empty above the tables).
    let under = |law: &[regions::Size]| column.room - regions::diagrams_above(law, column.plan.width, column.text_h);
    let mut shorter: Vec<f64> =
        SHORTER.iter().copied().chain([under(&small.law_sizes), under(&large.law_sizes)]).collect();
    shorter.retain(|s| *s >= 0.0);
    shorter.sort_by(f64::total_cmp);
    shorter.dedup();
    let plans: Vec<diagrams::Plan> = shorter.iter().map(|&s| shorter_plan(p, &column, s)).collect();
    // The nomogram at the largest GOST scale that fits, unless its labels then find no clean
    // spot (a tall, narrow nomogram beside the profile leaves r_min's label no room): then a
    // GOST scale coarser.
    let mut fine = true;
    let (lay, (law, rest), nm, pv, prof, large_differs) = loop {
        let views = Views {
            nomogram: ViewSize {
                extent: prepared.nomogram_extent,
                reach: prepared.nomogram_reach.clone(),
                heading_w: heading_w(l.nomogram_title()),
                fine,
            },
            profile: ViewSize {
                extent: prepared.profile_extent,
                reach: Vec::new(),
                heading_w: heading_w(l.profile_title()),
                fine: true,
            },
        };
        let arranged = |plan: &diagrams::Plan, t: &Lettered| {
            regions::regions(&views.content((plan, column.text_h), &t.law_sizes, &t.rest_sizes))
        };
        let kept = |a: &Regions, b: &Regions| a.profile_mu <= b.profile_mu && a.nomogram_mu <= b.nomogram_mu;
        // The diagrams as tall as the column allows, unless shorter ones leave the views larger
        // (the nomogram under them, the profile alone on the right at a larger scale): planned
        // for the tables in each lettering.
        let planned = |tables: &Lettered| {
            let tried = plans.iter().map(|plan| (*plan, arranged(plan, tables))).collect();
            let plan = balanced(tried).map_or(column.plan, |(plan, _)| plan);
            (plan, arranged(&plan, tables))
        };
        let (small_plan, on_small) = planned(small);
        let (large_plan, on_large) = planned(large);
        // The tables in 3.5 mm lettering where the views keep their scales beside them and
        // the diagrams most of their height.
        let by_rule = kept(&on_large, &on_small) && large_plan.height >= small_plan.height * LARGE_KEEPS;
        let large_fits = on_large.tables_fit(&large.law_sizes, &large.rest_sizes);
        let lettered_large = (lettering == Lettering::Large || by_rule) && large_fits;
        let large_differs = large_fits && !lettered_large;
        column.plan = if lettered_large { large_plan } else { small_plan };
        let (lay, tables) = if lettered_large { (on_large, large) } else { (on_small, small) };
        let content = views.content((&column.plan, column.text_h), &tables.law_sizes, &tables.rest_sizes);
        let (nomogram_room, profile_room) = lay.label_rooms();
        let mut nm = view_group("nomogram", nomogram_room, l.nomogram_title());
        let mut nl = Labels::new();
        let at = Placement {
            area: view_area(lay.nomogram),
            extent: content.nomogram.at(lay.nomogram_mu),
            mu: lay.nomogram_mu,
        };
        nomogram::draw(&mut nm, (&at, &prepared.boundary), d, phis, &mut nl, &words);
        scale_note(&mut nm, lay.nomogram_mu, None, &words);
        let placed = nl.place(&mut nm, nomogram_room);
        if fine && placed.contains(&false) {
            fine = false;
            continue;
        }
        let mut pv = view_group("profile", profile_room, l.profile_title());
        let mut pl = Labels::new();
        let at =
            Placement { area: view_area(lay.profile), extent: content.profile.at(lay.profile_mu), mu: lay.profile_mu };
        let prof = profile_view::draw(&mut pv, &at, d, fitted, phis, &mut pl, &words);
        scale_note(&mut pv, prof.mu, Some(scale::ratio(prof.mu)), &words);
        pl.place(&mut pv, profile_room);
        break (lay, (tables.law.clone(), tables.rest.clone()), nm, pv, prof, large_differs);
    };
    let (dg, scales) = diagrams_group(&lay, &column, p, &integrated, &words);
    let answers = AnswerKeys::of(&format!("sheet{}", KIND.number), notes);
    let mut measured = segments::diagrams(d, &scales, &integrated, phis, &answers);
    let pivot_drawn = nomogram::draws_pivot(d, prepared.nomogram_extent);
    measured.extend(segments::nomogram(d, (lay.nomogram_mu, pivot_drawn), &answers));
    measured.extend(segments::profile(d, prof.mu, phis, &answers));
    let pressure = lay.pressure.and_then(|r| pressure_view::draw(r, d, phis, l.pressure_title(), &words));
    let mut groups = vec![dg, nm, pv];
    groups.extend(pressure.as_ref().map(|(g, _)| g.clone()));
    groups.extend(table_groups(&lay, law, rest));
    let composition = Composition {
        name: l.sheet_name().to_string(),
        mu_l: prof.mu,
        groups,
        tables: notes.clone(),
        results: serde_json::Value::Null,
        diagnostics: diagrams::squeezed(d, &scales).into_iter().collect(),
        smallest_plan_mm: None,
        segments: measured,
        measured: None,
    };
    Ok(CamBuild {
        composition,
        scales,
        integrated,
        errors,
        nomogram_mu: lay.nomogram_mu,
        profile_mu: prof.mu,
        profile_pieces: prof.pieces,
        profile_deviation: prof.deviation,
        pressure: pressure.map(|(_, scales)| scales),
        large_differs,
    })
}

/// The diagrams' column: the laws' title, the three diagrams, the notes; its region ends
/// under the last note.
fn diagrams_group(
    lay: &Regions,
    column: &Column,
    p: &CamProject,
    integrated: &[Integrated; 2],
    words: &CamWords,
) -> (Group, Scales) {
    let width = lay.diagrams.width() - 4.0;
    let mut dg = Group::new("diagrams", lay.diagrams);
    let (at, lines) = title_lines(&column.title, lay.diagrams);
    let mut y = paragraph(&mut dg, at, &lines, TITLE_H, Anchor::Start);
    // The diagrams spread over what the region leaves under the notes.
    let below = lay.diagrams.y1 - (y + 2.0 + column.plan.height + 4.0 + notes_h(&column.notes, width) + 1.0);
    let area =
        Rect::new(lay.diagrams.x0 + 2.0, y + 2.0, lay.diagrams.x1, y + 2.0 + column.plan.height + below.max(0.0));
    let drawn = diagrams::draw(&mut dg, area, &column.plan, &p.design, integrated, words);
    y = drawn.bottom + 4.0;
    let notes = notes_set(&column.notes, width);
    columns::draw(&mut dg, Point::new(lay.diagrams.x0 + 2.0, y), &notes, CELL_TEXT);
    y += notes.height;
    dg.region = Rect::new(lay.diagrams.x0, lay.diagrams.y0, lay.diagrams.x1, (y + 1.0).max(lay.diagrams.y0 + 10.0));
    (dg, drawn.scales)
}

/// The tables: the law's under the diagrams when the regions keep room there, the rest (or
/// all) in the strip.
fn table_groups(lay: &Regions, law: Vec<Table>, rest: Vec<Table>) -> Vec<Group> {
    match lay.law_tables {
        Some(r) => {
            vec![table::flow("law-tables", law, r, TABLE_GAP), table::flow("tables", rest, lay.tables, TABLE_GAP)]
        }
        None => vec![table::flow("tables", law.into_iter().chain(rest), lay.tables, TABLE_GAP)],
    }
}

impl Sheet for CamSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn table_count(&self) -> u32 {
        tables::TABLE_COUNT
    }

    fn name(&self, lang: crate::drawing::labels::Language) -> String {
        labels::CamLabels::get(lang).sheet_name().to_string()
    }

    fn compose(&self, ctx: &Context) -> Result<Composition, SheetError> {
        let b = build(ctx, self.project)?;
        let results = results::section(self.project, &b);
        Ok(Composition { results, ..b.composition })
    }
}
