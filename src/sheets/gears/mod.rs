//! Sheet 2: the gears. The external pair's mesh on the left half (three exact teeth per
//! wheel at a GOST scale making the tooth taller than 50 mm), the planetary stage's two
//! views and the tables on the right, the notes and the title block.

pub mod labels;
mod mesh_view;
mod planetary_view;

pub use mesh_view::{INVOLUTE_PIECES, MeshDrawn};

use super::{COURSE, Context, Sheet, SheetError, SheetKind, SheetOutput};
use crate::drawing::fmt;
use crate::drawing::frame::{self, A1_H, A1_W};
use crate::drawing::labels::{Common, Language};
use crate::drawing::layout::{self, Layout};
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Scene, Text};
use crate::drawing::table::{CELL_TEXT, Table};
use crate::drawing::text::{LabelText, paragraph, wrap};
use crate::gears::pair::PairWarning;
use crate::gears::tooth::Outline;
use crate::project::gears::PlanetaryProject;
use crate::project::{GearsProject, Project};
use crate::report::{self, NoteTable, NumTable};
use kurbo::{Point, Rect};
use labels::GearLabels;
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
    pub scene: Scene,
    pub mesh: MeshDrawn,
    /// μ_l of the planetary views, m/mm.
    pub planetary_mu: Option<f64>,
    pub layout: Layout,
    pub tables: Vec<(&'static str, NumTable)>,
}

/// Left half: the mesh.
const MESH: Rect = Rect { x0: 24.0, y0: 9.0, x1: 440.0, y1: 585.0 };
/// Right half, above the title block's column.
const RIGHT_X0: f64 = 448.0;

/// Builds sheet 2.
pub fn build(ctx: &Context, p: &GearsProject) -> Result<GearsBuild, SheetError> {
    let lang = ctx.info.language;
    let (l, c) = (GearLabels::get(lang), Common::get(lang));
    let outlines = [Outline::new(&p.pair.spec, &p.pair.wheels[0]), Outline::new(&p.pair.spec, &p.pair.wheels[1])];
    let inner = frame::inner();
    let mut fr = Group::new("frame", Rect::new(0.0, 0.0, A1_W, A1_H));
    frame::frame(&mut fr);

    // The mesh: title on top, notes at the bottom, the drawing between.
    let notes = mesh_notes(p, l, lang);
    let mut mesh = Group::new("mesh", MESH);
    let mut labels = Labels::new();
    let title = l.mesh_title(
        &fmt::trimmed(p.pair.spec.module * 1e3, lang),
        &p.pair.wheels[0].z.to_string(),
        &p.pair.wheels[1].z.to_string(),
    );
    mesh.text(Text::new(Point::new(MESH.x0 + 2.0, MESH.y0 + 6.0), title, 5.0, Anchor::Start));
    // The notes' height: four lines of results and the notes, each wrapped.
    let notes_w = MESH.width() - 4.0;
    let wrapped = |n: &str| wrap(n, CELL_TEXT, notes_w);
    let lines: usize = 4 + notes.iter().map(|n| wrapped(n).len()).sum::<usize>();
    let notes_h = lines as f64 * CELL_TEXT * crate::drawing::text::LINE_PITCH + lines as f64 * 0.5 + 6.0;
    let area = Rect::new(MESH.x0 + 2.0, MESH.y0 + 10.0, MESH.x1 - 2.0, MESH.y1 - notes_h);
    let drawn =
        draw_mesh(&mut mesh, area, &MeshInput { pair: &p.pair, outlines: [&outlines[0], &outlines[1]] }, &mut labels);
    let mut y = area.y1 + 5.0;
    let eps = &fmt::value;
    let diff = (drawn.contact_ratio_drawn - p.pair.contact_ratio) / p.pair.contact_ratio * 100.0;
    let head = [
        l.scale(&fmt::localise(&scale::ratio(drawn.mu), lang)),
        l.contact_ratio_exact(&eps(p.pair.contact_ratio, lang)),
        l.contact_ratio_drawn(&eps(drawn.contact_ratio_drawn, lang), &fmt::scientific(diff, lang)),
        l.involute_note(&fmt::value(drawn.involute_deviation * 1e6, lang)),
    ];
    for n in head.iter().chain(&notes) {
        y = paragraph(&mut mesh, Point::new(MESH.x0 + 2.0, y), &wrapped(n), CELL_TEXT, Anchor::Start) + 0.5;
    }
    labels.place(&mut mesh, area);

    // The right half: the planetary views on top, the tables below.
    let mut groups = vec![fr, mesh];
    let right = Rect::new(RIGHT_X0, inner.y0 + 4.0, inner.x1 - 4.0, frame::title_block_rect().y0 - 4.0);
    let mut y_tables = right.y0;
    let mut planetary_mu = None;
    if let Some(pl) = &p.planetary {
        let (g, mu, bottom) = planetary_group(pl, right, l, lang);
        planetary_mu = Some(mu);
        groups.push(g);
        y_tables = bottom + 4.0;
    }
    let tables = note_tables_of(p, drawn.contact_ratio_drawn);
    let tolerance = p.planetary.as_ref().map(|pl| pl.stage.tolerance);
    groups.push(tables_group(&tables, Rect::new(right.x0, y_tables, right.x1, right.y1), tolerance, l, c, lang));

    let sheet_name = if p.planetary.is_some() { l.sheet_name() } else { l.sheet_name_pair() };
    let tb = ctx.title_block(c, sheet_name, &fmt::localise(&scale::ratio(drawn.mu), lang), KIND.number)?;
    groups.push(tb);
    let scene = Scene { width: A1_W, height: A1_H, title: format!("{} — {sheet_name}", ctx.info.title()), groups };
    let layout = layout::measure(&scene);
    Ok(GearsBuild { scene, mesh: drawn, planetary_mu, layout, tables })
}

/// The notes under the mesh: shifts chosen, warnings, the user's assumptions.
fn mesh_notes(p: &GearsProject, l: &GearLabels, lang: Language) -> Vec<String> {
    let v = |x: f64| fmt::value(x, lang);
    let mut out = vec![l.active_note().to_string()];
    for (i, w) in p.pair.wheels.iter().enumerate() {
        if p.auto_shift[i] {
            out.push(l.auto_shift_note(&(i + 1).to_string(), &v(w.shift)));
        }
    }
    for w in &p.warnings {
        out.push(match w {
            PairWarning::Undercut { wheel, x, x_min } => l.undercut_note(&wheel.to_string(), &v(*x), &v(*x_min)),
            PairWarning::ThinTip { wheel, s_a, .. } => l.thin_tip_note(&wheel.to_string(), &v(s_a * 1e3)),
            PairWarning::LowContactRatio { eps } => l.low_ratio_note(&v(*eps)),
            PairWarning::Interference { wheel } => l.interference_note(&wheel.to_string()),
        });
    }
    out.extend(p.assumptions.iter().map(|a| a.get(lang).to_string()));
    out
}

/// The planetary views in the top of `right`; returns the group, its μ_l and its bottom.
fn planetary_group(pl: &PlanetaryProject, right: Rect, l: &GearLabels, lang: Language) -> (Group, f64, f64) {
    let s = &pl.stage;
    let size = (right.width() * 0.5 - 10.0).min(190.0);
    let mu = planetary_view::scale_for(s, pl.module, size);
    let view_h = 2.0 * planetary_view::extent(s, pl.module) / mu + 16.0;
    let region = Rect::new(right.x0, right.y0, right.x1, right.y0 + 14.0 + view_h + 6.0);
    let mut g = Group::new("planetary", region);
    let title =
        l.planetary_title(&fmt::value(s.ratio, lang), &fmt::value(s.ratio_required, lang), &s.planets.to_string());
    g.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 6.0), title, 3.5, Anchor::Start));
    let scheme = match s.scheme {
        crate::gears::planetary::Scheme::SunPlanetRing => l.scheme_sun_planet_ring(),
        crate::gears::planetary::Scheme::DoublePlanet => l.scheme_double_planet(),
    };
    let sc = l.scale(&fmt::localise(&scale::ratio(mu), lang));
    g.text(Text::new(Point::new(region.x0 + 2.0, region.y0 + 11.0), format!("{scheme}; {sc}"), 2.5, Anchor::Start));
    let half = region.width() / 2.0;
    let front = Rect::new(region.x0, region.y0 + 14.0, region.x0 + half, region.y1 - 6.0);
    let side = Rect::new(region.x0 + half, region.y0 + 14.0, region.x1, region.y1 - 6.0);
    g.text(Text::new(Point::new(front.center().x, region.y1 - 1.5), l.front_view(), 2.5, Anchor::Middle));
    g.text(Text::new(Point::new(side.center().x, region.y1 - 1.5), l.side_view(), 2.5, Anchor::Middle));
    let mut labels = Labels::new();
    planetary_view::draw(&mut g, front, side, s, pl.module, mu, &mut labels);
    labels.place(&mut g, region);
    (g, mu, region.y1)
}

/// The note's tables as numbers, by file stem.
fn note_tables_of(p: &GearsProject, eps_drawn: f64) -> Vec<(&'static str, NumTable)> {
    let mut out = vec![("wheels", report::gears::wheels(&p.pair)), ("pair", report::gears::pair(&p.pair, eps_drawn))];
    if let Some(pl) = &p.planetary {
        out.push(("planetary", report::gears::stage(&pl.stage, pl.module)));
        out.push(("conditions", report::gears::conditions(&pl.stage)));
    }
    out
}

fn table_title<'a>(stem: &str, l: &'a GearLabels) -> &'a str {
    match stem {
        "wheels" | "pair" => l.pair_table(),
        "planetary" => l.planetary_table(),
        _ => l.conditions_table(),
    }
}

/// Draws the tables in `region`, in columns left to right.
fn tables_group(
    tables: &[(&'static str, NumTable)],
    region: Rect,
    tolerance: Option<f64>,
    l: &GearLabels,
    c: &Common,
    lang: Language,
) -> Group {
    let drawn = tables.iter().map(|(stem, t)| sheet_table(stem, t, tolerance, l, c, lang));
    crate::drawing::table::flow("tables", drawn, region, 4.0)
}

fn sheet_table(stem: &str, t: &NumTable, tolerance: Option<f64>, l: &GearLabels, c: &Common, lang: Language) -> Table {
    let is_conditions = stem == "conditions";
    let rows: Vec<(LabelText, Vec<String>)> = t
        .rows
        .iter()
        .map(|r| {
            let mut label = if is_conditions && r.symbol == "ratio" {
                // The ratio's condition is the stated tolerance.
                let tol = tolerance.map(|t| format!(" ±{} %", fmt::trimmed(t * 100.0, lang))).unwrap_or_default();
                LabelText::new(format!("{}{tol}", l.condition(&r.symbol)), "")
            } else if is_conditions {
                LabelText::new(l.condition(&r.symbol), "")
            } else {
                LabelText::new(r.symbol.clone(), l.sub(&r.sub))
            };
            let unit = c.si_unit(&r.unit);
            if !unit.is_empty() && !is_conditions {
                label.tail = format!(", {unit}");
            }
            // Counts (z, K, sums of teeth) print as integers.
            let counts = is_conditions || r.symbol == "z" || r.symbol == "K";
            let num = |v: f64| {
                if counts && v.fract() == 0.0 && v.abs() < 1e9 { format!("{v:.0}") } else { fmt::value(v, lang) }
            };
            let cells = if is_conditions {
                vec![num(r.values[0]), num(r.values[1]), (if r.values[2] > 0.5 { l.yes() } else { l.no() }).to_string()]
            } else {
                r.values.iter().map(|&v| num(v)).collect()
            };
            (label, cells)
        })
        .collect();
    let header = match stem {
        "wheels" => vec![l.wheel("1"), l.wheel("2")],
        "conditions" => vec![l.value_col().into(), l.limit_col().into(), l.ok_col().into()],
        _ => vec![c.value().into()],
    };
    let label_w = rows.iter().map(|(x, _)| x.width(CELL_TEXT) + 4.0).fold(14.0, f64::max);
    // The pair's table continues the wheels': titled as the continuation.
    let title = if stem == "pair" {
        crate::drawing::table::continued_title(table_title(stem, l), c.continued())
    } else {
        table_title(stem, l).to_string()
    };
    Table {
        title,
        header,
        rows,
        label_w,
        cell_w: 14.0,
        corner: if is_conditions { l.condition_col().into() } else { c.quantity().into() },
    }
}

impl GearsBuild {
    /// The note's tables with titles, headings and units in the sheet's language.
    pub fn note_tables(&self, lang: Language) -> Vec<NoteTable> {
        let (l, c) = (GearLabels::get(lang), Common::get(lang));
        self.tables
            .iter()
            .map(|(stem, t)| NoteTable {
                stem,
                title: table_title(stem, l).to_string(),
                headings: [c.quantity().into(), c.unit().into()],
                units: t.rows.iter().map(|r| c.si_unit(&r.unit).to_string()).collect(),
                table: NumTable {
                    // Words in the sheet's language: subscripts, and the conditions' names.
                    rows: t
                        .rows
                        .iter()
                        .map(|r| report::Row {
                            symbol: if *stem == "conditions" {
                                l.condition(&r.symbol).to_string()
                            } else {
                                r.symbol.clone()
                            },
                            sub: l.sub(&r.sub).to_string(),
                            ..r.clone()
                        })
                        .collect(),
                    ..t.clone()
                },
                column_titles: match *stem {
                    "wheels" => vec![l.wheel("1"), l.wheel("2")],
                    "conditions" => vec![l.value_col().into(), l.limit_col().into(), l.ok_col().into()],
                    _ => vec![c.value().into()],
                },
                decimal_comma: lang != Language::En,
                whole_numbers: true,
            })
            .collect()
    }
}

impl Sheet for GearsSheet<'_> {
    fn kind(&self) -> SheetKind {
        KIND
    }

    fn build(&self, ctx: &Context) -> Result<SheetOutput, SheetError> {
        let b = build(ctx, self.project)?;
        let mut diagnostics: Vec<String> = b.layout.problems.iter().map(|p| format!("layout: {p}")).collect();
        diagnostics.extend(self.project.warnings.iter().filter_map(|w| match w {
            PairWarning::ThinTip { wheel, s_a, limit } => {
                Some(format!("wheel {wheel}'s tip is thin: s_a = {:.3} mm < 0.25·m = {:.3} mm", s_a * 1e3, limit * 1e3))
            }
            PairWarning::LowContactRatio { eps } => Some(format!("the contact ratio {eps:.3} is below 1.2")),
            PairWarning::Interference { wheel } => {
                Some(format!("wheel {wheel}'s tip passes the other wheel's N: the contact ends at N (undercut root)"))
            }
            PairWarning::Undercut { .. } => None,
        }));
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
pub fn results(p: &GearsProject, b: &GearsBuild) -> serde_json::Value {
    use serde_json::json;
    let pr = &p.pair;
    let wheel = |f: &dyn Fn(usize) -> f64| json!([f(0), f(1)]);
    let w = &pr.wheels;
    let mut out = json!({
        "pair": {
            "module": pr.spec.module,
            "z": [w[0].z, w[1].z],
            "shift": wheel(&|i| w[i].shift),
            "shift_auto": p.auto_shift,
            "pressure_angle_deg": pr.spec.pressure_angle.to_degrees(),
            "working_pressure_angle_deg": pr.working_pressure_angle.to_degrees(),
            "centre_distance": pr.centre_distance,
            "reference_centre_distance": pr.reference_centre_distance,
            "y": pr.y,
            "delta_y": pr.delta_y,
            "ratio": pr.ratio,
            "contact_ratio": pr.contact_ratio,
            "contact_ratio_drawing": b.mesh.contact_ratio_drawn,
            "radii": {
                "pitch": wheel(&|i| w[i].pitch),
                "base": wheel(&|i| w[i].base),
                "tip": wheel(&|i| w[i].tip),
                "root": wheel(&|i| w[i].root),
                "working": wheel(&|i| w[i].working),
            },
            "tooth_height": pr.tooth_height,
            "pitch": pr.pitch,
            "base_pitch": pr.base_pitch,
            "tooth_thickness": wheel(&|i| w[i].tooth_thickness),
            "tip_thickness": wheel(&|i| w[i].tip_thickness),
            "undercut": [w[0].undercut, w[1].undercut],
            "x_min": wheel(&|i| w[i].x_min),
            "interference": pr.interference,
        },
        "drawing": {
            "mu_l": b.mesh.mu,
            "tooth_height_mm": b.mesh.tooth_height_mm,
            "involute_pieces_per_flank": INVOLUTE_PIECES,
            "involute_deviation": b.mesh.involute_deviation,
            "fillet_deviation": b.mesh.fillet_deviation,
            "planetary_mu_l": b.planetary_mu,
        },
        "layout": {
            "texts_crossed": b.layout.texts_crossed,
            "text_overlaps": b.layout.text_overlaps,
            "outside_region": b.layout.outside_region,
            "problems": b.layout.problems.iter().take(20).collect::<Vec<_>>(),
        },
    });
    if let Some(pl) = &p.planetary {
        let s = &pl.stage;
        out["planetary"] = json!({
            "scheme": s.scheme.key(),
            "z": s.z,
            "planets": s.planets,
            "ratio": s.ratio,
            "ratio_required": s.ratio_required,
            "tolerance": s.tolerance,
            "module": pl.module,
            "conditions": s.conditions.iter().map(|c| json!({"name": c.name, "value": c.value, "limit": c.limit, "ok": c.ok})).collect::<Vec<_>>(),
        });
    }
    out
}
