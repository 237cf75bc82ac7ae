//! The planetary stage in two views at one GOST scale: the front view (pitch circles of the
//! sun, the planets and the ring, the carrier's arms) and the side view as a kinematic
//! scheme by GOST 2.770 (shafts in their bearings with their senses of rotation, the gears'
//! rims, the fixed ring, the carrier).

use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, Group, MAIN, THIN};
use crate::drawing::symbols;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::gears::planetary::Stage;
use crate::num::math::{self, from_angle};
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

/// The stage's pitch radii (m): sun, planet meshing the sun, planet meshing the ring (the
/// same for a single row), ring; and the carrier's radius.
struct Radii {
    sun: f64,
    planet: f64,
    planet2: f64,
    ring: f64,
    carrier: f64,
}

fn radii(s: &Stage, m: f64) -> Radii {
    let r = |z: u32| m * f64::from(z) / 2.0;
    let (sun, planet) = (r(s.z[0]), r(s.z[1]));
    let (planet2, ring) = if s.z.len() == 4 { (r(s.z[2]), r(s.z[3])) } else { (planet, r(s.z[2])) };
    Radii { sun, planet, planet2, ring, carrier: sun + planet }
}

/// The radius the front view reaches (m): the ring's rim, or a double planet's larger gear.
pub fn extent(s: &Stage, m: f64) -> f64 {
    let r = radii(s, m);
    (r.ring + 1.25 * m).max(r.carrier + r.planet.max(r.planet2) + m)
}

/// The scale (μ_l, m/mm) at which the front view fits `size` mm across.
pub fn scale_for(s: &Stage, m: f64, size: f64) -> f64 {
    crate::drawing::scale::length_scale(2.0 * extent(s, m) / size)
}

/// The heights (mm) above the axis at which the kinematic scheme drawn at μ_l `mu` puts the
/// sun's pitch point A, the planet's axle B and the planet's contact with the ring C (see
/// [`SchemePoints`]).
pub fn heights(s: &Stage, m: f64, mu: f64) -> [f64; 3] {
    let r = radii(s, m);
    [r.sun / mu, r.carrier / mu, r.ring / mu]
}

/// The stage as drawn: its radii, the module (m) and the view of its lengths.
struct Drawn<'a> {
    stage: &'a Stage,
    r: Radii,
    m: f64,
    view: View,
    /// A double planet (two gears on each planet's axle).
    double: bool,
}

/// Draws the front view centred in `front` and the kinematic scheme in `side`, at μ_l `mu`;
/// returns the scheme's points for the velocity picture.
pub fn draw(g: &mut Group, front: Rect, side: Rect, s: &Stage, m: f64, mu: f64, labels: &mut Labels) -> SchemePoints {
    let view = View::new(front.center(), mu);
    let drawn = Drawn { stage: s, r: radii(s, m), m, view, double: s.z.len() == 4 };
    front_view(g, front, &drawn, labels);
    kinematic_scheme(g, side, &drawn, labels)
}

/// The front view: the pitch circles, the ring's rim, the carrier's circle and arms.
fn front_view(g: &mut Group, front: Rect, st: &Drawn, labels: &mut Labels) {
    let (s, r, m, v, double) = (st.stage, &st.r, st.m, st.view, st.double);
    let o = front.center();
    let ext = v.len(extent(s, m)) + 4.0;
    g.line(o - Vec2::new(ext, 0.0), o + Vec2::new(ext, 0.0), AXIS);
    g.line(o - Vec2::new(0.0, ext), o + Vec2::new(0.0, ext), AXIS);
    g.circle(o, v.len(r.sun), MAIN);
    g.circle(o, v.len(r.ring), MAIN);
    g.circle(o, v.len(r.ring + 1.25 * m) + 2.0, THIN);
    g.circle(o, v.len(r.carrier), AXIS);
    for i in 0..s.planets {
        // Planets from the top, counter-clockwise on paper.
        let a = -FRAC_PI_2 - TAU * f64::from(i) / f64::from(s.planets);
        let c = o + from_angle(a) * (v.len(r.carrier));
        g.circle(c, v.len(r.planet), MAIN);
        if double {
            g.circle(c, v.len(r.planet2), THIN);
        }
        g.line(o, c, MAIN);
        g.circle(c, 1.2, THIN);
    }
    g.circle(o, 1.5, MAIN);
    let top = o - Vec2::new(0.0, v.len(r.carrier));
    labels.add_ranked_at_any(&sun_spots(o, v.len(r.sun), s.planets), LabelText::new("1", ""), 3.5, 0);
    labels.add_text_ranked(
        top + Vec2::new(v.len(r.planet) * 0.7, -v.len(r.planet) * 0.7),
        Vec2::new(1.0, -1.0),
        "2",
        3.5,
        0,
    );
    if double {
        labels.add_text_ranked(
            top + Vec2::new(-v.len(r.planet2) * 0.7, -v.len(r.planet2) * 0.7),
            Vec2::new(-1.0, -1.0),
            "2′",
            3.5,
            0,
        );
    }
    // The ring's number on its rim between two planets (a planet drawn over the rim, a
    // double planet's larger gear, would otherwise seem to be what "3" names).
    let between = ring_label_angle(s.planets);
    let out = from_angle(between);
    labels.add_text_ranked(o + out * v.len(r.ring), out, "3", 3.5, 0);
    labels.add_text_ranked(o + Vec2::new(0.0, -v.len(r.carrier) * 0.5), Vec2::new(1.0, 0.0), "H", 3.5, 0);
}

/// Where the sun's number may stand: inside the sun, in the middle of the wedge between
/// the carrier's upright arm and the next arm or the horizontal centre line to its right;
/// else outside on its circle, up and right; else in the middle of any gap between two
/// arms (a small sun's wedge has no room, and its gaps between the planets are narrow:
/// numbered up and right only, it hung on 28 mm leaders on 16 of the catalogue's sheets).
fn sun_spots(o: Point, r_sun: f64, planets: u32) -> Vec<(Point, Vec2)> {
    let n = f64::from(planets.max(1));
    let next_arm = -FRAC_PI_2 + TAU / n;
    let wedge = (-FRAC_PI_2 + next_arm.min(0.0)) / 2.0;
    let inside = (o + from_angle(wedge) * (0.3 * r_sun), from_angle(wedge));
    let gaps = (0..planets.max(1)).map(|i| from_angle(-FRAC_PI_2 - TAU * (f64::from(i) + 0.5) / n));
    let mut out = vec![inside, (o + Vec2::new(r_sun * 0.7, -r_sun * 0.7), Vec2::new(1.0, -1.0))];
    out.extend(gaps.map(|d| (o + d * r_sun, d)));
    out
}

/// The angle on paper (y down, radians) at which the ring is numbered: of the directions
/// midway between neighbouring planets (drawn from the top, counter-clockwise on paper),
/// the one nearest the lower right.
fn ring_label_angle(planets: u32) -> f64 {
    let k = planets.max(1);
    let mid = |i: u32| -FRAC_PI_2 - TAU * (f64::from(i) + 0.5) / f64::from(k);
    // The angle between a direction and the lower right, either way round.
    let off = |a: f64| (a - FRAC_PI_4).rem_euclid(TAU).min((FRAC_PI_4 - a).rem_euclid(TAU));
    (0..k).map(mid).min_by(|a, b| off(*a).total_cmp(&off(*b))).unwrap_or(FRAC_PI_4)
}

/// Where the kinematic scheme puts the points the velocity picture projects (paper mm): the
/// axis, the sun's pitch point A, the planet's axle B and the planet's contact with the ring C
/// (each the right end of its rim on the scheme), with their heights above the axis.
#[derive(Debug, Clone, Copy)]
pub struct SchemePoints {
    pub axis: Point,
    pub a: Point,
    pub b: Point,
    pub c: Point,
}

/// Half the length of a gear's rim on the scheme (its face width), mm.
const RIM_HALF: f64 = 4.0;
/// Two rims in mesh are drawn this far apart, mm: the double line of a mesh.
const MESH_GAP: f64 = 1.5;

/// The side view as a kinematic scheme by GOST 2.770, symmetric about the axis across: the
/// input shaft in its bearing with ω₁ and the sun 1 on it; each planet 2 (with 2′ on its axle
/// for a double planet) on the carrier's axle; the ring 3 fixed to the frame (hatched); the
/// carrier H as an arm on the output shaft in its bearing with ω_H. Every gear is its
/// diameter across the axis with its rim at both ends; rims in mesh are a double line.
fn kinematic_scheme(g: &mut Group, side: Rect, st: &Drawn, labels: &mut Labels) -> SchemePoints {
    let (r, v, double) = (&st.r, st.view, st.double);
    let (w, cy) = (side.width(), side.center().y);
    let x_in = side.x0 + 3.0;
    let x_sun = side.x0 + 0.34 * w;
    let x_ring = if double { x_sun + 4.0 * RIM_HALF + 2.0 } else { x_sun };
    let x_h = x_ring + 0.24 * w;
    let x_out = side.x1 - 3.0;
    let y = |sign: f64, radius: f64| cy + sign * v.len(radius);
    g.line(Point::new(x_in - 2.0, cy), Point::new(x_out + 2.0, cy), AXIS);
    // The input shaft with the sun, the carrier's arm with the output shaft.
    g.line(Point::new(x_in, cy), Point::new(x_sun, cy), MAIN);
    g.line(Point::new(x_h, y(-1.0, r.carrier)), Point::new(x_h, y(1.0, r.carrier)), MAIN);
    g.line(Point::new(x_h, cy), Point::new(x_out, cy), MAIN);
    let half_gap = MESH_GAP / 2.0;
    gear(g, x_sun, cy - v.len(r.sun) + half_gap, cy + v.len(r.sun) - half_gap);
    for sign in [-1.0, 1.0] {
        let lo = |a: f64, b: f64| (a.min(b), a.max(b));
        // The planet meshes the sun at r1 and (a single row) the ring at r3.
        let inner = y(sign, r.sun) + sign * half_gap;
        let outer = y(sign, r.carrier + r.planet) - if double { 0.0 } else { sign * half_gap };
        let (a, b) = lo(inner, outer);
        gear(g, x_sun, a, b);
        if double {
            let (a, b) = lo(y(sign, r.carrier - r.planet2), y(sign, r.ring) - sign * half_gap);
            gear(g, x_ring, a, b);
        }
        // The planet's axle on the carrier, the planet turning on it in a bearing (a
        // revolute pair with the carrier: not hatched, as it is not the frame's).
        g.line(Point::new(x_sun, y(sign, r.carrier)), Point::new(x_h, y(sign, r.carrier)), MAIN);
        let x_planet = if double { x_ring } else { x_sun };
        axle_bearing(g, Point::new(x_planet + 0.45 * (x_h - x_planet), y(sign, r.carrier)));
        fixed_ring(g, x_ring, y(sign, r.ring) + sign * half_gap, sign);
    }
    // The bearings nearer the gears, the senses of rotation at the shafts' free ends.
    for x in [x_in + 0.62 * (x_sun - x_in), x_h + 0.4 * (x_out - x_h)] {
        bearing(g, Point::new(x, cy));
    }
    shaft_turn(g, Point::new(x_in + 3.0, cy), labels, LabelText::new("ω", "1"));
    shaft_turn(g, Point::new(x_out - 3.0, cy), labels, LabelText::new("ω", "H"));
    let lab = |labels: &mut Labels, at: Point, t: &str, pref: Vec2| {
        labels.add_ranked(at, pref, LabelText::new(t, ""), 3.5, 0);
    };
    lab(labels, Point::new(x_sun, cy - v.len(r.sun) * 0.5), "1", Vec2::new(-1.0, 0.0));
    let planet_mid = y(-1.0, r.carrier + r.planet * 0.5);
    lab(labels, Point::new(x_sun, planet_mid), "2", Vec2::new(-1.0, 0.0));
    if double {
        lab(labels, Point::new(x_ring, y(-1.0, r.carrier + r.planet2 * 0.5)), "2′", Vec2::new(1.0, 0.0));
    }
    lab(labels, Point::new(x_ring, y(-1.0, r.ring) - 4.0), "3", Vec2::new(-1.0, 0.0));
    lab(labels, Point::new(x_h, y(-1.0, r.carrier * 0.5)), "H", Vec2::new(1.0, 0.0));
    SchemePoints {
        axis: Point::new(x_h, cy),
        a: Point::new(x_sun + RIM_HALF, y(-1.0, r.sun)),
        b: Point::new(x_h, y(-1.0, r.carrier)),
        c: Point::new(x_ring + RIM_HALF, y(-1.0, r.ring)),
    }
}

/// A gear on the scheme: its diameter from `y0` to `y1` at `x`, its rim at both ends.
fn gear(g: &mut Group, x: f64, y0: f64, y1: f64) {
    g.line(Point::new(x, y0), Point::new(x, y1), MAIN);
    for y in [y0, y1] {
        g.line(Point::new(x - RIM_HALF, y), Point::new(x + RIM_HALF, y), MAIN);
    }
}

/// The fixed ring's rim at `yr` on one side (`sign` ±1), its body out to the frame (hatched).
fn fixed_ring(g: &mut Group, x_ring: f64, yr: f64, sign: f64) {
    g.line(Point::new(x_ring - RIM_HALF, yr), Point::new(x_ring + RIM_HALF, yr), MAIN);
    let yf = yr + sign * 7.0;
    g.line(Point::new(x_ring, yr), Point::new(x_ring, yf), MAIN);
    g.line(Point::new(x_ring - 6.0, yf), Point::new(x_ring + 6.0, yf), MAIN);
    symbols::hatch(g, Point::new(x_ring - 6.0, yf), Point::new(x_ring + 6.0, yf), Vec2::new(0.0, sign), 2.0);
}

/// A radial bearing on the shaft at `c` (GOST 2.770: a short line along the shaft on each
/// side), held by the frame (hatched).
fn bearing(g: &mut Group, c: Point) {
    for sign in [-1.0, 1.0] {
        let (a, b) = (c + Vec2::new(-3.5, sign * 2.2), c + Vec2::new(3.5, sign * 2.2));
        g.line(a, b, MAIN);
        symbols::hatch(g, a, b, Vec2::new(0.0, sign), 1.6);
    }
}

/// The bearing of a planet on its axle at `c` (GOST 2.770's radial bearing: a short line
/// along the axle on each side), in the carrier, so without the frame's hatching.
fn axle_bearing(g: &mut Group, c: Point) {
    for sign in [-1.0, 1.0] {
        g.line(c + Vec2::new(-2.5, sign * 1.6), c + Vec2::new(2.5, sign * 1.6), MAIN);
    }
}

/// A shaft's sense of rotation at `c`: an arrow turning round the shaft (the near half of its
/// circle seen edge-on), named by `name`.
fn shaft_turn(g: &mut Group, c: Point, labels: &mut Labels, name: LabelText) {
    let (rx, ry) = (2.0, 5.0);
    let pts: Vec<Point> = (0..=16)
        .map(|i| {
            let t = -0.4 * PI + 1.3 * PI * f64::from(i) / 16.0;
            c + Vec2::new(rx * math::cos(t), ry * math::sin(t))
        })
        .collect();
    let (tip, back) = (pts[pts.len() - 1], pts[pts.len() - 3]);
    g.path(pts, false, THIN);
    symbols::arrowhead(g, tip, tip - back);
    labels.add_ranked(c + Vec2::new(0.0, -ry), Vec2::new(0.0, -1.0), name, 3.5, 0);
}
