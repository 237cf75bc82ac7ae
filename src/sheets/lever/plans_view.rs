//! Velocity and acceleration plans, each position in its own cell at one common scale.
//!
//! Course drawings either overlay all velocity plans on one pole or give each position
//! its own small plan. Overlaid, 9–13 plans share their vectors' directions near the pole
//! and their labels collide; separate cells keep every image point readable, so each
//! position gets its own plan here.

use crate::drawing::place::Placer;
use crate::drawing::scene::{Anchor, DASHED, Group, Pen, THIN, Text, VECTOR};
use crate::drawing::symbols::vector;
use crate::lever::plans::{Plan, SegKind};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// Room left around a plan inside its cell for the labels, mm.
pub const MARGIN: f64 = 7.0;
/// Images closer than this (mm) share one label, e.g. "p=b=d".
const SHARED_LABEL: f64 = 0.8;
/// Height of a cell's title strip, mm.
pub const TITLE: f64 = 6.0;

/// Bounding box of a plan in its own units (m/s or m/s²), pole included.
pub fn plan_bbox(plan: &Plan) -> Rect {
    let mut r = Rect::from_points(Point::ZERO, Point::ZERO);
    for s in &plan.segs {
        r = r.union_pt(s.from.to_point()).union_pt(s.to.to_point());
    }
    for i in &plan.images {
        r = r.union_pt(i.at.to_point());
    }
    r
}

/// The scale factor needed for `plan` to fit a cell of `cell` size (units per mm).
pub fn required_mu(plan: &Plan, cell: (f64, f64)) -> f64 {
    let bb = plan_bbox(plan);
    let (w, h) = (cell.0 - 2.0 * MARGIN, cell.1 - TITLE - 2.0 * MARGIN);
    (bb.width() / w).max(bb.height() / h)
}

/// Splits `region` into a grid of at least `n` cells, as square as possible.
pub fn grid(region: Rect, n: usize) -> Vec<Rect> {
    let mut best = (0.0, 1, 1);
    for rows in 1..=n {
        let cols = n.div_ceil(rows);
        let (w, h) = (region.width() / cols as f64, region.height() / rows as f64);
        let score = w.min(h * 1.15);
        if score > best.0 {
            best = (score, rows, cols);
        }
    }
    let (_, rows, cols) = best;
    let (w, h) = (region.width() / cols as f64, region.height() / rows as f64);
    (0..n)
        .map(|i| {
            let (r, c) = (i / cols, i % cols);
            Rect::new(
                region.x0 + c as f64 * w,
                region.y0 + r as f64 * h,
                region.x0 + (c + 1) as f64 * w,
                region.y0 + (r + 1) as f64 * h,
            )
        })
        .collect()
}

fn pen_of(kind: SegKind) -> Pen {
    match kind {
        SegKind::Absolute => VECTOR,
        SegKind::Relative | SegKind::Normal | SegKind::Coriolis => THIN,
        SegKind::Tangential | SegKind::Sliding => DASHED,
    }
}

/// Draws one plan in `cell` at scale `mu`, with the pole named `pole`.
pub fn draw_plan(g: &mut Group, cell: Rect, title: &str, plan: &Plan, mu: f64, pole: &str) {
    let inner = Rect::new(cell.x0 + 1.0, cell.y0 + TITLE, cell.x1 - 1.0, cell.y1 - 1.0);
    draw_plan_with(g, cell, title, plan, mu, pole, &mut Placer::new(inner));
}

/// [`draw_plan`] with the caller's label placer (to add labels of its own afterwards);
/// returns the paper position of the pole.
pub fn draw_plan_with(
    g: &mut Group,
    cell: Rect,
    title: &str,
    plan: &Plan,
    mu: f64,
    pole: &str,
    placer: &mut Placer,
) -> Point {
    let inner = Rect::new(cell.x0 + 1.0, cell.y0 + TITLE, cell.x1 - 1.0, cell.y1 - 1.0);
    let t = Text::new(Point::new(cell.x0 + 2.0, cell.y0 + 4.5), title, 3.5, Anchor::Start);
    placer.block(t.bbox());
    g.text(t);
    let bb = plan_bbox(plan);
    let area_c = Rect::new(inner.x0 + MARGIN, inner.y0 + MARGIN, inner.x1 - MARGIN, inner.y1 - MARGIN).center();
    // Paper position of the pole: the plan's box centred in the cell.
    let pole_p = Point::new(area_c.x - (bb.center().x) / mu, area_c.y + (bb.center().y) / mu);
    let p = |v: Vec2| Point::new(pole_p.x + v.x / mu, pole_p.y - v.y / mu);
    for s in &plan.segs {
        vector(g, p(s.from), p(s.to), pen_of(s.kind));
    }
    g.dot(pole_p, 0.5);
    // Labels: images closer than 0.8 mm share one label, e.g. "p=b=d".
    let mut clusters: Vec<(Point, Vec<String>)> = vec![(pole_p, vec![pole.to_string()])];
    for img in &plan.images {
        let at = p(img.at);
        match clusters.iter_mut().find(|(c, _)| (*c - at).norm() < SHARED_LABEL) {
            Some((_, names)) => names.push(img.label.clone()),
            None => clusters.push((at, vec![img.label.clone()])),
        }
    }
    let centre = {
        let pts: Vec<Point> = clusters.iter().map(|c| c.0).collect();
        crate::drawing::scene::points_bbox(&pts).center()
    };
    for (at, names) in &clusters {
        if *at != pole_p {
            g.dot(*at, 0.35);
        }
        let pref = if (*at - centre).norm() < tol::PAPER { Vec2::new(-1.0, 1.0) } else { *at - centre };
        g.text(placer.place(*at, pref, &names.join("="), 3.5));
    }
    pole_p
}
