//! The diagram of specific sliding λ1, λ2 over the line of action N1N2 (`gears::sliding`),
//! drawn inside the mesh's region in the largest room its circles leave (a large wheel's
//! inside is otherwise empty), the active line B1B2 marked and the largest sliding of each
//! flank, at B1 and B2, written under the scales. Left out where no room is large enough
//! or a label finds no clean spot: the mesh is never moved or shrunk for it.

use super::labels::GearWords;
use crate::drawing::fmt;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::place::Labels;
use crate::drawing::plot::{Axis, Plot, round_ticks};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN, Text};
use crate::drawing::text::LabelText;
use crate::gears::sliding::Sliding;
use kurbo::{Point, Rect, Vec2};

/// The room's grid, mm: a cell is free where nothing of the mesh meets it grown by 1 mm.
const CELL: f64 = 4.0;
/// The least room, mm (width, height), and how much taller than wide its plot may be.
const MIN_ROOM: (f64, f64) = (120.0, 80.0);
const MAX_ASPECT: f64 = 0.75;
/// Room round the plot inside the diagram's box, mm: title, two scale lines and the
/// largest slidings' line above (and the y axis' arrow), values left, the x axis' arrow
/// and name right, the points' names below.
const TOP: f64 = 30.0;
const LEFT: f64 = 12.0;
const RIGHT: f64 = 18.0;
const BOTTOM: f64 = 8.0;
/// The most negative sliding shown: the curves run off the plot beyond it.
const LAMBDA_FLOOR: f64 = -8.0;

/// What the diagram measured: λ1 at B1 and λ2 at B2 (none where that end of the active line
/// is at N: interference, the sliding there unbounded), and its scales (m/mm, 1/mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingDrawn {
    pub lambda: [Option<f64>; 2],
    pub mu_l: f64,
    pub mu_lambda: f64,
}

/// Draws the diagram into `mesh` in the largest free room of `area`; `None` (nothing
/// drawn) where there is no room at least [`MIN_ROOM`] or its labels find no spot.
pub fn draw(mesh: &mut Group, area: Rect, s: &Sliding, title: &str, words: &GearWords) -> Option<SlidingDrawn> {
    let room = free_room(mesh, area)?;
    let mut g = Group::new("sliding", room);
    let drawn = draw_in(&mut g, room, s, title, words)?;
    mesh.items.extend(g.items);
    Some(drawn)
}

/// The largest rectangle of `area` on the grid of [`CELL`] that nothing of `g` meets, at
/// least [`MIN_ROOM`], scored by the plot it holds.
fn free_room(g: &Group, area: Rect) -> Option<Rect> {
    let plot = |w: f64, h: f64| (w - LEFT - RIGHT) * (h - TOP - BOTTOM).min((w - LEFT - RIGHT) * MAX_ASPECT);
    super::room::largest(&Obstacles::of_items(&g.items), area, CELL, MIN_ROOM, plot).map(|r| r.inset(-1.0))
}

/// The diagram in `room`: its plot at round scales that fill the room.
fn draw_in(g: &mut Group, room: Rect, s: &Sliding, title: &str, words: &GearWords) -> Option<SlidingDrawn> {
    let lang = words.lang;
    // An end of the active line at N (a tip reaching past it: interference) slides without
    // bound there.
    let at_b = [
        (s.active[0] > s.line * 1e-9).then(|| s.lambda(0, s.active[0])),
        (s.active[1] < s.line * (1.0 - 1e-9)).then(|| s.lambda(1, s.active[1])),
    ];
    let lowest = at_b.iter().map(|l| l.unwrap_or(f64::NEG_INFINITY)).fold(-1.0, f64::min).clamp(LAMBDA_FLOOR, -1.0);
    let w = room.width() - LEFT - RIGHT;
    let mu_l = scale::plan_round_up(s.line / w);
    let h = (room.height() - TOP - BOTTOM).min(s.line / mu_l * MAX_ASPECT);
    let mu_lambda = scale::plan_round_up((1.0 - lowest) / h);
    let ticks: Vec<(f64, String)> = Vec::new();
    let plot = Plot {
        origin: Point::new(room.x0 + LEFT, room.y0 + TOP + 1.0 / mu_lambda),
        x: Axis { lo: 0.0, hi: s.line, mu: mu_l, name: "N₁N₂".into(), ticks },
        y: Axis { lo: lowest, hi: 1.0, mu: mu_lambda, name: "λ".into(), ticks: lambda_ticks(lowest, mu_lambda, lang) },
        x_above: None,
    };
    g.text(Text::new(Point::new(room.x0 + 2.0, room.y0 + 5.0), title, 3.5, Anchor::Start));
    let unit = words.common.unit_m_per_mm();
    let line =
        |g: &mut Group, t: LabelText, y: f64| t.draw(g, Point::new(room.x0 + 2.0, room.y0 + y), 2.5, Anchor::Start);
    line(g, LabelText::new("μ", "l").with_tail(format!(" = {} {unit}", fmt::trimmed(mu_l, lang))), 10.5);
    line(
        g,
        LabelText::new("μ", "λ").with_tail(format!(
            " = {} 1/{}",
            fmt::trimmed(mu_lambda, lang),
            words.common.unit_mm()
        )),
        15.0,
    );
    let mut x = room.x0 + 2.0;
    for (i, point) in [(0, "B₁"), (1, "B₂")] {
        let v = LabelText::new("λ", if i == 0 { "1" } else { "2" }).with_tail(match at_b[i] {
            Some(v) => format!(" ({point}) = {}", fmt::value(v, lang)),
            None => format!(" ({point}) → −∞"),
        });
        v.draw(g, Point::new(x, room.y0 + 19.5), 2.5, Anchor::Start);
        // Further apart than two values read as one phrase (a gap of exactly phrases::APART
        // heights, 5 mm, ran «λ₁ (B₁) → −∞» into «λ₂ (B₂) = −2.610»).
        x += v.width(2.5) + (crate::drawing::phrases::APART + 0.4) * 2.5;
    }
    plot.draw_axes(g);
    // Each flank's curve where it is within the plot: λ1 from where it reaches the lowest
    // value to N2, λ2 from N1 to where it reaches it.
    let from1 = s.line / (1.0 + (1.0 - lowest) * s.ratio);
    let to2 = (1.0 - lowest) * s.line / (s.ratio + 1.0 - lowest);
    // Laid as the mesh draws N1N2: N2 on the left (where the λ axis stands), N1 on the
    // right; `x` is measured from N1 as the sliding is.
    let flip = |x: f64| s.line - x;
    let curve = |i: usize, a: f64, b: f64| -> Vec<(f64, f64)> {
        (0..=200).map(|k| a + (b - a) * k as f64 / 200.0).map(|x| (flip(x), s.lambda(i, x).max(lowest))).collect()
    };
    // Both flanks work only on the active line B1B2: there the curves are main lines, beyond
    // it thin (each runs on to the plot's floor, or to its N).
    let edge = s.line * 1e-6;
    let active = (s.active[0].max(edge), s.active[1].min(s.line - edge));
    for (i, (a, b)) in [(0, (from1, s.line - edge)), (1, (edge, to2))] {
        let (lo, hi) = (a.max(active.0), b.min(active.1));
        if lo >= hi {
            plot.line(g, &curve(i, a, b), THIN);
            continue;
        }
        plot.line(g, &curve(i, lo, hi), MAIN);
        for (x0, x1) in [(a, lo), (hi, b)] {
            if x1 - x0 > edge {
                plot.line(g, &curve(i, x0, x1), THIN);
            }
        }
    }
    let mut labels = Labels::new();
    // The active line's ends, each with the sliding there; N1, P, N2 on the axis.
    for (&xb, v) in s.active.iter().zip(at_b) {
        if let Some(v) = v {
            g.line(plot.at(flip(xb), 0.0), plot.at(flip(xb), v.max(lowest)), DASHED);
        }
    }
    // A B at its N (interference: the sliding there unbounded) is named with it, "N₁ ≡ B₁".
    let at_n = |i: usize, n: &str| if at_b[i].is_none() { format!(" ≡ B{n}") } else { String::new() };
    let names = [
        (Some(0.0), LabelText::new("N", "1").with_tail(at_n(0, "₁"))),
        (at_b[0].map(|_| s.active[0]), LabelText::new("B", "1")),
        (Some(s.pitch_point), LabelText::new("P", "")),
        (at_b[1].map(|_| s.active[1]), LabelText::new("B", "2")),
        (Some(s.line), LabelText::new("N", "2").with_tail(at_n(1, "₂"))),
    ];
    for (x, name) in names.into_iter().filter_map(|(x, name)| x.map(|x| (x, name))) {
        let p = plot.at(flip(x), 0.0);
        g.line(p, p + Vec2::new(0.0, 1.5), THIN);
        labels.add(p + Vec2::new(0.0, 1.5), Vec2::new(0.0, 1.0), name, 2.5);
    }
    for (i, x) in [(0, (s.pitch_point + s.line) / 2.0), (1, s.pitch_point / 2.0)] {
        let p = plot.at(flip(x), s.lambda(i, x).max(lowest));
        labels.add(
            p,
            Vec2::new(if i == 0 { -1.0 } else { 1.0 }, -1.0),
            LabelText::new("λ", if i == 0 { "1" } else { "2" }),
            2.5,
        );
    }
    let placed = labels.place(g, room);
    (!placed.contains(&false)).then_some(SlidingDrawn { lambda: at_b, mu_l, mu_lambda })
}

/// The λ axis's ticks: the round ones from `lowest` up, and λ = 1, the most a flank slides
/// (at the other wheel's N), where no round one is within 4 mm of it: the axis read only
/// −6, −4, −2 under the curves' tops.
fn lambda_ticks(lowest: f64, mu: f64, lang: crate::drawing::labels::Language) -> Vec<(f64, String)> {
    let mut ticks = round_ticks(lowest, 1.0, mu, lang);
    if ticks.iter().all(|(v, _)| (1.0 - v) / mu >= 4.0) {
        ticks.push((1.0, "1".to_string()));
    }
    ticks
}
