//! A load diagram: the force on a slider against S/H over both strokes, the analysed
//! position marked.

use super::legend::{cell_title, scale_item, text_rows};
use super::{ForcesInput, LINE};
use crate::drawing::fmt;
use crate::drawing::obstacles::segment_meets_rect;
use crate::drawing::place::Labels;
use crate::drawing::plot::{Axis, Plot, level_ticks};
use crate::drawing::scale;
use crate::drawing::scene::{DASHED, Group, MAIN, THIN};
use crate::drawing::text::LabelText;
use crate::lever::load::{Load, Stroke};
use crate::num::math::Norm;
use kurbo::{Point, Rect, Vec2};

/// Room around a load diagram's plot, mm: the title and the P axis' arrow and name above,
/// the tick values on the left, the legend's two lines below.
const TOP: f64 = 20.0;
const LEFT: f64 = 20.0;
const BOTTOM: f64 = 22.0;
/// The plot's size, mm: S/H over `WIDTH`; P over at least `MIN_HEIGHT` (a round μ_P is
/// chosen for twice that, so the plot is between one and two times it).
pub(super) const WIDTH: f64 = 100.0;
const MIN_HEIGHT: f64 = 60.0;

/// The P range (spanning zero, where the S/H axis runs) and its round scale μ_P, N/mm, for
/// a plot `grown` times the least.
fn force_scale(load: &Load, grown: f64) -> (f64, f64, f64) {
    let values = load.branches.iter().flat_map(|br| br.curve.points.iter().map(move |p| p.1 * br.scale));
    let (least, most) = values.fold((0.0f64, 0.0f64), |(lo, hi), y| (lo.min(y), hi.max(y)));
    (least, most, scale::round_up((most - least) / (2.0 * MIN_HEIGHT * grown)))
}

/// A load diagram's cell, mm: the plot `grown` times the least at its scale and the room
/// around it.
pub(super) fn cell_size(load: &Load, grown: f64) -> (f64, f64) {
    let (lo, hi, mu) = force_scale(load, grown);
    (LEFT + WIDTH * grown + 14.0, TOP + ((hi - lo) / mu).max(MIN_HEIGHT * grown) + BOTTOM)
}

/// A load diagram, its plot `grown` times the least: force against S/H for both strokes,
/// the analysed position marked; returns its μ_P and the length of its S/H axis, mm.
pub(super) fn draw_load(
    g: &mut Group,
    labels: &mut Labels,
    r: Rect,
    inp: &ForcesInput,
    (i, grown): (usize, f64),
) -> (f64, f64) {
    let load: &Load = &inp.fa.model.loads[i];
    let value = inp.fa.forces.loads[i];
    let n = inp.m.links[load.link].number;
    let lang = inp.words.lang;
    cell_title(g, r, &inp.words.sheet.load_title(&n.to_string()));
    let area = Rect::new(r.x0 + LEFT, r.y0 + TOP, r.x1 - 14.0, r.y1 - BOTTOM);
    let signed = |b: usize, y: f64| y * load.branches[b].scale;
    let (lo, hi, mu) = force_scale(load, grown);
    let along = value.along;
    let x = Axis {
        lo: 0.0,
        hi: 1.0,
        mu: 1.0 / area.width(),
        name: "S/H".into(),
        ticks: [0.0, 0.5, 1.0].map(|v| (v, fmt::localise(&format!("{v}"), lang))).to_vec(),
    };
    // Every level the diagram's corners stand at, read on the axis (the largest first where
    // two are closer than its ticks allow): P_max, the idle level and the steps between
    // them (only each stroke's least and largest were, leaving a working stroke's −21229 N
    // corner to be read off between round ticks).
    let levels: Vec<f64> = (0..load.branches.len())
        .flat_map(|b| load.branches[b].curve.points.iter().map(move |p| signed(b, p.1)))
        .collect();
    let ticks = level_ticks(&levels, lo, hi, mu, lang);
    let y = Axis { lo, hi, mu, name: format!("P, {}", inp.words.common.unit_n()), ticks };
    let mut plot = Plot::in_area(Rect::new(area.x0, area.y1 - (hi - lo) / mu, area.x1, area.y1), x, y);
    let (foot, mark) = (plot.at(value.s, 0.0), plot.at(value.s, along));
    let data: Vec<Vec<(f64, f64)>> = (load.branches.iter().enumerate())
        .map(|(b, br)| br.curve.points.iter().map(|&(s, y)| (s, signed(b, y))).collect())
        .collect();
    plot.x_above = Some(values_side(&plot, &data));
    leave_out_crossed_values(&mut plot, (foot, mark));
    plot.draw_axes(g);
    let mut names = Vec::new();
    for (b, br) in load.branches.iter().enumerate() {
        plot.line(g, &data[b], if b == 0 { MAIN } else { DASHED });
        let name = match br.name {
            Stroke::Working => inp.words.sheet.stroke_working(),
            Stroke::Idle => inp.words.sheet.stroke_idle(),
            Stroke::TowardHead => inp.words.sheet.stroke_toward_head(),
            Stroke::AwayFromHead => inp.words.sheet.stroke_away_from_head(),
            Stroke::Expansion => inp.words.sheet.stroke_expansion(),
            Stroke::Exhaust => inp.words.sheet.stroke_exhaust(),
            Stroke::Intake => inp.words.sheet.stroke_intake(),
            Stroke::Compression => inp.words.sheet.stroke_compression(),
        };
        names.push(name);
    }
    g.line(foot, mark, THIN);
    g.circle(mark, MARK_R, MAIN);
    let at_s = |b: usize, s: f64| signed(b, load.branches[b].curve.at(s));
    let arrows = stroke_arrows(g, &plot, &at_s, value.s);
    // Each stroke named beside its arrow, on the side away from the other stroke's line
    // (where the lines run together, the first above and the second below) or, along the
    // axis, from the S/H values; without an
    // arrow, at its own fraction of the stroke (apart from the other's name and from the S/H
    // values at 0, ½ and 1).
    let names: Vec<(Point, Vec2, &str)> = (names.into_iter().enumerate())
        .map(|(b, name)| {
            let s = arrows[b].unwrap_or((b + 1) as f64 / (load.branches.len() + 1) as f64);
            let (at, other) = (plot.at(s, at_s(b, s)), plot.at(s, at_s(1 - b, s)));
            // A line along the axis (within 3 mm) is named on the side away from the S/H
            // values: beside them «0,5 от крышки» read as one phrase (two fixtures).
            let axis_y = plot.at(s, 0.0).y;
            let up = if (at.y - axis_y).abs() < 3.0 {
                !plot.x_values_above()
            } else if (other.y - at.y).abs() > 1.0 {
                other.y > at.y
            } else {
                b == 0
            };
            (at, Vec2::new(0.3, if up { -1.0 } else { 1.0 }), name)
        })
        .collect();
    let phi = fmt::localise(&format!("{:.1}", inp.phi_deg), lang);
    // On the side of its branch away from that branch's name: beside the name,
    // "φ1 = 45,0° ishchi yurish" read as one phrase.
    let off = |b: usize| (signed(b, load.branches[b].curve.at(value.s)) - along).abs();
    let on = (0..load.branches.len()).min_by(|&a, &b| off(a).total_cmp(&off(b))).unwrap_or(0);
    // A mark on the axis (within 3 mm) takes φ₁ away from the S/H values, whose row it
    // would join («0   φ₁ = 60,0°   0,5   1», the offset crank-slider); the band of their
    // row is kept clear of it either way.
    let on_axis = (mark.y - foot.y).abs() < 3.0;
    let side = if on_axis {
        if plot.x_values_above() { 1.0 } else { -1.0 }
    } else {
        -names.get(on).map_or(-1.0, |n| n.1.y.signum())
    };
    if let Some(row) = x_values_row(&plot) {
        labels.keep_clear(row);
    }
    for (at, pref, name) in names {
        labels.add_text(at, pref, name, 2.5);
    }
    labels.add(mark, Vec2::new(1.0, side), LabelText::new("φ", "1").with_tail(format!(" = {phi}°")), 2.5);
    let lines = [
        vec![LabelText::new("φ", "1").with_tail(format!(
            ": S/H = {}, P = {} {}",
            fmt::value(value.s, lang),
            fmt::value(along, lang),
            inp.words.common.unit_n()
        ))],
        vec![scale_item(inp, "P", mu, inp.words.common.unit_n_per_mm())],
    ];
    text_rows(g, r.x0 + 2.0, r.y1 - 2.0 - LINE, &lines);
    (mu, area.width())
}

/// The band of the S/H values' row, along the whole axis (a label there reads as one more
/// value), if any value is written.
fn x_values_row(plot: &Plot) -> Option<Rect> {
    let row = (plot.x.ticks.iter())
        .filter(|(_, label)| !label.is_empty())
        .map(|(v, label)| plot.x_value(*v, label).bbox())
        .reduce(|a, b| a.union(b))?;
    let area = plot.area();
    Some(Rect::new(area.x0, row.y0, area.x1, row.y1))
}

/// The side of the S/H axis (above: `true`) its values stand on: the plot's own where no
/// curve runs through them, else the other where none does there (a small idle force's line
/// ran through "0", "0.5" and "1" above the axis, an audit of 120 random crank-sliders; one
/// passing over their tops, within a millimetre, reads as crossing them too); `data` are the
/// curves in the plot's units.
fn values_side(plot: &Plot, data: &[Vec<(f64, f64)>]) -> bool {
    let curves: Vec<Vec<Point>> = data.iter().map(|c| c.iter().map(|&(x, y)| plot.at(x, y)).collect()).collect();
    let crossed = |above: bool| {
        let p = Plot { x_above: Some(above), ..plot.clone() };
        p.x.ticks.iter().filter(|(_, label)| !label.is_empty()).any(|(v, label)| {
            let b = p.x_value(*v, label).bbox().inflate(1.0, 1.0);
            curves.iter().any(|c| c.windows(2).any(|w| segment_meets_rect(w[0], w[1], b)))
        })
    };
    let own = plot.x_values_above();
    if crossed(own) && !crossed(!own) { !own } else { own }
}

/// Leaves out an x value that the analysed position's ordinate (from the axis to its mark)
/// or its mark's circle would cross: its tick stays, and the position's S/H is written under
/// the diagram (a mark at S/H = 0 on an idle level 5 mm up stood on the «0»).
fn leave_out_crossed_values(plot: &mut Plot, (foot, mark): (Point, Point)) {
    let (y0, y1) = (foot.y.min(mark.y), foot.y.max(mark.y));
    let circle = Rect::from_center_size(mark, (2.0 * MARK_R, 2.0 * MARK_R)).inflate(0.3, 0.3);
    let crossed: Vec<bool> = plot
        .x
        .ticks
        .iter()
        .map(|(v, label)| {
            let b = plot.x_value(*v, label).bbox();
            let on_ordinate = (b.x0 - 0.3..=b.x1 + 0.3).contains(&foot.x) && b.y0 < y1 && b.y1 > y0;
            on_ordinate || b.intersect(circle).area() > 0.0
        })
        .collect();
    for ((_, label), crossed) in plot.x.ticks.iter_mut().zip(crossed) {
        if crossed {
            label.clear();
        }
    }
}

/// The radius of the analysed position's mark on its stroke's line, mm.
const MARK_R: f64 = 1.0;

/// Clearance of a stroke's arrow from the analysed position's ordinate, the S/H values and
/// the other stroke's arrow, along the axis, mm.
const ARROW_CLEAR: f64 = 6.0;
/// A stroke's arrowhead's length and half width, mm: a thin line's (3 × 0.55) hid in the
/// working stroke's main line.
const STROKE_ARROW: (f64, f64) = (5.0, 1.3);
/// How far behind its arrowhead a stroke's name hangs from its line, mm.
const NAME_BEHIND: f64 = 1.5;

/// The sense in S/H of stroke `b`'s arrow: the first along the axis, the second back.
fn stroke_sense(b: usize) -> f64 {
    if b == 0 { 1.0 } else { -1.0 }
}

/// Stroke `b`'s arrowhead at `s`: [`STROKE_ARROW`], narrowed where a line runs beside it
/// nearer than its wings reach (the axis or the other stroke, not one it lies on): the
/// axial crank-slider's exhaust at 228 N, 1.1 mm over the axis, had its head across the
/// axis, and the two read as one line.
fn arrow_size(plot: &Plot, y_at: &dyn Fn(usize, f64) -> f64, b: usize, s: f64) -> (f64, f64) {
    let (long, half) = STROKE_ARROW;
    let reach = long / 2.0 * plot.x.mu;
    let beside = [s - reach, s, s + reach].into_iter().flat_map(|at| {
        let here = plot.at(at, y_at(b, at)).y;
        let others = (0..2).filter(|&o| o != b).map(move |o| y_at(o, at));
        std::iter::once(0.0).chain(others).map(move |y| (plot.at(at, y).y - here).abs())
    });
    let nearest = beside.filter(|&d| d > ON_THE_LINE).fold(f64::INFINITY, f64::min);
    (long, half.min((nearest - ARROW_GAP).max(ARROW_HALF_LEAST)))
}

/// A line nearer a stroke's than this, mm, is the one it lies on.
const ON_THE_LINE: f64 = 0.2;
/// An arrowhead's wings keep this far from a line beside its stroke's, mm.
const ARROW_GAP: f64 = 0.35;
/// The narrowest half width of a stroke's arrowhead, mm.
const ARROW_HALF_LEAST: f64 = 0.5;

/// Whether a line through the three points on paper rises no steeper than
/// [`ARROW_SLOPE`] between any two neighbours.
fn gentle([l, m, r]: [Point; 3]) -> bool {
    [(l, m), (m, r)].iter().all(|(a, c)| (c.y - a.y).abs() <= ARROW_SLOPE * (c.x - a.x).abs())
}

/// Steepest slope on paper a stroke's arrow stands on (63°): on a step it would read as
/// pointing up or down; a compression's curve is steep all along.
const ARROW_SLOPE: f64 = 2.0;

/// Each stroke's direction of travel, an arrowhead on its line (the first branch moves
/// along the axis, towards S/H = 1; the second back): the two strokes share the S/H axis,
/// and without them a reader cannot tell the working stroke's line from the idle one's
/// where both run along it. Each stands where its line runs farthest (up to 4 mm) from
/// the other's and flat, in the middle of such stretch, clear of the analysed position
/// `mark_s`, the S/H values and the other arrow; `y_at(b, s)` is stroke b's force at s, in
/// the plot's units. Returns the S/H each stroke's name hangs from, behind its arrow.
fn stroke_arrows(g: &mut Group, plot: &Plot, y_at: &dyn Fn(usize, f64) -> f64, mark_s: f64) -> Vec<Option<f64>> {
    // A load has two branches (`Load::branches`): along the axis, and back.
    const STROKES: usize = 2;
    let mm = |s: f64| s / plot.x.mu;
    let mut taken: Vec<f64> = vec![mark_s, 0.0, 0.5, 1.0];
    let mut chosen = Vec::with_capacity(STROKES);
    for b in 0..STROKES {
        let others: Vec<usize> = (0..STROKES).filter(|&o| o != b).collect();
        let point = |s: f64| plot.at(s, y_at(b, s));
        let flat = |s: f64| gentle([point(s - 0.02), point(s), point(s + 0.02)]);
        let apart = |s: f64| {
            let here = point(s);
            others.iter().map(|&o| (plot.at(s, y_at(o, s)).y - here.y).abs()).fold(4.0f64, f64::min)
        };
        let clear = |s: f64| taken.iter().all(|&t| (mm(s) - mm(t)).abs() >= ARROW_CLEAR);
        let candidates: Vec<f64> = (6..=94).map(|k| f64::from(k) / 100.0).filter(|&s| flat(s) && clear(s)).collect();
        let most = candidates.iter().map(|&s| apart(s)).fold(0.0f64, f64::max);
        let best: Vec<f64> = candidates.into_iter().filter(|&s| apart(s) >= most - 1e-9).collect();
        let Some(&s) = best.get(best.len() / 2) else {
            chosen.push(None);
            continue;
        };
        let sense = stroke_sense(b);
        let dir = (point(s + 0.02) - point(s - 0.02)) * sense;
        let len = dir.norm();
        if len > 0.0 {
            let (u, (long, half)) = (dir / len, arrow_size(plot, y_at, b, s));
            let (tip, n) = (point(s) + u * (long / 2.0), Vec2::new(-u.y, u.x));
            let base = tip - u * long;
            g.fill(&[tip, base + n * half, base - n * half]);
        }
        taken.push(s);
        // The name hangs from the line behind the arrowhead (from the arrow's middle its
        // leader ran out across the filled head: 83 catalogue sheets), at its base where
        // the line bends sooner (behind a step's corner, the name hung halfway up the step).
        let at_base = s - sense * STROKE_ARROW.0 / 2.0 * plot.x.mu;
        let behind = at_base - sense * NAME_BEHIND * plot.x.mu;
        let straight = gentle([point(behind), point((behind + s) / 2.0), point(s)]);
        chosen.push(Some(if straight { behind } else { at_base }));
    }
    chosen
}
