//! The course's graphical check of the planetary stage's ratio (Smirnov's method), drawn
//! beside the kinematic scheme and sharing its heights. Above the axis, the picture of linear
//! velocities: the radius line with the scheme's A (the sun meets the planet), B (the planet's
//! axle) and C (the planet meets the fixed ring) projected onto it, v_A drawn at an arbitrary
//! length, the sun's line O–a, the planet's line C–a (C does not move) and the carrier's line
//! O–b. Below it, the plan of angular velocities: rays from a pole P parallel to those lines
//! cut a horizontal line in segments proportional to ω1, ω2 and ω_H. u_1H = (0–1)/(0–H) is
//! read off the plan as a student reads it, each segment to [`READ_TO_MM`], and set beside the
//! analytic ratio. The plan is u_1H + ω2/ω_H times as wide as 0–H is long (the worked
//! example's 10.8): beside the scheme it had 76 mm and 0–H 7.3 mm, read to ±0.7 %; it takes a
//! strip under the views as wide as the sheet's right half, tall enough for 0–H of
//! [`CARRIER_TARGETS_MM`] where the tables below still fit ([`strip_height`]; the choice in
//! `stage_layout`): 20 mm on the worked example, its 0–1 190.6 mm.

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

/// The length 0–H is drawn to where the room allows, best first, mm: read to [`READ_TO_MM`],
/// 20 mm gives u_1H to ±0.25 %, 15 mm to ±0.33 %.
pub const CARRIER_TARGETS_MM: [f64; 2] = [20.0, 15.0];
/// The pole distance h is kept within these, mm: a plan for a small ratio (a steep carrier's
/// line) reaches 0–H at an h that outgrows the plan's width; a large ratio's, width-bound,
/// draws its rays nearly flat.
const H_MOST: f64 = 40.0;
const H_LEAST: f64 = 3.0;
/// Room round the plan, mm: over its line for the labels 2, 0, H, 1 (and 4 mm between them
/// and the views' captions over the strip: 2 mm read the captions as the plan's); under its
/// pole for P's; at either end of its line.
const ABOVE: f64 = 10.0;
const BELOW: f64 = 6.0;
const ENDS: f64 = 7.0;

/// The run (mm across) per mm of rise of the sun's, the carrier's and the planet's velocity
/// lines in the picture of linear velocities, the rays' slopes in the plan: as ω1, ω_H and
/// ω2 (the planet's on the other side).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slopes {
    pub sun: f64,
    pub carrier: f64,
    pub planet: f64,
}

impl Slopes {
    /// For A, B and C at `heights` above the axis (mm) and v_A drawn `v_a` long.
    pub fn new([h_a, h_b, h_c]: [f64; 3], v_a: f64) -> Slopes {
        let v_b = v_a * (h_c - h_b) / (h_c - h_a);
        Slopes { sun: v_a / h_a, carrier: v_b / h_b, planet: v_a / (h_c - h_a) }
    }

    /// The pole distance that draws 0–H `target` long in a room `width` wide, within
    /// [`H_LEAST`]..[`H_MOST`].
    fn pole_distance(&self, width: f64, target: f64) -> f64 {
        let widest = (width - 2.0 * ENDS) / (self.sun + self.planet);
        (target / self.carrier).min(widest).clamp(H_LEAST, H_MOST)
    }
}

/// v_A's length (mm) in a picture of linear velocities `width` wide: the radius line 6 mm in,
/// 8 mm left at the right for a's name.
pub fn v_a_length(width: f64) -> f64 {
    (width - 14.0).clamp(10.0, V_A_MAX_MM)
}

/// The height of a strip `width` wide that holds the plan with 0–H `target` long, or as
/// long as the width or [`H_MOST`] allows, mm.
pub fn strip_height(slopes: Slopes, width: f64, target: f64) -> f64 {
    slopes.pole_distance(width, target) + ABOVE + BELOW
}

/// The pole distance the plan takes in `room`: as wide as it, within its height.
fn pole_in(slopes: Slopes, room: Rect) -> f64 {
    slopes.pole_distance(room.width(), f64::INFINITY).min(room.height() - ABOVE - BELOW).max(H_LEAST)
}

/// The length 0–H the plan draws in `room`, mm.
pub fn carrier_mm(slopes: Slopes, room: Rect) -> f64 {
    pole_in(slopes, room) * slopes.carrier
}

/// Draws the picture of linear velocities in `upper` (its bottom on the scheme's axis) and
/// the plan of angular velocities in `plan` (its line at the top, right-aligned), for the
/// scheme's points `pts`; returns the plan's reading and its bottom (its pole's name).
pub fn draw(g: &mut Group, upper: Rect, plan: Rect, pts: &SchemePoints, labels: &mut Labels) -> (Reading, f64) {
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
    let v_a = v_a_length(upper.width());
    let slopes = Slopes::new([h_a, h_b, h_c], v_a);
    let v_b = slopes.carrier * h_b;
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
    angular_plan(g, plan, slopes, labels)
}

/// The plan of angular velocities in `room`: its line [`ABOVE`] under the top, the pole P at
/// the distance that fills the width (within the height and [`H_MOST`]), the plan as far
/// right as the room goes (under the picture of linear velocities, its 1 under a).
fn angular_plan(g: &mut Group, room: Rect, slopes: Slopes, labels: &mut Labels) -> (Reading, f64) {
    let y_line = room.y0 + ABOVE;
    let h = pole_in(slopes, room);
    let x0 = room.x1 - ENDS - h * slopes.sun;
    let foot = Point::new(x0, y_line);
    let p = Point::new(x0, y_line + h);
    let at = |slope: f64| Point::new(x0 + h * slope, y_line);
    let (p1, p_h, p2) = (at(slopes.sun), at(slopes.carrier), at(-slopes.planet));
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
