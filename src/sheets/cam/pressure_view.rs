//! The pressure angle over the working angle, α(φ): read off the finished profile (not the
//! analog construction the centre was found with), each position's ordinate drawn, the
//! allowed angle of each phase dashed over its span and the largest angle of each phase
//! marked. It shows on the sheet the check the nomogram promises; it is drawn where the
//! other views leave room for it ([`super::regions::free_room`]).

use super::labels::CamWords;
use super::nomogram::position_labels;
use crate::cams::Design;
use crate::cams::radius::Phase;
use crate::drawing::fmt;
use crate::drawing::place::Labels;
use crate::drawing::plot::{Axis, Plot, round_ticks};
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN};
use crate::drawing::text::LabelText;
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// Room round the plot inside its region, mm: the title, two scale lines and the largest
/// angles' line above (and the y axis' arrow and name over the plot), the y values on the left, the x axis' arrow and
/// name on the right, the position numbers below.
const TOP: f64 = 30.5;
const LEFT: f64 = 12.0;
const RIGHT: f64 = 14.0;
const BOTTOM: f64 = 9.0;

/// The least plot the diagram is drawn at, mm (width, height): below it the values would
/// not be measurable and the diagram is left out.
pub const MIN_PLOT: (f64, f64) = (100.0, 40.0);

/// The plot is at most this much taller than wide.
const MAX_ASPECT: f64 = 1.0;

/// The diagram's scales, for `results.json`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureScales {
    /// °/mm along the working angle.
    pub mu_phi_deg: f64,
    /// °/mm of pressure angle.
    pub mu_alpha_deg: f64,
}

/// The plot's size in a region `r`, mm, if it is at least [`MIN_PLOT`].
pub fn plot_size(r: Rect) -> Option<(f64, f64)> {
    let w = r.width() - LEFT - RIGHT;
    let h = (r.height() - TOP - BOTTOM).min(w * MAX_ASPECT);
    (w >= MIN_PLOT.0 && h >= MIN_PLOT.1).then_some((w, h))
}

/// The largest pressure angle the diagram shows, degrees: the allowed ones and the largest
/// reached, whichever is higher.
fn alpha_top(d: &Design) -> f64 {
    let a = &d.spec.allowed;
    let reached = d.max_pressure.iter().map(|m| m.0).fold(0.0, f64::max);
    a.rise.max(a.ret).max(reached).to_degrees()
}

/// The diagram in `region` (its title and scales at the top left, the plot under them at
/// round scales that fill the room), and its scales; `None` where the region is too small.
pub fn draw(region: Rect, d: &Design, phis: &[f64], title: &str, words: &CamWords) -> Option<(Group, PressureScales)> {
    let (w, h) = plot_size(region)?;
    // A region narrower than the title in the sheet's section lettering leaves it out, as
    // one too small for its plot does.
    if super::view_heading::heading_w(title) > region.width() {
        return None;
    }
    let p = &d.spec.program;
    let work = (p.rise + p.far_dwell + p.ret).to_degrees();
    let lang = words.lang;
    let mu_phi = scale::plan_round_up(work / w);
    let top = alpha_top(d);
    // Where the numbers take two rows, the plot gives the second its height.
    let names = position_labels(phis);
    let lower = staggered(mu_phi, phis, &names);
    let h = if lower { (h - STAGGER).max(MIN_PLOT.1) } else { h };
    let mu_alpha = scale::plan_round_up(top / h);
    let mut g = super::view_heading::view_group("pressure", region, title);
    let l = words.sheet;
    let mu_line = |q: &str, mu: f64, y: f64, g: &mut Group| {
        LabelText::new("μ", q).with_tail(format!(" = {} {}", fmt::trimmed(mu, lang), l.unit_deg_per_mm())).draw(
            g,
            Point::new(region.x0 + 2.0, region.y0 + y),
            2.5,
            crate::drawing::scene::Anchor::Start,
        );
    };
    mu_line("φ", mu_phi, 10.5, &mut g);
    mu_line("α", mu_alpha, 15.0, &mut g);
    let ticks: Vec<(f64, String)> = phis.iter().map(|&phi| (phi.to_degrees(), String::new())).collect();
    let plot = Plot {
        origin: Point::new(region.x0 + LEFT, region.y0 + TOP + top / mu_alpha),
        x: Axis { lo: 0.0, hi: work, mu: mu_phi, name: "φ".into(), ticks },
        y: Axis {
            lo: 0.0,
            hi: top,
            mu: mu_alpha,
            name: format!("α, {}", l.unit_deg()),
            ticks: round_ticks(0.0, top, mu_alpha, lang),
        },
        x_above: None,
    };
    plot.draw_axes(&mut g);
    let alpha = |phi: f64| d.profile.pressure_angle_on_profile(phi).to_degrees();
    let n = (work * 4.0).ceil() as usize;
    let curve: Vec<(f64, f64)> = (0..=n)
        .map(|k| {
            // Just inside the working angle at its end, where the near dwell begins.
            let phi = (work * k as f64 / n as f64).to_radians().min((work).to_radians() - tol::INSIDE_PHASE);
            (phi.to_degrees(), alpha(phi))
        })
        .collect();
    plot.line(&mut g, &curve, MAIN);
    let mut labels = Labels::new();
    for (k, (&phi, name)) in phis.iter().zip(names).enumerate() {
        let a = alpha(phi.min((work).to_radians() - tol::INSIDE_PHASE));
        if a / mu_alpha >= 0.5 {
            g.line(plot.at(phi.to_degrees(), 0.0), plot.at(phi.to_degrees(), a), THIN);
        }
        if let Some(name) = name {
            let below = if lower && k % 2 == 1 { 1.5 + STAGGER } else { 1.5 };
            let at = plot.at(phi.to_degrees(), 0.0) + Vec2::new(0.0, below);
            labels.add_text(at, Vec2::new(0.0, 1.0), &name, NUMBER_H);
        }
    }
    allowed_and_largest(&mut g, &plot, d, &mut labels, words);
    labels.place(&mut g, region);
    Some((g, PressureScales { mu_phi_deg: mu_phi, mu_alpha_deg: mu_alpha }))
}

/// The position numbers' lettering, mm.
const NUMBER_H: f64 = 2.5;
/// How much lower the odd positions' numbers stand where the numbers do not fit side by
/// side, mm: a row of their own under the even ones, clear of them by the labels' own
/// clearance (the plot is this much lower for it).
const STAGGER: f64 = 4.4;

/// Whether the odd positions' numbers go a row lower: where two neighbours' numbers, each
/// with the room the labels keep round them, are wider than the step between their
/// positions (task 2 variant 35: 4.4 mm between "13" and "14"; in one row the numbers from
/// 11 on slid right, "15" under position 16's tick and "17" under the axis' arrow).
fn staggered(mu_phi: f64, phis: &[f64], names: &[Option<String>]) -> bool {
    let width = |n: &Option<String>| {
        n.as_ref().map_or(0.0, |n| crate::drawing::place::label_size(&LabelText::new(n.as_str(), ""), NUMBER_H).0)
    };
    (1..phis.len()).any(|k| {
        let step = (phis[k] - phis[k - 1]).abs().to_degrees() / mu_phi;
        let room = (width(&names[k - 1]) + width(&names[k])) / 2.0 + NUMBERS_APART;
        names[k - 1].is_some() && names[k].is_some() && step < room
    })
}

/// The least clear space between two numbers side by side, mm (the labels' own clearance
/// each side and a little).
const NUMBERS_APART: f64 = 1.4;

/// Each phase's allowed angle dashed over its span, named above its middle, and its largest
/// angle as a dot on the curve, its value in a line under the scales (beside the dot, where
/// the largest angle is the allowed one, the value's subscript met the dashed line).
fn allowed_and_largest(g: &mut Group, plot: &Plot, d: &Design, labels: &mut Labels, words: &CamWords) {
    // The largest angles' line under the scales, the values side by side.
    let (mut x, baseline) = (g.region.x0 + 2.0, g.region.y0 + 19.5);
    let (l, lang) = (words.sheet, words.lang);
    for (k, ph) in Phase::BOTH.into_iter().enumerate() {
        let (a, b) = ph.span(&d.spec.program);
        if b - a <= 0.0 {
            continue;
        }
        let allowed = ph.allowed(&d.spec.allowed).to_degrees();
        let (pa, pb) = (plot.at(a.to_degrees(), allowed), plot.at(b.to_degrees(), allowed));
        g.line(pa, pb, DASHED);
        let (sub_allowed, sub_max) = match ph {
            Phase::Rise => (l.sub_allowed_rise(), l.sub_max_rise()),
            Phase::Return => (l.sub_allowed_return(), l.sub_max_return()),
        };
        let deg = |v: f64| format!(" = {}°", fmt::trimmed(v, lang));
        labels.add(
            pa.midpoint(pb),
            Vec2::new(0.0, -1.0),
            LabelText::new("α", sub_allowed).with_tail(deg(allowed)),
            2.5,
        );
        let (largest, at) = d.max_pressure[k];
        g.dot(plot.at(at.to_degrees(), largest.to_degrees()), 0.6);
        let value = LabelText::new("α", sub_max).with_tail(deg(largest.to_degrees()));
        value.draw(g, Point::new(x, baseline), 2.5, Anchor::Start);
        x += value.width(2.5) + 5.0;
    }
}
