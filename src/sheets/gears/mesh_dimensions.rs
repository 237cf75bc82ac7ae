//! The mesh's dimensions as the course's drawings give them, in the wheels' true sizes (mm):
//! on wheel 1's pitch circle the tooth thickness s, the space e and the pitch p, as arc
//! dimensions in the wheel's body under its teeth, right of the line of centres (left of it
//! the space's flank runs through P, on the line itself). A dimension whose lines would leave
//! the drawing's area is not drawn. The centre distance a_w between O1 and O2, right of the
//! teeth, where both centres are on the drawing; wheel 1's addendum h_a and dedendum h_f
//! along a radius upper left, where only its circles pass; the base pitch p_b on the line of
//! action from P.

use crate::drawing::along::{Set, along_extension, along_line, clear_inside, value_along};
use crate::drawing::fmt;
use crate::drawing::labels::Language;
use crate::drawing::obstacles::{Obstacles, Piece};
use crate::drawing::path::Path;
use crate::drawing::place::Labels;
use crate::drawing::scene::{Anchor, Group, THIN, Text};
use crate::drawing::symbols::{self, ARROW_LEN};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::gears::pair::Pair;
use crate::num::math::{Norm, from_angle, tan};
use crate::num::units::mm;
use kurbo::{Point, Rect, Vec2};

/// The dimension arcs of s and e this far inside wheel 1's root circle, and p's further in, mm:
/// 20 mm apart, so that a value the placer sets under its arc is still nearer its own arc.
pub(super) const S_INSIDE_ROOT: f64 = 12.0;
pub(super) const P_INSIDE_ROOT: f64 = 32.0;
/// The values' lettering, mm.
const TEXT_H: f64 = 3.5;

/// The mesh drawing's obstacle index, kept up to date with its group's items: built once
/// for all the dimensions (each rebuild flattened every circle of the mesh again).
pub struct Drawn {
    obstacles: Obstacles,
    /// The group's items already in the index.
    upto: usize,
}

impl Drawn {
    /// The index of everything `g` holds.
    pub fn of(g: &Group) -> Drawn {
        Drawn { obstacles: Obstacles::of_items(&g.items), upto: g.items.len() }
    }

    /// The index with the items drawn into `g` since it was last brought up to date.
    fn sync(&mut self, g: &Group) -> &Obstacles {
        self.obstacles.add_items(&g.items[self.upto..], self.upto);
        self.upto = g.items.len();
        &self.obstacles
    }

    /// Keeps the dimensions' values off `r`: a label's anchor, placed after them (a value
    /// set on α_w's arc end left α_w a leader across the value only).
    pub fn reserve(&mut self, r: Rect) {
        self.obstacles.add(Piece::TextBox(r), usize::MAX);
    }

    /// Draws a value set beside its line (and the line's extension under it, if any),
    /// indexed by its pieces (a rotated text's pieces hug its letters where one box would
    /// block its whole slant).
    fn set(&mut self, g: &mut Group, Set { text, extension }: Set) {
        if let Some((e, f)) = extension {
            g.line(e, f, THIN);
        }
        self.sync(g);
        for b in text.bbox_pieces() {
            self.obstacles.add(Piece::TextBox(b), usize::MAX);
        }
        g.text(text);
        self.upto = g.items.len();
    }
}

/// Draws s, e and p on wheel 1: s on its tooth centred at world angle `tooth`, e on the space
/// after it (toward the line of centres), p over both, each value along its arc.
pub fn draw(
    g: &mut Group,
    (labels, drawn): (&mut Labels, &mut Drawn),
    v: View,
    area: Rect,
    p: &Pair,
    tooth: f64,
    lang: Language,
) {
    let w1 = &p.wheels[0];
    let step = std::f64::consts::TAU / f64::from(w1.z);
    let psi = w1.tooth_thickness / (2.0 * w1.pitch);
    // s and e are wheel 1's and p the pair's; unsubscripted, as the course writes them on the
    // mesh (s₁ widened its value past a random pair's extension line).
    let value = |name: &str, sub: &str, x: f64| {
        LabelText::new(name, sub).with_tail(format!(" = {}", fmt::dimension(mm(x), lang)))
    };
    let r_s = v.len(w1.root) - S_INSIDE_ROOT;
    let r_p = v.len(w1.root) - P_INSIDE_ROOT;
    let arc = Arc { v, area, r_feature: v.len(w1.pitch) };
    let (right, left) = (tooth - psi, tooth + psi);
    let next = tooth + step - psi;
    let values = [
        arc.dimension(g, r_s, (right, left), value("s", "", w1.tooth_thickness)),
        arc.dimension(g, r_s, (left, next), value("e", "", p.pitch - w1.tooth_thickness)),
        arc.dimension(g, r_p, (right, next), value("p", "", p.pitch)),
    ];
    // s's value set first may take the only spot e's has (and the other way round): the
    // order that leaves fewer values to the placer's leaders, s's first on a tie.
    let indexed = drawn.sync(g);
    let orders: [&[usize]; 2] = [&[0, 1, 2], &[1, 0, 2]];
    let tried = orders.map(|order| {
        let order: Vec<usize> = order.iter().copied().filter(|&k| values[k].is_some()).collect();
        let set = set_values(&arc, &order.iter().filter_map(|&k| values[k].as_ref()).collect::<Vec<_>>(), indexed, r_s);
        (order, set)
    });
    let left = |set: &[Option<Text>]| set.iter().filter(|t| t.is_none()).count();
    let (order, set) = tried.into_iter().min_by_key(|(_, set)| left(set)).expect("two orders");
    for (k, t) in order.into_iter().zip(set) {
        let Some(Value { r, mid, text, .. }) = &values[k] else { continue };
        match t {
            Some(t) => drawn.set(g, Set::beside(t)),
            None => {
                labels.add_ranked(arc.at(*mid, *r), arc.at(*mid, r + 1.0) - arc.at(*mid, *r), text.clone(), TEXT_H, 1)
            }
        }
    }
}

/// Each of `values` in turn beside its arc, clear of `drawn` and of the values set before it
/// (None: no spot, left to the label placer's leaders): along the arc over it, as GOST 2.307
/// writes a dimension's value, else under it, else level.
fn set_values(arc: &Arc, values: &[&Value], drawn: &Obstacles, r_s: f64) -> Vec<Option<Text>> {
    let mut out = Vec::new();
    // The pieces of the values set so far (a handful: no index).
    let mut placed: Vec<Rect> = Vec::new();
    // Whether a value of s's arc went under it, into the band between the arcs.
    let mut in_the_band = false;
    for &&Value { r, mid, half, ref text } in values {
        // p's arc lies inside s's: p's value over its arc stands in the band between them,
        // where an s or e value set under its arc would make the two one stack; p then goes
        // under its arc, toward the wheel's empty body. Away from the other arc a value may
        // stand far enough to clear what crosses its band; toward it, half the band at most.
        let away = r < r_s;
        let own = if away { -1.0 } else { 1.0 };
        let first = if away && in_the_band { -1.0 } else { 1.0 };
        let steps = |far: bool| (0..=if far { 30 } else { 12 }).map(|k| 1.0 + 0.5 * f64::from(k));
        let allowed = |off: f64| off.signum() == own || off.abs() <= 7.0;
        let apart =
            |t: &Text| t.bbox_pieces().all(|b| placed.iter().all(|p| p.intersect(b.inflate(0.5, 0.5)).area() <= 0.0));
        let clear = |t: &Text| clear_inside(t, drawn, arc.area) && apart(t);
        // Along the arc: on the first side within a few millimetres, then on the other (the
        // other wheel's circles cross the band over s's arc), then either, farther; moved
        // along the arc by up to a quarter of its length where its middle is crowded.
        let near = |sign: f64| steps(false).take_while(|&d| d <= 4.0).map(move |d| sign * d);
        let farther = steps(true).filter(|&d| d > 4.0).flat_map(|d| [own * d, -own * d]);
        let offs = near(first).chain(near(-first)).chain(farther).filter(|&off| allowed(off));
        let shifts: Vec<f64> =
            (0..=(r * half / 2.0).floor() as i32).flat_map(|k| [k, -k]).skip(1).map(f64::from).collect();
        let along = offs.flat_map(|off| shifts.iter().map(move |&shift| (off, shift)));
        let along = along.map(|(off, shift)| arc.along(mid + shift / r, r, off, text));
        // Level at the arc's middle, moved along the radius: a short arc's value between
        // extension lines too close for it along the arc.
        let over = steps(!away).map(|d| text.text(arc.at(mid, r + d), TEXT_H, Anchor::Middle));
        // Level with its top at `top`.
        let hanging = |top: Point| text.text(Point::new(top.x, top.y + TEXT_H), TEXT_H, Anchor::Middle);
        let under = steps(away).map(|d| hanging(arc.at(mid, r - d)));
        // Level, moved along the arc's tangent within its span where its middle is crowded
        // (e's value under its arc, between s's and p's extension lines, where along the
        // arc its length left it a 37 mm leader).
        let tangent = (arc.at(mid + 1.0 / r, r) - arc.at(mid, r)).unit();
        let reach = (r * half).floor() as i32;
        let level_shifted = steps(false).flat_map(|d| {
            (1..=reach).flat_map(move |k| [k, -k]).map(move |k| hanging(arc.at(mid, r - d) + tangent * f64::from(k)))
        });
        let set = if first < 0.0 {
            along.chain(under).chain(over).chain(level_shifted).find(clear)
        } else {
            along.chain(over).chain(under).chain(level_shifted).find(clear)
        };
        if let Some(t) = &set {
            placed.extend(t.bbox_pieces());
            in_the_band |= !away && (t.core_box().center() - arc.at(mid, 0.0)).norm() < r;
        }
        out.push(set);
    }
    out
}

/// The dimension line of a_w this far right of the teeth's drawn box, and the room its value
/// needs right of it, mm.
const A_W_CLEAR: f64 = 12.0;
const A_W_ROOM: f64 = 30.0;

/// The centre distance a_w from O1 to O2 (`teeth`: the teeth's drawn box): extension lines
/// from both centres to the right, the dimension line clear of the teeth (it crosses only the
/// wheels' circles). With O2 off the drawing's `area` (a large wheel 2), the line runs from
/// O1's extension line to the area's top with one arrow. Not drawn when O1 is off the area
/// or no room is left right of the teeth: the table gives a_w. Returns the dimension line
/// for [`centre_distance_value`].
pub fn centre_distance(g: &mut Group, v: View, area: Rect, p: &Pair, teeth: Rect) -> Option<(Point, Point)> {
    let (o1, o2) = (v.p(Vec2::ZERO), v.p(Vec2::new(0.0, p.centre_distance)));
    let x = teeth.x1 + A_W_CLEAR;
    if !area.contains(o1) || x + A_W_ROOM > area.x1 {
        return None;
    }
    let far = if area.contains(o2) {
        symbols::dimension(g, o2, o1, Vec2::new(x - o1.x, 0.0));
        o2.y
    } else {
        // O2 off the drawing: the dimension line broken off at the drawing's edge with its
        // one arrow at O1's extension line (GOST 2.307), its value the whole a_w.
        g.line(Point::new(o1.x + 1.0, o1.y), Point::new(x + 2.0, o1.y), THIN);
        let top = Point::new(x, area.y0.max(o2.y) + 2.0);
        g.line(Point::new(x, o1.y), top, THIN);
        symbols::arrowhead(g, Point::new(x, o1.y), Vec2::new(0.0, 1.0));
        top.y
    };
    Some((Point::new(x, o1.y), Point::new(x, far)))
}

/// a_w's value along its dimension line `line` (GOST 2.307: turned, read upward), where it
/// is clear of the drawing; else level beside it a quarter of the way up from O1, in wheel
/// 1's body where the drawing is empty, placed with the labels.
pub fn centre_distance_value(
    g: &mut Group,
    (labels, drawn): (&mut Labels, &mut Drawn),
    area: Rect,
    p: &Pair,
    (o1, far): (Point, Point),
    lang: Language,
) {
    let value = LabelText::new("a", "w").with_tail(format!(" = {}", fmt::dimension(mm(p.centre_distance), lang)));
    match along_line((drawn.sync(g), area), (o1, far), (&value, TEXT_H), None) {
        Some(text) => drawn.set(g, Set::beside(text)),
        None => labels.add_ranked(o1 + (far - o1) * 0.25, Vec2::new(1.0, 0.0), value, TEXT_H, 1),
    }
}

/// The world angles (degrees from wheel 1's centre, y up) tried for the heights' radial
/// dimension, upper left of the teeth first: away from the teeth (about 90°) and the s, e and
/// p arcs right of the line of centres, where only the wheel's circles pass.
const HEIGHTS_AT_DEG: [f64; 6] = [130.0, 140.0, 120.0, 150.0, 160.0, 170.0];

/// The addendum h_a (pitch to tip circle) and the dedendum h_f (root to pitch circle) of
/// wheel 1, as a chain of two dimensions along one radius of the wheel, its arrows on the
/// circles themselves, at the first of [`HEIGHTS_AT_DEG`] where the radius from a little
/// inside the root circle to a little past the tip is on the drawing and clear of the
/// teeth's box `teeth`; not drawn where none is.
pub fn heights(
    g: &mut Group,
    (labels, drawn): (&mut Labels, &mut Drawn),
    v: View,
    area: Rect,
    p: &Pair,
    teeth: Rect,
    lang: Language,
) {
    let w1 = &p.wheels[0];
    let on = |deg: f64, r: f64| v.p(from_angle(deg.to_radians()) * r);
    let clear = |deg: f64| {
        let (a, b) = (on(deg, w1.root - 6.0 * v.mu), on(deg, w1.tip + 6.0 * v.mu));
        area.contains(a) && area.contains(b) && teeth.intersect(Rect::from_points(a, b)).area() <= 0.0
    };
    let Some(deg) = HEIGHTS_AT_DEG.into_iter().find(|&d| clear(d)) else { return };
    let value = |name: &str, x: f64| LabelText::new("h", name).with_tail(format!(" = {}", fmt::dimension(mm(x), lang)));
    let along = on(deg, 1.0) - on(deg, 0.0);
    // A value left to the placer stands toward the teeth (the angles are past 90°), where the
    // wheel's body is empty: the circles' names stand at the other side, at the area's edge.
    // Along its line it stands over it (along.rs), as GOST 2.307 writes it.
    let side = Vec2::new(-along.y, along.x);
    // Wheel 1's heights (a shifted pair's wheel 2 has others).
    let dims =
        [(w1.pitch, w1.tip, value("a1", w1.tip - w1.pitch)), (w1.root, w1.pitch, value("f1", w1.pitch - w1.root))];
    let mids: Vec<kurbo::Point> =
        dims.iter().map(|&(r0, r1, _)| symbols::dimension(g, on(deg, r0), on(deg, r1), Vec2::ZERO)).collect();
    // Each value along its line where it fits between the circles crossing it, else level
    // beside it (the placer's): h_f hung 21 mm off on a leader.
    // Else on the line's extension past an arrow, into the wheel's empty body (GOST 2.307).
    for ((r0, r1, v_), mid) in dims.into_iter().zip(mids) {
        let (a, b) = (on(deg, r0), on(deg, r1));
        let indexed = drawn.sync(g);
        // The extension from the inner end first.
        let set = along_line((indexed, area), (a, b), (&v_, TEXT_H), None)
            .map(Set::beside)
            .or_else(|| along_extension((indexed, area), (b, a), (&v_, TEXT_H)));
        match set {
            Some(set) => drawn.set(g, set),
            None => labels.add_ranked(mid, side, v_, TEXT_H, 1),
        }
    }
}

/// The base pitch p_b of wheel 1 on a normal to its flanks — a tangent to its base circle
/// clear of the line of action — between two neighbouring same-side flanks of its three
/// drawn teeth: their involutes are p_b apart along every such normal. A point at roll
/// length L along the tangent at base angle θ lies on the involute from base angle θ + L/r_b
/// (world angles, the tangent turned counter-clockwise from the radius, as the line of action
/// from N1 toward N2); the flank through P comes from θ_N1 + N1P/r_b, its neighbours a tooth
/// step either side. The two points are taken at roll lengths where the involute is drawn
/// (between the form or base circle and the tip), as near the middle of that span as the
/// teeth allow; not drawn where the flank is shorter than p_b or the points leave the
/// drawing. Not on the line of action, nor beside it within [`ACTION_CLEAR`]: drawn there, the
/// thin dimension line and its arrowheads were lost in the bold line (task 13 variant 22,
/// a teacher's mark); its mirror image through P crossed it there.
pub fn base_pitch(
    g: &mut Group,
    (labels, drawn): (&mut Labels, &mut Drawn),
    (v, area): (View, Rect),
    p: &Pair,
    middle: f64,
    lang: Language,
) {
    let w1 = &p.wheels[0];
    let (rb, pb) = (w1.base, p.base_pitch);
    let aw = p.working_pressure_angle;
    let margin = 0.02 * pb;
    let low = (w1.form_radius.max(rb).powi(2) - rb * rb).max(0.0).sqrt() + margin;
    let high = (w1.tip * w1.tip - rb * rb).max(0.0).sqrt() - margin;
    if high - low < pb {
        return;
    }
    let theta_n1 = std::f64::consts::FRAC_PI_2 - aw;
    let n1p = rb * tan(aw);
    let flank_p = theta_n1 + n1p / rb;
    let step = pb / rb;
    // Centred in the flank's span, else anywhere along it (eight steps).
    let spread = (0..=8).map(|k| low + (high - pb - low) * f64::from(k) / 8.0);
    let rolls = [(low + high - pb) / 2.0, low, high - pb].into_iter().chain(spread);
    let tried: Vec<(f64, f64)> =
        rolls.filter(|&l| l >= low && l + pb <= high).flat_map(|l| [(0.0, l), (-1.0, l)]).collect();
    let world = |(k, l): (f64, f64)| {
        let theta = flank_p + k * step - l / rb;
        let (radial, along) = (from_angle(theta), from_angle(theta + std::f64::consts::FRAC_PI_2));
        let t = radial * rb;
        [t, t + along * l, t + along * (l + pb)]
    };
    // The other flanks of the three teeth, their mirror images about the middle tooth's axis.
    let axis = from_angle(middle);
    let mirror = |q: Vec2| axis * (2.0 * q.dot(axis)) - q;
    let direct = tried.iter().map(|&kl| world(kl));
    // The line of action: through N1, square to O1N1.
    let (n1, action) = (from_angle(theta_n1) * rb, from_angle(theta_n1 + std::f64::consts::FRAC_PI_2));
    let off_action = |q: Vec2| v.len((q - n1).cross(action).abs());
    let clear = |qs: &[Vec2; 3]| off_action(qs[1]).max(off_action(qs[2])) >= ACTION_CLEAR;
    let both = direct.clone().chain(direct.map(|qs| qs.map(mirror)));
    let points = both.filter(clear).map(|qs| qs.map(|q| v.p(q)));
    let inside = points.filter(|qs| qs.iter().all(|q| area.contains(*q)));
    let candidates: Vec<(kurbo::Point, kurbo::Point)> = inside.map(|[_, a, b]| (a, b)).collect();
    let Some(&first) = candidates.first() else {
        return;
    };
    let value = LabelText::new("p", "b").with_tail(format!(" = {}", fmt::dimension(mm(pb), lang)));
    // Its value along its line, as the arcs' values: beside its middle, else moved along it
    // up to its ends, on either side, the nearest clear. The first place of the dimension
    // with room for it; else the first with room on its line's extension past an arrow
    // (GOST 2.307); where none has, the first place, and the placer sets the value off on a
    // leader (it hung 20–37 mm off across the teeth).
    let indexed = drawn.sync(g);
    let beside = |(a, b): (kurbo::Point, kurbo::Point)| along_line((indexed, area), (a, b), (&value, TEXT_H), None);
    let past = |(a, b): (kurbo::Point, kurbo::Point)| along_extension((indexed, area), (a, b), (&value, TEXT_H));
    let between = candidates.iter().find_map(|&(a, b)| beside((a, b)).map(|t| (a, b, Some(Set::beside(t)))));
    let outside = || candidates.iter().find_map(|&(a, b)| past((a, b)).map(|set| (a, b, Some(set))));
    let (a, b, set) = between.or_else(outside).unwrap_or((first.0, first.1, None));
    let mid = symbols::dimension(g, a, b, Vec2::ZERO);
    match set {
        Some(set) => drawn.set(g, set),
        None => {
            let u = (b - a).unit();
            labels.add_ranked(mid, Vec2::new(u.y, -u.x), value, TEXT_H, 1)
        }
    }
}

/// The least distance of p_b's dimension line from the line of action at either end,
/// paper mm: nearer, the two read as one line.
const ACTION_CLEAR: f64 = 3.0;

/// Arc dimensions about wheel 1's centre from features on the circle of paper radius
/// `r_feature`.
struct Arc {
    v: View,
    area: Rect,
    r_feature: f64,
}

/// A dimension's value and where it goes: over the arc of paper radius `r` at world angle `mid`.
struct Value {
    r: f64,
    mid: f64,
    /// Half the arc's span, world radians.
    half: f64,
    text: LabelText,
}

impl Arc {
    /// The paper point at world angle `a` and paper radius `radius` about wheel 1's centre.
    fn at(&self, a: f64, radius: f64) -> kurbo::Point {
        let u = from_angle(a);
        self.v.p(Vec2::ZERO) + Vec2::new(u.x, -u.y) * radius
    }

    /// `value` set along the arc of paper radius `r` at world angle `mid`, read from the
    /// left, its box `off` mm outside the arc (inside where negative).
    fn along(&self, mid: f64, r: f64, off: f64, value: &LabelText) -> Text {
        let at = self.at(mid, r);
        value_along(at, self.at(mid, r + 1.0) - at, off, value, TEXT_H)
    }

    /// The dimension between world angles `(a0, a1)` (a0 < a1) on a dimension arc of paper
    /// radius `r`: extension lines from the features to 2 mm past the arc, the arc with its
    /// arrowheads (inside when they fit, else outside on 5 mm), the value beside its middle.
    fn dimension(&self, g: &mut Group, r: f64, (a0, a1): (f64, f64), value: LabelText) -> Option<Value> {
        let c = self.v.p(Vec2::ZERO);
        let at = |a: f64, radius: f64| self.at(a, radius);
        let ends = [at(a0, self.r_feature - 1.0), at(a1, self.r_feature - 1.0), at(a0, r - 2.0), at(a1, r - 2.0)];
        if r < 10.0 || !ends.iter().all(|q| self.area.contains(*q)) {
            return None;
        }
        for a in [a0, a1] {
            g.line(at(a, self.r_feature - 1.0), at(a, r - 2.0), THIN);
        }
        let length = r * (a1 - a0);
        // Paper angles run the other way (y down).
        let inside = length >= 2.0 * ARROW_LEN + 2.0;
        let out = if inside { 0.0 } else { 5.0 / r };
        g.curve(Path::arc(c, r, -(a0 - out), -(a1 - a0 + 2.0 * out)), THIN);
        let tangent = |a: f64, toward: f64| at(a, r) - at(a + toward * 0.5 / r, r);
        let sign = if inside { 1.0 } else { -1.0 };
        symbols::arrowhead(g, at(a0, r), tangent(a0, sign));
        symbols::arrowhead(g, at(a1, r), tangent(a1, -sign));
        Some(Value { r, mid: (a0 + a1) / 2.0, half: (a1 - a0) / 2.0, text: value })
    }
}
