//! The phase angles on the profile, as the inversion lays them off from O: a ray through the
//! base circle where each working phase starts and ends (the follower's start position
//! carried against the cam's rotation by the phase's angle) and, for the rise, the far dwell
//! and the return, an arc dimension inside the working profile with its value, φ_rise = 70°,
//! as the diagrams' dimensions write it. The near dwell is the rest of the turn, where r_min
//! stands.

use crate::cams::Design;
use crate::cams::follower::Follower;
use crate::drawing::fmt;
use crate::drawing::obstacles::Obstacles;
use crate::drawing::path::on_circle;
use crate::drawing::place::Labels;
use crate::drawing::scene::{Group, THIN};
use crate::drawing::symbols::{ARROW_LEN, arc_dimension, turn};
use crate::drawing::text::LabelText;
use crate::drawing::view::View;
use crate::num::math::{self, Norm};
use crate::sheets::cam::labels::CamWords;
use kurbo::{Point, Vec2};

/// Room kept round the cam's bearing and ω's arrow, mm: the arcs start this far past it.
const ARROW_CLEAR: f64 = 4.0;
/// Kept between the arcs and the working profile (the base circle for a knife edge), mm.
const PROFILE_CLEAR: f64 = 3.0;
/// The least room between those for the arcs to be drawn at all, mm.
const LEAST_BAND: f64 = 8.0;
/// An arc at least this long has its arrowheads inside it, mm (two heads and a gap).
const ARROWS_INSIDE: f64 = 2.0 * ARROW_LEN + 2.0;
/// The phases' values are placed after the profiles' names (rank 3), which have fewer spots
/// to choose from: placed first, a value took the working profile's spot and hung its name
/// 57 mm off (task 14 variant 37).
const PHASE_RANK: u8 = 4;
/// The radii tried across the band, as shares of it from its inner edge, nearest O first:
/// the band's outer part is where the working profile's name stands inside the cam (an arc
/// through it there hung the name 57 mm off, task 14 variant 37).
const SHARES: [f64; 3] = [0.0, 0.2, 0.4];

/// Where along its arc a phase's value is tried, as shares of the arc from its start.
const VALUE_AT: [f64; 5] = [0.5, 0.3, 0.7, 0.15, 0.85];

/// The rays and arcs of the working phases with their values, if the working profile leaves
/// room for them round O (`arrow_r`: the radius of ω's arrow on paper).
pub(super) fn draw(g: &mut Group, labels: &mut Labels, view: View, d: &Design, words: &CamWords, arrow_r: f64) {
    let p = &d.spec.program;
    let (rise, dwell, work) = (p.rise, p.rise + p.far_dwell, p.rise + p.far_dwell + p.ret);
    let l = words.sheet;
    let phases = [(0.0, rise, l.sub_rise()), (rise, dwell, l.sub_far_dwell()), (dwell, work, l.sub_return())];
    let o = view.origin;
    let ends = Ends::of(view, d);
    // The band free of the working profile: under its nearest approach to O.
    let inner = arrow_r + ARROW_CLEAR;
    let outer = view.len(working_reach(d)) - PROFILE_CLEAR;
    if outer - inner < LEAST_BAND || ends.offset >= inner {
        return;
    }
    // The paper's turn from φ to φ + Δφ: the inversion runs against the rotation, and the
    // view may mirror it.
    let sense = turn(ends.ray(0.0), ends.ray(1e-3)).1.signum();
    let drawn = Obstacles::of_items(&g.items);
    let mut arcs = Vec::new();
    for (a, b, sub) in phases.into_iter().filter(|(a, b, _)| b > a) {
        let (a0, sweep) = (angle_of(ends.ray(a)), sense * (b - a));
        // The radius whose arc crosses fewest lines drawn so far, the nearest O first.
        let crossings = |r: f64| {
            let pts: Vec<Point> = (0..=24).map(|k| on_circle(o, r, a0 + sweep * f64::from(k) / 24.0)).collect();
            drawn.hits_polyline(&pts)
        };
        let r = SHARES.iter().map(|s| inner + (outer - inner) * s).min_by_key(|&r| crossings(r)).unwrap_or(inner);
        arcs.push((a, b, sub, sweep, r));
    }
    // A rocker's rays from O to the base circle, each phase's ends once; a translating
    // follower's axis lines in those positions are drawn already.
    if ends.rays {
        let mut phis: Vec<f64> = arcs.iter().flat_map(|&(a, b, ..)| [a, b]).collect();
        phis.dedup_by(|x, y| (*x - *y).abs() < 1e-12);
        for phi in phis {
            let line = g.mark();
            g.line(o + ends.ray(phi) * (inner - ARROW_CLEAR / 2.0), view.p(d.profile.carried(Vec2::ZERO, phi)), THIN);
            g.breakable_from(line);
        }
    }
    for (a, b, sub, sweep, r) in arcs {
        // The arc's ends where it meets the lines: the phase's angle apart.
        let a0 = angle_of(ends.at(a, r) - o);
        arc_dimension(g, o, (a0, sweep), r, ARROWS_INSIDE);
        let value = format!(" = {}°", fmt::trimmed((b - a).to_degrees(), words.lang));
        // Beside the arc's middle, else further along it: ω's value took the middle's room
        // on task 4 variant 40 and hung φ_q = 120° 45 mm off.
        let spots: Vec<(Point, Vec2)> = VALUE_AT
            .iter()
            .map(|f| {
                let at = a0 + sweep * f;
                (on_circle(o, r, at), Vec2::new(math::cos(at), math::sin(at)))
            })
            .collect();
        labels.add_on_line_at_any(&spots, LabelText::new("φ", sub).with_tail(value), 2.5, PHASE_RANK);
    }
}

/// The lines the phases' arcs end on, on paper: a rocker's rays from O through the
/// follower's start B₀ carried by φ (on the base circle); a translating follower's axis in
/// that position, tangent to the offset circle (through O without an offset).
struct Ends<'a> {
    view: View,
    d: &'a Design,
    rays: bool,
    /// The axes' distance from O on paper, mm (0 for the rays).
    offset: f64,
}

impl<'a> Ends<'a> {
    fn of(view: View, d: &'a Design) -> Self {
        let rays = matches!(d.spec.follower, Follower::Rocker { .. });
        let offset = if rays { 0.0 } else { view.len(d.centre.o.x.abs()) };
        Ends { view, d, rays, offset }
    }

    /// The unit direction from O, on paper, of the line at cam angle φ (an axis where it is
    /// 10 mm further from O than its foot: near enough for the arcs' search).
    fn ray(&self, phi: f64) -> Vec2 {
        let (o, pr) = (self.view.origin, &self.d.profile);
        if self.rays {
            (self.view.p(pr.carried(Vec2::ZERO, phi)) - o).unit()
        } else {
            (self.at(phi, self.offset + 10.0) - o).unit()
        }
    }

    /// Where the line at cam angle φ meets the circle of paper radius `r` round O (the
    /// point toward the roller on an axis).
    fn at(&self, phi: f64, r: f64) -> Point {
        let (v, pr) = (self.view, &self.d.profile);
        if self.rays {
            return v.origin + (v.p(pr.carried(Vec2::ZERO, phi)) - v.origin).unit() * r;
        }
        let foot = v.p(pr.carried(super::axis_foot(self.d), phi));
        let u = (v.p(pr.pitch(phi).p) - foot).unit();
        let w = foot - v.origin;
        let (b, c) = (w.dot(u), w.dot(w) - r * r);
        foot + u * (-b + (b * b - c).max(0.0).sqrt())
    }
}

/// The paper angle of the unit direction `u`, radians.
fn angle_of(u: Vec2) -> f64 {
    math::atan2(u.y, u.x)
}

/// The working profile's nearest approach to O, metres: the base circle less the roller
/// (the pitch profile is nowhere nearer O than r_min), sampled along the turn for a roller
/// larger than a concave part's curvature allows to be exact.
fn working_reach(d: &Design) -> f64 {
    if d.roller == 0.0 {
        return d.centre.r_min;
    }
    let tau = std::f64::consts::TAU;
    (0..720)
        .map(|k| d.profile.working(d.roller, tau * f64::from(k) / 720.0).0.norm())
        .fold(d.centre.r_min - d.roller, f64::min)
}
