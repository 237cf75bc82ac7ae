//! The external mesh as the course draws it: both wheels' circles, the common tangent τ–τ,
//! the pitch point P, the line of action N1N2 and its active part B1B2, three exact teeth
//! per wheel in mesh (touching at P), the active profiles thick, the arc of action on the
//! working pitch circle of wheel 1 with the contact ratio measured on it.
//!
//! World coordinates are the pair's, metres, y up: O1 at the origin, O2 at (0, a_w), P at
//! (0, r_w1). Wheel 1 turns counter-clockwise and drives; the contact runs from B1 (on
//! wheel 2's tip circle, toward N1) to B2.

use super::clip::{clipped_line, visible_arc};
use super::teeth_view::{ACTIVE, Flank, active_flanks, flank, map_cubic, teeth_path};
use crate::drawing::path::Path;
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, Group, MAIN, Pen, THIN};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::gears::pair::Pair;
use crate::gears::tooth::{Outline, polar};
use crate::num::math::{Norm, cos, from_angle, rotate, sin, tan};
use crate::num::tol;
use kurbo::{CubicBez, Point, Rect, Vec2};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

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

/// What the mesh view needs.
pub struct MeshInput<'a> {
    pub pair: &'a Pair,
    pub outlines: [&'a Outline; 2],
    /// The dimensions' values are written in its numbers.
    pub lang: crate::drawing::labels::Language,
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

/// The mesh's points in the world: O2 (O1 is the origin), the line of action's N1 and N2
/// and its active ends B1 and B2, the pitch point P, and the line's direction from N1 to N2.
struct MeshPoints {
    o2: Vec2,
    n1: Vec2,
    n2: Vec2,
    b1: Vec2,
    b2: Vec2,
    p: Vec2,
    dir: Vec2,
}

impl MeshPoints {
    fn of(p: &Pair) -> MeshPoints {
        let [w1, w2] = &p.wheels;
        let aw = p.working_pressure_angle;
        let o2 = Vec2::new(0.0, p.centre_distance);
        let dir = Vec2::new(-cos(aw), sin(aw)); // from N1 toward N2 (world)
        let n1 = Vec2::ZERO + Vec2::new(sin(aw), cos(aw)) * w1.base;
        let n2 = o2 - Vec2::new(sin(aw), cos(aw)) * w2.base;
        let wp = Vec2::new(0.0, w1.working);
        MeshPoints { o2, n1, n2, b1: wp - dir * p.approach, b2: wp + dir * p.recess, p: wp, dir }
    }
}

/// The radius of the arc marking α_w at P, mm.
const ALPHA_ARC_MM: f64 = 28.0;
/// The dimensions' values keep off a square this wide round α_w's anchor, mm: room for its
/// name beside it.
const ALPHA_ROOM: f64 = 8.0;

/// Draws the mesh into `g` (its region): title above, notes below are the caller's; the
/// drawing is placed in `area`.
pub fn draw_mesh(g: &mut Group, area: Rect, inp: &MeshInput, labels: &mut Labels) -> MeshDrawn {
    let p = inp.pair;
    let (fl1, dev1, fd1) = flank(inp.outlines[0]);
    let (fl2, dev2, fd2) = flank(inp.outlines[1]);
    let mu = mesh_scale(inp, [&fl1, &fl2], area);
    let (v, pp) = placement(p, area, mu);
    let centres = tooth_centres(inp);
    let circle_labels = draw_circles(g, v, area, p);
    let start = g.mark();
    draw_teeth(g, v, inp, [&fl1, &fl2], &centres);
    let teeth = g.items[start..].iter().map(|i| i.bbox()).reduce(|a, b| a.union(b)).unwrap_or(Rect::ZERO);
    let points = MeshPoints::of(p);
    let tau = draw_lines(g, v, area, pp, p, &points);
    let contact_ratio_drawn = draw_arc_of_action(g, v, inp, &fl1, centres[0][1], &points);
    let a_w = super::mesh_dimensions::centre_distance(g, v, area, p, teeth);
    // The sense arrows before the dimensions' values, which keep clear of them (a 5-tooth
    // pinion's p, set along the line of centres, stood across ω₁'s arrow); their names
    // with the other labels, below.
    let senses = senses_of_rotation(g, v, area, &points, v.len(p.wheels[1].root));
    // One index of the drawing for the dimensions' values, each added to it as it is set.
    let mut drawn = super::mesh_dimensions::Drawn::of(g);
    let alpha_at = pp + Vec2::new(-ALPHA_ARC_MM - 2.0, -ALPHA_ARC_MM * 0.18);
    drawn.reserve(Rect::from_center_size(alpha_at, (ALPHA_ROOM, ALPHA_ROOM)));
    if let Some(line) = a_w {
        super::mesh_dimensions::centre_distance_value(g, (labels, &mut drawn), area, p, line, inp.lang);
    }
    super::mesh_dimensions::heights(g, (labels, &mut drawn), v, area, p, teeth, inp.lang);
    super::mesh_dimensions::draw(g, (labels, &mut drawn), v, area, p, centres[0][0], inp.lang);
    super::mesh_dimensions::base_pitch(g, (labels, &mut drawn), (v, area), p, centres[0][1], inp.lang);
    point_labels(labels, v, area, &points);
    for (spots, name) in senses {
        labels.add_ranked_at_any(&spots, name, 3.5, 1);
    }
    labels.add_ranked(pp - Vec2::new(tau, 0.0), Vec2::new(0.0, -1.0), LabelText::new("τ", ""), 3.5, 1);
    labels.add_ranked(pp + Vec2::new(tau, 0.0), Vec2::new(0.0, -1.0), LabelText::new("τ", ""), 3.5, 1);
    labels.add_ranked(alpha_at, Vec2::new(-1.0, -0.4), LabelText::new("α", "w"), 3.5, 1);
    for (at, l) in circle_labels {
        labels.add_ranked(at, Vec2::new(-1.0, 0.0), l, 3.5, 2);
    }
    MeshDrawn {
        mu,
        contact_ratio_drawn,
        involute_deviation: dev1.max(dev2),
        fillet_deviation: fd1.max(fd2),
        // Paper mm per metre times metres, as results.json has always had it (`/ mu` can
        // differ in the last bit).
        tooth_height_mm: p.tooth_height * (1.0 / mu),
    }
}

/// μ_l of the mesh: the teeth over 50 mm high, as the course draws them, unless a wheel's
/// three teeth would then reach past the region's sides — a many-toothed wheel beside a
/// small pinion, a large shift turning the teeth off the line of centres — when the largest
/// scale at which they fit. The teeth's half-width from the line of centres is their tip
/// radius times the sine of the farthest tooth's angle from it (half a pitch beyond its
/// centre).
fn mesh_scale(inp: &MeshInput, flanks: [&Flank; 2], area: Rect) -> f64 {
    let p = inp.pair;
    let tall = crate::drawing::scale::length_scale_below(p.tooth_height / 50.0);
    let centres = tooth_centres(inp);
    let half_width = |i: usize, axis: f64| {
        let w = &p.wheels[i];
        let half_pitch = PI / f64::from(w.z);
        let far = centres[i].iter().map(|c| (c - axis).abs() + half_pitch).fold(0.0, f64::max);
        w.tip * if far >= FRAC_PI_2 { 1.0 } else { sin(far) }
    };
    // The outline as drawn reaches further where a large shift's fillet loops past the
    // outer teeth (a 363-tooth wheel at x = 0.993 reached 0.4 mm past its region): its
    // extent from the line of centres, in the world (a view at 1 m per mm).
    let world = View::new(Point::ZERO, 1.0);
    let o2 = Vec2::new(0.0, p.centre_distance);
    let drawn = |i: usize, c: Vec2| {
        let b = teeth_path(world, c, inp.outlines[i], flanks[i], &centres[i]).bbox();
        (-b.x0).max(b.x1)
    };
    let widest = half_width(0, FRAC_PI_2).max(half_width(1, -FRAC_PI_2)).max(drawn(0, Vec2::ZERO)).max(drawn(1, o2));
    let fits = crate::drawing::scale::length_scale(widest / (area.width() / 2.0 - MESH_MARGIN));
    tall.max(fits)
}

/// Paper mm kept free on each side of the widest wheel's three teeth.
const MESH_MARGIN: f64 = 6.0;

/// The view of the pair in `area` at μ_l `mu`, and P on paper: P in the middle across; both
/// centres on the sheet when they fit, else P in the middle.
fn placement(p: &Pair, area: Rect, mu: f64) -> (View, Point) {
    let [w1, w2] = &p.wheels;
    let span = p.centre_distance / mu;
    let py = if span + 24.0 <= area.height() {
        area.y0 + 12.0 + w2.working / mu + (area.height() - span - 24.0) / 2.0
    } else {
        area.center().y
    };
    let pp = Point::new(area.center().x, py);
    (View::new(Point::new(pp.x, pp.y + w1.working / mu), mu), pp)
}

/// Both wheels' circles, clipped to `area`; returns where each circle's name goes.
fn draw_circles(g: &mut Group, v: View, area: Rect, p: &Pair) -> Vec<(Point, LabelText)> {
    let [w1, w2] = &p.wheels;
    let mut circle = |c: Vec2, r: f64, mid: f64, pen: Pen| {
        if let Some((a0, sweep)) = visible_arc(v.p(c), v.len(r), mid, area) {
            g.curve(Path::arc(v.p(c), v.len(r), a0, sweep), pen);
            Some((a0, sweep))
        } else {
            None
        }
    };
    let mut circle_labels = Vec::new();
    let o2 = Vec2::new(0.0, p.centre_distance);
    for (i, (c, w, mid)) in [(Vec2::ZERO, w1, -FRAC_PI_2), (o2, w2, FRAC_PI_2)].into_iter().enumerate() {
        let n = (i + 1).to_string();
        let mut set = vec![
            (w.tip, THIN, LabelText::new("r", format!("a{n}"))),
            (w.root, THIN, LabelText::new("r", format!("f{n}"))),
            (w.base, THIN, LabelText::new("r", format!("b{n}"))),
            (w.pitch, AXIS, LabelText::new("r", n.clone())),
        ];
        if (w.working - w.pitch).abs() > tol::SAME_CIRCLE {
            set.push((w.working, AXIS, LabelText::new("r", format!("w{n}"))));
        }
        for (r, pen, label) in set {
            if let Some((a0, sweep)) = circle(c, r, mid, pen) {
                circle_labels.push((crate::drawing::path::on_circle(v.p(c), v.len(r), a0 + sweep * 0.04), label));
            }
        }
    }
    circle_labels
}

/// Three teeth of each wheel, and the active part of their upper flanks thick: from the
/// lowest point of contact (B1 on wheel 1, B2 on wheel 2) to the tip.
fn draw_teeth(g: &mut Group, v: View, inp: &MeshInput, flanks: [&Flank; 2], centres: &[Vec<f64>; 2]) {
    let p = inp.pair;
    let [w1, w2] = &p.wheels;
    let o2 = Vec2::new(0.0, p.centre_distance);
    g.curve(teeth_path(v, Vec2::ZERO, inp.outlines[0], flanks[0], &centres[0]), MAIN);
    g.curve(teeth_path(v, o2, inp.outlines[1], flanks[1], &centres[1]), MAIN);
    let t_alpha = tan(p.working_pressure_angle);
    let r_low1 = (w1.base.powi(2) + (w1.base * t_alpha - p.approach).powi(2)).sqrt();
    let r_low2 = (w2.base.powi(2) + (w2.base * t_alpha - p.recess).powi(2)).sqrt();
    active_flanks(g, v, Vec2::ZERO, inp.outlines[0], r_low1, &centres[0]);
    active_flanks(g, v, o2, inp.outlines[1], r_low2, &centres[1]);
}

/// The line of centres, τ–τ through P, the line of action with its active part B1B2 thick,
/// the points on it and the angle α_w; returns τ–τ's half length, mm.
fn draw_lines(g: &mut Group, v: View, area: Rect, pp: Point, p: &Pair, m: &MeshPoints) -> f64 {
    let a_w = p.centre_distance;
    let o1 = Vec2::ZERO;
    clipped_line(g, v.p(o1 - Vec2::new(0.0, 0.02 * a_w)), v.p(m.o2 + Vec2::new(0.0, 0.02 * a_w)), area, AXIS);
    let tau = 0.45 * area.width().min(v.len(2.2 * p.spec.module * 10.0)).max(60.0);
    g.line(pp - Vec2::new(tau, 0.0), pp + Vec2::new(tau, 0.0), THIN);
    let ext = 8.0 * v.mu; // 8 mm on paper
    clipped_line(g, v.p(m.n1 - m.dir * ext), v.p(m.n2 + m.dir * ext), area, THIN);
    g.line(v.p(m.b1), v.p(m.b2), ACTIVE);
    for q in [m.n1, m.n2] {
        if area.contains(v.p(q)) {
            g.dot(v.p(q), 0.6);
        }
    }
    for q in [m.b1, m.b2, m.p] {
        g.dot(v.p(q), 0.7);
    }
    // The angle α_w between τ–τ (to the left of P) and the line of action (toward N2).
    g.curve(Path::arc(pp, ALPHA_ARC_MM, PI, p.working_pressure_angle), THIN);
    tau
}

/// The arc of action on wheel 1's working pitch circle: wheel 1's flank (of the tooth at
/// `c_contact`) through B1 and through B2, and the arc between them; returns the contact
/// ratio measured on the drawing.
fn draw_arc_of_action(g: &mut Group, v: View, inp: &MeshInput, fl1: &Flank, c_contact: f64, m: &MeshPoints) -> f64 {
    let o = inp.outlines[0];
    let w1 = &inp.pair.wheels[0];
    let o1 = Vec2::ZERO;
    let turn_to = |x: Vec2| polar(x) - (c_contact + o.involute_angle(x.norm()));
    let (d1, d2) = (turn_to(m.b1), turn_to(m.b2));
    for d in [d1, d2] {
        let cs: Vec<CubicBez> =
            fl1.involute.iter().map(|x| map_cubic(x, |q| v.p(o1 + rotate(q, c_contact + d)))).collect();
        g.curve(Path::cubics(&cs), THIN);
    }
    let (e1, e2) = (FRAC_PI_2 + d1, FRAC_PI_2 + d2);
    let rw = v.len(w1.working);
    g.curve(Path::arc(v.p(o1), rw, -e1, -(e2 - e1)), ACTIVE);
    // Measured on the drawing: the drawn ends, as written (to 1 µm), against the drawn pitch.
    let round = |q: Point| Point::new((q.x * 1e3).round() / 1e3, (q.y * 1e3).round() / 1e3);
    let (q1, q2, oc) =
        (round(v.p(o1 + from_angle(e1) * w1.working)), round(v.p(o1 + from_angle(e2) * w1.working)), round(v.p(o1)));
    let drawn_angle = ((q2 - oc).arg() - (q1 - oc).arg()).abs();
    drawn_angle * f64::from(w1.z) / TAU
}

/// The letters of the points that fall inside `area`: P, N1, N2, B1, B2, O1, O2.
fn point_labels(labels: &mut Labels, v: View, area: Rect, m: &MeshPoints) {
    let named = [
        (m.p, "P", "", Vec2::new(1.0, -1.0)),
        (m.n1, "N", "1", Vec2::new(1.0, 0.3)),
        (m.n2, "N", "2", Vec2::new(-1.0, -0.3)),
        (m.b1, "B", "1", Vec2::new(1.0, 0.5)),
        (m.b2, "B", "2", Vec2::new(-1.0, -0.5)),
        (Vec2::ZERO, "O", "1", Vec2::new(1.0, 0.6)),
        (m.o2, "O", "2", Vec2::new(1.0, -0.6)),
    ];
    // A B on its N (the active line cut at N) is named once, "N₁ ≡ B₁", not twice on one dot.
    let coincide = |b: Vec2, n: Vec2| (v.p(b) - v.p(n)).norm() < 0.5;
    let merged = [coincide(m.b1, m.n1), coincide(m.b2, m.n2)];
    for (at, main, sub, pref) in named {
        let q = v.p(at);
        let wheel = usize::from(sub == "2");
        if !area.contains(q) || (main == "B" && merged[wheel]) {
            continue;
        }
        let mut label = LabelText::new(main, sub);
        if main == "N" && merged[wheel] {
            label = label.with_tail(format!(" ≡ B{}", ["₁", "₂"][wheel]));
        }
        labels.add_ranked(q, pref, label, 3.5, 0);
    }
}

/// The senses of rotation at the centres on the sheet: wheel 1 drives counter-clockwise,
/// wheel 2 turns clockwise. A large wheel 2 whose centre is off the drawing gets its arrow
/// on an arc about that centre inside its own body (`root2`: its root radius, mm), near the
/// drawing's top on the line of centres.
/// Returns each arrow's name with the spots it may take (the first preferred).
fn senses_of_rotation(g: &mut Group, v: View, area: Rect, m: &MeshPoints, root2: f64) -> Vec<(Vec<Spot>, LabelText)> {
    let mut names = Vec::new();
    for (q, ccw, n) in [(Vec2::ZERO, true, "1"), (m.o2, false, "2")] {
        let c = v.p(q);
        if area.contains(c) {
            g.dot(c, 0.8);
            // Under the centre, else (a centre near the drawing's foot: its arc ran into the
            // notes under it) over it, wholly: from 35° to 145° above the horizontal (paper
            // angles fall as the sheet turns counter-clockwise).
            let low = c.y + 10.0 > area.y1;
            let start = match (low, ccw) {
                (false, true) => 200.0,
                (false, false) => 20.0,
                (true, true) => -35.0,
                (true, false) => -145.0,
            };
            crate::drawing::symbols::turn_arrow(g, c, 9.0, start, 110.0, ccw, THIN);
            // Named beside the arrow's middle, else beside its tail or its head, outward:
            // a centre near the drawing's edge leaves room on one side only.
            let on = |deg: f64| from_angle((start + if ccw { -deg } else { deg }).to_radians());
            let spots = [
                (c + on(55.0) * 9.0, Vec2::new(-1.0, 0.0)),
                (c + on(0.0) * 9.0, on(0.0)),
                (c + on(110.0) * 9.0, on(110.0)),
            ];
            names.push((spots.to_vec(), LabelText::new("ω", n)));
        } else if n == "2"
            && let Some((r, mid)) = rim_arrow_radius(c, v.p(Vec2::ZERO), area, root2)
        {
            let sweep = (OFF_SHEET_ARROW_MM / r).to_degrees();
            crate::drawing::symbols::turn_arrow(g, c, r, mid - sweep / 2.0, sweep, ccw, THIN);
            let at = c + from_angle(mid.to_radians()) * r;
            names.push((vec![(at, Vec2::new(-1.0, 0.0))], LabelText::new("ω", n)));
        }
    }
    names
}

/// A label's anchor and the direction it is set off in.
type Spot = (Point, Vec2);

/// The length of wheel 2's sense arrow about its centre off the drawing, and how far inside
/// the drawing's top its middle stands and inside the wheel's root circle, mm.
const OFF_SHEET_ARROW_MM: f64 = 22.0;
const OFF_SHEET_INSIDE_TOP: f64 = 14.0;
const OFF_SHEET_INSIDE_ROOT: f64 = 10.0;

/// For wheel 2's centre `c2` off the drawing `area` (wheel 1's centre `c1` on it): the radius
/// of its sense arrow about `c2` and the paper angle (degrees) of the arrow's middle, on the
/// line of centres [`OFF_SHEET_INSIDE_TOP`] inside the area's top, if that is
/// [`OFF_SHEET_INSIDE_ROOT`] inside the wheel's root circle `root2` (mm) and the whole arc is
/// on the drawing; `None` otherwise.
fn rim_arrow_radius(c2: Point, c1: Point, area: Rect, root2: f64) -> Option<(f64, f64)> {
    let u = (c1 - c2).unit();
    if !u.is_finite() || u.y <= 0.0 {
        return None;
    }
    let r = (area.y0 + OFF_SHEET_INSIDE_TOP - c2.y) / u.y;
    let reach = crate::drawing::symbols::ARROW_HALF + OFF_SHEET_ARROW_MM / 2.0;
    let mid = c2 + u * r;
    let on = area.inset(-reach).contains(mid) && r > OFF_SHEET_ARROW_MM && r <= root2 - OFF_SHEET_INSIDE_ROOT;
    on.then(|| (r, u.arg().to_degrees()))
}

#[cfg(test)]
#[path = "mesh_view_tests.rs"]
mod tests;
