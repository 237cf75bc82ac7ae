//! A dimension's value written along its line, as GOST 2.307 writes it: the text turned
//! parallel to the line, read from the left, beside it on either side, moved along it where
//! its middle is crowded — for dimensions that are not level (the mesh's arcs and radii, a
//! cam's r_min), where a level value finds no room between the lines crossing them.

use super::obstacles::{Obstacles, segment_meets_rect};
use super::scene::{Anchor, Text};
use super::text::LabelText;
use crate::num::math::{self, Norm};
use kurbo::{Point, Rect, Vec2};

/// A value set beside its dimension line, with the line's extension to draw under it where
/// it stands past an arrow.
pub struct Set {
    pub text: Text,
    pub extension: Option<(Point, Point)>,
}

impl Set {
    /// A value between its arrows: no extension.
    pub fn beside(text: Text) -> Set {
        Set { text, extension: None }
    }
}

/// sin 60°: a line running down to the right steeper than this has its value read upward.
const STEEP_DOWN: f64 = 0.866_025_403_784_438_6;

/// `value` set along a dimension line through `at` whose unit normal is `normal`, centred
/// on `at`, its box `off` mm from the line on `normal`'s side (on the other where negative).
pub fn value_along(at: Point, normal: Vec2, off: f64, value: &LabelText, h: f64) -> Text {
    let (d, up) = reading(Vec2::new(-normal.y, normal.x));
    // The baseline this far from the line along `normal`: the box's near side `off` from it.
    let (depth, top) = (0.3 * h, 1.05 * h);
    let shift = match (off > 0.0, up.dot(normal) > 0.0) {
        (true, true) => off + depth,
        (true, false) => off + top,
        (false, true) => off - top,
        (false, false) => off - depth,
    };
    let mut t = value.text(at + normal * shift, h, Anchor::Middle);
    t.rotate = math::atan2(-d.y, d.x).to_degrees();
    t
}

/// The room the text `t`, set along the line a–b, leaves on the line's other side: its box
/// mirrored across the line, which a label keeps clear of (a profile's name just under
/// r_min's line read as a second line of its value, «r_min = 75,14 / рабочий профиль»).
pub fn mirrored_room(t: &Text, (a, b): (Point, Point)) -> Rect {
    let r = t.bbox();
    let u = (b - a).unit();
    let c = r.center().to_vec2() - a.to_vec2();
    let along = u * c.dot(u);
    let mirrored = a + along * 2.0 - c;
    Rect::from_center_size(mirrored, r.size())
}

/// The side of the line a–b a value set along it stands over (GOST 2.307 writes it there):
/// its letters' up, as [`value_along`] turns them — above a level or slanted line, left of
/// a vertical one.
pub fn over(a: Point, b: Point) -> Vec2 {
    reading((b - a).unit()).1
}

/// The baseline's direction and the letters' up of a value along a line running `u` (a
/// unit vector either way along it): read from the drawing's bottom or its right (GOST
/// 2.307's aligned values) — left to right, or upward where the line runs within 30° of
/// the vertical down to the right (read downward, they face the left).
fn reading(u: Vec2) -> (Vec2, Vec2) {
    let right = if u.x >= 0.0 { u } else { -u };
    let d = if right.y > STEEP_DOWN { -right } else { right };
    (d, Vec2::new(d.y, -d.x))
}

/// `value` along the dimension line a–b, clear of `drawn` and inside `area`: beside its middle, else moved
/// along it up to its ends, the nearest clear within 8 mm: on `pref`'s side first at each
/// distance; where None, over the line up to 2.5 mm before any spot under it.
pub fn along_line(
    (drawn, area): (&Obstacles, Rect),
    (a, b): (Point, Point),
    (value, h): (&LabelText, f64),
    pref: Option<Vec2>,
) -> Option<Text> {
    let (along, mid) = (b - a, a.midpoint(b));
    let (length, u) = (along.norm(), along.unit());
    let normal = Vec2::new(u.y, -u.x);
    let distances = (0..=14).map(|k| 1.0 + 0.5 * f64::from(k));
    let offs: Vec<f64> = match pref {
        // The preferred side first at each distance.
        Some(pref) => {
            let first = if pref.dot(normal) < 0.0 { -1.0 } else { 1.0 };
            distances.flat_map(|d| [first * d, -first * d]).collect()
        }
        None => over_first(if over(a, b).dot(normal) < 0.0 { -1.0 } else { 1.0 }, distances).collect(),
    };
    let shifts: Vec<f64> = (0..=(length / 2.0).floor() as i32).flat_map(|k| [k, -k]).skip(1).map(f64::from).collect();
    let tried = offs.into_iter().flat_map(|off| shifts.iter().map(move |&shift| (off, shift)));
    tried.map(|(off, shift)| value_along(mid + u * shift, normal, off, value, h)).find(|t| clear_inside(t, drawn, area))
}

/// How far over its line a value is tried before any place under it, mm: a slanted value's
/// box needs about a millimetre more room over its line than under it, and nearest first
/// set the worked example's h_a1 and h_f1 under their lines. Farther over, a value taking a
/// label's room turned a cam sheet's profile to a smaller scale.
const OVER_FIRST: f64 = 2.5;

/// The offsets from a line, `distances` (ascending) on either side, the side `up` (±1,
/// the normal's sign of "over") alone first up to [`OVER_FIRST`], then both sides, nearest
/// first, over before under at each distance.
fn over_first(up: f64, distances: impl Iterator<Item = f64> + Clone) -> impl Iterator<Item = f64> + Clone {
    let near = distances.clone().take_while(|&d| d <= OVER_FIRST).map(move |d| up * d);
    // Both sides at each distance, less the near ones over the line tried already.
    let rest =
        distances.flat_map(move |d| [up * d, -up * d]).filter(move |&off| off * up < 0.0 || off.abs() > OVER_FIRST);
    near.chain(rest)
}

/// Whether `t` meets nothing of `drawn` (0.5 mm clear) and lies inside `area`.
pub fn clear_inside(t: &Text, drawn: &Obstacles, area: Rect) -> bool {
    let b = t.bbox();
    area.contains(b.origin())
        && area.contains(Point::new(b.x1, b.y1))
        && t.bbox_pieces().all(|b| drawn.is_clear(b.inflate(0.5, 0.5)))
}

/// `value` on the extension of the dimension line a–b past one of its arrows (GOST 2.307,
/// where the value has no room between them): beside the extension 1–4 mm, over it up to
/// 2.5 mm first (its own line 0.5 mm clear of the text's pieces, as every other line), b's
/// end first, clear of `drawn` and inside `area`, the extension crossing no line (it would read as part
/// of another dimension), with the extension from that end of a–b to its far end.
pub fn along_extension(
    (drawn, area): (&Obstacles, Rect),
    (a, b): (Point, Point),
    (value, h): (&LabelText, f64),
) -> Option<Set> {
    let u = (b - a).unit();
    let width = value.width(h);
    let ends = [(b, u), (a, -u)];
    let mut tried = ends.into_iter().flat_map(|(end, out)| {
        (0..=6).flat_map(move |k| {
            let gap = 2.0 + f64::from(k);
            let far = end + out * (gap + width + 1.0);
            let normal = over(end, far);
            over_first(1.0, (0..=6).map(|j| 1.0 + 0.5 * f64::from(j)))
                .map(move |off| (end, far, value_along(end + out * (gap + width / 2.0), normal, off, value, h)))
        })
    });
    let clear = |(end, far, t): &(Point, Point, Text)| {
        let from = *end + (*far - *end).unit() * 0.5;
        area.contains(*far)
            && !drawn.segment_crosses_text(*end, *far)
            && !drawn.segment_crosses_stroke(from, *far)
            && clear_inside(t, drawn, area)
            && t.bbox_pieces().all(|b| !segment_meets_rect(*end, *far, b.inflate(0.5, 0.5)))
    };
    tried.find(clear).map(|(end, far, text)| Set { text, extension: Some((end, far)) })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a line at any angle, the side `over` names is the one a value set along the line
    /// has its letters' up towards, and it is the upper side (GOST 2.307's "over") unless
    /// the line is within 30° of the vertical, where it is the left.
    #[test]
    fn over_is_the_side_the_letters_face_up_to() {
        let value = LabelText::new("r", "min");
        for k in 0..72 {
            let angle = f64::from(k) * 5.0_f64.to_radians() + 0.01;
            let (a, b) =
                (Point::new(10.0, 10.0), Point::new(10.0 + 50.0 * math::cos(angle), 10.0 + 50.0 * math::sin(angle)));
            let u = (b - a).unit();
            let side = over(a, b);
            assert!(side.dot(u).abs() < 1e-12 && (side.norm() - 1.0).abs() < 1e-12, "across the line at {k}");
            let t = value_along(a.midpoint(b), Vec2::new(u.y, -u.x), 1.0, &value, 2.5);
            let turned = t.rotate.to_radians();
            let up = Vec2::new(-math::sin(turned), -math::cos(turned));
            assert!((up - side).norm() < 1e-9, "at {}°: letters up {up:?}, over {side:?}", f64::from(k) * 5.0);
            let steep = u.x.abs() < 0.5;
            assert!(if steep { side.x < 0.0 } else { side.y < 0.0 }, "at {}°: over is {side:?}", f64::from(k) * 5.0);
        }
    }
}
