//! The cam's design (sheet 3) against references computed here from first principles: the
//! pressure angle from the relative instant centre, the minimum radius by brute force over a
//! grid of centres, the profile by inversion, its curvature by finite differences, and the
//! chord integration's error against the exact law.
//!
//! Nothing here calls the crate's pressure angle, its region or the laws' closed forms for a
//! reference: the laws used in the references are coded below.
//!
//! **The physics.** The follower frame has B₀ (the roller centre at the start of the rise) at
//! the origin and the rise's motion there along +y; the cam, centred at O, turns clockwise, and
//! φ is the angle it has turned (dφ/dt = ω > 0, so ω_cam = −ω about z). Per unit ω:
//! - the follower point B moves with dB/dφ; a rocker about A turns at
//!   k = (B − A) × dB/dφ / |B − A|² (z component);
//! - the relative instant centre P of cam and follower: the cam's velocity there equals the
//!   follower's, −J(P − O) = dB/dφ for a translating follower (P = O + J·dB/dφ), and
//!   −(P − O) = k(P − A) for a rocker (P = (O + kA)/(1 + k)), J the quarter turn
//!   counter-clockwise;
//! - the common normal at the contact passes through B and P (Aronhold–Kennedy). Oriented out
//!   of the cam it is n = (B − O) − J·dB/dφ, the pitch curve's outward normal by inversion
//!   (the curve X = R(φ)(B − O) runs counter-clockwise, X′ = R(J(B − O) + dB/dφ), outward is
//!   X′ turned clockwise); `the_normal_passes_through_the_relative_pole` checks n ∥ B − P;
//! - the pressure angle is the angle from the rise's direction of motion t to n. For the
//!   translating follower with O = (e, −s0) this is tan α = −(ds/dφ − e)/(s0 + s): its
//!   magnitude is the textbook (ds/dφ − e)/(s0 + s).
#![allow(clippy::disallowed_methods)]

use kurbo::Vec2;
use std::f64::consts::PI;
use tmm_sheets::cams::follower::Follower;
use tmm_sheets::cams::integrate::chords;
use tmm_sheets::cams::laws::{Program, Standard as Law};
use tmm_sheets::cams::radius::{Allowed, Phase, Placement};
use tmm_sheets::cams::{CamSpec, CamWarning, Design, Roller, Sense, design};

// ------------------------------------------------------------------------------------------
// The laws, coded here: S(x) and S′(x) on the phase, x ∈ [0, 1].

#[derive(Debug, Clone, Copy, PartialEq)]
enum L {
    /// Cycloidal: x − sin(2πx)/(2π).
    Sine,
    /// Harmonic: (1 − cos πx)/2.
    Cosine,
    /// 10x³ − 15x⁴ + 6x⁵.
    P345,
    /// The guide's linearly decreasing acceleration: 3x² − 2x³.
    Cubic,
    /// Uniform acceleration: 2x², then 1 − 2(1 − x)².
    Parabolic,
}

impl L {
    const ALL: [L; 5] = [L::Sine, L::Cosine, L::P345, L::Cubic, L::Parabolic];

    fn law(self) -> Law {
        match self {
            L::Sine => Law::Sine,
            L::Cosine => Law::Cosine,
            L::P345 => Law::Polynomial345,
            L::Cubic => Law::LinearlyDecreasing,
            L::Parabolic => Law::UniformAcceleration,
        }
    }

    fn eval(self, x: f64) -> (f64, f64) {
        let x = x.clamp(0.0, 1.0);
        match self {
            L::Sine => (x - (2.0 * PI * x).sin() / (2.0 * PI), 1.0 - (2.0 * PI * x).cos()),
            L::Cosine => ((1.0 - (PI * x).cos()) / 2.0, PI / 2.0 * (PI * x).sin()),
            L::P345 => (x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x)),
            L::Cubic => (x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x)),
            L::Parabolic => {
                if x <= 0.5 {
                    (2.0 * x * x, 4.0 * x)
                } else {
                    (1.0 - 2.0 * (1.0 - x) * (1.0 - x), 4.0 * (1.0 - x))
                }
            }
        }
    }
}

// ------------------------------------------------------------------------------------------
// Vectors.

fn j(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

fn dot(a: Vec2, b: Vec2) -> f64 {
    a.x * b.x + a.y * b.y
}

fn norm(v: Vec2) -> f64 {
    (v.x * v.x + v.y * v.y).sqrt()
}

/// Rotation by `a` radians, counter-clockwise for a > 0.
fn rot(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(v.x * c - v.y * s, v.x * s + v.y * c)
}

// ------------------------------------------------------------------------------------------
// The cam as specified, and the follower's motion from first principles.

#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Translating,
    Rocker(f64),
}

#[derive(Debug, Clone)]
struct Cam {
    kind: Kind,
    /// Phase angles, radians.
    rise: f64,
    far: f64,
    ret: f64,
    laws: (L, L),
    /// Metres, or radians of swing.
    lift: f64,
    /// Allowed pressure angles (rise, return), radians.
    allow: [f64; 2],
}

/// The follower at one φ, in the follower frame.
struct Motion {
    b: Vec2,
    /// dB/dφ.
    db: Vec2,
    /// The unit direction of B's motion on the rise.
    t: Vec2,
}

fn r(deg: f64) -> f64 {
    deg.to_radians()
}

impl Cam {
    fn new(kind: Kind, phases_deg: (f64, f64, f64), laws: (L, L), lift: f64, allow_deg: (f64, f64)) -> Cam {
        Cam {
            kind,
            rise: r(phases_deg.0),
            far: r(phases_deg.1),
            ret: r(phases_deg.2),
            laws,
            lift,
            allow: [r(allow_deg.0), r(allow_deg.1)],
        }
    }

    fn span(&self, phase: usize) -> (f64, f64) {
        if phase == 0 { (0.0, self.rise) } else { (self.rise + self.far, self.rise + self.far + self.ret) }
    }

    /// The lift and its derivative in φ (periodic: φ taken modulo a turn).
    fn lift_at(&self, phi: f64) -> (f64, f64) {
        let phi = phi.rem_euclid(2.0 * PI);
        let h = self.lift;
        let back = self.rise + self.far;
        if phi < self.rise {
            let (s, ds) = self.laws.0.eval(phi / self.rise);
            (h * s, h * ds / self.rise)
        } else if phi < back {
            (h, 0.0)
        } else if phi < back + self.ret {
            let (s, ds) = self.laws.1.eval((phi - back) / self.ret);
            (h * (1.0 - s), -h * ds / self.ret)
        } else {
            (0.0, 0.0)
        }
    }

    fn pivot(&self) -> Option<Vec2> {
        match self.kind {
            Kind::Translating => None,
            Kind::Rocker(l) => Some(Vec2::new(l, 0.0)),
        }
    }

    fn motion(&self, phi: f64) -> Motion {
        let (s, ds) = self.lift_at(phi);
        match self.kind {
            Kind::Translating => Motion { b: Vec2::new(0.0, s), db: Vec2::new(0.0, ds), t: Vec2::new(0.0, 1.0) },
            Kind::Rocker(l) => {
                // B = A + l(−cos β, sin β): dB/dβ = l(sin β, cos β).
                let (sb, cb) = s.sin_cos();
                let b = Vec2::new(l - l * cb, l * sb);
                let t = Vec2::new(sb, cb);
                Motion { b, db: t * (l * ds), t }
            }
        }
    }

    /// The contact normal, out of the cam, for a centre at `o`.
    fn normal(&self, phi: f64, o: Vec2) -> (Motion, Vec2) {
        let m = self.motion(phi);
        let n = (m.b - o) - j(m.db);
        (m, n)
    }

    /// The signed pressure angle at φ: from the rise's direction of motion to the normal.
    fn alpha(&self, phi: f64, o: Vec2) -> f64 {
        let (m, n) = self.normal(phi, o);
        cross(m.t, n).atan2(dot(m.t, n))
    }

    fn program(&self) -> Program {
        Program::new(self.rise, self.far, self.ret, (self.laws.0.law(), self.laws.1.law()), self.lift).unwrap()
    }

    fn follower(&self) -> Follower {
        match self.kind {
            Kind::Translating => Follower::Translating,
            Kind::Rocker(l) => Follower::Rocker { length: l },
        }
    }

    fn spec(&self, placement: Placement, roller: Roller) -> CamSpec {
        CamSpec {
            follower: self.follower(),
            program: self.program(),
            allowed: Allowed { rise: self.allow[0], ret: self.allow[1] },
            placement,
            roller,
            sense: Sense::Cw,
        }
    }
}

// ------------------------------------------------------------------------------------------
// Admissibility on a fine φ grid, every near-binding sampled maximum refined.

/// Golden-section maximum of `f` on [a, b]: (argmax, max).
fn golden_max(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if b - a < 1e-13 {
            break;
        }
        if fc > fd {
            b = d;
            (d, fd) = (c, fc);
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            (c, fc) = (d, fd);
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    let m = (a + b) / 2.0;
    let fm = f(m);
    [(c, fc), (d, fd), (m, fm)].into_iter().fold((m, f64::NEG_INFINITY), |x, y| if y.1 > x.1 { y } else { x })
}

struct PhaseGrid {
    phi: Vec<f64>,
    /// B − J·dB/dφ: the normal is this minus O.
    apex: Vec<Vec2>,
    t: Vec<Vec2>,
    allow: f64,
    tan_allow: f64,
}

struct Checker<'a> {
    cam: &'a Cam,
    phases: [PhaseGrid; 2],
}

/// Sampled maxima within this of the allowed angle are refined.
const NEAR: f64 = 1e-3;

impl<'a> Checker<'a> {
    fn new(cam: &'a Cam, n: usize) -> Checker<'a> {
        let grid = |phase: usize| {
            let (a, b) = cam.span(phase);
            let phi: Vec<f64> = (0..=n).map(|k| if k == n { b } else { a + (b - a) * k as f64 / n as f64 }).collect();
            let ms: Vec<Motion> = phi.iter().map(|&p| cam.motion(p)).collect();
            PhaseGrid {
                apex: ms.iter().map(|m| m.b - j(m.db)).collect(),
                t: ms.iter().map(|m| m.t).collect(),
                phi,
                allow: cam.allow[phase],
                tan_allow: cam.allow[phase].tan(),
            }
        };
        Checker { cam, phases: [grid(0), grid(1)] }
    }

    /// Every pressure angle within the allowed one (exactly, up to the refinement).
    fn admissible(&self, o: Vec2) -> bool {
        let mut q = Vec::new();
        for g in &self.phases {
            q.clear();
            for (apex, t) in g.apex.iter().zip(&g.t) {
                let n = *apex - o;
                let (c, d) = (cross(*t, n).abs(), dot(*t, n));
                if d <= 0.0 || c > g.tan_allow * d {
                    return false;
                }
                q.push(c / d);
            }
            let near = (g.allow - NEAR).tan();
            let last = q.len() - 1;
            for k in 0..=last {
                let is_max = (k == 0 || q[k] >= q[k - 1]) && (k == last || q[k] >= q[k + 1]);
                if is_max && q[k] > near {
                    let (lo, hi) = (g.phi[k.saturating_sub(1)], g.phi[(k + 1).min(last)]);
                    if golden_max(|p| self.cam.alpha(p, o).abs(), lo, hi).1 > g.allow {
                        return false;
                    }
                }
            }
        }
        true
    }

    /// The largest |pressure angle| of each phase and its φ: every sampled local maximum near
    /// the sampled largest refined.
    fn max_alpha(&self, o: Vec2) -> [(f64, f64); 2] {
        let one = |g: &PhaseGrid| {
            let a: Vec<f64> = g.phi.iter().map(|&p| self.cam.alpha(p, o).abs()).collect();
            let top = a.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            let last = a.len() - 1;
            let mut best = (0.0, f64::NEG_INFINITY);
            for k in 0..=last {
                let is_max = (k == 0 || a[k] >= a[k - 1]) && (k == last || a[k] >= a[k + 1]);
                if is_max && a[k] > top - NEAR {
                    let (lo, hi) = (g.phi[k.saturating_sub(1)], g.phi[(k + 1).min(last)]);
                    let m = golden_max(|p| self.cam.alpha(p, o).abs(), lo, hi);
                    let m = if a[k] > m.1 { (g.phi[k], a[k]) } else { m };
                    if m.1 > best.1 {
                        best = m;
                    }
                }
            }
            (best.1, best.0)
        };
        [one(&self.phases[0]), one(&self.phases[1])]
    }
}

// ------------------------------------------------------------------------------------------
// Brute force.

/// A translating follower with offset e: the smallest s0 by bisection (admissibility only
/// grows with s0: the constraint is |ds/dφ − e| ≤ tan α·(s0 + s)). Returns the centre.
fn brute_offset(ck: &Checker, e: f64) -> Vec2 {
    let at = |s0: f64| Vec2::new(e, -s0);
    let mut hi = 0.01;
    while !ck.admissible(at(hi)) {
        hi *= 2.0;
        assert!(hi < 100.0, "no admissible s0 for e = {e}");
    }
    let mut lo = 0.0;
    for _ in 0..200 {
        let mid = (lo + hi) / 2.0;
        if mid <= lo || mid >= hi {
            break;
        }
        if ck.admissible(at(mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    at(hi)
}

/// The admissible centre nearest to B₀ over an n × n grid on [lo, hi], refined: each level's
/// next window is the bounding box of the admissible points near the level's best, widened.
/// The optimum O* keeps inside the window: the region holds O* + its recession cone
/// (half-opening γ = min α − swing/2), and that cone holds a grid point within
/// (1 + 1/sin γ)/2 diagonals of O*, whose value is then within as many diagonals of the best.
/// Stops at a diagonal of `stop` metres.
fn brute_grid(ck: &Checker, mut lo: Vec2, mut hi: Vec2, n: usize, stop: f64) -> (Vec2, usize) {
    // The recession cone's half-opening, and how many diagonals from O* its nearest grid point
    // may be: the cone holds a disc of radius ρ at ρ/sin γ from its apex, and every disc of
    // half a diagonal holds a grid point.
    let cam = ck.cam;
    let gamma = cam.allow[0].min(cam.allow[1]) - if cam.pivot().is_some() { cam.lift / 2.0 } else { 0.0 };
    assert!(gamma > 0.05, "the admissible region's recession cone is too narrow: {gamma} rad");
    let reach = (1.0 + 1.0 / gamma.sin()) / 2.0;
    let (near, widen) = (reach + 0.3, reach + 1.3);
    let n = n.max((8.0 * widen).ceil() as usize + 1);
    let mut best: Option<(f64, Vec2)> = None;
    let mut levels = 0;
    loop {
        levels += 1;
        assert!(levels < 200, "the grid search does not converge: window {lo:?}–{hi:?}");
        let h = (hi - lo) / (n - 1) as f64;
        let mut pts: Vec<(f64, Vec2)> = Vec::new();
        for i in 0..n {
            for k in 0..n {
                let o = Vec2::new(lo.x + h.x * i as f64, lo.y + h.y * k as f64);
                if ck.admissible(o) {
                    pts.push((norm(o), o));
                }
            }
        }
        if let Some(b) = best {
            pts.push(b);
        }
        assert!(!pts.is_empty(), "no admissible centre in {lo:?}–{hi:?}");
        let b = pts.iter().cloned().fold((f64::INFINITY, Vec2::ZERO), |m, p| if p.0 < m.0 { p } else { m });
        best = Some(b);
        let diag = norm(h);
        if diag < stop {
            return (b.1, levels);
        }
        let (mut nlo, mut nhi) = (b.1, b.1);
        for &(v, p) in &pts {
            if v <= b.0 + near * diag {
                nlo = Vec2::new(nlo.x.min(p.x), nlo.y.min(p.y));
                nhi = Vec2::new(nhi.x.max(p.x), nhi.y.max(p.y));
            }
        }
        // The optimum is within `reach` diagonals of its admissible neighbour in the near set,
        // and its neighbour in the next grid (a smaller diagonal) must be inside too.
        let margin = Vec2::new(widen * diag, widen * diag);
        lo = nlo - margin;
        hi = nhi + margin;
    }
}

// ------------------------------------------------------------------------------------------
// Acceptance.

/// 1e-6° in radians.
const ANGLE_TOL: f64 = 1e-6 * PI / 180.0;

/// The program's centre admissible by the formula here, and its r_min no larger than the brute
/// force's (+1e-9 m); the brute force converged to within 1e-8 m above it. Returns r_min.
fn accept(label: &str, cam: &Cam, ck: &Checker, d: &Design, brute: Vec2) -> f64 {
    let (program, brute_r) = (d.centre.r_min, norm(brute));
    assert!((norm(d.centre.o) - program).abs() < 1e-12, "{label}: r_min is |O − B₀|");
    let max = ck.max_alpha(d.centre.o);
    for (ph, (&(a, at), allow)) in max.iter().zip(cam.allow).enumerate() {
        assert!(
            a <= allow + ANGLE_TOL,
            "{label}: phase {ph}: the program's centre {:?} gives |α| = {:.9}° at φ = {:.6}° > {:.6}°",
            d.centre.o,
            a.to_degrees(),
            at.to_degrees(),
            allow.to_degrees()
        );
    }
    println!(
        "{label}: r_min program {:.9} mm, brute force {:.9} mm (brute − program = {:+.3e} m); O program ({:.6}, {:.6}) mm, brute ({:.6}, {:.6}) mm; max |α| {:.7}° / {:.7}°",
        program * 1e3,
        brute_r * 1e3,
        brute_r - program,
        d.centre.o.x * 1e3,
        d.centre.o.y * 1e3,
        brute.x * 1e3,
        brute.y * 1e3,
        max[0].0.to_degrees(),
        max[1].0.to_degrees(),
    );
    assert!(program <= brute_r + 1e-9, "{label}: program r_min {program} m > brute force {brute_r} m");
    assert!(brute_r <= program + 1e-8, "{label}: the brute force did not converge: {brute_r} m vs {program} m");
    program
}

// ------------------------------------------------------------------------------------------
// Cases.

/// Asymmetric translating cams (the best offset is not zero).
fn translating_cases() -> Vec<(&'static str, Cam)> {
    vec![
        (
            "T1 sine/cosine 120-30-90 α30/45",
            Cam::new(Kind::Translating, (120.0, 30.0, 90.0), (L::Sine, L::Cosine), 0.03, (30.0, 45.0)),
        ),
        (
            "T2 345/parabolic 90-20-120 α25/40",
            Cam::new(Kind::Translating, (90.0, 20.0, 120.0), (L::P345, L::Parabolic), 0.02, (25.0, 40.0)),
        ),
        (
            "T3 cosine/sine 100-0-80 α35/35",
            Cam::new(Kind::Translating, (100.0, 0.0, 80.0), (L::Cosine, L::Sine), 0.025, (35.0, 35.0)),
        ),
    ]
}

/// The guide's rocker: l = 0.105 m, swing 25°, rise = return = 70°, far dwell 10°, α = 45°.
fn guide_rocker(law: L) -> Cam {
    Cam::new(Kind::Rocker(0.105), (70.0, 10.0, 70.0), (law, law), r(25.0), (45.0, 45.0))
}

fn rocker_cases() -> Vec<(&'static str, Cam)> {
    vec![
        ("R sine (guide)", guide_rocker(L::Sine)),
        ("R cosine (guide)", guide_rocker(L::Cosine)),
        ("R 3-4-5 (guide)", guide_rocker(L::P345)),
        (
            "R asym cubic/sine 90-20-60 α35/50",
            Cam::new(Kind::Rocker(0.12), (90.0, 20.0, 60.0), (L::Cubic, L::Sine), r(20.0), (35.0, 50.0)),
        ),
    ]
}

/// Harder cases: strongly unequal allowed angles, a long dwell-free program, a rocker whose
/// swing nearly uses up the allowed angle (the region's cone half-opening 10°).
fn extreme_cases() -> Vec<(&'static str, Cam)> {
    vec![
        (
            "X1 translating sine/sine 60-0-60 α15/75",
            Cam::new(Kind::Translating, (60.0, 0.0, 60.0), (L::Sine, L::Sine), 0.01, (15.0, 75.0)),
        ),
        (
            "X2 translating cosine/345 150-60-150 α20/20",
            Cam::new(Kind::Translating, (150.0, 60.0, 150.0), (L::Cosine, L::P345), 0.05, (20.0, 20.0)),
        ),
        (
            "X3 rocker sine/cosine 60-0-60 swing 40° α30/40",
            Cam::new(Kind::Rocker(0.08), (60.0, 0.0, 60.0), (L::Sine, L::Cosine), r(40.0), (30.0, 40.0)),
        ),
        (
            "X4 rocker 345/parabolic 120-30-100 swing 10° α25/60",
            Cam::new(Kind::Rocker(0.2), (120.0, 30.0, 100.0), (L::P345, L::Parabolic), r(10.0), (25.0, 60.0)),
        ),
    ]
}

fn extreme_min_radius(samples: usize, grid: usize) {
    for (name, cam) in extreme_cases() {
        let ck = Checker::new(&cam, samples);
        if cam.kind == Kind::Translating {
            for e in [0.0, 0.008, -0.004] {
                let d = design(&cam.spec(Placement::Offset(e), Roller::Knife)).unwrap();
                accept(&format!("{name}, e = {} mm", e * 1e3), &cam, &ck, &d, brute_offset(&ck, e));
            }
        }
        let d = design(&cam.spec(Placement::Free, Roller::Knife)).unwrap();
        let (brute, levels) = brute_grid(&ck, Vec2::new(-0.5, -1.0), Vec2::new(0.5, 0.2), grid, 1e-12);
        accept(&format!("{name}, free ({levels} levels)"), &cam, &ck, &d, brute);
        assert!(norm(brute - d.centre.o) < 1e-6, "{name}: centres {brute:?} vs {:?}", d.centre.o);
    }
}

#[test]
fn extreme_minimum_radius_by_brute_force() {
    extreme_min_radius(LIGHT, 25);
}

#[test]
#[ignore = "heavy: 4000 samples a phase, a 41 × 41 grid (run with --ignored)"]
fn extreme_minimum_radius_by_brute_force_fine() {
    extreme_min_radius(HEAVY, 41);
}

/// Samples per phase: the default run, and the heavy (ignored) one.
const LIGHT: usize = 1000;
const HEAVY: usize = 4000;

fn translating_min_radius(samples: usize, grid: usize) {
    for (name, cam) in translating_cases() {
        let ck = Checker::new(&cam, samples);
        for (placement, label) in [(Placement::Offset(0.0), "e = 0"), (Placement::Offset(0.008), "e = 8 mm")] {
            let Placement::Offset(e) = placement else { unreachable!() };
            let d = design(&cam.spec(placement, Roller::Knife)).unwrap();
            assert_eq!(d.centre.o.x, e, "{name} {label}: the offset is the centre's x");
            assert_eq!(d.offset(), Some(e));
            let brute = brute_offset(&ck, e);
            accept(&format!("{name}, {label}"), &cam, &ck, &d, brute);
        }
        let d = design(&cam.spec(Placement::Free, Roller::Knife)).unwrap();
        let (brute, levels) = brute_grid(&ck, Vec2::new(-0.3, -0.8), Vec2::new(0.3, 0.1), grid, 1e-12);
        let program = accept(&format!("{name}, free offset ({levels} levels)"), &cam, &ck, &d, brute);
        // The best offset is not zero here, and it beats both given offsets.
        assert!(d.centre.o.x.abs() > 1e-4, "{name}: best offset {} m", d.centre.o.x);
        for e in [0.0, 0.008] {
            assert!(program <= norm(brute_offset(&ck, e)) + 1e-12, "{name}: free worse than e = {e}");
        }
        // The brute force's best centre is the program's (the optimum is unique).
        assert!(norm(brute - d.centre.o) < 1e-7, "{name}: centres {brute:?} vs {:?}", d.centre.o);
    }
}

#[test]
fn translating_minimum_radius_by_brute_force() {
    translating_min_radius(LIGHT, 25);
}

#[test]
#[ignore = "heavy: 4000 samples a phase, a 41 × 41 grid (run with --ignored)"]
fn translating_minimum_radius_by_brute_force_fine() {
    translating_min_radius(HEAVY, 41);
}

fn rocker_min_radius(samples: usize, grid: usize) {
    for (name, cam) in rocker_cases() {
        let ck = Checker::new(&cam, samples);
        let d = design(&cam.spec(Placement::Free, Roller::Knife)).unwrap();
        let (brute, levels) = brute_grid(&ck, Vec2::new(-0.5, -0.8), Vec2::new(0.5, 0.2), grid, 1e-12);
        accept(&format!("{name} ({levels} levels)"), &cam, &ck, &d, brute);
        assert!(norm(brute - d.centre.o) < 1e-6, "{name}: centres {brute:?} vs {:?}", d.centre.o);
        // The pivot to the centre, and the rocker's starting angle between A→O and A→B₀.
        let a = cam.pivot().unwrap();
        let (to_o, to_b) = (d.centre.o - a, Vec2::ZERO - a);
        let dist = norm(to_o);
        let start = (dot(to_o, to_b) / (dist * norm(to_b))).clamp(-1.0, 1.0).acos();
        let (cd, rs) = (d.centre_distance().unwrap(), d.rocker_start().unwrap());
        println!("{name}: a_w = |O − A| = {:.6} mm, ψ₀ = {:.6}°", dist * 1e3, start.to_degrees());
        assert!((cd - dist).abs() < 1e-12, "{name}: centre distance {cd} vs {dist}");
        assert!((rs - start).abs() < 1e-9, "{name}: rocker start {rs} vs {start}");
    }
}

#[test]
fn rocker_minimum_radius_by_brute_force() {
    rocker_min_radius(LIGHT, 25);
}

#[test]
#[ignore = "heavy: 4000 samples a phase, a 41 × 41 grid (run with --ignored)"]
fn rocker_minimum_radius_by_brute_force_fine() {
    rocker_min_radius(HEAVY, 41);
}

#[test]
fn the_normal_passes_through_the_relative_pole() {
    // The oriented normal used above against the instant-centre construction, at arbitrary
    // centres (not only admissible ones) and cam angles.
    let cams = [translating_cases()[0].1.clone(), rocker_cases()[0].1.clone(), rocker_cases()[3].1.clone()];
    for cam in &cams {
        for (i, o) in [Vec2::new(0.01, -0.05), Vec2::new(-0.02, -0.08), Vec2::new(0.03, -0.04)].into_iter().enumerate()
        {
            for k in 0..200 {
                let phi = 2.0 * PI * (k as f64 + 0.37 * i as f64) / 200.0;
                let (m, n) = cam.normal(phi, o);
                let p = match cam.pivot() {
                    None => o + j(m.db),
                    Some(a) => {
                        // The rocker's angular velocity from B's own motion about A.
                        let w = cross(m.b - a, m.db) / (m.b - a).hypot2();
                        assert!((norm(m.db) - w.abs() * norm(m.b - a)).abs() < 1e-12);
                        if (1.0 + w).abs() < 1e-6 {
                            continue;
                        }
                        // −(P − O) = w(P − A): the cam's velocity at P is the rocker's.
                        let p = (o + a * w) / (1.0 + w);
                        let (vc, vf) = (-j(p - o), j(p - a) * w);
                        assert!(norm(vc - vf) < 1e-12);
                        p
                    }
                };
                let bp = m.b - p;
                if norm(bp) > 1e-9 {
                    let sin = cross(n, bp) / (norm(n) * norm(bp));
                    assert!(sin.abs() < 1e-9, "{cam:?} φ = {phi}: normal {n:?}, B − P {bp:?}");
                }
                // The translating follower's textbook form.
                if cam.kind == Kind::Translating {
                    let (s, ds) = cam.lift_at(phi);
                    let (e, s0) = (o.x, -o.y);
                    let textbook = ((ds - e) / (s0 + s)).atan();
                    assert!((cam.alpha(phi, o) + textbook).abs() < 1e-12);
                }
            }
        }
    }
}

// ------------------------------------------------------------------------------------------
// The profile.

/// Designs for the profile checks: both follower kinds, several laws, a roller.
fn profile_designs() -> Vec<(String, Cam, Design)> {
    let mut out = Vec::new();
    let t = translating_cases();
    for (name, cam) in [&t[0], &t[1]] {
        for (placement, p) in [(Placement::Free, "free"), (Placement::Offset(0.008), "e = 8 mm")] {
            let d = design(&cam.spec(placement, Roller::Auto)).unwrap();
            out.push((format!("{name}, {p}"), cam.clone(), d));
        }
    }
    for (name, cam) in rocker_cases() {
        let d = design(&cam.spec(Placement::Free, Roller::Auto)).unwrap();
        out.push((name.to_string(), cam, d));
    }
    out
}

/// The signed curvature of the circle through three points (positive turning left).
fn three_point_curvature(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    2.0 * cross(b - a, c - b) / (norm(b - a) * norm(c - b) * norm(c - a))
}

#[test]
fn the_pitch_profile_is_the_roller_centre_carried_back() {
    // Turning the cam clockwise by φ brings its pitch point at φ onto the roller centre:
    // R(−φ)·P(φ) = B(φ) − O with B from the motion computed here.
    for (name, cam, d) in profile_designs() {
        for k in 0..=720 {
            let phi = 2.0 * PI * k as f64 / 720.0;
            let p = d.profile.pitch(phi).p;
            let back = rot(p, -phi);
            let want = cam.motion(phi).b - d.centre.o;
            assert!(norm(back - want) < 1e-12, "{name} φ = {phi}: {back:?} vs {want:?}");
            // Its derivative by finite differences.
            let h = 1e-6;
            let fd = (rot(cam.motion(phi + h).b - d.centre.o, phi + h)
                - rot(cam.motion(phi - h).b - d.centre.o, phi - h))
                / (2.0 * h);
            let dp = d.profile.pitch(phi).dp;
            assert!(norm(fd - dp) < 1e-7 * (1.0 + norm(dp)), "{name} φ = {phi}: P′ {dp:?} vs {fd:?}");
        }
    }
}

#[test]
fn the_working_profile_is_the_roller_radius_from_the_pitch_profile() {
    for (name, _cam, d) in profile_designs() {
        let r = d.roller;
        assert!(r > 0.0 && r < d.rho_min, "{name}: roller {r}");
        let m = 20_000;
        let pitch: Vec<Vec2> = (0..m).map(|k| d.profile.pitch(2.0 * PI * k as f64 / m as f64).p).collect();
        let mut worst = 0.0f64;
        for k in 0..150 {
            let phi = 2.0 * PI * (k as f64 + 0.123) / 150.0;
            let (w, _) = d.profile.working(r, phi);
            let i = (0..m).min_by(|&a, &b| norm(pitch[a] - w).total_cmp(&norm(pitch[b] - w))).unwrap();
            let step = 2.0 * PI / m as f64;
            let psi = i as f64 * step;
            let (_, neg) = golden_max(|x| -norm(d.profile.pitch(x).p - w), psi - step, psi + step);
            let dist = -neg;
            worst = worst.max((dist - r).abs());
            assert!((dist - r).abs() < 1e-7, "{name} φ = {phi}: distance {dist} m, roller {r} m");
        }
        println!("{name}: roller {:.3} mm, worst |distance − r| = {worst:.2e} m", r * 1e3);
    }
}

/// Where any law's acceleration may jump: the phases' eighths (the dwells' ends among them).
fn joints(spans: [(f64, f64); 2]) -> Vec<f64> {
    let mut js: Vec<f64> =
        spans.iter().flat_map(|&(a, b)| (0..=8).map(move |k| a + (b - a) * k as f64 / 8.0)).collect();
    js.extend([0.0, 2.0 * PI]);
    js
}

/// Sample points for a three-point stencil of half-width h that stays on one side of every
/// joint: a regular grid of `m` (stencils across a joint left out) and each joint's two
/// one-sided limits.
fn stencil_centres(spans: [(f64, f64); 2], m: usize, h: f64) -> Vec<f64> {
    let js = joints(spans);
    let mut out: Vec<f64> = (0..m)
        .map(|k| 2.0 * PI * (k as f64 + 0.5) / m as f64)
        .filter(|phi| js.iter().all(|j| (phi - j).abs() > 1.001 * h))
        .collect();
    for j in js {
        out.extend([j - 1.001 * h, j + 1.001 * h]);
    }
    out
}

#[test]
fn the_curvature_is_the_curvature_of_the_points() {
    // Points computed here (R(φ)(B − O)) for the designs above.
    let h = 1e-4;
    for (name, cam, d) in profile_designs() {
        let spans = [cam.span(0), cam.span(1)];
        let point = |phi: f64| rot(cam.motion(phi).b - d.centre.o, phi);
        for phi in stencil_centres(spans, 2000, h) {
            let fd = three_point_curvature(point(phi - h), point(phi), point(phi + h));
            let kappa = d.profile.curvature(phi);
            assert!((fd - kappa).abs() < 1e-5 * kappa.abs() + 1e-3, "{name} φ = {phi}: κ {kappa} vs {fd}");
        }
    }
}

fn all_law_designs() -> Vec<(String, Design)> {
    let mut out = Vec::new();
    for law in Law::ALL {
        let tp = Program::new(r(120.0), r(30.0), r(90.0), (law, law), 0.03).unwrap();
        let ta = Allowed { rise: r(30.0), ret: r(45.0) };
        for (placement, p) in [(Placement::Free, "free"), (Placement::Offset(0.0), "e = 0")] {
            let spec = CamSpec {
                follower: Follower::Translating,
                program: tp.clone(),
                allowed: ta,
                placement,
                roller: Roller::Auto,
                sense: Sense::Cw,
            };
            out.push((format!("{} translating {p}", law.key()), design(&spec).unwrap()));
        }
        let rp = Program::new(r(70.0), r(10.0), r(70.0), (law, law), r(25.0)).unwrap();
        let spec = CamSpec {
            follower: Follower::Rocker { length: 0.105 },
            program: rp,
            allowed: Allowed { rise: r(45.0), ret: r(45.0) },
            placement: Placement::Free,
            roller: Roller::Auto,
            sense: Sense::Cw,
        };
        out.push((format!("{} rocker", law.key()), design(&spec).unwrap()));
    }
    out
}

#[test]
fn the_pressure_angle_on_the_profile_is_within_the_allowed_and_tight() {
    for (name, d) in all_law_designs() {
        let allowed = [d.spec.allowed.rise, d.spec.allowed.ret];
        let mp = d.max_pressure.map(|m| m.0);
        for ph in 0..2 {
            assert!(mp[ph] <= allowed[ph] + ANGLE_TOL, "{name}: phase {ph}: {}°", mp[ph].to_degrees());
        }
        let gap = (0..2).map(|ph| (allowed[ph] - mp[ph]).abs()).fold(f64::INFINITY, f64::min);
        assert!(gap <= ANGLE_TOL, "{name}: not tight: {:?}°", mp.map(f64::to_degrees));

        // The same read off the profile's points here: the normal of a central-difference
        // chord, taken back to the follower frame, against the motion there.
        let p = &d.profile;
        let o = d.centre.o;
        let mut ours = [0.0f64; 2];
        for (ph, phase) in Phase::BOTH.into_iter().enumerate() {
            let (a, b) = phase.span(&d.spec.program);
            let n = 4000;
            for k in 0..=n {
                let phi = a + (b - a) * k as f64 / n as f64;
                let h = 1e-5;
                let chord = p.pitch(phi + h).p - p.pitch(phi - h).p;
                let normal = rot(Vec2::new(chord.y, -chord.x), -phi);
                let bb = o + rot(p.pitch(phi).p, -phi);
                let t = match d.spec.follower.pivot() {
                    None => Vec2::new(0.0, 1.0),
                    Some(a) => {
                        let u = bb - a;
                        Vec2::new(u.y, -u.x) / norm(u)
                    }
                };
                ours[ph] = ours[ph].max(cross(t, normal).atan2(dot(t, normal)).abs());
            }
            assert!(
                ours[ph] <= mp[ph] + 1e-8,
                "{name}: phase {ph}: sampled {}° > {}°",
                ours[ph].to_degrees(),
                mp[ph].to_degrees()
            );
            assert!(
                mp[ph] - ours[ph] < 1e-5,
                "{name}: phase {ph}: sampled {}° vs {}°",
                ours[ph].to_degrees(),
                mp[ph].to_degrees()
            );
        }
    }
}

#[test]
fn the_max_pressure_is_the_pressure_angle_computed_here() {
    let mut cases: Vec<(String, Cam, Design)> = profile_designs();
    for law in L::ALL {
        let t = Cam::new(Kind::Translating, (120.0, 30.0, 90.0), (law, law), 0.03, (30.0, 45.0));
        for placement in [Placement::Free, Placement::Offset(0.0), Placement::Offset(-0.005)] {
            let d = design(&t.spec(placement, Roller::Knife)).unwrap();
            cases.push((format!("{law:?} translating {placement:?}"), t.clone(), d));
        }
        let rk = guide_rocker(law);
        let d = design(&rk.spec(Placement::Free, Roller::Knife)).unwrap();
        cases.push((format!("{law:?} rocker"), rk, d));
    }
    for (name, cam, d) in cases {
        let ck = Checker::new(&cam, LIGHT);
        let max = ck.max_alpha(d.centre.o);
        for (ph, ((&(ours, _), &(theirs, _)), allow)) in max.iter().zip(&d.max_pressure).zip(cam.allow).enumerate() {
            assert!(
                (ours - theirs).abs() < ANGLE_TOL,
                "{name}: phase {ph}: {}° here, {}° the program's",
                ours.to_degrees(),
                theirs.to_degrees()
            );
            assert!(ours <= allow + ANGLE_TOL, "{name}: phase {ph}: {}°", ours.to_degrees());
        }
    }
}

#[test]
fn rho_min_is_the_smallest_convex_radius_of_curvature() {
    let h = 1e-4;
    for (name, d) in all_law_designs() {
        let p = &d.profile;
        let pr = &d.spec.program;
        let spans = [Phase::Rise.span(pr), Phase::Return.span(pr)];
        let mut kmax = f64::NEG_INFINITY;
        for phi in stencil_centres(spans, 20_000, h) {
            let kappa = three_point_curvature(p.pitch(phi - h).p, p.pitch(phi).p, p.pitch(phi + h).p);
            kmax = kmax.max(kappa);
        }
        let sampled = 1.0 / kmax;
        assert!(kmax > 0.0, "{name}");
        assert!(d.rho_min <= sampled * (1.0 + 1e-6), "{name}: ρ_min {} vs sampled {sampled}", d.rho_min);
        assert!(d.rho_min >= sampled * (1.0 - 1e-3), "{name}: ρ_min {} vs sampled {sampled}", d.rho_min);
        let at = p.curvature(d.rho_min_phi);
        assert!(
            (1.0 / at - d.rho_min).abs() < 1e-9 * d.rho_min.max(1.0),
            "{name}: 1/κ(φ) = {} vs {}",
            1.0 / at,
            d.rho_min
        );
    }
}

// ------------------------------------------------------------------------------------------
// Graphical integration.

#[test]
fn chord_integration_of_the_cosine_law_converges_as_one_over_n_squared() {
    let (rise, far, ret, h) = (r(120.0), r(30.0), r(90.0), 0.03);
    let program = Program::new(rise, far, ret, (Law::Cosine, Law::Cosine), h).unwrap();
    let exact = |phase: Phase, phi: f64| match phase {
        Phase::Rise => h * (1.0 - (PI * phi / rise).cos()) / 2.0,
        Phase::Return => h - h * (1.0 - (PI * (phi - rise - far) / ret).cos()) / 2.0,
    };
    for phase in Phase::BOTH {
        let err = |n: usize| {
            let it = chords(&program, phase, n);
            assert_eq!(it.s.len(), n + 1);
            it.phi.iter().zip(&it.s).map(|(&phi, &s)| (s - exact(phase, phi)).abs()).fold(0.0, f64::max)
        };
        for n in [6, 8, 12, 16, 24, 48] {
            let (e1, e2) = (err(n), err(2 * n));
            let ratio = e1 / e2;
            println!("{phase:?}: n = {n}: max |s − exact| = {e1:.3e} m, 2n: {e2:.3e} m, ratio {ratio:.3}");
            assert!((ratio - 4.0).abs() < 0.8, "{phase:?} n = {n}: ratio {ratio}");
        }
    }
}

/// The automatic roller is inside the course's 0.25–0.4·r_min (rounded up to a whole mm, it
/// was 14 mm = 0.2485·r_min on the guide's rocker rounded down), or smaller with the
/// warning that says why: the profile's curvature.
#[test]
fn the_automatic_roller_is_inside_the_course_range_or_warned() {
    let cases = translating_cases().into_iter().chain(rocker_cases()).chain(extreme_cases());
    for (label, cam) in cases {
        let d = design(&cam.spec(Placement::Free, Roller::Auto)).unwrap();
        let share = d.roller / d.centre.r_min;
        let mm = d.roller * 1000.0;
        assert!((mm - mm.round()).abs() < 1e-9 || mm < 2.0, "{label}: {mm} mm is not a whole millimetre");
        if !d.warnings.iter().any(|w| matches!(w, CamWarning::RollerBelowCourse { .. })) {
            assert!((0.25..=0.4).contains(&share), "{label}: roller {mm} mm = {share}·r_min");
        } else {
            assert!(share < 0.25, "{label}: warned, yet {share}·r_min");
        }
    }
    let d = design(&guide_rocker(L::Sine).spec(Placement::Free, Roller::Auto)).unwrap();
    assert_eq!((d.roller * 1000.0).round(), 15.0, "0.25·56.34 mm = 14.08 mm, up to 15 mm");
}
