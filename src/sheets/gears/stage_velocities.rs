//! The course's graphical check of the planetary stage's ratio (Smirnov's method), drawn
//! beside the kinematic scheme and sharing its heights. Above the axis, the picture of linear
//! velocities: the radius line with the scheme's A (the sun meets the planet), B (the planet's
//! axle) and C (the planet meets the fixed ring) projected onto it, v_A drawn at an arbitrary
//! length, the sun's line O–a, the planet's line C–a (C does not move) and the carrier's line
//! O–b. Below the axis, the plan of angular velocities: rays from a pole P parallel to those
//! lines cut a horizontal line in segments proportional to ω1, ω2 and ω_H. u_1H = (0–1)/(0–H)
//! is read off the plan as a student reads it, each segment to [`READ_TO_MM`], and set beside
//! the analytic ratio.

use super::planetary_view::SchemePoints;
use crate::drawing::place::Labels;
use crate::drawing::scene::{Group, THIN, VECTOR};
use crate::drawing::symbols;
use crate::drawing::text::LabelText;
use kurbo::{Point, Rect, Vec2};

/// A segment of the plan is read to this, mm: a ruler's resolution.
pub const READ_TO_MM: f64 = 0.1;

/// The longest v_A drawn, mm: the picture need not fill a wide region.
const V_A_MAX_MM: f64 = 90.0;

/// What the plan of angular velocities gives (paper mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reading {
    /// The segments 0–1 (ω1) and 0–H (ω_H) as drawn.
    pub sun_mm: f64,
    pub carrier_mm: f64,
    /// The ratio of the two segments each read to [`READ_TO_MM`]; `None` when 0–H reads
    /// shorter than that (the ratio cannot be read off the drawing).
    pub ratio: Option<f64>,
}

impl Reading {
    /// A segment as a student reads it.
    pub fn read(mm: f64) -> f64 {
        (mm / READ_TO_MM).round() * READ_TO_MM
    }
}

/// Draws the picture of linear velocities in `upper` (its bottom on the scheme's axis) and
/// the plan of angular velocities in `lower` (from the axis down), for the scheme's points
/// `pts`; returns the plan's reading and its bottom (its pole's name), for the notes under it.
pub fn draw(g: &mut Group, upper: Rect, lower: Rect, pts: &SchemePoints, labels: &mut Labels) -> (Reading, f64) {
    let x_p = upper.x0 + 6.0;
    let (h_a, h_b, h_c) = (pts.axis.y - pts.a.y, pts.axis.y - pts.b.y, pts.axis.y - pts.c.y);
    let on_radius = |p: Point| Point::new(x_p, p.y);
    let o = Point::new(x_p, pts.axis.y);
    // The radius line and the scheme's points projected onto it.
    g.line(o, Point::new(x_p, pts.c.y - 3.0), THIN);
    for p in [pts.a, pts.b, pts.c] {
        g.line(p, on_radius(p), THIN);
    }
    // v_A, and v_B where the planet's line (through C, at rest, and a) passes B's height.
    let v_a = (upper.x1 - 8.0 - x_p).clamp(10.0, V_A_MAX_MM);
    let v_b = v_a * (h_c - h_b) / (h_c - h_a);
    let a = on_radius(pts.a) + Vec2::new(v_a, 0.0);
    let b = on_radius(pts.b) + Vec2::new(v_b, 0.0);
    symbols::vector(g, on_radius(pts.a), a, VECTOR);
    symbols::vector(g, on_radius(pts.b), b, VECTOR);
    for (from, to) in [(o, a), (on_radius(pts.c), a), (o, b)] {
        g.line(from, to, VECTOR);
    }
    let text = |t: &str| LabelText::new(t, "");
    for (p, t) in [(o, "O"), (on_radius(pts.a), "A"), (on_radius(pts.b), "B"), (on_radius(pts.c), "C")] {
        labels.add_ranked(p, Vec2::new(-1.0, -1.0), text(t), 3.5, 0);
    }
    labels.add_ranked(a, Vec2::new(1.0, 0.0), text("a"), 3.5, 0);
    labels.add_ranked(b, Vec2::new(1.0, 0.0), text("b"), 3.5, 0);
    let mid = |p: Point, q: Point| p.midpoint(q);
    labels.add_line_name(mid(o, a) + (a - o) * 0.2, Vec2::new(0.3, 1.0), text("1"), 3.5, 1);
    // The planet's name nearer C than b, which halves a single row's line.
    let c_on = on_radius(pts.c);
    labels.add_line_name(c_on + (a - c_on) * 0.25, Vec2::new(1.0, -0.6), text("2"), 3.5, 1);
    labels.add_line_name(mid(o, b), Vec2::new(-0.6, -1.0), text("H"), 3.5, 1);
    angular_plan(g, lower, [(v_a, h_a), (v_b, h_b), (v_a, h_c - h_a)], labels)
}

/// The plan of angular velocities in `lower`: `slopes` are the run and rise (mm) of the sun's,
/// the carrier's and the planet's velocity lines.
fn angular_plan(g: &mut Group, lower: Rect, slopes: [(f64, f64); 3], labels: &mut Labels) -> (Reading, f64) {
    let [(run1, rise1), (run_h, rise_h), (run2, rise2)] = slopes;
    let y_line = lower.y0 + 10.0;
    let room_w = lower.width() - 14.0;
    // P at the distance that fills the width, if the height allows it.
    let h = (room_w / (run1 / rise1 + run2 / rise2)).min(lower.height() - 18.0).max(3.0);
    let x0 = lower.x0 + 7.0 + h * run2 / rise2;
    let foot = Point::new(x0, y_line);
    let p = Point::new(x0, y_line + h);
    let at = |run: f64, rise: f64, sign: f64| Point::new(x0 + sign * h * run / rise, y_line);
    let (p1, p_h, p2) = (at(run1, rise1, 1.0), at(run_h, rise_h, 1.0), at(run2, rise2, -1.0));
    g.line(Point::new(p2.x - 4.0, y_line), Point::new(p1.x + 4.0, y_line), THIN);
    g.line(p, foot, THIN);
    for q in [p1, p_h, p2] {
        g.line(p, q, VECTOR);
    }
    let text = |t: &str| LabelText::new(t, "");
    labels.add_ranked(p, Vec2::new(0.0, 1.0), text("P"), 3.5, 0);
    for (q, t) in [(foot, "0"), (p1, "1"), (p_h, "H"), (p2, "2")] {
        labels.add_ranked(q, Vec2::new(0.0, -1.0), text(t), 3.5, 0);
    }
    let (sun_mm, carrier_mm) = (p1.x - x0, p_h.x - x0);
    let read_h = Reading::read(carrier_mm);
    let ratio = (read_h >= READ_TO_MM).then(|| Reading::read(sun_mm) / read_h);
    (Reading { sun_mm, carrier_mm, ratio }, p.y + 5.0)
}
