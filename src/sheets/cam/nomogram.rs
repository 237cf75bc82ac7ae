//! The nomogram of the minimum radius, drawn in the follower's frame at one round scale:
//! the roller centre's positions B_k with their velocity-analog segments to B′_k (across the
//! axis for a translating follower, along the rocker lines for a rocker), the B′ curve, the
//! course's limiting lines at the allowed angle for the rise and the return, the exact
//! boundary of the admissible zone, and the centre O with r_min (and e, or the pivot and the
//! centre distance).

use super::labels::CamWords;
use crate::cams::follower::Follower;
use crate::cams::radius::{Phase, Region};
use crate::cams::{Design, Sense};
use crate::drawing::along::{along_line, mirrored_room};
use crate::drawing::fmt;
use crate::drawing::obstacles::{Obstacles, Piece};
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, DASHED, Group, MAIN, THIN};
use crate::drawing::symbols::{angle_mark, dimension, frame_pivot, hatch_along, vector};
use crate::drawing::text::{self, LabelText};
use crate::drawing::view::View;
use crate::num::math::Norm;
use crate::num::tol;
use crate::num::units::mm;
use kurbo::{Line, ParamCurveNearest, Point, Rect, Vec2};
use std::sync::{Mutex, PoisonError};

mod extent;
pub use extent::{bounds, centred, draws_pivot, extent, reach};
use extent::{exit, holds, offset_depth, toward};

/// The cam angles of the numbered positions: each phase's division points.
pub fn positions(d: &Design, divisions: usize) -> Vec<f64> {
    Phase::BOTH
        .iter()
        .flat_map(|ph| {
            let (a, b) = ph.span(&d.spec.program);
            (0..=divisions).map(move |k| a + (b - a) * k as f64 / divisions as f64)
        })
        .collect()
}

/// Each position's number as the drawing writes it: a position that coincides with the one
/// before it (the rise's end and the return's start without a far dwell) shares its label
/// ("8≡9") and gets none of its own.
pub fn position_labels(phis: &[f64]) -> Vec<Option<String>> {
    merged_labels(phis.len(), |j, k| (phis[j] - phis[k]).abs() < tol::ANGLE_ROUND_OFF)
}

/// Positions closer than this on paper (mm) are one point to the reader and share a label.
const SAME_POINT_MM: f64 = 1.5;

/// Each position's number as a drawing writes it at the paper points `at`: positions at one
/// angle (see [`position_labels`]) or drawn less than [`SAME_POINT_MM`] apart share one label
/// ("10≡11"): a rocker's pivots a phase of 1° apart are one point to the reader.
pub fn drawn_position_labels(phis: &[f64], at: &[Point]) -> Vec<Option<String>> {
    merged_labels(phis.len(), |j, k| {
        (phis[j] - phis[k]).abs() < tol::ANGLE_ROUND_OFF || (at[j] - at[k]).norm() < SAME_POINT_MM
    })
}
/// The radius of the allowed angle's mark at a limiting line's apex, mm.
const ANGLE_MARK_MM: f64 = 10.0;
/// The zone's boundary: points traced across the picture, the hatching's step, and how near
/// a limiting line the boundary runs along it (not dashed over it), mm.
const BOUNDARY_POINTS: usize = 240;
const HATCH_STEP_MM: f64 = 2.5;
const ON_LINE_MM: f64 = 0.3;
/// The labels keep out of discs this large (mm) set this far into the zone from each of the
/// boundary's points: the strokes reach 0.9·step/√2 ≈ 1.6 mm across the boundary, so the
/// discs keep letters about 1.5 mm off the line and the tips.
const BAND_CENTRE_MM: f64 = 0.8;
const BAND_KEEP_MM: f64 = 2.3;
/// The point the zone's name points at stays this far inside the picture, mm.
const ZONE_NAME_INSET_MM: f64 = 4.0;

/// The numbers 0…n−1 as labels, a number that is `same` as an earlier labelled one merged
/// into its label ("0≡17") and given none of its own.
fn merged_labels(n: usize, same: impl Fn(usize, usize) -> bool) -> Vec<Option<String>> {
    text::merged_labels((0..n).map(|k| k.to_string()), same, "≡")
}

/// Where a view of the follower (or cam) frame goes: its box in the world (metres), centred
/// in `area` at `mu` m/mm.
#[derive(Debug, Clone, Copy)]
pub struct Placement {
    pub area: Rect,
    pub extent: (Vec2, Vec2),
    pub mu: f64,
}

impl Placement {
    /// The view, mirrored for a counter-clockwise cam.
    pub fn view(&self, sense: Sense) -> View {
        centred(self.area, self.extent, self.mu, sense == Sense::Ccw)
    }
}

/// Draws the nomogram of the box [`extent`] as `at` places it.
pub fn draw(
    g: &mut Group,
    (at, memo): (&Placement, &BoundaryMemo),
    d: &Design,
    phis: &[f64],
    labels: &mut Labels,
    words: &CamWords,
) {
    let view = at.view(d.spec.sense);
    draw_follower(g, labels, view, at.extent, d, phis);
    draw_positions(g, labels, view, d, phis);
    // The B′ curve, exact.
    for ph in Phase::BOTH {
        let (a, b) = ph.span(&d.spec.program);
        let pts: Vec<Point> =
            (0..=200).map(|k| view.p(d.region.state(a + (b - a) * k as f64 / 200.0).analog)).collect();
        g.path(pts, false, MAIN);
    }
    let limiting = draw_limiting_lines(g, labels, view, at.extent, d, words);
    draw_zone_boundary(g, labels, (view, memo), at.extent, d, &limiting);
    let lines = two_lines(words.sheet.zone());
    labels.add_text_lines_ranked(view.p(zone_anchor(d, at.extent, at.mu)), Vec2::ZERO, &lines, 2.5, 3);
    draw_centre(g, labels, (view, at.extent, at.area), d, words);
}

/// `text` in two lines of about one length, split at the space that makes the longer
/// shortest: in one line, 25–35 mm long, the zone's name found no room inside the wedge under
/// O and hung 36 mm off on a leader (translating-offset-auto); split at its last space,
/// «ruxsat etilgan» still 20 mm wide, its one spot in reach stood a word's space after
/// «e = 1,596 mm».
fn two_lines(text: &str) -> Vec<String> {
    let longer = |at: usize| text[..at].chars().count().max(text[at + 1..].chars().count());
    match text.match_indices(' ').map(|(at, _)| at).min_by_key(|&at| longer(at)) {
        Some(at) => vec![text[..at].to_string(), text[at + 1..].to_string()],
        None => vec![text.to_string()],
    }
}

/// Where the zone's name points: into the zone from O, 0.4 r_min deep, but inside the
/// picture, [`ZONE_NAME_INSET_MM`] short of its edge (or halfway there, if the picture is that
/// small under O). The depth is the radius's share while the picture's room under O is a
/// share of the whole picture: a long radius over a short lift put the point (and the
/// leader drawn from it) below the picture, out of the nomogram's region.
fn zone_anchor(d: &Design, (lo, hi): (Vec2, Vec2), mu: f64) -> Vec2 {
    let o = d.centre.o;
    let room = exit(o, d.region.d, lo, hi);
    o + d.region.d * (0.4 * d.centre.r_min).min((room - ZONE_NAME_INSET_MM * mu).max(0.5 * room))
}

/// The follower: its axis, or the rocker's pivot, the arc of its roller's centre and its
/// lines to the positions.
fn draw_follower(g: &mut Group, labels: &mut Labels, view: View, (lo, hi): (Vec2, Vec2), d: &Design, phis: &[f64]) {
    let r = &d.region;
    match d.spec.follower {
        Follower::Translating => {
            g.line(view.p(Vec2::new(0.0, lo.y)), view.p(Vec2::new(0.0, hi.y)), AXIS);
        }
        Follower::Rocker { length } => {
            let a = Vec2::new(length, 0.0);
            if holds(a, (lo, hi)) {
                frame_pivot(g, view.p(a), 1.5);
                labels.add_text(view.p(a), Vec2::new(1.0, -1.0), "A", 3.5);
            }
            let arc: Vec<Point> = (0..=60)
                .map(|k| view.p(r.state(phis[0] + (phis[phis.len() / 2 - 1] - phis[0]) * k as f64 / 60.0).b))
                .collect();
            g.path(arc, false, THIN);
            // The rocker's positions toward its pivot: thin lines a label may interrupt.
            let lines = g.mark();
            for &phi in phis {
                let b = r.state(phi).b;
                g.line(view.p(toward(b, a, (lo, hi))), view.p(b), THIN);
            }
            g.breakable_from(lines);
        }
    }
}

/// The positions and their analog segments; positions drawn at one point share a label.
fn draw_positions(g: &mut Group, labels: &mut Labels, view: View, d: &Design, phis: &[f64]) {
    let r = &d.region;
    let analogs: Vec<Point> = phis.iter().map(|&phi| view.p(r.state(phi).analog)).collect();
    for ((&phi, &at), name) in phis
        .iter()
        .zip(&analogs)
        .zip(merged_labels(analogs.len(), |j, k| (analogs[j] - analogs[k]).norm() < SAME_POINT_MM))
    {
        let line = g.mark();
        g.line(view.p(r.state(phi).b), at, THIN);
        g.breakable_from(line);
        g.dot(at, 0.45);
        if let Some(name) = name {
            labels.add_text_apart(at, Vec2::ZERO, &name, 2.5, 2);
        }
    }
}

/// The limiting lines through the most binding B′, to the picture's edge, each with its
/// angle from the wedge's axis (the direction opposite the follower's motion there); returns
/// them on paper.
fn draw_limiting_lines(
    g: &mut Group,
    labels: &mut Labels,
    view: View,
    (lo, hi): (Vec2, Vec2),
    d: &Design,
    words: &CamWords,
) -> Vec<Line> {
    let r = &d.region;
    let paper = |v: Vec2| (view.p(v) - view.p(Vec2::ZERO)).unit();
    let mut limiting = Vec::new();
    for (ph, left) in [(Phase::Rise, true), (Phase::Return, false)] {
        let (apex, dir, phi) = r.limiting_ray(ph, left, d.centre.o);
        let end = apex + dir * exit(apex, dir, lo, hi);
        let (a, b) = (view.p(apex), view.p(end));
        g.line(a, b, THIN);
        limiting.push(Line::new(a, b));
        let axis = paper(-r.state(phi).t);
        g.line(a, a + axis * (ANGLE_MARK_MM + 4.0), THIN);
        let at = angle_mark(g, a, axis, paper(dir), ANGLE_MARK_MM);
        let alpha = ph.allowed(&d.spec.allowed).to_degrees();
        let sub = if ph == Phase::Rise { words.sheet.sub_rise() } else { words.sheet.sub_return() };
        let text = LabelText::new("α", sub).with_tail(format!(" = {}°", fmt::trimmed(alpha, words.lang)));
        labels.add_on_line_at_any(&[(at, at - a)], text, 2.5, 1);
    }
    limiting
}

/// The zone boundary's heights already found, by the span of the picture they cross: the
/// widths and letterings sheet 3 tries draw the same nomogram (the boundary's exact search
/// was a sixth of the sheet, three times over).
#[derive(Default)]
pub struct BoundaryMemo(Mutex<Vec<(u64, Vec<f64>)>>);

impl BoundaryMemo {
    /// The region's floor at `us`, the columns across a picture of `span`.
    fn floors(&self, r: &Region, span: f64, us: &[f64]) -> Vec<f64> {
        let key = span.to_bits();
        // Held while the floors are computed: the layout variants are built on two threads
        // and both asked for the same span at once, each computing it (15 % of sheet 3).
        let mut memo = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(e) = memo.iter().find(|e| e.0 == key) {
            return e.1.clone();
        }
        let floors = r.floors(us);
        memo.push((key, floors.clone()));
        floors
    }
}

/// The zone's exact boundary across the picture, hatched on the zone's side; dashed where
/// it does not run along a limiting line. The hatched band is kept out of every label: the
/// placer sees only the strokes, so a label fitted between their tips (the zone's name in
/// ru, "e = …" over the boundary's dashes) read as written over the hatching.
fn draw_zone_boundary(
    g: &mut Group,
    labels: &mut Labels,
    (view, memo): (View, &BoundaryMemo),
    (lo, hi): (Vec2, Vec2),
    d: &Design,
    limiting: &[Line],
) {
    let r = &d.region;
    let paper = |v: Vec2| (view.p(v) - view.p(Vec2::ZERO)).unit();
    let span = (hi - lo).norm();
    let us: Vec<f64> = (0..=BOUNDARY_POINTS).map(|k| span * (2.0 * k as f64 / BOUNDARY_POINTS as f64 - 1.0)).collect();
    let boundary: Vec<Point> = us
        .iter()
        .zip(memo.floors(r, span, &us))
        .map(|(&u, w)| r.point(u, w))
        .filter(|p| p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
        .map(|p| view.p(p))
        .collect();
    hatch_along(g, &boundary, paper(r.d), HATCH_STEP_MM);
    // Discs along the band, centred BAND_CENTRE_MM into the zone: they reach past the
    // boundary and the strokes' tips on either side.
    for p in &boundary {
        labels.keep_out(*p + paper(r.d) * BAND_CENTRE_MM, BAND_KEEP_MM);
    }
    let on_limiting = |p: &Point| limiting.iter().any(|l| l.nearest(*p, 0.0).distance_sq < ON_LINE_MM * ON_LINE_MM);
    for run in boundary.split(on_limiting).filter(|run| run.len() >= 2) {
        g.path(run.to_vec(), false, DASHED);
    }
}

/// The room round O that r_min's value leaves for O's letter, mm.
const O_LETTER_ROOM: f64 = 4.5;

/// O and r_min as a radius (thin, its arrow at B₀ as on the profile), and the rocker's
/// centre distance or the translating follower's offset.
fn draw_centre(
    g: &mut Group,
    labels: &mut Labels,
    (view, extent, area): (View, (Vec2, Vec2), Rect),
    d: &Design,
    words: &CamWords,
) {
    let (l, lang) = (words.sheet, words.lang);
    let o = d.centre.o;
    g.dot(view.p(o), 0.8);
    labels.add_text(view.p(o), Vec2::new(-1.0, 1.0), "O", 3.5);
    vector(g, view.p(o), view.p(Vec2::ZERO), THIN);
    // The dimensions without their unit, as GOST 2.307 writes a drawing's millimetres.
    let r_text = LabelText::new("r", l.sub_min()).with_tail(format!(" = {}", fmt::trimmed(mm(d.centre.r_min), lang)));
    if let Some(a) = d.spec.follower.pivot() {
        let end = toward(o, a, extent);
        g.line(view.p(o), view.p(end), DASHED);
        if end != a {
            // The pivot off the picture: an arrow to it at the edge, named.
            vector(g, view.p(o + (end - o) * 0.8), view.p(end), THIN);
            labels.add_text(view.p(end), view.p(end) - view.p(o), "A", 3.5);
        }
        let dist = d.centre_distance().unwrap_or_default();
        let t = LabelText::new("a", "w").with_tail(format!(" = {}", fmt::trimmed(mm(dist), lang)));
        labels.add(view.p((o + end) * 0.5), Vec2::new(0.0, 1.0), t, 3.5);
    } else if o.x.abs() > tol::ZERO_OFFSET {
        let depth = offset_depth(d, view.len(o.x.abs()));
        let mid = dimension(g, view.p(Vec2::new(0.0, o.y)), view.p(o), Vec2::new(0.0, depth));
        // Still with its unit: without it, the shorter label took the admissible zone's
        // middle from its name on a translating-offset cam and went 46 mm off (left open).
        let t = format!("e = {} {}", fmt::trimmed(mm(o.x.abs()), lang), words.common.unit_mm());
        labels.add_text(mid, Vec2::new(0.0, 1.0), &t, 3.5);
    }
    let mut drawn = Obstacles::of_items(&g.items);
    // O's letter is placed round O after the value: the value keeps a letter's room from O
    // (set along the radius from O's very dot, it left the letter a spot whose leader
    // crossed it: a random rocker's "r_min = 1761").
    drawn.add(Piece::Disc(view.p(o), O_LETTER_ROOM), usize::MAX);
    // Along its radius where it finds room there (GOST 2.307), else level beside it: between
    // the limiting lines a level value hung 22–35 mm off on a leader.
    match along_line((&drawn, area), (view.p(o), view.p(Vec2::ZERO)), (&r_text, 3.5), None) {
        Some(t) => {
            labels.keep_clear(mirrored_room(&t, (view.p(o), view.p(Vec2::ZERO))));
            g.text(t)
        }
        None => labels.add(view.p(o * 0.5), Vec2::new(1.0, 0.0), r_text, 3.5),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::path::Seg;
    use crate::drawing::scene::Item;

    /// The hatching marks the admissible zone: each stroke starts on the boundary and runs
    /// into the zone. Tested against the pressure angle computed here, for a translating
    /// follower whose allowed angles differ (30° on the rise, 45° on the return): a centre C
    /// is admissible where every B′ of a phase sees C within the phase's allowed angle of
    /// the direction against the follower's motion (down the axis). A stroke on the wrong
    /// side has neither end inside.
    #[test]
    fn the_hatching_is_on_the_admissible_side_of_the_boundary() {
        let text = include_str!("../../../fixtures/cams/translating-offset-auto.yaml");
        let p = crate::project::load(text).unwrap();
        let d = &p.cam.as_ref().unwrap().design;
        let phis = positions(d, 8);
        let ext = extent(d, &phis);
        let area = Rect::new(0.0, 0.0, 300.0, 300.0);
        let mu = 0.0005;
        let mut g = Group::new("nomogram", area);
        let at = Placement { area, extent: ext, mu };
        draw(
            &mut g,
            (&at, &BoundaryMemo::default()),
            d,
            &phis,
            &mut Labels::new(),
            &CamWords::new(crate::drawing::labels::Language::Uz),
        );
        let view = at.view(d.spec.sense);
        let to_frame = |q: Point| {
            let x = (q.x - view.origin.x) * mu;
            Vec2::new(if view.mirror { -x } else { x }, (view.origin.y - q.y) * mu)
        };
        // The analog points of each phase, densely, with the phase's allowed angle.
        let pr = &d.spec.program;
        let allowed = &d.spec.allowed;
        let analogs: Vec<(Vec2, f64)> = [(0.0, pr.rise, allowed.rise), (pr.rise + pr.far_dwell, pr.ret, allowed.ret)]
            .iter()
            .flat_map(|&(start, len, a)| (0..=400).map(move |k| (start + len * k as f64 / 400.0, a)))
            .map(|(phi, a)| (d.region.state(phi).analog, a))
            .collect();
        // The least margin, radians, by which C meets every phase's allowed angle.
        let slack = |c: Vec2| {
            analogs
                .iter()
                .map(|&(b, a)| {
                    let v = c - b; // from B′ to the centre: down and to a side
                    a - crate::num::math::atan2(v.x.abs(), -v.y)
                })
                .fold(f64::INFINITY, f64::min)
        };
        let strokes: Vec<(Point, Point)> = g
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Path { path, .. } if path.segs.len() == 1 => match path.segs[0] {
                    Seg::Line(q) if ((q - path.start).norm() - 2.25).abs() < 1e-6 => Some((path.start, q)),
                    _ => None,
                },
                _ => None,
            })
            .collect();
        assert!(strokes.len() >= 20, "{} strokes", strokes.len());
        for (a, b) in strokes {
            let (sa, sb) = (slack(to_frame(a)), slack(to_frame(b)));
            let (inner, edge) = if sa > sb { (sa, sb) } else { (sb, sa) };
            assert!(inner > 1e-3, "a stroke {a:?}–{b:?} outside the zone: margins {sa}, {sb}");
            assert!(edge > -2e-3, "a stroke {a:?}–{b:?} starts outside the boundary: margin {edge}");
        }
    }
}

#[cfg(test)]
mod zone_name_tests {
    use super::two_lines;

    /// The zone's name splits where its longer line is shortest, in every language's
    /// wording, and a word stays whole.
    #[test]
    fn the_zones_name_splits_into_two_lines_of_about_one_length() {
        assert_eq!(two_lines("ruxsat etilgan soha"), ["ruxsat", "etilgan soha"]);
        assert_eq!(two_lines("допустимая зона"), ["допустимая", "зона"]);
        assert_eq!(two_lines("admissible zone"), ["admissible", "zone"]);
        assert_eq!(two_lines("zone"), ["zone"]);
    }
}
