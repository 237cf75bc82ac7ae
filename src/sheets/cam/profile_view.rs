//! The cam's profile at a GOST scale, by inversion as the course builds it: the follower
//! carried round the cam against its rotation. For a rocker, its pivot's positions A_k on the
//! circle of radius a_w round O, and from each an arc of radius l from the base circle to the
//! roller centre B_k (the swing β_k) with the rocker line A_k B_k; for a translating follower
//! with an offset, its axis in each position tangent to the circle of radius e; without one,
//! its axis through O. Then the pitch profile through the B_k, the rollers, the working
//! profile (the rollers' envelope as Bézier pieces), the base circle with r_min, the follower
//! in the start position, the cam's sense of rotation and the phase angles at O
//! (`phase_angles.rs`).

mod centre;
mod phase_angles;

use super::labels::{CamLabels, CamWords};
use super::nomogram::{Placement, bounds, drawn_position_labels};
use crate::cams::Design;
use crate::cams::follower::Follower;
use crate::drawing::path::Path;
use crate::drawing::place::Labels;
use crate::drawing::scene::{AXIS, DASHED, Group, MAIN, THIN};
use crate::drawing::symbols::{angle_mark, frame_pivot, hatch};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::num::bezier::Fitted;
use crate::num::math::{Norm, atan2};
use crate::num::tol;
use crate::num::units::mm;
use kurbo::{CubicBez, Point, Vec2};
use std::f64::consts::TAU;

/// The profiles' accuracy, metres ([`tol::PROFILE_FIT`]), and the most pieces a part may take.
pub const PROFILE_TOL: f64 = tol::PROFILE_FIT;
pub const MAX_PIECES: usize = 256;

/// The translating follower's stem above the roller, in r_max.
const STEM: f64 = 0.4;
/// Between the stem and each side of its guide, mm.
const GUIDE_GAP_MM: f64 = 2.5;

/// The profiles as Bézier pieces, part by part, fitted once for the notes and the drawing.
pub struct Pieces {
    pub pitch: Vec<Fitted>,
    /// The working profile (none for a knife edge, whose working profile is the pitch one).
    pub working: Option<Vec<Fitted>>,
    /// The pieces of the profile the cam is cut to and their largest measured deviation, m.
    pub count: usize,
    pub deviation: f64,
}

/// Fits the profiles within [`PROFILE_TOL`].
pub fn fit(d: &Design) -> Pieces {
    let pitch = d.profile.cubics(0.0, PROFILE_TOL, MAX_PIECES);
    let working = (d.roller > 0.0).then(|| d.profile.cubics(d.roller, PROFILE_TOL, MAX_PIECES));
    let cut = working.as_ref().unwrap_or(&pitch);
    let count = cut.iter().map(|f| f.cubics.len()).sum();
    let deviation = cut.iter().map(|f| f.deviation).fold(0.0, f64::max);
    Pieces { pitch, working, count, deviation }
}

/// What the profile view measured.
pub struct ProfileDrawn {
    /// μ_l, m/mm (a GOST scale).
    pub mu: f64,
    /// The pieces of the working (or, for a knife edge, the pitch) profile and their largest
    /// measured deviation, metres.
    pub pieces: usize,
    pub deviation: f64,
}

/// The largest distance of the pitch profile from O, metres.
fn r_max(d: &Design) -> f64 {
    (0..720).map(|k| d.profile.pitch(TAU * k as f64 / 720.0).p.norm()).fold(0.0, f64::max)
}

/// The box (cam frame, metres) the view must hold: the profiles with the rollers, the
/// inversion's construction (the pivots' circle of a rocker) and the follower at the start
/// of the rise, with room round them for the position numbers.
pub fn extent(d: &Design) -> (Vec2, Vec2) {
    let pitch: Vec<Vec2> = (0..720).map(|k| d.profile.pitch(TAU * k as f64 / 720.0).p).collect();
    let r_max = pitch.iter().map(|p| p.norm()).fold(0.0, f64::max);
    let b0 = pitch[0];
    // The translating follower's stem; the rocker's pivots on their arc.
    let follower: Vec<(Vec2, f64)> = match d.spec.follower {
        Follower::Translating => vec![(b0 + Vec2::new(0.0, STEM * r_max), 0.0)],
        Follower::Rocker { length } => {
            let (from, sweep) = pivot_arc(d);
            (0..=90).map(|k| (d.profile.carried(Vec2::new(length, 0.0), from + sweep * k as f64 / 90.0), 0.0)).collect()
        }
    };
    let (lo, hi) = bounds(pitch.iter().map(|&p| (p, d.roller)).chain(follower));
    let pad = 0.08 * r_max;
    (lo - Vec2::new(pad, pad), hi + Vec2::new(pad, pad))
}

/// Draws the profile of the box [`extent`] as `at` places it (at a GOST scale).
pub fn draw(
    g: &mut Group,
    at: &Placement,
    d: &Design,
    pieces: &Pieces,
    phis: &[f64],
    labels: &mut Labels,
    words: &CamWords,
) -> ProfileDrawn {
    let mu = at.mu;
    let view = at.view(d.spec.sense);
    inversion(g, d, phis, &|v| view.p(v), mu, labels);
    draw_profiles(g, view, d, pieces);
    draw_rollers(g, labels, view, d, phis);
    follower_at_start(g, d, &|v| view.p(v), mu);
    let (arrow_r, r_min) = centre::draw(g, labels, at, view, d, words);
    phase_angles::draw(g, labels, view, d, words, arrow_r);
    centre::write_r_min(g, labels, at.area, r_min);
    name_profiles(labels, view, d, phis, words.sheet);
    ProfileDrawn { mu, pieces: pieces.count, deviation: pieces.deviation }
}

/// The base circle and the profiles.
fn draw_profiles(g: &mut Group, view: View, d: &Design, pieces: &Pieces) {
    let path_of = |cubics: &[CubicBez]| Path::cubics(&cubics.iter().map(|c| view.cubic(c)).collect::<Vec<_>>());
    let knife = d.roller == 0.0;
    g.circle(view.origin, view.len(d.centre.r_min), DASHED);
    for f in &pieces.pitch {
        g.curve(path_of(&f.cubics), if knife { MAIN } else { THIN });
    }
    for f in pieces.working.iter().flatten() {
        g.curve(path_of(&f.cubics), MAIN);
    }
}

/// The numbered positions: the rollers and their numbers outside them, or inside them where
/// the rollers reach the rocker's pivot positions ([`numbers_inward`]).
fn draw_rollers(g: &mut Group, labels: &mut Labels, view: View, d: &Design, phis: &[f64]) {
    // At the roller's rim (a knife's point), outward: a leader, if any, reaches it.
    let centres: Vec<Vec2> = phis.iter().map(|&phi| d.profile.pitch(phi).p).collect();
    let side = if numbers_inward(view, d, &centres) { -1.0 } else { 1.0 };
    let rim = |p: Vec2| view.p(p * (1.0 + side * d.roller / p.norm()));
    let rims: Vec<Point> = centres.iter().map(|&p| rim(p)).collect();
    for ((&p, &rim), name) in centres.iter().zip(&rims).zip(drawn_position_labels(phis, &rims)) {
        if d.roller != 0.0 {
            g.circle(view.p(p), view.len(d.roller), THIN);
            labels.keep_out(view.p(p), view.len(d.roller));
        }
        // Kept off the centre's «O» on its line: «O 10» reads as O₁₀.
        if let Some(name) = name {
            labels.add_text_apart(rim, (rim - view.origin) * side, &name, 2.5, 2);
        }
    }
}

/// Whether the rollers' numbers go on their inner rims, toward the cam's centre: where a
/// roller's outer rim comes within [`NUMBERS_ROOM`] of the rocker's pivot positions' circle
/// (or past it), numbers outside the rollers stood among the pivots' names and read with
/// them («A₃ 1», «A₄ 2»: task 5 variant 7's rollers of 92 mm, a teacher's mark).
/// `centres`: the rollers' centres, cam frame.
fn numbers_inward(view: View, d: &Design, centres: &[Vec2]) -> bool {
    let Some(a_w) = d.centre_distance().filter(|_| d.roller > 0.0) else { return false };
    centres.iter().any(|p| view.len(a_w - (p.norm() + d.roller)) < NUMBERS_ROOM)
}

/// The least room between the rollers' outer rims and the pivots' circle that keeps the
/// rollers' numbers outside them, paper mm: a number (2.5 mm) with room on either side.
const NUMBERS_ROOM: f64 = 8.0;

/// The profiles' names.
fn name_profiles(labels: &mut Labels, view: View, d: &Design, phis: &[f64], l: &CamLabels) {
    let (pr, prog) = (&d.profile, &d.spec.program);
    // A knife's working profile is its pitch profile: one curve, both names.
    let knife = d.roller == 0.0;
    let name = if knife { l.knife_profile() } else { l.pitch_profile() };
    labels.add_line_name_at_any(&pitch_name_spots(view, d, phis), &[], LabelText::new(name, ""), 2.5, 3);
    if !knife {
        // On the curve itself (its leader reaches it), the text inside the cam, which is
        // free of the construction: at mid-rise, else mid-return or in a dwell; where these
        // leave it on a long leader, at a phase's quarters too, each as good as the next
        // (the middles alone hung it 56–59 mm off, across the cam or round it: task 11
        // variant 45's large cam had room inside a quarter of the way along its near dwell).
        let at = |phi: f64| {
            let (w, _) = pr.working(d.roller, phi);
            (view.p(w), view.origin - view.p(w))
        };
        let far = prog.rise + prog.far_dwell;
        let near = far + prog.ret;
        // Each phase's start and length, in the order its points are tried (a dwell of no
        // length keeps its point, the end of the phase before: each point keeps its rank).
        let phases = [(0.0, prog.rise), (far, prog.ret), (prog.rise, prog.far_dwell), (near, TAU - near)];
        let mut spots =
            PHASE_POINTS.iter().flat_map(|&f| phases.iter().map(move |&(from, span)| from + span * f)).map(at);
        let middles: Vec<(Point, Vec2)> = spots.by_ref().take(phases.len()).collect();
        let quarters: Vec<(Point, Vec2)> = spots.collect();
        labels.add_line_name_at_any(&middles, &quarters, LabelText::new(l.working_profile(), ""), 2.5, 3);
    }
}

/// Where the pitch profile's name may stand, best first, each with its outward direction
/// (inside, a leader would cross the working profile): the middle of the far dwell where no
/// roller covers it; else where the pitch profile leaves the last roller of the return and
/// meets the first of the rise, on the base circle it follows through the near dwell (from
/// a roller's centre its leader crossed the rollers and ran 20–59 mm out on 150 of the
/// catalogue's sheets); the middle of the far dwell, under the rollers, last.
fn pitch_name_spots(view: View, d: &Design, phis: &[f64]) -> Vec<(Point, Vec2)> {
    let (pr, prog) = (&d.profile, &d.spec.program);
    let spot = |phi: f64| {
        let p = view.p(pr.pitch(phi).p);
        (p, p - view.origin)
    };
    // Clear of every roller's circle by a line's clearance and a little; a knife's tip by
    // more: the name set level at position 0's tip lay along the rocker's arm drawn to it
    // and read as the arm's (knife-rocker).
    let reach = (view.len(d.roller) + ROLLER_CLEAR_MM).max(if d.roller == 0.0 { KNIFE_TIP_CLEAR_MM } else { 0.0 });
    let centres: Vec<Point> = phis.iter().map(|&k| view.p(pr.pitch(k).p)).collect();
    let clear = |phi: f64| {
        let p = view.p(pr.pitch(phi).p);
        centres.iter().all(|&c| (c - p).norm() >= reach)
    };
    let far = prog.rise + prog.far_dwell / 2.0;
    let near = prog.rise + prog.far_dwell + prog.ret;
    let steps = ((TAU - near) / NEAR_DWELL_STEP).floor() as usize;
    let after = (1..steps).map(|k| near + k as f64 * NEAR_DWELL_STEP).find(|&phi| clear(phi));
    let before = (1..steps).map(|k| TAU - k as f64 * NEAR_DWELL_STEP).find(|&phi| clear(phi));
    let far_clear = d.roller == 0.0 || clear(far);
    let mut spots = Vec::with_capacity(3);
    if far_clear {
        spots.push(spot(far));
    }
    spots.extend(after.into_iter().chain(before).map(spot));
    if !far_clear {
        spots.push(spot(far));
    }
    spots
}

/// Where in each phase the working profile's name may stand, as a share of the phase, the
/// middles first.
const PHASE_POINTS: [f64; 3] = [0.5, 0.25, 0.75];

/// How far outside a roller's circle the pitch profile's name may be set on it, mm.
const ROLLER_CLEAR_MM: f64 = 1.5;
/// How far from a knife's tip at a numbered position the profile's name may be set on the
/// profile, mm: about two lettering heights, off the follower's line drawn to the tip.
const KNIFE_TIP_CLEAR_MM: f64 = 6.0;
/// The step along the near dwell looking for the pitch profile clear of the rollers, rad.
const NEAR_DWELL_STEP: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// The inversion's construction for each numbered position (cam frame through `at`).
fn inversion(g: &mut Group, d: &Design, phis: &[f64], at: &dyn Fn(Vec2) -> Point, mu: f64, labels: &mut Labels) {
    let pr = &d.profile;
    let b0 = Vec2::ZERO; // the roller centre at the start of the rise, follower frame
    match d.spec.follower {
        Follower::Rocker { length } => {
            let pivot = Vec2::new(length, 0.0);
            // The pivot's circle where its positions are: the arc from A₀ to the last.
            let a_w = d.centre_distance().unwrap_or_default();
            let (from, sweep) = pivot_arc(d);
            let o = at(Vec2::ZERO);
            let (v0, v1) = (at(pr.carried(pivot, from)) - o, at(pr.carried(pivot, from + PROBE_TURN)) - o);
            // The carried pivot turns by φ; on paper clockwise or not as the view mirrors.
            let turn = if v0.cross(v1) > 0.0 { 1.0 } else { -1.0 };
            g.curve(Path::arc(o, a_w / mu, atan2(v0.y, v0.x), turn * sweep), AXIS);
            let pivots: Vec<Point> = phis.iter().map(|&phi| at(pr.carried(pivot, phi))).collect();
            for (&phi, name) in phis.iter().zip(drawn_position_labels(phis, &pivots)) {
                let a = pr.carried(pivot, phi);
                let (start, end) = (pr.carried(b0, phi), pr.pitch(phi).p);
                g.dot(at(a), 0.5);
                // The follower's positions: thin lines a label may interrupt.
                let line = g.mark();
                g.line(at(a), at(end), THIN);
                g.breakable_from(line);
                swing_arc(g, a, start, end, at, mu);
                // Each pivot position named by its position, outward from O.
                if let Some(name) = name {
                    let out = at(a) - at(Vec2::ZERO);
                    labels.add_ranked(at(a), out, LabelText::new("A", name), 2.5, 1);
                }
            }
        }
        Follower::Translating => {
            let e = d.centre.o.x.abs();
            if mm(e) > tol::OFFSET_CIRCLE_MM {
                g.circle(at(Vec2::ZERO), e / mu, AXIS);
            }
            let foot = axis_foot(d);
            let o = at(Vec2::ZERO);
            for &phi in phis {
                let (f, end) = (at(pr.carried(foot, phi)), at(pr.pitch(phi).p));
                let line = g.mark();
                g.line(outside_circle(o, CENTRE_CLEAR_MM, f, end), end, THIN);
                g.breakable_from(line);
            }
        }
    }
}

/// The translating follower's axis' foot nearest O (follower frame): its axis runs from it
/// past the roller centre.
fn axis_foot(d: &Design) -> Vec2 {
    Vec2::new(0.0, d.centre.o.y)
}

/// A small turn of the cam, rad, that shows which way the carried pivot runs on paper: far
/// above round-off, far below the pivot's arc.
const PROBE_TURN: f64 = 1e-3;

/// Round O, mm, the translating follower's axis lines stop: with a small offset they all
/// meet there and would hide the cam's bearing (its hatching reaches 7.3 mm from O; at 6
/// the lines from below ran into it, a reviewer).
const CENTRE_CLEAR_MM: f64 = 7.5;

/// The start of the segment `a`–`b` moved out of the circle of centre `o` and radius `r` if
/// it lies inside (paper).
fn outside_circle(o: Point, r: f64, a: Point, b: Point) -> Point {
    let (len, ao) = ((b - a).norm(), o - a);
    if ao.norm() >= r || len <= 0.0 {
        return a;
    }
    let u = (b - a) / len;
    let along = u.dot(ao);
    let t = along + (along * along - ao.dot(ao) + r * r).max(0.0).sqrt();
    a + u * t.min(len)
}

/// The cam angles `(from, sweep)` of the rocker pivot's arc drawn in the inversion: its
/// positions A_k with a margin each side, the whole circle when they go round.
fn pivot_arc(d: &Design) -> (f64, f64) {
    const MARGIN: f64 = 0.15;
    let p = &d.spec.program;
    let work = p.rise + p.far_dwell + p.ret;
    if work + 2.0 * MARGIN >= TAU { (0.0, TAU) } else { (-MARGIN, work + 2.0 * MARGIN) }
}

/// The arc of radius l round the pivot `a` from the base circle's point to the roller
/// centre (nothing where they coincide: the dwell at the base circle).
fn swing_arc(g: &mut Group, a: Vec2, from: Vec2, to: Vec2, at: &dyn Fn(Vec2) -> Point, mu: f64) {
    let (u, v) = (from - a, to - a);
    let r = u.norm();
    if (atan2(u.cross(v), u.dot(v)) * r / mu).abs() < 0.5 {
        return;
    }
    let paper = |w: Vec2| (at(a + w) - at(a)).unit();
    angle_mark(g, at(a), paper(u), paper(v), r / mu);
}

/// The follower at the start of the rise (the follower frame is the cam frame at φ = 0).
fn follower_at_start(g: &mut Group, d: &Design, at: &dyn Fn(Vec2) -> Point, mu: f64) {
    let pr = &d.profile;
    let b0 = pr.pitch(0.0).p;
    let r_max = r_max(d);
    match d.spec.follower {
        Follower::Translating => {
            let top = b0 + Vec2::new(0.0, STEM * r_max * 0.8);
            g.line(at(b0), at(top), MAIN);
            g.line(at(b0 - Vec2::new(0.0, 0.1 * r_max)), at(top + Vec2::new(0.0, 0.05 * r_max)), AXIS);
            // Its guide: the frame either side of the stem, hatched outside.
            let (lo, hi) = (at(b0 + Vec2::new(0.0, STEM * r_max * 0.4)), at(top));
            for side in [-1.0, 1.0] {
                let off = Vec2::new(side * GUIDE_GAP_MM, 0.0);
                g.line(lo + off, hi + off, MAIN);
                hatch(g, lo + off, hi + off, Vec2::new(side, 0.0), 2.5);
            }
        }
        Follower::Rocker { length } => {
            let a = pr.carried(Vec2::new(length, 0.0), 0.0);
            frame_pivot(g, at(a), 1.5);
            g.line(at(a), at(b0), MAIN);
        }
    }
    if d.roller > 0.0 {
        g.circle(at(b0), d.roller / mu, MAIN);
    }
}
