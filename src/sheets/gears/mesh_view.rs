//! The external mesh as the course draws it: both wheels' circles, the common tangent τ–τ,
//! the pitch point P, the line of action N1N2 and its active part B1B2, three exact teeth
//! per wheel in mesh (touching at P), the active profiles thick, the arc of action on the
//! working pitch circle of wheel 1 with the contact ratio measured on it.
//!
//! World coordinates are the pair's, metres, y up: O1 at the origin, O2 at (0, a_w), P at
//! (0, r_w1). Wheel 1 turns counter-clockwise and drives; the contact runs from B1 (on
//! wheel 2's tip circle, toward N1) to B2.

use crate::drawing::obstacles::segment_meets_rect;
use crate::drawing::path::{Path, Seg};
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, Group, MAIN, Pen, THIN};
use crate::drawing::text::LabelText;
use crate::gears::pair::Pair;
use crate::gears::tooth::{Outline, polar};
use crate::num::bezier;
use crate::num::math::{Norm, cos, from_angle, sin, tan};
use kurbo::{Arc, CubicBez, Point, Rect, Vec2};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Active profiles and the active line of action.
const ACTIVE: Pen = Pen { width: 1.2, line: crate::drawing::scene::LineType::Solid };
/// Cubic pieces per involute flank (the measured deviation is stated on the sheet).
pub const INVOLUTE_PIECES: usize = 2;
/// The fillet is fitted to this distance (metres), far below any drawn line.
const FILLET_TOL: f64 = 1e-7;

/// How the mesh was drawn and what was measured on it.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshDrawn {
    /// μ_l, m/mm.
    pub mu: f64,
    /// The contact ratio measured on the drawing: the drawn arc of action over the drawn pitch.
    pub contact_ratio_drawn: f64,
    /// The largest measured deviation of a drawn involute from the exact one, metres.
    pub involute_deviation: f64,
    /// The same for the fillets, metres.
    pub fillet_deviation: f64,
    /// The tooth height on paper, mm.
    pub tooth_height_mm: f64,
}

/// World → paper.
#[derive(Clone, Copy)]
struct View {
    /// Paper position of the world origin (O1).
    o: Point,
    /// Paper mm per metre.
    k: f64,
}

impl View {
    fn p(&self, w: Vec2) -> Point {
        Point::new(self.o.x + self.k * w.x, self.o.y - self.k * w.y)
    }
}

/// One wheel's fitted half-flank (upper, in the tooth frame, from the root up to the tip).
struct Flank {
    fillet: Vec<CubicBez>,
    involute: Vec<CubicBez>,
}

fn flank(o: &Outline) -> (Flank, f64, f64) {
    let inv = |t: f64| o.involute(t);
    let fil = |phi: f64| o.fillet(phi);
    let involute = bezier::fit(&inv, o.t_low, o.t_tip, INVOLUTE_PIECES);
    let dev_i = bezier::deviation(&inv, o.t_low, o.t_tip, &involute);
    let f = bezier::fit_within(&fil, o.phi_root, o.phi_join, FILLET_TOL, 64);
    (Flank { fillet: f.cubics, involute }, dev_i, f.deviation)
}

fn map_cubic(c: &CubicBez, f: impl Fn(Vec2) -> Point) -> CubicBez {
    CubicBez::new(f(c.p0.to_vec2()), f(c.p1.to_vec2()), f(c.p2.to_vec2()), f(c.p3.to_vec2()))
}

fn reversed(cs: &[CubicBez]) -> Vec<CubicBez> {
    cs.iter().rev().map(|c| CubicBez::new(c.p3, c.p2, c.p1, c.p0)).collect()
}

fn rot(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = (sin(a), cos(a));
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// Appends an arc about world centre `c` (radius r) from world angle a0 to a1.
fn push_arc(path: &mut Path, v: View, c: Vec2, r: f64, a0: f64, a1: f64) {
    if (a1 - a0).abs() < 1e-12 {
        return;
    }
    path.segs.push(Seg::Arc(Arc::new(v.p(c), (v.k * r, v.k * r), -a0, -(a1 - a0), 0.0)));
}

fn push_cubics(path: &mut Path, cs: &[CubicBez]) {
    path.segs.extend(cs.iter().map(|c| Seg::Cubic(c.p1, c.p2, c.p3)));
}

/// The outline of the teeth centred at world angles `centres` (ascending) of a wheel at `c`:
/// one path from the middle of the space before the first to the middle after the last.
fn teeth_path(v: View, c: Vec2, o: &Outline, fl: &Flank, centres: &[f64]) -> Path {
    let half_space = PI / f64::from(o.z);
    let psi_a = o.tip_half_angle();
    let first = centres[0] - half_space;
    let mut path = Path::new(v.p(c + from_angle(first) * o.root));
    let mut at = first;
    for &cc in centres {
        let world = |mirror: bool| move |p: Vec2| v.p(c + rot(if mirror { Vec2::new(p.x, -p.y) } else { p }, cc));
        push_arc(&mut path, v, c, o.root, at, cc - o.root_from);
        let lower = |cs: &[CubicBez]| cs.iter().map(|x| map_cubic(x, world(true))).collect::<Vec<_>>();
        push_cubics(&mut path, &lower(&fl.fillet));
        push_cubics(&mut path, &lower(&fl.involute));
        push_arc(&mut path, v, c, o.tip, cc - psi_a, cc + psi_a);
        let upper = |cs: &[CubicBez]| reversed(cs).iter().map(|x| map_cubic(x, world(false))).collect::<Vec<_>>();
        push_cubics(&mut path, &upper(&fl.involute));
        push_cubics(&mut path, &upper(&fl.fillet));
        at = cc + o.root_from;
        push_arc(&mut path, v, c, o.root, at, cc + half_space);
        at = cc + half_space;
    }
    path
}

/// The active part of the upper flanks (from radius `r_low` to the tip), thick.
fn active_flanks(g: &mut Group, v: View, c: Vec2, o: &Outline, r_low: f64, centres: &[f64]) {
    let t0 = crate::gears::tooth::roll(o.base, r_low).max(o.t_low);
    let inv = |t: f64| o.involute(t);
    let cs = bezier::fit(&inv, t0, o.t_tip, INVOLUTE_PIECES);
    for &cc in centres {
        let pieces: Vec<CubicBez> = cs.iter().map(|x| map_cubic(x, |p| v.p(c + rot(p, cc)))).collect();
        g.curve(Path::cubics(&pieces), ACTIVE);
    }
}

/// The largest arc of a circle (paper centre `c`, radius r) around paper angle `mid` that
/// stays inside `region`, as (start, sweep) in paper angles; sampled every 0.2°.
fn visible_arc(c: Point, r: f64, mid: f64, region: Rect) -> Option<(f64, f64)> {
    let inside = |a: f64| region.contains(crate::drawing::path::on_circle(c, r, a));
    if !inside(mid) {
        return None;
    }
    let step = 0.2f64.to_radians();
    let reach = |dir: f64| {
        let mut a = 0.0;
        while a + step < PI && inside(mid + dir * (a + step)) {
            a += step;
        }
        a
    };
    let (lo, hi) = (reach(-1.0), reach(1.0));
    Some((mid - lo, lo + hi))
}

/// A line from a to b clipped to `region` (nothing when it misses).
fn clipped_line(g: &mut Group, a: Point, b: Point, region: Rect, pen: Pen) {
    if !segment_meets_rect(a, b, region) {
        return;
    }
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, a.x - region.x0), (d.x, region.x1 - a.x), (-d.y, a.y - region.y0), (d.y, region.y1 - a.y)] {
        if p == 0.0 {
            continue;
        }
        let t = q / p;
        if p < 0.0 { t0 = t0.max(t) } else { t1 = t1.min(t) }
    }
    if t1 > t0 {
        g.line(a + d * t0, a + d * t1, pen);
    }
}

/// What the mesh view needs.
pub struct MeshInput<'a> {
    pub pair: &'a Pair,
    pub outlines: [&'a Outline; 2],
}

/// The three tooth centres of each wheel nearest the line of centres, in mesh: wheel 1's
/// upper flank and wheel 2's upper flank both pass through P.
fn tooth_centres(inp: &MeshInput) -> [Vec<f64>; 2] {
    let p = inp.pair;
    let alpha_w = p.working_pressure_angle;
    let centres = |i: usize, axis: f64| {
        let o = inp.outlines[i];
        let w = &p.wheels[i];
        let psi = o.theta0 - crate::gears::pair::inv(alpha_w);
        let step = TAU / f64::from(w.z);
        let c0 = axis - psi;
        vec![c0 - step, c0, c0 + step]
    };
    [centres(0, FRAC_PI_2), centres(1, -FRAC_PI_2)]
}

/// Draws the mesh into `g` (its region): title above, notes below are the caller's; the
/// drawing is placed in `area`.
pub fn draw_mesh(g: &mut Group, area: Rect, inp: &MeshInput, labels: &mut Labels) -> MeshDrawn {
    let p = inp.pair;
    let [w1, w2] = &p.wheels;
    let mu = crate::drawing::scale::length_scale_below(p.tooth_height / 50.0);
    let k = 1.0 / mu; // paper mm per metre
    let a_w = p.centre_distance;
    // P in the middle across; both centres on the sheet when they fit, else P in the middle.
    let span = k * a_w;
    let py = if span + 24.0 <= area.height() {
        area.y0 + 12.0 + k * w2.working + (area.height() - span - 24.0) / 2.0
    } else {
        area.center().y
    };
    let pp = Point::new(area.center().x, py);
    let v = View { o: Point::new(pp.x, pp.y + k * w1.working), k };
    let o1 = Vec2::ZERO;
    let o2 = Vec2::new(0.0, a_w);
    let centres = tooth_centres(inp);
    let (fl1, dev1, fd1) = flank(inp.outlines[0]);
    let (fl2, dev2, fd2) = flank(inp.outlines[1]);

    // Circles, clipped to the area around the mesh.
    let mut circle = |c: Vec2, r: f64, mid: f64, pen: Pen| {
        if let Some((a0, sweep)) = visible_arc(v.p(c), k * r, mid, area) {
            g.curve(Path::arc(v.p(c), k * r, a0, sweep), pen);
            Some((a0, sweep))
        } else {
            None
        }
    };
    let mut circle_labels = Vec::new();
    for (i, (c, w, mid)) in [(o1, w1, -FRAC_PI_2), (o2, w2, FRAC_PI_2)].into_iter().enumerate() {
        let n = (i + 1).to_string();
        let mut set = vec![
            (w.tip, THIN, LabelText::new("r", format!("a{n}"))),
            (w.root, THIN, LabelText::new("r", format!("f{n}"))),
            (w.base, THIN, LabelText::new("r", format!("b{n}"))),
            (w.pitch, AXIS, LabelText::new("r", n.clone())),
        ];
        if (w.working - w.pitch).abs() > 1e-9 {
            set.push((w.working, AXIS, LabelText::new("r", format!("w{n}"))));
        }
        for (r, pen, label) in set {
            if let Some((a0, sweep)) = circle(c, r, mid, pen) {
                circle_labels.push((crate::drawing::path::on_circle(v.p(c), k * r, a0 + sweep * 0.04), label));
            }
        }
    }

    // Teeth.
    g.curve(teeth_path(v, o1, inp.outlines[0], &fl1, &centres[0]), MAIN);
    g.curve(teeth_path(v, o2, inp.outlines[1], &fl2, &centres[1]), MAIN);
    // Lowest points of contact: B1 on wheel 1, B2 on wheel 2.
    let t_alpha = tan(p.working_pressure_angle);
    let r_low1 = (w1.base.powi(2) + (w1.base * t_alpha - p.approach).powi(2)).sqrt();
    let r_low2 = (w2.base.powi(2) + (w2.base * t_alpha - p.recess).powi(2)).sqrt();
    active_flanks(g, v, o1, inp.outlines[0], r_low1, &centres[0]);
    active_flanks(g, v, o2, inp.outlines[1], r_low2, &centres[1]);

    // Line of centres, τ–τ, the line of action.
    clipped_line(g, v.p(o1 - Vec2::new(0.0, 0.02 * a_w)), v.p(o2 + Vec2::new(0.0, 0.02 * a_w)), area, AXIS);
    let tau = 0.45 * area.width().min(k * 2.2 * p.spec.module * 10.0).max(60.0);
    g.line(pp - Vec2::new(tau, 0.0), pp + Vec2::new(tau, 0.0), THIN);
    let aw = p.working_pressure_angle;
    let dir = Vec2::new(-cos(aw), sin(aw)); // from N1 toward N2 (world)
    let n1 = o1 + Vec2::new(sin(aw), cos(aw)) * w1.base;
    let n2 = o2 - Vec2::new(sin(aw), cos(aw)) * w2.base;
    let wp = Vec2::new(0.0, w1.working);
    let b1 = wp - dir * p.approach;
    let b2 = wp + dir * p.recess;
    let ext = 8.0 / k;
    clipped_line(g, v.p(n1 - dir * ext), v.p(n2 + dir * ext), area, THIN);
    g.line(v.p(b1), v.p(b2), ACTIVE);
    for q in [n1, n2] {
        if area.contains(v.p(q)) {
            g.dot(v.p(q), 0.6);
        }
    }
    for q in [b1, b2, wp] {
        g.dot(v.p(q), 0.7);
    }

    // The angle α_w between τ–τ (to the left of P) and the line of action (toward N2).
    let ra = 28.0;
    g.curve(Path::arc(pp, ra, PI, aw), THIN);

    // The arc of action on wheel 1's working pitch circle: the flank through B1 and B2.
    let o = inp.outlines[0];
    let c_contact = centres[0][1];
    let turn_to = |x: Vec2| polar(x) - (c_contact + o.involute_angle(x.norm()));
    let (d1, d2) = (turn_to(b1), turn_to(b2));
    for d in [d1, d2] {
        let cs: Vec<CubicBez> =
            fl1.involute.iter().map(|x| map_cubic(x, |q| v.p(o1 + rot(q, c_contact + d)))).collect();
        g.curve(Path::cubics(&cs), THIN);
    }
    let (e1, e2) = (FRAC_PI_2 + d1, FRAC_PI_2 + d2);
    let rw = k * w1.working;
    g.curve(Path::arc(v.p(o1), rw, -e1, -(e2 - e1)), ACTIVE);
    // Measured on the drawing: the drawn ends, as written (to 1 µm), against the drawn pitch.
    let round = |q: Point| Point::new((q.x * 1e3).round() / 1e3, (q.y * 1e3).round() / 1e3);
    let (q1, q2, oc) =
        (round(v.p(o1 + from_angle(e1) * w1.working)), round(v.p(o1 + from_angle(e2) * w1.working)), round(v.p(o1)));
    let drawn_angle = ((q2 - oc).arg() - (q1 - oc).arg()).abs();
    let contact_ratio_drawn = drawn_angle * f64::from(w1.z) / TAU;

    // Labels: points, lines, circles.
    let up = Vec2::new(0.0, -1.0);
    let pt = |labels: &mut Labels, at: Vec2, main: &str, sub: &str, pref: Vec2| {
        let q = v.p(at);
        if area.contains(q) {
            labels.add_ranked(q, pref, LabelText::new(main, sub), 3.5, 0);
        }
    };
    pt(labels, wp, "P", "", Vec2::new(1.0, -1.0));
    pt(labels, n1, "N", "1", Vec2::new(1.0, 0.3));
    pt(labels, n2, "N", "2", Vec2::new(-1.0, -0.3));
    pt(labels, b1, "B", "1", Vec2::new(1.0, 0.5));
    pt(labels, b2, "B", "2", Vec2::new(-1.0, -0.5));
    pt(labels, o1, "O", "1", Vec2::new(1.0, 0.6));
    pt(labels, o2, "O", "2", Vec2::new(1.0, -0.6));
    // The senses of rotation: wheel 1 drives counter-clockwise, wheel 2 turns clockwise.
    for (q, ccw, n) in [(o1, true, "1"), (o2, false, "2")] {
        let c = v.p(q);
        if area.contains(c) {
            g.dot(c, 0.8);
            let start = if ccw { 200.0 } else { 20.0 };
            crate::drawing::symbols::turn_arrow(g, c, 9.0, start, 110.0, ccw, THIN);
            let at = c + from_angle((start + 55.0f64).to_radians() * if ccw { -1.0 } else { 1.0 }) * 9.0;
            labels.add_ranked(at, Vec2::new(-1.0, 0.0), LabelText::new("ω", n), 3.5, 1);
        }
    }
    labels.add_ranked(pp - Vec2::new(tau, 0.0), up, LabelText::new("τ", ""), 3.5, 1);
    labels.add_ranked(pp + Vec2::new(tau, 0.0), up, LabelText::new("τ", ""), 3.5, 1);
    labels.add_ranked(pp + Vec2::new(-ra - 2.0, -ra * 0.18), Vec2::new(-1.0, -0.4), LabelText::new("α", "w"), 3.5, 1);
    for (at, l) in circle_labels {
        labels.add_ranked(at, Vec2::new(-1.0, 0.0), l, 3.5, 2);
    }
    MeshDrawn {
        mu,
        contact_ratio_drawn,
        involute_deviation: dev1.max(dev2),
        fillet_deviation: fd1.max(fd2),
        tooth_height_mm: p.tooth_height * k,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gears::pair::PairSpec;

    #[test]
    fn the_teeth_outline_is_one_continuous_path() {
        let spec = PairSpec::standard(0.005, [17, 19]);
        let pair = Pair::new(&spec).unwrap();
        let o = Outline::new(&spec, &pair.wheels[0]);
        let (fl, _, _) = flank(&o);
        let v = View { o: Point::new(400.0, 390.0), k: 6000.0 };
        let path = teeth_path(v, Vec2::ZERO, &o, &fl, &[1.2, 1.57, 1.94]);
        let mut end = path.start;
        for s in &path.segs {
            if let Seg::Arc(a) = s {
                let start = crate::drawing::path::on_circle(a.center, a.radii.x, a.start_angle);
                assert!((start - end).norm() < 1e-9, "an arc starts {:e} mm off", (start - end).norm());
            }
            end = match s {
                Seg::Line(p) | Seg::Cubic(_, _, p) => *p,
                Seg::Arc(a) => crate::drawing::path::on_circle(a.center, a.radii.x, a.start_angle + a.sweep_angle),
            };
        }
    }

    /// Half the angular thickness of a wheel's tooth at radius `r` (root ≤ r ≤ tip), exact:
    /// the involute above the junction, the fillet below (its radius grows monotonically
    /// from the root to the junction, so a bisection finds the point).
    fn half_angle(o: &Outline, r: f64) -> f64 {
        let join = o.fillet(o.phi_join).0.norm();
        if r >= join {
            return o.involute_angle(r);
        }
        let (mut a, mut b) = (o.phi_root, o.phi_join);
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if o.fillet(m).0.norm() < r { a = m } else { b = m }
        }
        polar(o.fillet(0.5 * (a + b)).0)
    }

    /// How deep a point lies inside a wheel's material (m; negative: outside), exactly.
    fn depth(o: &Outline, centre: Vec2, tooth_centre: f64, q: Vec2) -> f64 {
        let d = q - centre;
        let r = d.norm();
        if r > o.tip {
            return o.tip - r;
        }
        if r < o.root {
            return o.root - r;
        }
        let step = TAU / f64::from(o.z);
        let rel = (polar(d) - tooth_centre).rem_euclid(step);
        let off = rel.min(step - rel); // angle from the nearest tooth's middle
        (half_angle(o, r) - off) * r
    }

    #[test]
    fn the_drawn_flanks_of_the_two_wheels_never_interpenetrate() {
        for (z, x) in [
            ([17u32, 19u32], [0.0, 0.0]),
            ([12, 30], [0.299, 0.0]),
            ([12, 24], [0.6, 0.36]),
            ([10, 27], [0.0, 0.0]),
            ([40, 60], [0.0, 0.0]),
        ] {
            let spec = PairSpec { shift: x, ..PairSpec::standard(0.005, z) };
            let pair = Pair::new(&spec).unwrap();
            let outlines = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
            let inp = MeshInput { pair: &pair, outlines: [&outlines[0], &outlines[1]] };
            let centres = tooth_centres(&inp);
            let o = [Vec2::ZERO, Vec2::new(0.0, pair.centre_distance)];
            let mut allowance = 1e-12;
            let mut worst: f64 = f64::NEG_INFINITY;
            let mut touch: f64 = f64::INFINITY;
            for i in 0..2 {
                let (fl, dev, fdev) = flank(&outlines[i]);
                allowance += dev.max(fdev);
                let j = 1 - i;
                for &cc in &centres[i] {
                    for mirror in [false, true] {
                        for c in fl.involute.iter().chain(&fl.fillet) {
                            for k in 0..=200 {
                                let p = kurbo::ParamCurve::eval(c, f64::from(k) / 200.0).to_vec2();
                                let p = if mirror { Vec2::new(p.x, -p.y) } else { p };
                                let q = o[i] + rot(p, cc);
                                let d = depth(&outlines[j], o[j], centres[j][1], q);
                                worst = worst.max(d);
                                touch = touch.min(-d);
                            }
                        }
                    }
                }
            }
            assert!(
                worst <= allowance,
                "{z:?} {x:?}: a drawn flank lies {worst:e} m inside the other wheel (allowance {allowance:e})"
            );
            // And they do touch: the pair is drawn in mesh, not apart.
            assert!(touch.abs() <= allowance, "{z:?}: the nearest flanks are {touch:e} m apart");
        }
    }

    #[test]
    fn the_contact_ratio_measured_on_the_drawing_agrees_with_the_closed_form() {
        for z in [[17u32, 19u32], [12, 30], [40, 60]] {
            let spec = PairSpec::standard(0.005, z);
            let pair = Pair::new(&spec).unwrap();
            let outlines = [Outline::new(&spec, &pair.wheels[0]), Outline::new(&spec, &pair.wheels[1])];
            let mut g = Group::new("m", Rect::new(0.0, 0.0, 420.0, 580.0));
            let mut labels = Labels::new();
            let d = draw_mesh(
                &mut g,
                Rect::new(2.0, 10.0, 418.0, 540.0),
                &MeshInput { pair: &pair, outlines: [&outlines[0], &outlines[1]] },
                &mut labels,
            );
            // The drawn ends are rounded to 1 µm on paper, about 20 mm from each other.
            assert!(
                (d.contact_ratio_drawn - pair.contact_ratio).abs() < 1e-4,
                "{z:?}: {} vs {}",
                d.contact_ratio_drawn,
                pair.contact_ratio
            );
            assert!(d.tooth_height_mm > 50.0);
            assert!(d.involute_deviation < 1e-6, "{z:?}: {:e}", d.involute_deviation);
        }
    }
}
