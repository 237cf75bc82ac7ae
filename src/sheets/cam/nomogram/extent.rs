//! The nomogram's picture in the follower frame: the box it shows (a rocker's far pivot
//! left out), the room its paper-sized parts need, and the view centring it.

use crate::cams::Design;
use crate::drawing::view::View;
use crate::num::math::{self, Norm};
use crate::num::tol;
use kurbo::{Point, Rect, Vec2};

/// The box holding discs (centre, radius): its lowest and highest corners.
pub fn bounds(discs: impl IntoIterator<Item = (Vec2, f64)>) -> (Vec2, Vec2) {
    discs.into_iter().fold((Vec2::new(f64::MAX, f64::MAX), Vec2::new(f64::MIN, f64::MIN)), |(lo, hi), (p, r)| {
        (Vec2::new(lo.x.min(p.x - r), lo.y.min(p.y - r)), Vec2::new(hi.x.max(p.x + r), hi.y.max(p.y + r)))
    })
}

/// Every point of the nomogram's picture round its curve: each B_k and B′_k, and O.
fn near_points(d: &Design, phis: &[f64]) -> Vec<Vec2> {
    let r = &d.region;
    let mut pts: Vec<Vec2> = phis.iter().flat_map(|&phi| [r.state(phi).b, r.state(phi).analog]).collect();
    pts.push(d.centre.o);
    pts
}

/// A rocker's pivot further from the picture of the curve and O than this many times that
/// picture's longer side is left off the nomogram: drawn, it set the scale, and the curve,
/// the zone and their labels shrank into a few millimetres by O (a 20 mm rocker swinging
/// 5.7°: its curve 6 mm across at 2:1 with the pivot 40 mm away, the limiting line across
/// three labels). The rocker lines then run to the picture's edge, and O's line to the
/// pivot ends there in an arrow named A, a_w written along it. The catalogue's rockers are
/// at most 2.5 times (task 4): drawn whole, as the course draws them; the stress sweep's
/// small rockers, 7 times.
const PIVOT_FAR: f64 = 4.0;

/// Whether the nomogram of the box `extent` draws the follower's pivot (see [`PIVOT_FAR`]).
pub fn draws_pivot(d: &Design, extent: (Vec2, Vec2)) -> bool {
    d.spec.follower.pivot().is_some_and(|a| holds(a, extent))
}

/// Whether the box `(lo, hi)` holds `a`.
pub(super) fn holds(a: Vec2, (lo, hi): (Vec2, Vec2)) -> bool {
    a.x >= lo.x && a.x <= hi.x && a.y >= lo.y && a.y <= hi.y
}

/// How far a ray from `p` (inside the box) along the unit `dir` runs before it leaves the box.
pub(super) fn exit(p: Vec2, dir: Vec2, lo: Vec2, hi: Vec2) -> f64 {
    let along = |p: f64, d: f64, lo: f64, hi: f64| {
        if d > tol::ALONG_SIDE {
            (hi - p) / d
        } else if d < -tol::ALONG_SIDE {
            (lo - p) / d
        } else {
            f64::INFINITY
        }
    };
    along(p.x, dir.x, lo.x, hi.x).min(along(p.y, dir.y, lo.y, hi.y)).max(0.0)
}

/// The follower-frame box (metres) the nomogram shows: every B_k and B′_k, O and the pivot
/// (unless it is far, [`PIVOT_FAR`]), with room below O for the limiting lines to meet and
/// round the picture for labels. The room is in proportion to the curve and O, where the
/// labels are, not to a rocker's pivot as well: a_w away, it made the room round a rocker's
/// nomogram half as wide again as its curve (a knife-edged rocker's nomogram came out at
/// 1:1 where 2:1 fits once it goes).
pub fn extent(d: &Design, phis: &[f64]) -> (Vec2, Vec2) {
    let (near_lo, near_hi) = bounds(near_points(d, phis).into_iter().map(|p| (p, 0.0)));
    let side = (near_hi.x - near_lo.x).max(near_hi.y - near_lo.y);
    let gap = |a: Vec2| Vec2::new(a.x - a.x.clamp(near_lo.x, near_hi.x), a.y - a.y.clamp(near_lo.y, near_hi.y)).norm();
    let pivot = d.spec.follower.pivot().filter(|&a| gap(a) <= PIVOT_FAR * side);
    let (lo, hi) = bounds([near_lo, near_hi].into_iter().chain(pivot).map(|p| (p, 0.0)));
    let pad = 0.15 * (near_hi - near_lo).norm();
    (lo - Vec2::new(pad, pad), hi + Vec2::new(pad, pad * 0.5))
}

/// The offset's dimension, from the follower's axis to O, runs this far under O on paper
/// (mm) for an offset `e_mm` long on paper: where the zone between the limiting lines (at the
/// allowed angles from the axis) is wide enough for it and its arrows, clear of the hatching.
pub(super) fn offset_depth(d: &Design, e_mm: f64) -> f64 {
    ((e_mm + OFFSET_SPARE_MM) / wedge_widening(d) + 2.0).max(8.0)
}

/// How much wider the zone between the limiting lines gets per unit of depth under O.
fn wedge_widening(d: &Design) -> f64 {
    let a = &d.spec.allowed;
    math::tan(a.rise) + math::tan(a.ret)
}

/// The offset's dimension line is this much longer than the room it needs between the
/// limiting lines (its arrows and their gap), mm; its value is written under it, in a band
/// this deep, mm.
const OFFSET_SPARE_MM: f64 = 20.0;
const OFFSET_TEXT_MM: f64 = 6.0;

/// What the nomogram draws at a paper distance from the follower frame: the offset's
/// dimension and its value under O, [`offset_depth`] deep — e/(tan α_rise + tan α_return)
/// in metres and the rest in mm whatever the scale — with their text. The picture's box
/// must hold them: pads proportional to the picture fall short of a paper depth under a
/// small drawing. Returns (world point, offset in mm, y up).
pub fn reach(d: &Design) -> Vec<(Vec2, Vec2)> {
    let o = d.centre.o;
    if d.spec.follower.pivot().is_some() || o.x.abs() <= tol::ZERO_OFFSET {
        return Vec::new();
    }
    let k = wedge_widening(d);
    // offset_depth(e/μ) ≤ e/(kμ) + max(20/k + 2, 8): the world part and the paper part.
    let paper = (OFFSET_SPARE_MM / k + 2.0).max(8.0) + OFFSET_TEXT_MM;
    vec![(Vec2::new(o.x, o.y - o.x.abs() / k), Vec2::new(0.0, -paper))]
}

/// A view of the follower-frame box `(lo, hi)` centred in `area` at `mu` m/mm, mirrored for a
/// counter-clockwise cam.
pub fn centred(area: Rect, (lo, hi): (Vec2, Vec2), mu: f64, mirror: bool) -> View {
    let (cx, cy) = ((lo.x + hi.x) / 2.0, (lo.y + hi.y) / 2.0);
    let mx = if mirror { -cx } else { cx };
    let centre = area.center();
    View::new(Point::new(centre.x - mx / mu, centre.y + cy / mu), mu).mirrored(mirror)
}

/// From `p` toward `a`: `a` itself where the box `(lo, hi)` holds it, else where the line
/// leaves the box.
pub(super) fn toward(p: Vec2, a: Vec2, (lo, hi): (Vec2, Vec2)) -> Vec2 {
    if holds(a, (lo, hi)) {
        return a;
    }
    let dir = (a - p).unit();
    p + dir * exit(p, dir, lo, hi)
}
