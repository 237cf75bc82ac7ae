//! The planetary stage in two views at one GOST scale: the front view (pitch circles of the
//! sun, the planets and the ring, the carrier's arms) and the side view as a kinematic
//! scheme (shafts, the carrier, the gear rims, the fixed ring and the bearings).

use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, Group, MAIN, THIN};
use crate::drawing::symbols;
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::gears::planetary::Stage;
use crate::num::math::from_angle;
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::{FRAC_PI_2, TAU};

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

/// The stage as drawn: its radii, the module (m) and the view of its lengths.
struct Drawn<'a> {
    stage: &'a Stage,
    r: Radii,
    m: f64,
    view: View,
    /// A double planet (two gears on each planet's axle).
    double: bool,
}

/// Draws the front view centred in `front` and the kinematic scheme in `side`, at μ_l `mu`.
pub fn draw(g: &mut Group, front: Rect, side: Rect, s: &Stage, m: f64, mu: f64, labels: &mut Labels) {
    let view = View::new(front.center(), mu);
    let drawn = Drawn { stage: s, r: radii(s, m), m, view, double: s.z.len() == 4 };
    front_view(g, front, &drawn, labels);
    kinematic_scheme(g, side, &drawn, labels);
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
    labels.add_text_ranked(o + Vec2::new(v.len(r.sun) * 0.7, -v.len(r.sun) * 0.7), Vec2::new(1.0, -1.0), "1", 3.5, 0);
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
    labels.add_text_ranked(o + Vec2::new(v.len(r.ring) * 0.71, v.len(r.ring) * 0.71), Vec2::new(1.0, 1.0), "3", 3.5, 0);
    labels.add_text_ranked(o + Vec2::new(0.0, -v.len(r.carrier) * 0.5), Vec2::new(1.0, 0.0), "H", 3.5, 0);
}

/// The side view as a kinematic scheme, symmetric about the axis across: the input shaft
/// and the sun, the planets' rims on the carrier, the fixed ring held by the frame, the
/// carrier H and the output shaft, the bearings.
fn kinematic_scheme(g: &mut Group, side: Rect, st: &Drawn, labels: &mut Labels) {
    let (r, v, double) = (&st.r, st.view, st.double);
    let c = Point::new(side.x0 + 0.15 * side.width(), side.center().y);
    let x_sun = c.x + 0.25 * side.width();
    let x_ring = if double { x_sun + 16.0 } else { x_sun };
    let x_h = x_ring + 0.25 * side.width();
    let x_out = side.x1 - 6.0;
    let x_in = side.x0 + 4.0;
    g.line(Point::new(x_in - 2.0, c.y), Point::new(x_out + 2.0, c.y), AXIS);
    // Input shaft and the sun.
    g.line(Point::new(x_in, c.y), Point::new(x_sun, c.y), MAIN);
    // Gears meshing in one plane meet at their pitch radii: a small gap there keeps each rim
    // a line of its own, as kinematic schemes draw them.
    let gap = 0.8;
    let ys = v.len(r.sun);
    g.line(Point::new(x_sun, c.y - ys + gap), Point::new(x_sun, c.y + ys - gap), MAIN);
    for side_sign in [-1.0, 1.0] {
        let ya = c.y + side_sign * v.len(r.carrier);
        // The planet's rims and its axle on the carrier.
        let rim = |g: &mut Group, x: f64, half: f64| {
            g.line(Point::new(x, ya - half + gap), Point::new(x, ya + half - gap), MAIN);
        };
        rim(g, x_sun, v.len(r.planet));
        if double {
            rim(g, x_ring, v.len(r.planet2));
        }
        g.line(Point::new(x_sun - 6.0, ya), Point::new(x_h, ya), MAIN);
        fixed_ring(g, x_ring, c.y + side_sign * v.len(r.ring), side_sign, gap);
    }
    // The carrier H and the output shaft.
    g.line(Point::new(x_h, c.y - v.len(r.carrier)), Point::new(x_h, c.y + v.len(r.carrier)), MAIN);
    g.line(Point::new(x_h, c.y), Point::new(x_out, c.y), MAIN);
    // Bearings on the input and output shafts.
    for x in [x_in + 0.35 * (x_sun - x_in), x_h + 0.5 * (x_out - x_h)] {
        for sgn in [-1.0, 1.0] {
            let b = Point::new(x, c.y + sgn * 1.6);
            g.path(vec![b, b + Vec2::new(-2.0, sgn * 3.5), b + Vec2::new(2.0, sgn * 3.5)], true, THIN);
        }
    }
    let lab = |labels: &mut Labels, at: Point, t: &str, pref: Vec2| {
        labels.add_ranked(at, pref, LabelText::new(t, ""), 3.5, 0);
    };
    lab(labels, Point::new(x_sun, c.y - ys * 0.6), "1", Vec2::new(-1.0, 0.0));
    lab(labels, Point::new(x_sun, c.y - v.len(r.carrier) - v.len(r.planet) * 0.6), "2", Vec2::new(-1.0, 0.0));
    if double {
        lab(labels, Point::new(x_ring, c.y - v.len(r.carrier) + v.len(r.planet2) * 0.6), "2′", Vec2::new(1.0, 0.0));
    }
    lab(labels, Point::new(x_ring, c.y - v.len(r.ring) - 4.0), "3", Vec2::new(1.0, 0.0));
    lab(labels, Point::new(x_h, c.y - v.len(r.carrier) * 0.5), "H", Vec2::new(1.0, 0.0));
}

/// The fixed ring's rim at `yr` on one side (`side_sign` ±1), turned back toward the planet,
/// held by the frame.
fn fixed_ring(g: &mut Group, x_ring: f64, yr: f64, side_sign: f64, gap: f64) {
    g.path(
        vec![
            Point::new(x_ring - 5.0, yr + side_sign * gap),
            Point::new(x_ring, yr + side_sign * gap),
            Point::new(x_ring, yr + side_sign * 8.0),
        ],
        false,
        MAIN,
    );
    let yf = yr + side_sign * 8.0;
    g.line(Point::new(x_ring - 6.0, yf), Point::new(x_ring + 6.0, yf), MAIN);
    symbols::hatch(g, Point::new(x_ring - 6.0, yf), Point::new(x_ring + 6.0, yf), Vec2::new(0.0, side_sign), 2.0);
}
