//! The Zhukovsky lever: the velocity plan turned by 90° with every force at its point's
//! image, the balancing force P′ₘ from it and its difference from the kinetostatics.

use super::arrows::{Arrows, Push, arrow_scale, twin_rows, unit_directions};
use super::legend::{
    couple_label, decimals_of, force_label, scale_item, text_rows, value_item, with_semicolon, with_short_note,
    wrap_items,
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

/// Lines under the lever besides its legend, in a cell `width` mm wide (less its margins):
/// μ_v and μ_F, then [`balancing_rows`].
pub(super) fn lever_lines(inp: &ForcesInput, width: f64) -> usize {
    1 + balancing_rows(inp, width).len()
}

/// P′ₘ from the lever, its difference Δ from the kinetostatics' Pₘ and P″ₘ from the balance
/// of powers (table 5's three), said where each comes from, wrapped to `width` mm.
fn balancing_rows(inp: &ForcesInput, width: f64) -> Vec<Vec<LabelText>> {
    let (f, w) = (&inp.fa.forces, &inp.words);
    let balancing = |prime: &str, v: f64| {
        value_item(inp, LabelText::new(prime, w.sheet.sub_balancing()), (v, None), w.common.unit_n(), false)
    };
    let mut power = balancing("P″", f.p_m_power);
    power.tail = format!("{} {}", power.tail, w.sheet.from_power_balance());
    let items = vec![
        balancing("P′", f.p_m_lever),
        LabelText::new("Δ", "").with_tail(format!(" = {} %", fmt::value(f.difference_percent(), w.lang))),
        power,
    ];
    wrap_items(items, width, ";", "")
}
/// Room under the last line's baseline for its subscripts and descenders, mm (3.5 mm
/// lettering).
pub(super) const DESCENT: f64 = 1.5;

/// The crank pin's image on the lever, where P′ₘ is applied.
pub(super) fn balancing_image(inp: &ForcesInput) -> Vec2 {
    inp.state.points[inp.m.crank().pin].v.turn_90() * inp.m.sense().sign()
}

/// The lever's box at `mu` ((m/s)/mm) with its forces at `mu_f`, in the plan's units: the
/// turned plan and every force arrow's far end, twins pushing or slid as drawn. The
/// lever's cell is sized round it and the drawing centred on it, so arrows that point
/// into the plan leave no room unused and a row of twins has the room it takes.
pub(super) fn lever_extent(inp: &ForcesInput, plan: &Plan, mu: f64, mu_f: f64) -> Rect {
    // Twins are found on paper, the pole at the origin.
    let view = View::new(Point::ZERO, mu);
    let forces = on_paper(&lever_forces(inp), &view);
    let push = lever_push(plan, &view, &forces, mu_f);
    let rows = twin_rows(forces, Some(&push), mu_f);
    let world = |p: Point| Point::new(p.x * mu, -p.y * mu);
    rows.iter().map(|&(at, d, reach)| world(at + d * reach)).fold(plan_bbox(plan), |r, p| r.union_pt(p))
}

/// The lever's `forces` at their images on paper by `view`: each's point and direction.
fn on_paper(forces: &[(Vec2, Vec2, LabelText)], view: &View) -> Vec<(Point, Vec2)> {
    forces.iter().map(|(at, force, _)| (view.p(*at), view.dir(*force))).collect()
}

/// What the lever's twins drawn pushing keep clear of on paper by `view` (see [`Push`]):
/// the plan's lines and points, every force (`forces` on paper) and the box the arrows
/// reach slid.
fn lever_push(plan: &Plan, view: &View, forces: &[(Point, Vec2)], mu_f: f64) -> Push {
    let bb = plan_bbox(plan);
    let plan_box = Rect::from_points(view.p(bb.origin().to_vec2()), view.p(Vec2::new(bb.x1, bb.y1)));
    let slid = twin_rows(forces.iter().copied(), None, mu_f);
    let within = slid.iter().fold(plan_box, |r, &(at, d, reach)| r.union_pt(at + d * reach));
    Push {
        lines: plan.segs.iter().map(|s| (view.p(s.from), view.p(s.to))).collect(),
        points: plan.images.iter().map(|i| view.p(i.at)).collect(),
        forces: unit_directions(forces.iter().copied()),
        within,
        keep_lines: true,
    }
}

/// The lever's forces at their images, with their labels, in the kinetostatics' order and
/// P′ₘ last: of two twins the later is drawn pushing where it may.
fn lever_forces(inp: &ForcesInput) -> Vec<(Vec2, Vec2, LabelText)> {
    let f = &inp.fa.forces;
    let mut forces: Vec<(Vec2, Vec2, LabelText)> = f
        .lever
        .iter()
        .map(|l| {
            let label = if l.couple { couple_label(inp, l.on) } else { force_label(inp, l.kind, l.on) };
            (l.image, l.force, label)
        })
        .collect();
    let balancing = LabelText::new("P′", inp.words.sheet.sub_balancing());
    forces.push((balancing_image(inp), f.dir_m * f.p_m_lever, balancing));
    forces
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
        let (label, decimals) = if l.couple {
            (couple_label(inp, l.on), None)
        } else {
            (force_label(inp, l.kind, l.on), decimals_of(inp, l.kind))
        };
        if items.iter().any(|i| i.main == label.main && i.sub == label.sub) {
            continue;
        }
        let s = f / mu_f < ARROW_MIN;
        short |= s;
        items.push(value_item(inp, label, (f, decimals), inp.words.common.unit_n(), s));
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
    let legend = lever_legend(inp, mu_f, r.width() - 4.0);
    let mut lines = vec![vec![
        with_semicolon(scale_item(inp, "v", mu, inp.words.common.unit_v_per_mm())),
        scale_item(inp, "F", mu_f, inp.words.common.unit_n_per_mm()),
    ]];
    lines.extend(balancing_rows(inp, r.width() - 4.0));
    let text_h = (lines.len() + legend.len()) as f64 * LINE + DESCENT;
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
    let forces = lever_forces(inp);
    let push = Some(lever_push(plan, &view, &on_paper(&forces, &view), mu_f));
    let mut arrows = Arrows { view, links: Vec::new(), push, blocks: Vec::new(), drawn: Vec::new(), mu_f, h: 2.5 };
    for (image, force, label) in forces {
        arrows.arrow(g, labels, at(image), force, label);
    }
    let y = text_rows(g, r.x0 + 2.0, r.y1 - text_h + LINE, &legend);
    text_rows(g, r.x0 + 2.0, y, &lines);
}

/// The lever's longer side on paper at velocity scale `mu`, mm: its turned velocity plan's
/// box (what `results.json` reports as `lever_mm`).
pub(super) fn lever_side_mm(plan: &Plan, mu: f64) -> f64 {
    let bb = plan_bbox(plan);
    bb.width().max(bb.height()) / mu
}
