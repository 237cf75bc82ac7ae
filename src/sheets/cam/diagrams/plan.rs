//! The diagrams' scales, chosen before they are drawn: μ_φ to fill the column's width, μ_s
//! the largest drawing whose acceleration analog stands near the guide's 70 mm within the
//! height, μ_d²s/dφ² round, the poles H1 and H2 derived from them by the course's rules.

use super::{GAP, PHASES, POLE_NAME};
use crate::cams::Design;
use crate::drawing::scale;
use crate::num::digits::{significant, written};
use std::f64::consts::PI;

/// The chosen scales: μ_φ in degrees and radians per mm, the three ordinate scales (the
/// lift's unit — metres or radians — per mm, per radian for the analogs) and the poles, mm.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Scales {
    pub mu_phi_deg: f64,
    pub mu_phi_rad: f64,
    pub mu_s: f64,
    pub mu_ds: f64,
    pub mu_dds: f64,
    pub h1: f64,
    pub h2: f64,
}

/// The lift's most height on paper, mm.
const LIFT_MAX_MM: f64 = 100.0;
/// The lift's least height on paper when the shared scale of s and ds/dφ would leave it
/// lower, mm.
const LIFT_MIN_MM: f64 = 30.0;
/// The acceleration analog's height each side of its axis, mm: the guide's worked example
/// takes "the maximum amplitude along the ordinate axis 70 mm" (its fig. 1.8), and the range
/// accepted around it (a column too low for 70 takes less).
const ACCELERATION_MM: (f64, f64, f64) = (20.0, 70.0, 75.0);
/// The pole distance H2's range, mm: below 15 mm its rays merge.
const H2_MM: (f64, f64) = (15.0, 40.0);
/// How far a pole derived from a two-digit μ_d²s/dφ² may fall short of the least H2, mm: the
/// scale's steps are up to a tenth, and a whole mm kept 7 more of the catalogue's Russian
/// sheets 3 at the course's shared scale of s and ds/dφ.
const H2_SHORT: f64 = 1.0;
/// μ_φ's series, degrees per mm (times 10ⁿ): finer than the plans' round series, so that the
/// working angle fills the column (the guide takes 0.73 °/mm).
const PHI_MANTISSAS: [f64; 10] = [1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];
/// Room right of the x axis' end for its arrow and name, mm.
const RIGHT: f64 = 14.0;

/// The diagrams' scales and the room they take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plan {
    pub scales: Scales,
    /// Width and height of the three diagrams with their poles, scale texts and gaps, mm.
    pub width: f64,
    pub height: f64,
}

/// The course's scales for diagrams in at most `max_w` × `max_h` mm:
/// - μ_φ from [`PHI_MANTISSAS`], the smallest that fits the width (at most
///   `phi_max` mm for the working angle);
/// - H1 = 1/μ_φ, so that s and ds/dφ share μ_s;
/// - μ_s of the plans' round series (steps of at most 1.5×: 5 → 6 → 7.5 → 10), the smallest
///   (the largest drawing) with the lift at most [`LIFT_MAX_MM`]
///   whose acceleration analog can be drawn between [`ACCELERATION_MM`] with H2 in
///   [`H2_MM`] within the height: the analog's height is H2·d²s/dφ²·μ_φ/μ_s, so a large
///   μ_s's small drawing is what keeps H2 from merging its rays;
/// - μ_d²s/dφ² of two significant digits (steps under 10 %: the plans' series' steps of a
///   third left the analog that much lower in a column it filled), the analog nearest the guide's 70 mm (or the
///   largest the height leaves room for), and H2 = μ_ds/dφ/(μ_d²s/dφ²·μ_φ), the course's
///   rule read for the pole: round scales, poles derived from them, as the guide derives
///   H1 = 1/μ_φ (its 78.74 mm).
///
/// Where one phase is so much shorter than the other that the shared scale would leave the
/// lift under [`LIFT_MIN_MM`] (a 3° return after a 280° rise: its ds/dφ is ~90 times the
/// rise's), μ_ds/dφ is its own round scale and H1 = μ_s/(μ_ds/dφ·μ_φ), the course's rule
/// read the other way, at least the least H2 (shorter, the rays merge): the lift keeps a
/// measurable height. A phase too short for any such H1 (its chords a fraction of a mm at
/// the width the long phase needs) is drawn at the shared scale, the lift as low as it must.
pub fn plan(d: &Design, (max_w, phi_max): (f64, f64), max_h: f64) -> Plan {
    let p = &d.spec.program;
    let work = (p.rise + p.far_dwell + p.ret).to_degrees();
    let width = |mu_deg: f64| POLE_NAME + (180.0 / PI / mu_deg).max(H2_MM.1) + work / mu_deg + RIGHT;
    // m·10ᵉ as the nearest double to the decimal (0.6, not 6 × 0.1 = 0.6000000000000001).
    let series =
        (-2..=3).flat_map(|e| PHI_MANTISSAS.map(|m| if e < 0 { m / 10f64.powi(-e) } else { m * 10f64.powi(e) }));
    let mu_phi_deg = series
        .clone()
        .find(|&m| work / m <= phi_max && width(m) <= max_w)
        .unwrap_or_else(|| series.clone().find(|&m| work / m <= phi_max).unwrap_or(1.0));
    let mu_phi_rad = mu_phi_deg.to_radians();
    let (_, amax) = peaks(d);
    let (v_lo, v_hi) = velocity_range(d);
    // μ_d²s/dφ² of two significant digits, H2 = μ_ds/dφ/(μ_d²s/dφ²·μ_φ) derived from it:
    // the analog nearest the guide's 70 mm with H2 in its range; `giving`, the largest the
    // column's height leaves room for (down to the least accepted).
    let all = |mu_s: f64, mu_ds: f64| {
        let rest = p.lift / mu_s + (v_hi - v_lo) / mu_ds + 4.0 * GAP + PHASES + 8.0;
        let drawn = move |(mu_dds, h2, a): (f64, f64, f64)| Fit { mu_dds, h2, a, height: rest + 2.0 * a };
        acceleration_scales(amax, mu_ds, mu_phi_rad).into_iter().map(drawn)
    };
    let nearest_70 = |fits: &mut dyn Iterator<Item = Fit>| {
        fits.min_by(|x, y| (x.a - ACCELERATION_MM.1).abs().total_cmp(&(y.a - ACCELERATION_MM.1).abs()))
    };
    let fit = |mu_s: f64, mu_ds: f64, giving: bool| {
        let mut accepted = all(mu_s, mu_ds).filter(|f| (ACCELERATION_MM.0..=ACCELERATION_MM.2).contains(&f.a));
        if giving { accepted.find(|f| f.height <= max_h) } else { nearest_70(&mut accepted) }
    };
    let fits = |mu_s: f64, mu_ds: f64, giving: bool| fit(mu_s, mu_ds, giving).is_some_and(|f| f.height <= max_h);
    let first = scale::plan_round_up(p.lift / LIFT_MAX_MM);
    let steps = |from: f64| std::iter::successors(Some(from), |&m| Some(scale::plan_next_round(m))).take(40);
    let lift_readable = |m: f64| p.lift / m >= LIFT_MIN_MM;
    // The course's shared scale; else the lift (at least LIFT_MIN_MM, the highest first) with
    // ds/dφ at a scale of its own, H1 at least the least H2; each first with the acceleration
    // analog near 70 mm, then lower. Else (nothing fits the height) the shared scale at which
    // the acceleration fits.
    let shared = |giving| steps(first).find(|&m| lift_readable(m) && fits(m, m, giving)).map(|m| (m, m, giving));
    let h1_at_least = |mu_s: f64, m: f64| mu_s / (m * mu_phi_rad) >= H2_MM.0;
    let own = |giving| {
        // Near 70 mm, the lift at its largest only (the acceleration is what fills the rest).
        let lifts = if giving { 40 } else { 1 };
        steps(first).take(lifts).take_while(|&s| lift_readable(s)).find_map(|s| {
            let mut ds = steps(s).skip(1).take_while(|&m| h1_at_least(s, m));
            ds.find(|&m| fits(s, m, giving)).map(|m| (s, m, giving))
        })
    };
    let fallback = || {
        let m = steps(first).find(|&m| fits(m, m, false)).unwrap_or_else(|| steps(first).last().unwrap_or(first));
        (m, m, false)
    };
    let (mu_s, mu_ds, giving) =
        [false, true].into_iter().find_map(|giving| shared(giving).or_else(|| own(giving))).unwrap_or_else(fallback);
    // None accepted (an analog too low or too high at every H2 in range): the nearest.
    let chosen = fit(mu_s, mu_ds, giving).or_else(|| nearest_70(&mut all(mu_s, mu_ds)));
    let Fit { mu_dds, h2, height, .. } =
        chosen.unwrap_or(Fit { mu_dds: mu_ds / (H2_MM.1 * mu_phi_rad), h2: H2_MM.1, a: 0.0, height: max_h });
    // Shared, H1 = 1/μ_φ exactly (the ratio's rounding would move its last digit).
    let h1 = if mu_s == mu_ds { 1.0 / mu_phi_rad } else { mu_s / (mu_ds * mu_phi_rad) };
    let scales = Scales { mu_phi_deg, mu_phi_rad, mu_s, mu_ds, mu_dds, h1, h2 };
    Plan { scales, width: width(mu_phi_deg), height }
}

/// One way to draw the acceleration analog: μ_d²s/dφ², the pole distance H2 derived from it
/// and the analog's height each side of its axis, mm, with the three diagrams' height.
#[derive(Debug, Clone, Copy)]
struct Fit {
    mu_dds: f64,
    h2: f64,
    a: f64,
    height: f64,
}

/// Every μ_d²s/dφ² of two significant digits whose pole H2 = μ_ds/dφ/(μ_d²s/dφ²·μ_φ) is in
/// [`H2_MM`] (less [`H2_SHORT`]), with H2 and the analog's height amax/μ, mm (the highest drawing first).
fn acceleration_scales(amax: f64, mu_ds: f64, mu_phi_rad: f64) -> Vec<(f64, f64, f64)> {
    let first = scale::two_digits_up(mu_ds / (H2_MM.1 * mu_phi_rad));
    std::iter::successors(Some(first), |&m| Some(scale::two_digits_next(m)))
        .map(|mu_dds| (mu_dds, mu_ds / (mu_dds * mu_phi_rad), amax / mu_dds))
        .take_while(|&(_, h2, _)| h2 >= H2_MM.0 - H2_SHORT)
        .collect()
}

/// A warning when the lift is drawn lower than [`LIFT_MIN_MM`]: a phase so short beside the
/// other that its analogs, at the μ_φ the long phase needs, leave the lift no height.
pub fn squeezed(d: &Design, sc: &Scales) -> Option<String> {
    let p = &d.spec.program;
    let lift_mm = p.lift / sc.mu_s;
    let (short, long) =
        if p.ret < p.rise { (("return", p.ret), ("rise", p.rise)) } else { (("rise", p.rise), ("return", p.ret)) };
    let ratio = long.1 / short.1;
    // Phases of a like length squeeze the lift only by their analogs' size, not their ratio.
    let why = if ratio >= 2.0 {
        format!(
            "the {} of {}° is {ratio:.0} times shorter than the {} of {}°, and its ds/dφ and d²s/dφ² at the scale the working angle needs take the column's height; phases nearer each other draw readable diagrams",
            short.0,
            written(short.1.to_degrees()),
            long.0,
            written(long.1.to_degrees()),
        )
    } else {
        "ds/dφ and d²s/dφ² at the course's least pole distances take the column's height".to_string()
    };
    (lift_mm < LIFT_MIN_MM).then(|| {
        format!(
            "diagrams: the lift is drawn {} mm high (the course's scales want {}–{} mm): {why}",
            significant(lift_mm),
            written(LIFT_MIN_MM),
            written(LIFT_MAX_MM),
        )
    })
}

/// The largest |ds/dφ| and |d²s/dφ²| over both phases (from the laws' peak coefficients).
pub(super) fn peaks(d: &Design) -> (f64, f64) {
    let p = &d.spec.program;
    let (rv, ra) = p.rise_law.peaks();
    let (tv, ta) = p.return_law.peaks();
    let h = p.lift;
    ((rv * h / p.rise).max(tv * h / p.ret), (ra * h / (p.rise * p.rise)).max(ta * h / (p.ret * p.ret)))
}

/// The velocity analog's range over the working angle, (lowest, highest), each side of 0
/// (from the exact law, four points a degree): a rise's ds/dφ is positive and a return's
/// negative, so a slow rise before a fast return leaves no room empty over the rise's hump.
pub(super) fn velocity_range(d: &Design) -> (f64, f64) {
    let p = &d.spec.program;
    let work = p.rise + p.far_dwell + p.ret;
    let n = (work.to_degrees() * 4.0).ceil() as usize;
    let (vmax, _) = peaks(d);
    let (lo, hi) = (0..=n)
        .map(|k| p.at((work * k as f64 / n as f64).min(work - crate::num::tol::INSIDE_PHASE)).ds)
        .fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    // Between samples a peak may be a little higher: the law's own peak where the sampled
    // one is within a hundredth of it.
    let snap = |v: f64| if v.abs() >= 0.99 * vmax { vmax.copysign(v) } else { v * 1.001 };
    (snap(lo), snap(hi))
}
