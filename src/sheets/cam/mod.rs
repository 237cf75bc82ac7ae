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
use crate::cams::radius::Phase;
use crate::cams::{CamWarning, Design};
use crate::drawing::fmt;
use crate::drawing::frame::{self, A1_H, A1_W};
use crate::drawing::labels::{Common, Language};
use crate::drawing::layout::{self, Layout};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Scene, Text};
use crate::drawing::table::{CELL_TEXT, Table};
use crate::drawing::text::{LabelText, paragraph, wrap};
use crate::project::{CamProject, Project};
use crate::report::{self, NoteTable, NumTable};
use kurbo::{Point, Rect};
use labels::CamLabels;

/// This sheet's place in the course.
pub const KIND: SheetKind = COURSE[2];

/// Divisions of each phase: the numbered positions and the chord integration.
pub const DIVISIONS: usize = 8;

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

const DIAGRAMS: Rect = Rect { x0: 24.0, y0: 9.0, x1: 300.0, y1: 585.0 };
const DIAGRAMS_BOTTOM: f64 = DIAGRAMS.y1 - NOTES_AND_TABLES;
const NOMOGRAM: Rect = Rect { x0: 306.0, y0: 9.0, x1: 560.0, y1: 330.0 };
const PROFILE: Rect = Rect { x0: 566.0, y0: 9.0, x1: 832.0, y1: 330.0 };
const TABLES: Rect = Rect { x0: 306.0, y0: 336.0, x1: 832.0, y1: 530.0 };
/// The left column's room below the diagrams: the notes and the law's tables.
const NOTES_AND_TABLES: f64 = 150.0;

/// Builds sheet 3.
pub fn build(ctx: &Context, p: &CamProject) -> Result<CamBuild, SheetError> {
    let lang = ctx.info.language;
    let (l, c) = (CamLabels::get(lang), Common::get(lang));
    let d = &p.design;
    let mut fr = Group::new("frame", Rect::new(0.0, 0.0, A1_W, A1_H));
    frame::frame(&mut fr);
    let integrated = Phase::BOTH.map(|ph| integrate::chords(&d.spec.program, ph, DIVISIONS));
    let errors = diagrams::error_percent(d, &integrated);

    // The nomogram and the profile.
    let phis = nomogram::positions(d, DIVISIONS);
    let mut nm = Group::new("nomogram", NOMOGRAM);
    nm.text(Text::new(Point::new(NOMOGRAM.x0 + 2.0, NOMOGRAM.y0 + 5.0), l.nomogram_title(), 3.5, Anchor::Start));
    let mut nl = Labels::new();
    let n_area = Rect::new(NOMOGRAM.x0 + 4.0, NOMOGRAM.y0 + 10.0, NOMOGRAM.x1 - 4.0, NOMOGRAM.y1 - 6.0);
    let nomogram_mu = nomogram::draw(&mut nm, n_area, d, &phis, &mut nl, l, c, lang);
    nl.place(&mut nm, NOMOGRAM);

    let mut pv = Group::new("profile", PROFILE);
    pv.text(Text::new(Point::new(PROFILE.x0 + 2.0, PROFILE.y0 + 5.0), l.profile_title(), 3.5, Anchor::Start));
    let mut pl = Labels::new();
    let p_area = Rect::new(PROFILE.x0 + 4.0, PROFILE.y0 + 10.0, PROFILE.x1 - 4.0, PROFILE.y1 - 8.0);
    let prof = profile_view::draw(&mut pv, p_area, d, &phis, &mut pl, l, c, lang);
    let tail = format!(
        " = {} {} ({})",
        fmt::trimmed(prof.mu, lang),
        c.unit_m_per_mm(),
        fmt::localise(&scale::ratio(prof.mu), lang)
    );
    LabelText::new("μ", "l").with_tail(tail).draw(
        &mut pv,
        Point::new(PROFILE.x0 + 2.0, PROFILE.y1 - 1.0),
        2.5,
        Anchor::Start,
    );
    pl.place(&mut pv, PROFILE);

    // The diagrams, with the law's name above and the notes below.
    let mut dg = Group::new("diagrams", DIAGRAMS);
    let title = if p.laws.0 == p.laws.1 {
        l.laws_title(l.law(p.laws.0))
    } else {
        l.laws_title_two(l.law(p.laws.0), l.law(p.laws.1))
    };
    let width = DIAGRAMS.width() - 4.0;
    let mut y = paragraph(
        &mut dg,
        Point::new(DIAGRAMS.x0 + 2.0, DIAGRAMS.y0 + 5.0),
        &wrap(&title, 3.5, width),
        3.5,
        Anchor::Start,
    );
    let area = Rect::new(DIAGRAMS.x0 + 2.0, y + 2.0, DIAGRAMS.x1 - 14.0, DIAGRAMS_BOTTOM);
    let drawn = diagrams::draw(&mut dg, area, d, &integrated, l, c, lang);
    y = drawn.bottom + 4.0;
    for n in sheet_notes(p, errors, prof.deviation, l, lang) {
        y = paragraph(&mut dg, Point::new(DIAGRAMS.x0 + 2.0, y), &wrap(&n, CELL_TEXT, width), CELL_TEXT, Anchor::Start)
            + 1.0;
    }
    // The group ends with its notes; the law's tables may follow in the column.
    dg.region = Rect::new(DIAGRAMS.x0, DIAGRAMS.y0, DIAGRAMS.x1, y + 1.0);

    // The tables: the law's under the notes when they fit there, the rest on the right.
    let tables = note_tables_of(d, &phis, errors);
    let left = Rect::new(DIAGRAMS.x0 + 2.0, y + 3.0, DIAGRAMS.x1, DIAGRAMS.y1);
    let (law, rest): (Vec<_>, Vec<_>) = tables.iter().cloned().partition(|(s, _)| s.starts_with("law"));
    let law_h: f64 = law.iter().map(|(s, t)| sheet_table(s, t, l, c, lang).size().1 + 3.0).sum();
    let table_groups = if law_h <= left.height() {
        let mut g = tables_group(&law, left, l, c, lang);
        g.id = "law-tables".into();
        vec![g, tables_group(&rest, TABLES, l, c, lang)]
    } else {
        vec![tables_group(&tables, TABLES, l, c, lang)]
    };

    let sheet_name = l.sheet_name();
    let tb = ctx.title_block(c, sheet_name, &fmt::localise(&scale::ratio(prof.mu), lang), KIND.number)?;
    let mut groups = vec![fr, dg, nm, pv];
    groups.extend(table_groups);
    groups.push(tb);
    let scene = Scene { width: A1_W, height: A1_H, title: format!("{} — {sheet_name}", ctx.info.title), groups };
    let layout = layout::measure(&scene);
    Ok(CamBuild {
        scene,
        scales: drawn.scales,
        integrated,
        errors,
        nomogram_mu,
        profile_mu: prof.mu,
        profile_pieces: prof.pieces,
        profile_deviation: prof.deviation,
        layout,
        tables,
    })
}

/// The notes under the diagrams: the phases, the integration, the nomogram's and the
/// profile's accuracy, the roller, the user's assumptions.
fn sheet_notes(p: &CamProject, errors: (f64, f64), deviation: f64, l: &CamLabels, lang: Language) -> Vec<String> {
    let d = &p.design;
    let pr = &d.spec.program;
    let deg = |x: f64| fmt::value(x.to_degrees(), lang);
    let (kind, q, dq) = match d.spec.follower {
        Follower::Translating => (l.follower_translating(), "s", "ds/dφ"),
        Follower::Rocker { .. } => (l.follower_rocker(), "β", "dβ/dφ"),
    };
    let mut out = vec![
        format!(
            "{kind}; {}",
            l.phases(&deg(pr.rise), &deg(pr.far_dwell), &deg(pr.ret), &deg(pr.rise + pr.far_dwell + pr.ret))
        ),
        l.integration_note(&DIVISIONS.to_string(), q, dq, &fmt::value(errors.0, lang), &fmt::value(errors.1, lang)),
        l.nomogram_note(&deg(d.spec.allowed.rise.min(d.spec.allowed.ret))),
    ];
    if d.roller == 0.0 {
        out.push(l.knife_note().to_string());
    } else {
        out.push(l.profile_note(&fmt::value(deviation * 1e6, lang)));
    }
    for w in &d.warnings {
        if let CamWarning::RollerBelowCourse { r, rho_min, .. } = w {
            out.push(l.roller_reduced(&fmt::value(r * 1e3, lang), &fmt::value(rho_min * 1e3, lang)));
        }
    }
    out.extend(p.assumptions.iter().cloned());
    out
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

/// Draws the tables in `region`, in columns left to right.
fn tables_group(tables: &[(&'static str, NumTable)], region: Rect, l: &CamLabels, c: &Common, lang: Language) -> Group {
    let drawn = tables.iter().map(|(stem, t)| sheet_table(stem, t, l, c, lang));
    crate::drawing::table::flow("tables", drawn, region, 3.0)
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
    let second = stem.ends_with("-return");
    Table {
        title: if second { String::new() } else { table_title(stem, l).to_string() },
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
        "integration_error": {"divisions": DIVISIONS, "rise": err[0], "return": err[1], "s_percent_of_lift": b.errors.0, "ds_percent_of_peak": b.errors.1},
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
