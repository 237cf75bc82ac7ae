//! Sheet 1's mechanism region: the largest GOST μ_l that fits its box (with a force
//! analysis, the tallest box that leaves the force drawings below it room), and the
//! mechanism drawn there with its header and the trajectories' legend.

use super::compose::{Column, HEADER, Input, TOP, force_region_below, region_header, side_region};
use super::forces_view::{ForcesInput, fit_comfortably};
use super::labels::LeverWords;
use super::mechanism_view::{MechanismView, TRAJECTORY, world_extent};
use crate::drawing::fmt;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{Anchor, Group, Text};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::lever::analysis::Kinematics;
use kurbo::{Point, Rect};

/// The mechanism's region at most, mm; it shrinks to the drawing at the chosen μ_l.
const MECH_MAX_W: f64 = 450.0;
const MECH_MAX_H: f64 = 300.0;
/// The least width of the mechanism's drawing, mm.
const MECH_MIN_W: f64 = 200.0;
/// The least where tables 3–5 go beside the mechanism, mm: its region is at least as wide
/// as its header and legend too.
const MECH_MIN_W_BESIDE: f64 = 120.0;
/// With a force analysis the mechanism's box is the first of these heights that leaves the
/// force drawings enough room.
const MECH_HEIGHTS_FORCES: [f64; 7] = [300.0, 260.0, 230.0, 200.0, 175.0, 150.0, 130.0];
/// Space around the mechanism drawing for its letters, pivots and guides.
const MECH_PAD: f64 = 14.0;
/// The mechanism's region and scale, before it is drawn.
pub(super) struct MechanismPlace {
    world: Rect,
    pub(super) region: Rect,
    pub(super) mu_l: f64,
    /// The drawing's height at `mu_l`, mm.
    draw_h: f64,
    /// Whether the force drawings fit below it comfortably.
    pub(super) comfortable: bool,
}

/// The mechanism drawn in its region.
pub(super) struct MechanismDrawn {
    pub(super) group: Group,
    pub(super) region: Rect,
    pub(super) mu_l: f64,
}

/// The mechanism's place: the largest GOST μ_l that fits its box, the region shrunk to the
/// drawing. With a force analysis the box is the tallest that leaves the force drawings
/// below it room without cramping them.
pub(super) fn mechanism_place(
    inp: &Input,
    k: &Kinematics,
    forces: Option<&ForcesInput>,
    column: Column,
) -> MechanismPlace {
    let world = world_extent(&inp.project.mechanism, k, &inp.project.kulisa_lengths);
    let words = LeverWords::new(inp.ctx.info.language);
    // Where the tables go beside the mechanism, a region wider than its drawing leaves
    // paper empty that they could use; narrower than its header, it would cross the
    // region beside it.
    let beside = forces.is_some_and(|f| f.tables_beside);
    let header_w = |mu_l: f64| if beside { header_width(mu_l, k, &words).max(MECH_MIN_W_BESIDE) } else { MECH_MIN_W };
    let heights: &[f64] = if forces.is_some() { &MECH_HEIGHTS_FORCES } else { &[MECH_MAX_H] };
    let fits = |h: f64| {
        let (r, _, _) = mechanism_region(world, h, column.inner, header_w);
        let below = force_region_below(r, column);
        forces.is_none_or(|fi| fit_comfortably(fi, below, side_region(r, below)))
    };
    let comfortable = heights.iter().copied().find(|&h| fits(h));
    let max_h = comfortable.unwrap_or(heights[heights.len() - 1]);
    let (region, mu_l, draw_h) = mechanism_region(world, max_h, column.inner, header_w);
    MechanismPlace { world, region, mu_l, draw_h, comfortable: comfortable.is_some() }
}

/// The mechanism drawn at its place.
pub(super) fn mechanism_group(
    inp: &Input,
    k: &Kinematics,
    words: &LeverWords,
    place: MechanismPlace,
) -> MechanismDrawn {
    let MechanismPlace { world, region, mu_l, draw_h, .. } = place;
    let m = &inp.project.mechanism;
    let mut group = Group::new("mechanism", region);
    let origin = Point::new(
        region.center().x - world.center().x / mu_l,
        region.y0 + HEADER + MECH_PAD + draw_h / 2.0 + world.center().y / mu_l,
    );
    mechanism_header(&mut group, region, mu_l, k, words);
    trajectory_legend(&mut group, region, words);
    let mut labels = Labels::new();
    MechanismView { m, k, view: View::new(origin, mu_l), kulisa: &inp.project.kulisa_lengths, words }
        .draw(&mut group, &mut labels);
    labels.place(&mut group, region.inflate(-0.5, -0.5));
    MechanismDrawn { group, region, mu_l }
}

/// The mechanism's title, μ_l, the structure formula and the degrees of freedom.
fn mechanism_header(g: &mut Group, region: Rect, mu_l: f64, k: &Kinematics, words: &LeverWords) {
    region_header(g, region, words.sheet.positions_title(), &header_lines(mu_l, k, words));
}

/// The header's line under its title: μ_l, the structure formula and the degrees of freedom.
fn header_lines(mu_l: f64, k: &Kinematics, words: &LeverWords) -> [LabelText; 3] {
    let (l, c, lang) = (words.sheet, words.common, words.lang);
    let s = &k.structure;
    [
        LabelText::new("μ", "l").with_tail(format!(
            " = {} {}",
            fmt::localise(&scale::format(mu_l), lang),
            c.unit_m_per_mm()
        )),
        LabelText::new(format!("{}: {}", l.structure(), s.formula), ""),
        LabelText::new(format!("W = 3·{} − 2·{} − {} = {}", s.moving_links, s.p5, s.p4, s.dof), ""),
    ]
}

/// The drawing's width that leaves its header and the trajectories' legend room at
/// `mu_l`, mm (as
/// [`region_header`] and [`trajectory_legend`] set them, with a margin).
fn header_width(mu_l: f64, k: &Kinematics, words: &LeverWords) -> f64 {
    let lines = header_lines(mu_l, k, words);
    let line = lines.iter().map(|l| l.width(3.5) + 8.0).sum::<f64>() - 8.0;
    let title = LabelText::new(words.sheet.positions_title(), "").width(5.0);
    let legend = 16.0 + LabelText::new(words.sheet.trajectories(), "").width(2.5);
    line.max(title).max(legend) + 6.0 - 2.0 * MECH_PAD
}

/// The legend shows the trajectories' own line type, then says what it is.
fn trajectory_legend(g: &mut Group, region: Rect, words: &LeverWords) {
    let legend_y = region.y1 - 2.0;
    let sample = (Point::new(region.x0 + 2.0, legend_y - 1.2), Point::new(region.x0 + 16.0, legend_y - 1.2));
    g.writing_line(sample.0, sample.1, TRAJECTORY);
    g.text(Text::new(Point::new(region.x0 + 18.0, legend_y), words.sheet.trajectories(), 2.5, Anchor::Start));
}

/// The mechanism's region for a box at most `max_h` tall, its drawing at least
/// `least_w(μ_l)` wide at the scale chosen: its scale, and the drawing's height.
fn mechanism_region(world: Rect, max_h: f64, inner: Rect, least_w: impl Fn(f64) -> f64) -> (Rect, f64, f64) {
    let (avail_w, avail_h) = (MECH_MAX_W - 2.0 * MECH_PAD, max_h - HEADER - 2.0 * MECH_PAD);
    let mu_l = scale::length_scale((world.width() / avail_w).max(world.height() / avail_h));
    let draw_w = (world.width() / mu_l).max(least_w(mu_l));
    let draw_h = world.height() / mu_l;
    let r = Rect::new(
        inner.x0 + 5.0,
        TOP,
        inner.x0 + 5.0 + draw_w + 2.0 * MECH_PAD,
        TOP + HEADER + draw_h + 2.0 * MECH_PAD + 4.0,
    );
    (r, mu_l, draw_h)
}
