//! Sheet 1: the lever mechanism's positions, velocity and acceleration plans and the
//! tables of the note, laid out on an A1 landscape sheet.
//!
//! Layout (mm, inside the frame): the mechanism at the top left, as wide as its scale
//! makes it; the velocity plans fill the rest of the top band; the acceleration plans at
//! the bottom left; the tables and notes at the bottom right, above the title block.

mod column;
mod corner;
mod header;
mod variant;
mod widen;

pub(super) use header::region_header;

use super::choice::{EMPTY_MOST, Floors, better, empty};
use super::drawn_once::DrawnOnce;
use super::forces_view::{CellMemo, ForceScales, ForcesInput, draw_forces};
use super::labels::LeverWords;
use super::mechanism_place::{MechanismDrawn, MechanismPlace, mechanism_group, mechanism_place};
use super::note_tables::{NoteParts, NoteTables, note_tables, sheet_table, tables_group, with_units};
pub use super::plan_regions::PlanDrawn;
use super::plan_regions::{LARGEST_PLAN, PlansRegion, Split, Twins, plans_group, split_plans};
use super::plans_view::{Sizing, off_scale};
use super::segments;
use crate::drawing::frame;
use crate::drawing::layout::Layout;
use crate::drawing::scene::{Group, Scene};
use crate::drawing::table::Table;
use crate::drawing::text::TooLong;
use crate::lever::analysis::{ForceAnalysis, Kinematics, Position};
use crate::lever::plans::{acceleration_plan, velocity_plan};
use crate::project::LeverProject;
use crate::report::NoteTable;
use crate::report::lever::{ForceTables, LegendDecimals};
use crate::report::{AnswerKeys, Segment};
use crate::sheets::scaffold::{self, Composition};
use crate::sheets::{Context, SheetKind};
use column::{FORCES_WIDTHS, compose_variant};
use corner::with_larger_plans;
use kurbo::Rect;
use variant::{FULLER, Variant};

/// The scales chosen for the sheet.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Scales {
    /// m/mm
    pub mu_l: f64,
    /// The crank's enlarged detail's μ_l, m/mm, when the crank is too small on paper.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub detail_mu_l: Option<f64>,
    /// (m/s)/mm, shared by every velocity plan (none without plans).
    pub mu_v: Option<f64>,
    /// (m/s²)/mm, shared by every acceleration plan (none without plans).
    pub mu_a: Option<f64>,
    /// Each velocity plan's scale and drawn size.
    pub velocity_plans: Vec<PlanDrawn>,
    pub acceleration_plans: Vec<PlanDrawn>,
}

impl Scales {
    /// How many plans are drawn at a scale of their own, off their kind's one.
    pub fn own_scales(&self) -> usize {
        let off = |plans: &[PlanDrawn], common: Option<f64>| {
            plans.iter().filter(|p| common.is_none_or(|c| off_scale(p.mu, c))).count()
        };
        off(&self.velocity_plans, self.mu_v) + off(&self.acceleration_plans, self.mu_a)
    }
}

/// The composed sheet and the scales it chose.
pub struct Composed {
    /// The drawings and tables, for the scaffold to finish.
    pub composition: Composition,
    /// The whole sheet as measured: the composition in its frame with its title block.
    pub scene: Scene,
    pub scales: Scales,
    pub force_scales: Option<ForceScales>,
    /// The smallest plan as the choice between compositions reads it, mm: what its plans'
    /// column could have drawn where its split gave some of it for larger plans.
    pub plan_reach_mm: Option<f64>,
    /// The largest distance of a drawn trajectory from the exact path, paper mm.
    pub trajectory_error_mm: f64,
    /// The sheet's own measurement of its layout.
    pub layout: Layout,
}

/// Inputs of sheet 1 beyond the kinematics.
pub struct Input<'a> {
    pub ctx: &'a Context<'a>,
    pub kind: SheetKind,
    pub project: &'a LeverProject,
    /// The note's tables 1 and 2 (and 3–5 with a force analysis), computed once by the
    /// caller.
    pub notes: &'a [NoteTable],
    /// The force analysis and its tables 3–5, when the project asks for one.
    pub forces: Option<&'a (ForceAnalysis, ForceTables)>,
}

/// The top of the mechanism's and the plans' regions, mm.
pub(super) const TOP: f64 = 12.0;
const FORCES_MIN_W: f64 = 470.0;
/// A region's title and scale lines.
pub(super) const HEADER: f64 = 17.0;

/// Lays out sheet 1; refuses a project text too long for its place on the sheet. With a
/// force analysis its tables 3–5 are lettered by the rule ([`CELL_TEXT`](crate::drawing::table::CELL_TEXT)) and, on rayon's
/// pool beside it, in [`LARGE_TEXT`](crate::drawing::table::LARGE_TEXT); the larger lettering is kept where it is better (as
/// clean, the rule's floors kept, less empty). Where the sheet kept is still more than half
/// empty (`EMPTY_MOST`), fuller variants are composed (`FULLER`) and the least empty that
/// keeps the rule's floors wins.
pub fn compose(inp: &Input, k: &Kinematics) -> Result<Composed, TooLong> {
    let plans = PlansOf::new(inp, k);
    let variant = |v| compose_variant(inp, k, &plans, v);
    if inp.forces.is_none() {
        // No force cells to grow or move: only table 1 into the corner.
        let rule = variant(Variant::RULE)?;
        if empty(&rule) <= EMPTY_MOST {
            return Ok(rule);
        }
        let corner = variant(Variant { corner: true, ..Variant::RULE })?;
        let kept = Floors::of(&rule).kept(&corner) && (corner.layout.is_clean() || !rule.layout.is_clean());
        return Ok(if kept && empty(&corner) < empty(&rule) {
            corner
        } else {
            with_larger_plans(&variant, (Variant::RULE, rule))
        });
    }
    let large_v = Variant::RULE.in_other_lettering();
    let (rule, large) = rayon::join(|| variant(Variant::RULE), || variant(large_v));
    let rule = rule?;
    let rule_floors = Floors::of(&rule);
    let (mut out, other) = match large.ok() {
        Some(l) if better(&l, &rule, 0.005) => ((large_v, l), Some((Variant::RULE, rule))),
        l => ((Variant::RULE, rule), l.map(|l| (large_v, l))),
    };
    // The fuller variants keep tables 3–5 together where the sheet kept so far has them so.
    let floors = rule_floors.with_tables_of(&out.1);
    // Composing more costs only the sheets left too empty, and stops once one is not.
    let mut candidates: Vec<(Variant, Composed)> = other.into_iter().collect();
    let admissible = |c: &Composed, out: &Composed| floors.kept(c) && (c.layout.is_clean() || !out.layout.is_clean());
    // The variants that could win, with how empty each is, to widen below.
    let mut kept: Vec<(f64, Variant)> = Vec::new();
    for [a, b] in FULLER {
        if empty(&out.1) <= EMPTY_MOST {
            break;
        }
        let (ca, cb) = rayon::join(|| variant(a), || variant(b));
        for (v, c) in [(a, ca), (b, cb)] {
            let Ok(c) = c else { continue };
            if admissible(&c, &out.1) {
                kept.push((empty(&c), v));
            }
            candidates.push((v, c));
        }
        for c in candidates.drain(..) {
            if admissible(&c.1, &out.1) && empty(&c.1) < empty(&out.1) {
                out = c;
            }
        }
    }
    // Still too empty: the least empty again with the force column widened (`widen`).
    if empty(&out.1) > EMPTY_MOST {
        for c in widen::least_empty_widened(&variant, kept) {
            if admissible(&c.1, &out.1) && empty(&c.1) < empty(&out.1) {
                out = c;
            }
        }
    }
    Ok(with_larger_plans(&variant, out))
}

/// What every composition of the sheet shares: the velocity and acceleration plans (the
/// same at every layout), those that coincide on paper drawn once, and the drawings made
/// so far of the mechanism and of each region of plans, by place.
struct PlansOf<'a> {
    velocity: Twins<'a>,
    acceleration: Twins<'a>,
    mechanisms: DrawnOnce<MechanismPlace, MechanismDrawn>,
    plans_drawn: DrawnOnce<(String, Rect, Sizing), PlansDrawn>,
    /// Tables 1 and 2 and the notes, the same in every layout.
    notes: NoteParts,
    /// The plans' column split by column (variants share columns; the kinds are the same).
    splits: DrawnOnce<Rect, Split>,
}

/// A region of plans drawn: its group, each plan as drawn, their common scale and the
/// segments drawn ([`plans_group`]).
type PlansDrawn = (Group, Vec<PlanDrawn>, Option<f64>, Vec<Segment>);

impl<'a> PlansOf<'a> {
    fn new(inp: &Input, k: &'a Kinematics) -> PlansOf<'a> {
        let m = &inp.project.mechanism;
        let vpositions: Vec<&Position> = k.positions.iter().collect();
        let apositions: Vec<&Position> = k.acceleration.iter().map(|&i| &k.positions[i]).collect();
        let velocity = Twins::of(vpositions.iter().map(|p| velocity_plan(m, &p.state)).collect(), &vpositions);
        let acceleration = Twins::of(apositions.iter().map(|p| acceleration_plan(m, &p.state)).collect(), &apositions);
        let notes = NoteParts::new(inp, &LeverWords::new(inp.ctx.info.language));
        let (mechanisms, plans_drawn, splits) = Default::default();
        PlansOf { velocity, acceleration, mechanisms, plans_drawn, notes, splits }
    }
}

/// Sheet 1 arranged with a force column at least some width wide: every region and scale,
/// nothing drawn yet.
struct Arrangement<'a> {
    words: LeverWords,
    force_input: Option<ForcesInput<'a>>,
    mech: MechanismPlace,
    force_region: Option<Rect>,
    notes: NoteTables,
    velocity: PlansRegion<'a>,
    acceleration: PlansRegion<'a>,
    vsizing: Sizing,
    asizing: Sizing,
    /// The smallest plan the plans' column could have drawn, where its split gave some of it
    /// for plans [`LARGEST_PLAN`] long ([`Split::reach`]).
    plan_reach: Option<f64>,
}

impl Arrangement<'_> {
    /// The smaller of the two kinds' largest plans, mm, up to [`LARGEST_PLAN`].
    fn largest_plan_mm(&self, plans: &PlansOf) -> f64 {
        let v = self.vsizing.largest(&plans.velocity.plans);
        let a = if plans.acceleration.plans.is_empty() { v } else { self.asizing.largest(&plans.acceleration.plans) };
        v.min(a).min(LARGEST_PLAN)
    }

    /// How many plans leave their kind's one scale for one of their own.
    fn own_scales(&self) -> usize {
        self.vsizing.own_count() + self.asizing.own_count()
    }

    /// The smallest plan as the choice between columns and compositions reads it, mm: the
    /// column's reach where its split gave some of it for larger plans, else as drawn.
    fn smallest_plan_reach(&self, plans: &PlansOf) -> Option<f64> {
        self.plan_reach.or_else(|| self.smallest_plan_mm(plans))
    }

    /// The largest side of the smallest plan, mm (as the drawn plans will have it).
    fn smallest_plan_mm(&self, plans: &PlansOf) -> Option<f64> {
        let drawn =
            self.vsizing.drawn(&plans.velocity.plans).into_iter().chain(self.asizing.drawn(&plans.acceleration.plans));
        drawn.map(|size_mm| size_mm[0].max(size_mm[1])).reduce(f64::min)
    }
}

/// Arranges sheet 1 with a force column at least `forces_w` wide, as the variant `v` asks.
fn arrange<'a>(
    inp: &'a Input,
    k: &'a Kinematics,
    plans: &PlansOf,
    (forces_w, v): (f64, Variant),
    (memo, force_tables): (&'a CellMemo, &Option<Vec<Table>>),
) -> Result<Arrangement<'a>, TooLong> {
    let words = LeverWords::new(inp.ctx.info.language);
    let inner = frame::inner();
    let force_input = force_input(inp, k, &words, (memo, v), force_tables);
    let mech = mechanism_place(inp, k, force_input.as_ref(), Column { width: forces_w, inner });
    // With a force analysis, its drawings fill the left column below the mechanism and the
    // acceleration plans move to the right column.
    let force_region = inp.forces.map(|_| force_region_below(mech.region, Column { width: forces_w, inner }));
    let left_x1 = force_region.map_or(mech.region.x1, |r| r.x1);

    // Right column: the tables above the title block decide how tall the velocity plans are.
    let right_x0 = left_x1 + 6.0;
    let notes = note_tables(&plans.notes, &words, (right_x0, inner.x1 - 4.0), v.corner)?;
    let plans_bottom = notes.region.y0 - 6.0;
    let (l, c) = (words.sheet, words.common);
    let mut velocity = PlansRegion {
        id: "velocity-plans",
        kind: &segments::VELOCITY,
        region: Rect::new(right_x0, TOP, inner.x1 - 4.0, plans_bottom),
        title: l.velocity_plans(),
        pole: "p",
        symbol: "v",
        unit: c.unit_v_per_mm(),
    };
    let mut acceleration = PlansRegion {
        id: "acceleration-plans",
        kind: &segments::ACCELERATION,
        region: Rect::new(inner.x0 + 5.0, mech.region.y1 + 4.0, mech.region.x1, inner.y1 - 4.0),
        title: l.acceleration_plans(),
        pole: "π",
        symbol: "a",
        unit: c.unit_a_per_mm(),
    };
    // With a force analysis both kinds of plans share the right column: split at the
    // height that leaves the smallest plan of either kind largest.
    let ([vsizing, asizing], plan_reach) = match force_region {
        Some(_) => {
            let column = Rect::new(right_x0, TOP, inner.x1 - 4.0, plans_bottom);
            let kinds = [(&velocity, &plans.velocity), (&acceleration, &plans.acceleration)];
            let Split { kinds: [(vr, vs), (ar, as_)], reach } =
                plans.splits.get(column, || split_plans(column, kinds, &words));
            (velocity.region, acceleration.region) = (vr, ar);
            ([vs, as_], reach)
        }
        None => ([velocity.sizing(&plans.velocity, &words), acceleration.sizing(&plans.acceleration, &words)], None),
    };
    Ok(Arrangement {
        words,
        force_input,
        mech,
        force_region,
        notes,
        velocity,
        acceleration,
        vsizing,
        asizing,
        plan_reach,
    })
}

/// Draws sheet 1 as arranged, and measures it.
fn draw(inp: &Input, k: &Kinematics, plans: &PlansOf, a: Arrangement) -> Result<Composed, TooLong> {
    // The plans' sizes walked once: the reach is the drawn smallest plan where the split
    // gave none of it.
    let smallest_plan_mm = a.smallest_plan_mm(plans);
    let plan_reach_mm = a.plan_reach.or(smallest_plan_mm);
    let Arrangement { words, force_input, mech, force_region, notes, velocity, acceleration, vsizing, asizing, .. } = a;
    let l = words.sheet;
    let mech = plans.mechanisms.get(mech.clone(), || mechanism_group(inp, k, &words, mech));
    let answer = AnswerKeys::of(&format!("sheet{}", inp.kind.number), inp.notes);
    let mut drawn_segments = segments::link_segments(&inp.project.mechanism, &k.positions, mech.mu_l);
    // Velocity plans: every position, one common μ_v.
    let plans_drawn = |r: &PlansRegion, twins, sizing: Sizing| {
        plans
            .plans_drawn
            .get((r.id.to_string(), r.region, sizing.clone()), || plans_group(r, twins, sizing, &words, &answer))
    };
    let (vel, vdrawn, mu_v, vel_segments) = plans_drawn(&velocity, &plans.velocity, vsizing);
    drawn_segments.extend(vel_segments);
    // Acceleration plans: the chosen positions, one common μ_a.
    let (acc, adrawn, mu_a, acc_segments) = plans_drawn(&acceleration, &plans.acceleration, asizing);
    drawn_segments.extend(acc_segments);

    let tables = tables_group(&notes, &words);
    let (forces, force_scales, force_segments) = force_groups(force_region, force_input.as_ref(), mech.region, &answer);
    drawn_segments.extend(force_segments);
    let (mu_l, detail_mu_l) = (mech.mu_l, mech.detail_mu_l);
    let mut groups = vec![mech.group, vel, acc];
    groups.extend(tables);
    groups.extend(forces);
    let composition = Composition {
        name: if inp.forces.is_some() { l.sheet_name_forces() } else { l.sheet_name() }.to_string(),
        mu_l,
        groups,
        tables: Vec::new(),
        results: serde_json::Value::Null,
        diagnostics: Vec::new(),
        smallest_plan_mm,
        segments: drawn_segments,
        measured: None,
    };
    let scene = scaffold::scene(inp.ctx, inp.kind, &composition)?;
    let layout = scaffold::measure(&scene, &composition);
    Ok(Composed {
        composition,
        scene,
        layout,
        scales: Scales { mu_l, detail_mu_l, mu_v, mu_a, velocity_plans: vdrawn, acceleration_plans: adrawn },
        force_scales,
        plan_reach_mm,
        trajectory_error_mm: k.trajectories.iter().map(|t| t.fitted.error).fold(0.0, f64::max) / mu_l,
    })
}

/// The left column's least width for the force drawings and the frame's inside, mm.
#[derive(Clone, Copy)]
pub(super) struct Column {
    pub(super) width: f64,
    pub(super) inner: Rect,
}

/// Tables 3–5 as drawn, lettered as the variant `v` asks (none without a force analysis).
fn force_tables(inp: &Input, v: Variant) -> Option<Vec<Table>> {
    let LeverWords { common: c, lang, .. } = LeverWords::new(inp.ctx.info.language);
    inp.forces.map(|_| {
        let (t3, t4, t5) = (&inp.notes[2], &inp.notes[3], &inp.notes[4]);
        let tables = [
            Table { corner: c.link_col().into(), ..with_units(sheet_table(t3, lang), t3, lang) },
            Table { cell_w: 16.0, ..sheet_table(t4, lang) },
            Table { cell_w: 18.0, header: vec![c.value().to_string()], ..with_units(sheet_table(t5, lang), t5, lang) },
        ];
        tables.into_iter().map(|t| Table { text_h: v.text_h, ..t }).collect()
    })
}

/// The force drawings' input, with the variant's tables 3–5 ([`force_tables`]), to size the regions by.
fn force_input<'a>(
    inp: &'a Input,
    k: &'a Kinematics,
    words: &LeverWords,
    (memo, v): (&'a CellMemo, Variant),
    tables: &Option<Vec<Table>>,
) -> Option<ForcesInput<'a>> {
    inp.forces.zip(tables.as_ref()).map(|((fa, force_tables), tables)| ForcesInput {
        m: &inp.project.mechanism,
        fa,
        decimals: LegendDecimals::of(force_tables),
        state: &k.assigned.state,
        phi_deg: k.assigned.phi.to_degrees(),
        words: *words,
        tables: tables.clone(),
        memo,
        grow_drawings: v.grow_drawings,
        side_first: v.side_first,
        tables_beside: v.tables_beside,
        compact_groups: v.compact_groups,
    })
}

/// The region of the force drawings below the mechanism's, at least as wide as the column.
pub(super) fn force_region_below(mech: Rect, column: Column) -> Rect {
    let inner = column.inner;
    Rect::new(inner.x0 + 5.0, mech.y1 + 4.0, mech.x1.max(inner.x0 + 5.0 + column.width), inner.y1 - 4.0)
}

/// The force drawings below the mechanism and, when it leaves room, beside it.
fn force_groups(
    region: Option<Rect>,
    input: Option<&ForcesInput>,
    mech_region: Rect,
    answers: &AnswerKeys,
) -> (Vec<Group>, Option<ForceScales>, Vec<Segment>) {
    let (Some(region), Some(input)) = (region, input) else {
        return (Vec::new(), None, Vec::new());
    };
    let mut fg = Group::new("forces", region);
    let mut side = side_region(mech_region, region).map(|r| Group::new("forces-beside-mechanism", r));
    let (scales, segments) = draw_forces(&mut fg, side.as_mut(), input, answers);
    let mut out = vec![fg];
    out.extend(side.filter(|g| !g.items.is_empty()));
    (out, Some(scales), segments)
}

/// The room beside a narrow mechanism drawing, above the force region, for force cells.
pub(super) fn side_region(mech: Rect, forces: Rect) -> Option<Rect> {
    let r = Rect::new(mech.x1 + 6.0, mech.y0, forces.x1, mech.y1);
    (r.width() >= SIDE_MIN.0 && r.height() >= SIDE_MIN.1).then_some(r)
}

/// The least room beside the mechanism worth giving to force cells, mm.
const SIDE_MIN: (f64, f64) = (80.0, 60.0);
