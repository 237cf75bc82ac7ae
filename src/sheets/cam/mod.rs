//! Sheet 3: the cam. The law's three diagrams by graphical integration on the left with the
//! notes under them, the nomogram of the minimum radius in the middle, the profile on the
//! right, the tables below those two, the title block.

mod diagrams;
pub mod labels;
mod nomogram;
mod profile_view;

pub use diagrams::Scales;
pub use profile_view::{MAX_PIECES, PROFILE_TOL};

use super::{COURSE, Context, Sheet, SheetError, SheetKind, SheetOutput};
use crate::cams::follower::Follower;
use crate::cams::integrate::{self, Integrated};
use crate::cams::laws::Law;
use crate::cams::{CamWarning, Design};
use crate::drawing::fmt;
use crate::drawing::frame::{self, A1_H, A1_W};
use crate::drawing::labels::{Common, Language};
use crate::drawing::layout::{self, Layout};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Scene, Text};
use crate::drawing::table::{self, CELL_TEXT, Table};
use crate::drawing::text::{LabelText, block_height, paragraph, wrap};
use crate::project::{CamProject, Project};
use crate::report::{self, NoteTable, NumTable};
use kurbo::{Point, Rect, Vec2};
use labels::CamLabels;

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
    pub scene: Scene,
    pub scales: Scales,
    pub integrated: [Integrated; 2],
    /// The integration's errors, percent of the lift and of the largest ds/dφ.
    pub errors: (f64, f64),
    pub nomogram_mu: f64,
    pub profile_mu: f64,
    pub profile_pieces: usize,
    pub profile_deviation: f64,
    pub layout: Layout,
    pub tables: Vec<(&'static str, NumTable)>,
}

/// The sheet inside its frame, with a 4 mm margin.
const SHEET: Rect = Rect { x0: 24.0, y0: 9.0, x1: 832.0, y1: 585.0 };
/// The diagrams' column is at most this wide, mm.
const LEFT_MAX: f64 = 320.0;
/// Between regions, mm.
const GAP: f64 = 6.0;
/// Room a view needs besides its drawing: its title and its scale above, its margins.
const VIEW_TOP: f64 = 15.0;
const VIEW_BOTTOM: f64 = 3.0;
const VIEW_SIDES: f64 = 8.0;
/// The nomogram's drawing is at least this long on its longer side when the profile can
/// be drawn smaller to allow it, mm.
const NOMOGRAM_MIN_MM: f64 = 130.0;

/// The regions of the sheet and the views' scales, chosen by content.
struct Layout3 {
    diagrams: Rect,
    law_tables: Option<Rect>,
    tables: Rect,
    nomogram: Rect,
    profile: Rect,
    nomogram_mu: f64,
    profile_mu: f64,
}

/// Builds sheet 3.
pub fn build(ctx: &Context, p: &CamProject) -> Result<CamBuild, SheetError> {
    let lang = ctx.info.language;
    let (l, c) = (CamLabels::get(lang), Common::get(lang));
    let d = &p.design;
    let mut fr = Group::new("frame", Rect::new(0.0, 0.0, A1_W, A1_H));
    frame::frame(&mut fr);
    let integrated = integrate::turn(&d.spec.program, DIVISIONS);
    let errors = diagrams::error_percent(d, &integrated);
    let phis = nomogram::positions(d, DIVISIONS);
    let tables = note_tables_of(d, &phis, errors);

    // The left column: the law's name, the diagrams, the notes, the law's tables if they fit.
    let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
    let title = if p.laws.0 == p.laws.1 {
        let name = law_name(p, &p.laws.0, l, lang);
        if rocker { l.laws_title_rocker(&name) } else { l.laws_title(&name) }
    } else {
        l.laws_title_two(&law_name(p, &p.laws.0, l, lang), &law_name(p, &p.laws.1, l, lang))
    };
    let fitted = profile_view::fit(d);
    let notes = sheet_notes(p, errors, fitted.deviation, l, lang);
    let title_lines = wrap(&title, 3.5, LEFT_MAX - 4.0);
    let notes_h =
        |w: f64| notes.iter().map(|n| block_height(wrap(n, CELL_TEXT, w).len(), CELL_TEXT) + 1.0).sum::<f64>();
    let head = 5.0 + block_height(title_lines.len(), 3.5) + 2.0;
    let plan = diagrams::plan(d, LEFT_MAX - 4.0, SHEET.height() - head - notes_h(LEFT_MAX - 4.0) - 8.0);
    let drawn_tables = |ts: Vec<&(&'static str, NumTable)>| -> Vec<Table> {
        ts.into_iter().map(|(s, t)| sheet_table(s, t, l, c, lang)).collect()
    };
    let (law, rest): (Vec<_>, Vec<_>) = tables.iter().partition(|(s, _)| s.starts_with("law"));
    let (law, rest) = (drawn_tables(law), drawn_tables(rest));
    let extents = (nomogram::extent(d, &phis), profile_view::extent(d));
    let lay = layout(extents, &plan, head + notes_h(plan.width.max(200.0)), &law, &rest);
    let width = lay.diagrams.width() - 4.0;

    let mut dg = Group::new("diagrams", lay.diagrams);
    let mut y = paragraph(
        &mut dg,
        Point::new(lay.diagrams.x0 + 2.0, lay.diagrams.y0 + 5.0),
        &wrap(&title, 3.5, width),
        3.5,
        Anchor::Start,
    );
    let area = Rect::new(lay.diagrams.x0 + 2.0, y + 2.0, lay.diagrams.x1, y + 2.0 + plan.height);
    let drawn = diagrams::draw(&mut dg, area, &plan, d, &integrated, l, c, lang);
    y = drawn.bottom + 4.0;
    for n in &notes {
        y = paragraph(
            &mut dg,
            Point::new(lay.diagrams.x0 + 2.0, y),
            &wrap(n, CELL_TEXT, width),
            CELL_TEXT,
            Anchor::Start,
        ) + 1.0;
    }
    dg.region = Rect::new(lay.diagrams.x0, lay.diagrams.y0, lay.diagrams.x1, (y + 1.0).max(lay.diagrams.y0 + 10.0));

    // The nomogram and the profile.
    let mut nm = Group::new("nomogram", lay.nomogram);
    view_title(&mut nm, l.nomogram_title());
    let mut nl = Labels::new();
    nomogram::draw(&mut nm, view_area(lay.nomogram), extents.0, lay.nomogram_mu, d, &phis, &mut nl, l, c, lang);
    scale_note(&mut nm, lay.nomogram_mu, None, c, lang);
    nl.place(&mut nm, lay.nomogram);

    let mut pv = Group::new("profile", lay.profile);
    view_title(&mut pv, l.profile_title());
    let mut pl = Labels::new();
    let prof = profile_view::draw(
        &mut pv,
        view_area(lay.profile),
        extents.1,
        lay.profile_mu,
        d,
        &fitted,
        &phis,
        &mut pl,
        l,
        c,
        lang,
    );
    scale_note(&mut pv, prof.mu, Some(scale::ratio(prof.mu)), c, lang);
    pl.place(&mut pv, lay.profile);

    // The tables.
    let mut table_groups = vec![];
    match lay.law_tables {
        Some(r) => {
            table_groups.push(table::flow("law-tables", law, r, 3.0));
            table_groups.push(table::flow("tables", rest, lay.tables, 3.0));
        }
        None => table_groups.push(table::flow("tables", law.into_iter().chain(rest), lay.tables, 3.0)),
    }

    let sheet_name = l.sheet_name();
    let tb = ctx.title_block(c, sheet_name, &fmt::localise(&scale::ratio(prof.mu), lang), KIND.number)?;
    let mut groups = vec![fr, dg, nm, pv];
    groups.extend(table_groups);
    groups.push(tb);
    let scene = Scene { width: A1_W, height: A1_H, title: format!("{} — {sheet_name}", ctx.info.title()), groups };
    let layout = layout::measure(&scene);
    Ok(CamBuild {
        scene,
        scales: drawn.scales,
        integrated,
        errors,
        nomogram_mu: lay.nomogram_mu,
        profile_mu: prof.mu,
        profile_pieces: prof.pieces,
        profile_deviation: prof.deviation,
        layout,
        tables,
    })
}

/// A view's title at its region's top left.
fn view_title(g: &mut Group, title: &str) {
    let r = g.region;
    g.text(Text::new(Point::new(r.x0 + 2.0, r.y0 + 5.0), title, 3.5, Anchor::Start));
}

/// Where a view draws: its region less its title, scale and margins.
fn view_area(r: Rect) -> Rect {
    Rect::new(r.x0 + VIEW_SIDES / 2.0, r.y0 + VIEW_TOP, r.x1 - VIEW_SIDES / 2.0, r.y1 - VIEW_BOTTOM)
}

/// "μ_l = … m/mm" (and the GOST ratio) under a view's title: below the view it read as the
/// scale of the view under it.
fn scale_note(g: &mut Group, mu: f64, ratio: Option<String>, c: &Common, lang: Language) {
    let mut tail = format!(" = {} {}", fmt::trimmed(mu, lang), c.unit_m_per_mm());
    if let Some(r) = ratio {
        tail.push_str(&format!(" ({})", fmt::localise(&r, lang)));
    }
    let r = g.region;
    LabelText::new("μ", "l").with_tail(tail).draw(g, Point::new(r.x0 + 2.0, r.y0 + 10.5), 2.5, Anchor::Start);
}

/// The sheet's regions by content, for the views' boxes `(nomogram, profile)` (metres). The
/// diagrams' column is as wide as its plan; the tables
/// not kept in that column go to a strip left of the title block, as low as fits. Three
/// arrangements of the views are tried, and the one with the larger profile wins (then the
/// larger nomogram, then the third):
/// - the nomogram under the notes in the diagrams' column, the profile alone on the right;
/// - both on the right side by side, the profile at the largest GOST scale that leaves the
///   nomogram [`NOMOGRAM_MIN_MM`], the law's tables under the notes when they fit;
/// - both on the right, the nomogram under the profile, the same way.
fn layout(
    (n_ext, p_ext): ((Vec2, Vec2), (Vec2, Vec2)),
    plan: &diagrams::Plan,
    text_h: f64,
    law: &[Table],
    rest: &[Table],
) -> Layout3 {
    let tb = frame::title_block_rect();
    let left_w = plan.width + 4.0;
    let column_used = text_h + plan.height + 10.0;
    let right_x = SHEET.x0 + left_w + GAP;
    let sizes = |ts: &[Table]| ts.iter().map(Table::size).collect::<Vec<_>>();
    let strip = |sizes: &[(f64, f64)]| {
        let h = table::flow_height(sizes, tb.x0 - GAP - right_x, 3.0).unwrap_or(SHEET.height() / 2.0);
        Rect::new(right_x, SHEET.y1 - h, tb.x0 - GAP, SHEET.y1)
    };
    let views_above = |tables: Rect| Rect::new(right_x, SHEET.y0, SHEET.x1, tables.y0.min(tb.y0) - GAP);
    let all: Vec<(f64, f64)> = sizes(law).into_iter().chain(sizes(rest)).collect();

    // The nomogram in the diagrams' column, the profile alone on the right.
    let below = {
        let tables = strip(&all);
        let views = views_above(tables);
        let column = Rect::new(SHEET.x0, SHEET.y0 + column_used + GAP, SHEET.x0 + left_w, SHEET.y1);
        let n = fit_view(n_ext, column, false).filter(|(mu, _)| longer_side(n_ext, *mu) >= NOMOGRAM_MIN_MM * 0.6);
        let p = fit_view(p_ext, views, true);
        n.zip(p).map(|((nomogram_mu, nomogram), (profile_mu, profile))| Layout3 {
            diagrams: Rect::new(SHEET.x0, SHEET.y0, SHEET.x0 + left_w, nomogram.y0 - GAP),
            law_tables: None,
            tables,
            nomogram,
            profile: centred_across(profile, views),
            nomogram_mu,
            profile_mu,
        })
    };

    // Both on the right.
    let law_h: f64 = sizes(law).iter().map(|s| s.1 + 3.0).sum();
    let law_fits = column_used + law_h <= SHEET.height() && sizes(law).iter().all(|s| s.0 <= left_w);
    let rest_sizes = sizes(rest);
    let tables = strip(if law_fits { &rest_sizes } else { &all });
    let views = views_above(tables);
    let law_tables = law_fits.then(|| Rect::new(SHEET.x0, SHEET.y1 - law_h, SHEET.x0 + left_w, SHEET.y1));
    let diagrams = Rect::new(SHEET.x0, SHEET.y0, SHEET.x0 + left_w, law_tables.map_or(SHEET.y1, |r| r.y0 - GAP));
    let beside = profile_and_nomogram((p_ext, n_ext), views, |profile| {
        Rect::new(views.x0, views.y0, views.x1 - profile.width() - GAP, views.y1)
    });
    let beside = beside.map(|(profile_mu, profile, nomogram_mu, nomogram)| {
        // The room left over, shared out between and round the two.
        let slack = ((views.width() - profile.width() - nomogram.width() - GAP) / 3.0).max(0.0);
        let nomogram = nomogram + Vec2::new(slack, 0.0);
        let px = (nomogram.x1 + GAP + slack).min(views.x1 - profile.width());
        let profile = profile + Vec2::new(px - profile.x0, 0.0);
        Layout3 { diagrams, law_tables, tables, nomogram, profile, nomogram_mu, profile_mu }
    });
    // The nomogram under the profile on the right (a wide, low profile: a rocker's pivots
    // on their arc above the cam).
    let stacked = profile_and_nomogram((p_ext, n_ext), views, |profile| {
        Rect::new(views.x0, profile.y1 + GAP, views.x1, views.y1)
    })
    .map(|(profile_mu, profile, nomogram_mu, nomogram)| Layout3 {
        diagrams,
        law_tables,
        tables,
        nomogram: centred_across(nomogram, views),
        profile: centred_across(profile, views),
        nomogram_mu,
        profile_mu,
    });
    // The larger profile wins, then the larger nomogram; on a tie, the views together on the
    // right (under a wide, low profile the sheet's middle is otherwise left empty).
    let better =
        |a: &Layout3, b: &Layout3| (a.profile_mu, a.nomogram_mu) < (b.profile_mu * 0.999, b.nomogram_mu * 0.999);
    let best = [stacked, below, beside].into_iter().flatten().reduce(|a, b| if better(&b, &a) { b } else { a });
    match best {
        Some(a) => a,
        // Nothing fits at any scale (an extent of no size): the views at 1:1 side by side.
        None => {
            let half = views.width() / 2.0;
            Layout3 {
                diagrams,
                law_tables,
                tables,
                nomogram: Rect::new(views.x0, views.y0, views.x0 + half - GAP, views.y1),
                profile: Rect::new(views.x0 + half, views.y0, views.x1, views.y1),
                nomogram_mu: 0.001,
                profile_mu: 0.001,
            }
        }
    }
}

/// The profile at the top left of `views` at the largest GOST scale that leaves the
/// nomogram [`NOMOGRAM_MIN_MM`] in the room `rest(profile)` (else the largest profile with
/// any nomogram): `(μ_profile, profile, μ_nomogram, nomogram)`.
fn profile_and_nomogram(
    (p_ext, n_ext): ((Vec2, Vec2), (Vec2, Vec2)),
    views: Rect,
    rest: impl Fn(Rect) -> Rect,
) -> Option<(f64, Rect, f64, Rect)> {
    let mut found = None;
    for mu_p in scale::length_scales() {
        let Some((_, profile)) = fit_at(p_ext, views, mu_p) else { continue };
        let Some((mu_n, nomogram)) = fit_view(n_ext, rest(profile), false) else { continue };
        let enough = longer_side(n_ext, mu_n) >= NOMOGRAM_MIN_MM;
        if found.is_none() || enough {
            found = Some((mu_p, profile, mu_n, nomogram));
        }
        if enough {
            break;
        }
    }
    found
}

/// The longer side of a view's drawing at `mu`, mm.
fn longer_side((lo, hi): (Vec2, Vec2), mu: f64) -> f64 {
    ((hi.x - lo.x) / mu).max((hi.y - lo.y) / mu)
}

/// The region a view of the box `ext` (metres) takes at `mu` at the top left of `room`, if it
/// fits there.
fn fit_at((lo, hi): (Vec2, Vec2), room: Rect, mu: f64) -> Option<(f64, Rect)> {
    let (w, h) = ((hi.x - lo.x) / mu + VIEW_SIDES, (hi.y - lo.y) / mu + VIEW_TOP + VIEW_BOTTOM);
    (w <= room.width() && h <= room.height()).then(|| (mu, Rect::new(room.x0, room.y0, room.x0 + w, room.y0 + h)))
}

/// The largest scale at which a view of the box `ext` fits `room` — a GOST one, or of the
/// round series — and its region there.
fn fit_view(ext: (Vec2, Vec2), room: Rect, gost: bool) -> Option<(f64, Rect)> {
    let (lo, hi) = ext;
    let need =
        ((hi.x - lo.x) / (room.width() - VIEW_SIDES)).max((hi.y - lo.y) / (room.height() - VIEW_TOP - VIEW_BOTTOM));
    if !(need.is_finite() && need > 0.0) {
        return None;
    }
    let mu = if gost { scale::length_scale(need) } else { scale::round_up(need) };
    fit_at(ext, room, mu)
}

/// `r` moved to the middle of `within` across.
fn centred_across(r: Rect, within: Rect) -> Rect {
    r + Vec2::new(within.x0 + (within.width() - r.width()) / 2.0 - r.x0, 0.0)
}

/// The notes under the diagrams: the phases, the integration, the nomogram's and the
/// profile's accuracy, the roller, the user's assumptions.
fn sheet_notes(p: &CamProject, errors: (f64, f64), deviation: f64, l: &CamLabels, lang: Language) -> Vec<String> {
    let d = &p.design;
    let pr = &d.spec.program;
    // Whole degrees as the file gives them (70°, not 70,00°).
    let deg = |x: f64| fmt::trimmed(x.to_degrees(), lang);
    let (kind, q, dq) = match d.spec.follower {
        Follower::Translating => (l.follower_translating(), "s", "ds/dφ"),
        Follower::Rocker { .. } => (l.follower_rocker(), "β", "dβ/dφ"),
    };
    let mut out = vec![
        format!(
            "{kind}. {}",
            l.phases(&deg(pr.rise), &deg(pr.far_dwell), &deg(pr.ret), &deg(pr.rise + pr.far_dwell + pr.ret))
        ),
        l.integration_note(&DIVISIONS.to_string(), q, dq, &fmt::value(errors.0, lang), &fmt::value(errors.1, lang)),
        l.nomogram_note(&allowed_angles(d, l, lang)),
    ];
    if d.roller == 0.0 {
        let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
        out.push(if rocker { l.knife_note_rocker() } else { l.knife_note() }.to_string());
    } else {
        out.push(l.profile_note(&fmt::value(deviation * 1e6, lang)));
    }
    for w in &d.warnings {
        if let CamWarning::RollerBelowCourse { r, rho_min, .. } = w {
            out.push(l.roller_reduced(&fmt::value(r * 1e3, lang), &fmt::value(rho_min * 1e3, lang)));
        }
    }
    for (k, law) in [&p.laws.0, &p.laws.1].into_iter().enumerate() {
        if let Law::Custom(c) = law
            && (k == 0 || p.laws.0 != p.laws.1)
        {
            let corners: Vec<String> =
                c.corners().map(|(x, a)| format!("({}; {})", fmt::value(x, lang), fmt::value(a, lang))).collect();
            let mut note = l.law_custom_note(&law_name(p, law, l, lang), &corners.join(", "));
            // The return runs the law backwards: its acceleration analog has the opposite sign.
            if k == 1 || p.laws.0 == p.laws.1 {
                note.push_str(l.law_custom_return());
            }
            out.push(note);
        }
    }
    out.extend(p.assumptions.iter().map(|a| a.get(lang).to_string()));
    out
}

/// The allowed pressure angle as the note states it: one value, or each phase's.
fn allowed_angles(d: &Design, l: &CamLabels, lang: Language) -> String {
    let deg = |x: f64| format!("{}°", fmt::value(x.to_degrees(), lang));
    let a = &d.spec.allowed;
    if a.rise == a.ret { deg(a.rise) } else { l.angles_two(&deg(a.rise), &deg(a.ret)) }
}

/// A law's name on the sheet: the built-in law's in the sheet's language; for a law of the
/// project's table, the name the file gives, else the replaced law's, else its key.
fn law_name(p: &CamProject, law: &Law, l: &CamLabels, lang: Language) -> String {
    match law {
        Law::Standard(s) => l.law(*s).to_string(),
        Law::Custom(c) => match p.law_names.iter().find(|(k, _)| k == c.key()) {
            Some((_, name)) => name.get(lang).to_string(),
            None => c.replaces().map_or_else(|| c.key().to_string(), |s| l.law(s).to_string()),
        },
    }
}

/// The note's tables as numbers, by file stem.
fn note_tables_of(d: &Design, phis: &[f64], errors: (f64, f64)) -> Vec<(&'static str, NumTable)> {
    let n = DIVISIONS + 1;
    let (rise, ret) = phis.split_at(n);
    vec![
        ("law-rise", report::cam::law(d, "law-rise", 0, rise)),
        ("law-return", report::cam::law(d, "law-return", n, ret)),
        ("profile-rise", report::cam::profile(d, "profile-rise", 0, rise)),
        ("profile-return", report::cam::profile(d, "profile-return", n, ret)),
        ("results", report::cam::results(d, errors)),
    ]
}

fn table_title<'a>(stem: &str, l: &'a CamLabels) -> &'a str {
    match stem {
        "law-rise" | "law-return" => l.law_table(),
        "profile-rise" | "profile-return" => l.profile_table(),
        _ => l.results_table(),
    }
}

fn sheet_table(stem: &str, t: &NumTable, l: &CamLabels, c: &Common, lang: Language) -> Table {
    let rows: Vec<(LabelText, Vec<String>)> = t
        .rows
        .iter()
        .map(|r| {
            let mut label = LabelText::new(r.symbol.clone(), l.sub(&r.sub));
            let unit = c.si_unit(&r.unit);
            if !unit.is_empty() {
                label.tail = format!(", {unit}");
            }
            (label, r.values.iter().map(|&v| fmt::value(v, lang)).collect())
        })
        .collect();
    let label_w = rows.iter().map(|(x, _)| x.width(CELL_TEXT) + 4.0).fold(14.0, f64::max);
    // The return's half may flow into another column: it names itself as the continuation.
    let title = table_title(stem, l);
    Table {
        title: if stem.ends_with("-return") { table::continued_title(title, c.continued()) } else { title.to_string() },
        header: if stem == "results" { vec![c.value().into()] } else { t.columns.clone() },
        rows,
        label_w,
        cell_w: 12.0,
        corner: if stem == "results" { c.quantity().into() } else { c.position_col().into() },
    }
}

impl CamBuild {
    /// The note's tables with titles, headings and units in the sheet's language.
    pub fn note_tables(&self, lang: Language) -> Vec<NoteTable> {
        let (l, c) = (CamLabels::get(lang), Common::get(lang));
        self.tables
            .iter()
            .map(|(stem, t)| NoteTable {
                stem,
                title: table_title(stem, l).to_string(),
                headings: [c.quantity().into(), c.unit().into()],
                units: t.rows.iter().map(|r| c.si_unit(&r.unit).to_string()).collect(),
                table: NumTable {
                    rows: t.rows.iter().map(|r| report::Row { sub: l.sub(&r.sub).to_string(), ..r.clone() }).collect(),
                    ..t.clone()
                },
                column_titles: if *stem == "results" { vec![c.value().into()] } else { vec![] },
                decimal_comma: lang != Language::En,
                whole_numbers: false,
            })
            .collect()
    }
}

impl Sheet for CamSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn build(&self, ctx: &Context) -> Result<SheetOutput, SheetError> {
        let b = build(ctx, self.project)?;
        let diagnostics: Vec<String> = b.layout.problems.iter().map(|p| format!("layout: {p}")).collect();
        Ok(SheetOutput {
            number: KIND.number,
            tables: b.note_tables(ctx.info.language),
            results: results(self.project, &b),
            scene: b.scene,
            diagnostics,
        })
    }
}

/// The sheet's section of `results.json` (SI; angles in degrees with `_deg`).
pub fn results(p: &CamProject, b: &CamBuild) -> serde_json::Value {
    use serde_json::json;
    let d = &p.design;
    let pr = &d.spec.program;
    let n = 4 * 360;
    let law: Vec<_> = (0..n)
        .map(|k| {
            let phi = std::f64::consts::TAU * k as f64 / n as f64;
            let x = pr.at(phi);
            json!([phi.to_degrees(), x.s, x.ds, x.dds])
        })
        .collect();
    let profile: Vec<_> = (0..360)
        .map(|k| {
            let phi = (k as f64).to_radians();
            let pt = d.profile.pitch(phi).p;
            let w = if d.roller > 0.0 { d.profile.working(d.roller, phi).0 } else { pt };
            let (pt, w) = (d.spec.sense.apply(pt), d.spec.sense.apply(w));
            json!([k, pt.x, pt.y, w.x, w.y])
        })
        .collect();
    let err = b.integrated.each_ref().map(|i| i.error(pr));
    let closure = integrate::closure(&b.integrated);
    let mut out = json!({
        "follower": match d.spec.follower { Follower::Translating => "translating", Follower::Rocker { .. } => "rocker" },
        "laws": [pr.rise_law.key(), pr.return_law.key()],
        "sense": d.spec.sense,
        "phases_deg": {"rise": pr.rise.to_degrees(), "far_dwell": pr.far_dwell.to_degrees(), "return": pr.ret.to_degrees()},
        "lift": pr.lift,
        "r_min": d.centre.r_min,
        "centre": [d.spec.sense.apply(d.centre.o).x, d.centre.o.y],
        "roller_radius": d.roller,
        "roller_auto": p.roller_auto,
        "pitch_min_radius_of_curvature": d.rho_min,
        "pitch_min_radius_of_curvature_at_deg": d.rho_min_phi.to_degrees(),
        "max_pressure_angle_deg": {"rise": d.max_pressure[0].0.to_degrees(), "return": d.max_pressure[1].0.to_degrees()},
        "allowed_pressure_angle_deg": {"rise": d.spec.allowed.rise.to_degrees(), "return": d.spec.allowed.ret.to_degrees()},
        "scales": b.scales,
        "nomogram_mu": b.nomogram_mu,
        "profile_mu_l": b.profile_mu,
        "profile_pieces": b.profile_pieces,
        "profile_deviation": b.profile_deviation,
        "integration_error": {"divisions": DIVISIONS, "rise": err[0], "return": err[1], "s_percent_of_lift": b.errors.0, "ds_percent_of_peak": b.errors.1, "closure_s": closure.0, "closure_ds": closure.1},
        "law_columns": ["phi_deg", "s", "ds", "dds"],
        "law": law,
        "profile_columns": ["phi_deg", "pitch_x", "pitch_y", "working_x", "working_y"],
        "profile": profile,
        "layout": {
            "texts_crossed": b.layout.texts_crossed,
            "text_overlaps": b.layout.text_overlaps,
            "outside_region": b.layout.outside_region,
            "problems": b.layout.problems.iter().take(20).collect::<Vec<_>>(),
        },
    });
    if let Some(e) = d.offset() {
        out["offset"] = json!(e);
        out["offset_auto"] = json!(p.offset_auto);
    }
    if let (Some(a), Some(psi)) = (d.centre_distance(), d.rocker_start()) {
        out["centre_distance"] = json!(a);
        out["rocker_start_deg"] = json!(psi.to_degrees());
    }
    out
}
