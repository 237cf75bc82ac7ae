//! The cam's profile at a GOST scale: the pitch profile, the working profile (the roller's
//! envelope as Bézier pieces), the base circle, the rollers and the numbered positions by
//! inversion, the follower in the start position and the cam's sense of rotation.

use super::labels::CamLabels;
use super::nomogram::{View, bounds};
use crate::cams::follower::Follower;
use crate::cams::{Design, Sense};
use crate::drawing::fmt;
use crate::drawing::labels::{Common, Language};
use crate::drawing::path::Path;
use crate::drawing::place::Labels;
use crate::drawing::scale;
use crate::drawing::scene::{AXIS, DASHED, Group, MAIN, THIN};
use crate::drawing::symbols::{frame_pivot, turn_arrow};
use crate::drawing::text::LabelText;
use crate::num::math::Norm;
use kurbo::{Affine, CubicBez, Rect, Vec2};

/// The profiles' accuracy, metres, and the most pieces a part may take.
pub const PROFILE_TOL: f64 = 1e-6;
pub const MAX_PIECES: usize = 256;

/// What the profile view measured.
pub struct ProfileDrawn {
    /// μ_l, m/mm (a GOST scale).
    pub mu: f64,
    /// The pieces of the working (or, for a knife edge, the pitch) profile and their largest
    /// measured deviation, metres.
    pub pieces: usize,
    pub deviation: f64,
}

/// The box (cam frame, metres) the view must hold: the profiles with the rollers, and the
/// follower at the start of the rise.
fn extent(d: &Design) -> (Vec2, Vec2) {
    let pitch: Vec<Vec2> = (0..720).map(|k| d.profile.pitch(std::f64::consts::TAU * k as f64 / 720.0).p).collect();
    let r_max = pitch.iter().map(|p| p.norm()).fold(0.0, f64::max);
    let b0 = pitch[0];
    let follower = match d.spec.follower {
        Follower::Translating => (b0 + Vec2::new(0.0, STEM * r_max), 0.0),
        Follower::Rocker { length } => (b0 + Vec2::new(length, 0.0), 0.01 * r_max),
    };
    let (lo, hi) = bounds(pitch.iter().map(|&p| (p, d.roller)).chain([follower]));
    // Room round the profile for the position numbers.
    let pad = 0.08 * r_max;
    (lo - Vec2::new(pad, pad), hi + Vec2::new(pad, pad))
}

/// The translating follower's stem above the roller, in r_max.
const STEM: f64 = 0.4;

/// Draws the profile centred in `area` (O at the centre for a translating follower; for a
/// rocker the view also holds the pivot).
#[allow(clippy::too_many_arguments)]
pub fn draw(
    g: &mut Group,
    area: Rect,
    d: &Design,
    phis: &[f64],
    labels: &mut Labels,
    l: &CamLabels,
    c: &Common,
    lang: Language,
) -> ProfileDrawn {
    let mirror = d.spec.sense == Sense::Ccw;
    let (lo, hi) = extent(d);
    let mu = scale::length_scale(((hi.x - lo.x) / area.width()).max((hi.y - lo.y) / area.height()));
    let mid = (lo + hi) * 0.5;
    let mx = if mirror { -mid.x } else { mid.x };
    let view = View { origin: area.center() + Vec2::new(-mx / mu, mid.y / mu), mu, mirror };
    let r_max = (hi - lo).norm() / 2.0;
    let o = Vec2::ZERO;
    let pr = &d.profile;
    // To paper: the cam frame's metres through the view (mirror and y up).
    let sx = if mirror { -1.0 / mu } else { 1.0 / mu };
    let to_paper = Affine::new([sx, 0.0, 0.0, -1.0 / mu, view.origin.x, view.origin.y]);
    let path_of = |cubics: &[CubicBez]| Path::cubics(&cubics.iter().map(|c| to_paper * *c).collect::<Vec<_>>());

    // The base circle and the pitch profile.
    g.circle(view.origin, d.centre.r_min / mu, DASHED);
    let pitch = pr.cubics(0.0, PROFILE_TOL, MAX_PIECES);
    let knife = d.roller == 0.0;
    for f in &pitch {
        g.curve(path_of(&f.cubics), if knife { MAIN } else { THIN });
    }
    let (pieces, deviation) = if knife {
        (pitch.iter().map(|f| f.cubics.len()).sum(), pitch.iter().map(|f| f.deviation).fold(0.0, f64::max))
    } else {
        let work = pr.cubics(d.roller, PROFILE_TOL, MAX_PIECES);
        for f in &work {
            g.curve(path_of(&f.cubics), MAIN);
        }
        (work.iter().map(|f| f.cubics.len()).sum(), work.iter().map(|f| f.deviation).fold(0.0, f64::max))
    };
    // The numbered positions: rays from O to the roller centres, the rollers.
    for (&phi, name) in phis.iter().zip(super::nomogram::position_labels(phis)) {
        let p = pr.pitch(phi).p;
        g.line(view.at(o), view.at(p), THIN);
        if !knife {
            g.circle(view.at(p), d.roller / mu, THIN);
        }
        let out = p * (1.0 + (d.roller + 3.0 * mu) / p.norm());
        if let Some(name) = name {
            labels.add_text_ranked(view.at(out), Vec2::ZERO, &name, 2.5, 2);
        }
    }
    // The follower at the start of the rise (the follower frame is the cam frame at φ = 0).
    let b0 = pr.pitch(0.0).p;
    match d.spec.follower {
        Follower::Translating => {
            let top = b0 + Vec2::new(0.0, STEM * r_max * 0.8);
            g.line(view.at(b0), view.at(top), MAIN);
            g.line(view.at(b0 - Vec2::new(0.0, 0.1 * r_max)), view.at(top + Vec2::new(0.0, 0.05 * r_max)), AXIS);
        }
        Follower::Rocker { length } => {
            let a = Vec2::new(length, 0.0) + b0;
            frame_pivot(g, view.at(a), 1.5);
            g.line(view.at(a), view.at(b0), MAIN);
            labels.add_text(view.at(a), Vec2::new(1.0, -1.0), "A₀", 3.5);
        }
    }
    if !knife {
        g.circle(view.at(b0), d.roller / mu, MAIN);
    }
    // O, and the sense of rotation.
    frame_pivot(g, view.origin, 1.5);
    labels.add_text(view.origin, Vec2::new(-1.0, 1.0), "O", 3.5);
    let arrow_r = 0.25 * d.centre.r_min / mu;
    turn_arrow(g, view.origin, arrow_r.max(6.0), 200.0, 60.0, mirror, THIN);
    labels.add_text_ranked(view.origin + Vec2::new(-arrow_r.max(6.0) - 3.0, 0.0), Vec2::new(-1.0, 0.0), "ω", 3.5, 1);
    // The curves' names.
    let far = pr.pitch(d.spec.program.rise + d.spec.program.far_dwell / 2.0).p;
    labels.add_ranked(view.at(far), Vec2::new(0.0, -1.0), LabelText::new(l.pitch_profile(), ""), 2.5, 3);
    if !knife {
        let (w, _) = pr.working(d.roller, d.spec.program.rise / 2.0);
        labels.add_ranked(view.at(w * 0.97), Vec2::ZERO, LabelText::new(l.working_profile(), ""), 2.5, 3);
    }
    let base = Vec2::new(0.0, -d.centre.r_min);
    labels.add_ranked(view.at(base), Vec2::new(0.0, 1.0), LabelText::new(l.base_circle(), ""), 2.5, 3);
    let r_text = LabelText::new("r", l.sub_min()).with_tail(format!(
        " = {} {}",
        fmt::value(d.centre.r_min * 1e3, lang),
        c.unit_mm()
    ));
    labels.add_ranked(view.at(base * 0.5), Vec2::new(1.0, 0.0), r_text, 2.5, 3);
    g.line(view.origin, view.at(base), THIN);
    ProfileDrawn { mu, pieces, deviation }
}
