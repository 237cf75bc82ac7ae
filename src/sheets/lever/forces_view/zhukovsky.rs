//! The Zhukovsky lever: the velocity plan turned by 90° with every force at its point's
//! image, the balancing force P′ₘ from it and its difference from the kinetostatics.

use super::arrows::{Arrows, arrow_scale, twin_rows};
use super::legend::{
    couple_label, force_label, scale_item, text_rows, value_item, with_semicolon, with_short_note, wrap_items,
};
use super::{ARROW_MIN, ForcesInput, LINE};
use crate::drawing::fmt;
use crate::drawing::place::Labels;
use crate::drawing::scene::Group;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::plans::Plan;
use crate::num::math::Norm;
use crate::sheets::lever::plans_view::{PlanCell, draw_plan, plan_bbox};
use kurbo::{Point, Rect, Vec2};

/// Lines under the lever besides its legend: μ_v and μ_F, P′ₘ, Δ.
pub(super) const LEVER_LINES: usize = 3;
/// Room under the last line's baseline for its subscripts and descenders, mm (3.5 mm
/// lettering).
pub(super) const DESCENT: f64 = 1.5;

/// The crank pin's image on the lever, where P′ₘ is applied.
pub(super) fn balancing_image(inp: &ForcesInput) -> Vec2 {
    inp.state.points[inp.m.crank().pin].v.turn_90() * inp.m.sense().sign()
}

/// The lever's box at `mu` ((m/s)/mm) with its forces at `mu_f`, in the plan's units: the
/// turned plan and every force arrow's tip, twins slid along their lines as drawn. The
/// lever's cell is sized round it and the drawing centred on it, so arrows that point
/// into the plan leave no room unused and a row of twins has the room it takes.
pub(super) fn lever_extent(inp: &ForcesInput, plan: &Plan, mu: f64, mu_f: f64) -> Rect {
    let f = &inp.fa.forces;
    let forces = f.lever.iter().map(|l| (l.image, l.force)).chain([(balancing_image(inp), f.dir_m * f.p_m_lever)]);
    // Twins are found on paper; turning the y axis over keeps every angle between forces.
    let rows = twin_rows(forces.map(|(at, force)| (Point::new(at.x / mu, at.y / mu), force)), mu_f);
    let tips = rows.iter().map(|&(at, d, reach)| Point::new(at.x * mu, at.y * mu) + d * (reach * mu));
    tips.fold(plan_bbox(plan), |r, p| r.union_pt(p))
}

pub(super) fn lever_arrow_scale(inp: &ForcesInput) -> f64 {
    let f = &inp.fa.forces;
    arrow_scale(f.lever.iter().map(|l| l.force.norm()).fold(f.p_m_lever.abs(), f64::max))
}

/// The lever's legend: each force once, with its value.
pub(super) fn lever_legend(inp: &ForcesInput, mu_f: f64, width: f64) -> Vec<Vec<LabelText>> {
    let mut items: Vec<LabelText> = Vec::new();
    let mut short = false;
    for l in &inp.fa.forces.lever {
        let f = l.force.norm();
        if f <= 0.0 {
            continue;
        }
        let label = if l.couple { couple_label(inp, l.on) } else { force_label(inp, l.kind, l.on) };
        if items.iter().any(|i| i.main == label.main && i.sub == label.sub) {
            continue;
        }
        let s = f / mu_f < ARROW_MIN;
        short |= s;
        items.push(value_item(inp, label, f, inp.words.common.unit_n(), s));
    }
    with_short_note(inp, wrap_items(items, width, ";", ""), short, width)
}

pub(super) fn draw_lever(
    g: &mut Group,
    labels: &mut Labels,
    r: Rect,
    inp: &ForcesInput,
    (plan, extent): (&Plan, Rect),
    (mu, mu_f): (f64, f64),
) {
    let f = &inp.fa.forces;
    let legend = lever_legend(inp, mu_f, r.width() - 4.0);
    let text_h = (LEVER_LINES + legend.len()) as f64 * LINE + DESCENT;
    let plan_cell = Rect::new(r.x0, r.y0, r.x1, r.y1 - text_h);
    let cell = PlanCell {
        cell: plan_cell,
        title: inp.words.sheet.lever_title(),
        plan,
        mu,
        pole: "p",
        scale_line: None,
        extent: Some(extent),
    };
    let pole = draw_plan(g, &cell, labels);
    let view = View::new(pole, mu);
    let at = |v: Vec2| view.p(v);
    let mut arrows = Arrows { view, links: Vec::new(), blocks: Vec::new(), drawn: Vec::new(), mu_f, h: 2.5 };
    for l in &f.lever {
        let label = if l.couple { couple_label(inp, l.on) } else { force_label(inp, l.kind, l.on) };
        arrows.arrow(g, labels, at(l.image), l.force, label);
    }
    arrows.arrow(
        g,
        labels,
        at(balancing_image(inp)),
        f.dir_m * f.p_m_lever,
        LabelText::new("P′", inp.words.sheet.sub_balancing()),
    );
    let lang = inp.words.lang;
    let lines = [
        vec![
            with_semicolon(scale_item(inp, "v", mu, inp.words.common.unit_v_per_mm())),
            scale_item(inp, "F", mu_f, inp.words.common.unit_n_per_mm()),
        ],
        vec![LabelText::new("P′", inp.words.sheet.sub_balancing()).with_tail(format!(
            " = {} {}",
            fmt::value(f.p_m_lever, lang),
            inp.words.common.unit_n()
        ))],
        vec![LabelText::new("Δ", "").with_tail(format!(" = {} %", fmt::value(f.difference_percent(), lang)))],
    ];
    let y = text_rows(g, r.x0 + 2.0, r.y1 - text_h + LINE, &legend);
    text_rows(g, r.x0 + 2.0, y, &lines);
}

/// The lever's longer side on paper at velocity scale `mu`, mm: its turned velocity plan's
/// box (what `results.json` reports as `lever_mm`).
pub(super) fn lever_side_mm(plan: &Plan, mu: f64) -> f64 {
    let bb = plan_bbox(plan);
    bb.width().max(bb.height()) / mu
}
