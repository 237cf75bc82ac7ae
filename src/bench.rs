//! `tmm bench`: on the user's machine, each accuracy trade-off's run time against the error
//! it buys, the error measured against an exact reference, and whole builds per sheet. The
//! worked example is the subject throughout; errors are given real size and on paper at the
//! sheet's own scale. A setting the sheets use is marked; the program's rule is the cheapest
//! setting whose error on paper is below [`PAPER_LIMIT_MM`].

use crate::cams::integrate::{DIVISIONS, chords, turn_within};
use crate::cams::profile::parts;
use crate::cams::radius::Phase;
use crate::gears::pair::{Pair, PairSpec};
use crate::gears::tooth::Outline;
use crate::lever::{Mechanism, Step, Turn, analysis, trajectory};
use crate::num::bezier;
use crate::num::math::{Norm, from_angle};
use crate::num::tol;
use crate::pipeline::{self, DEFAULT_PROJECT, Format};
use kurbo::Vec2;
use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::Instant;

/// Paper millimetres: an error below this cannot be seen or measured on a drawn sheet.
pub const PAPER_LIMIT_MM: f64 = 0.01;

/// One trade-off's measurements, as a Markdown table with a note under it.
#[derive(Debug, Clone)]
pub struct Table {
    pub title: String,
    pub header: Vec<&'static str>,
    pub rows: Vec<Vec<String>>,
    pub note: String,
}

impl Table {
    pub fn markdown(&self) -> String {
        let mut out = format!("### {}\n\n| {} |\n|", self.title, self.header.join(" | "));
        out.push_str(&"---|".repeat(self.header.len()));
        out.push('\n');
        for r in &self.rows {
            out.push_str(&format!("| {} |\n", r.join(" | ")));
        }
        if !self.note.is_empty() {
            out.push_str(&format!("\n{}\n", self.note));
        }
        out
    }
}

/// How long to measure each setting.
#[derive(Debug, Clone, Copy)]
pub struct Clock {
    /// Seconds spent per measured setting (at least `min_samples` batches).
    pub budget: f64,
    pub min_samples: usize,
}

impl Clock {
    /// `--quick`: a few batches each, the whole run well under 30 s.
    pub const QUICK: Clock = Clock { budget: 0.02, min_samples: 3 };
    pub const FULL: Clock = Clock { budget: 0.4, min_samples: 7 };

    /// The median time of one call, seconds, over batches of calls.
    pub fn time<R>(&self, mut f: impl FnMut() -> R) -> f64 {
        let t = Instant::now();
        black_box(f());
        let once = t.elapsed().as_secs_f64().max(1e-9);
        let batch = ((self.budget / 20.0) / once).clamp(1.0, 1e6) as usize;
        let mut samples = Vec::new();
        let start = Instant::now();
        while samples.len() < self.min_samples || (start.elapsed().as_secs_f64() < self.budget && samples.len() < 500) {
            let t = Instant::now();
            for _ in 0..batch {
                black_box(f());
            }
            samples.push(t.elapsed().as_secs_f64() / batch as f64);
        }
        samples.sort_by(f64::total_cmp);
        samples[samples.len() / 2]
    }
}

/// Every table, in order. Errors only when the embedded worked example cannot be built,
/// which the tests rule out.
pub fn run(clock: Clock) -> Result<Vec<Table>, String> {
    let p = pipeline::load(DEFAULT_PROJECT).map_err(|e| e.to_string())?;
    let built = pipeline::build(&p, &[]).map_err(|e| e.to_string())?;
    let scale = |sheet: u32, path: &[&str]| {
        let b = built.iter().find(|b| b.output.number == sheet)?;
        path.iter().try_fold(&b.output.results, |v, k| v.get(k))?.as_f64()
    };
    let missing = || "the worked example's results lack a scale".to_string();
    let mu_lever = scale(1, &["scales", "mu_l"]).ok_or_else(missing)?;
    let mu_mesh = scale(2, &["drawing", "mu_l"]).ok_or_else(missing)?;
    let mu_profile = scale(3, &["profile_mu_l"]).ok_or_else(missing)?;
    let mu_s = scale(3, &["scales", "mu_s"]).ok_or_else(missing)?;
    let lever = p.lever.as_ref().ok_or_else(missing)?;
    let cam = p.cam.as_ref().ok_or_else(missing)?;
    Ok(vec![
        solver(&lever.mechanism, mu_lever, clock),
        trajectories(lever, mu_lever, clock)?,
        involute(mu_mesh, clock)?,
        cam_profile(&cam.design, mu_profile, clock),
        integration(&cam.design.spec.program, mu_s, clock),
        builds(&p, &built, clock)?,
    ])
}

fn sci(x: f64) -> String {
    if x == 0.0 { "0".into() } else { format!("{x:.1e}") }
}

fn micros(s: f64) -> String {
    format!("{:.1} µs", s * 1e6)
}

fn millis(s: f64) -> String {
    format!("{:.1} ms", s * 1e3)
}

fn mark(used: bool) -> String {
    if used { "← drawn".into() } else { String::new() }
}

// ---- the solver ------------------------------------------------------------------------

/// The largest loop-closure residual of positions `p`, metres: each dyad's and the crank's
/// lengths, and a slider's distance from its guide.
fn residual(m: &Mechanism, p: &[Vec2]) -> f64 {
    let off = |a: Vec2, b: Vec2, l: f64| ((a - b).norm() - l).abs();
    m.steps
        .iter()
        .map(|s| match *s {
            Step::Crank { pivot, pin, length, .. } => off(p[pin], p[pivot], length),
            Step::Rrr { p: a, q, b, l_pb, l_qb, .. } => off(p[b], p[a], l_pb).max(off(p[b], p[q], l_qb)),
            Step::Rrp { p: a, d, length, through, dir, .. } => {
                off(p[d], p[a], length).max(((p[d] - through).cross(dir) / dir.norm()).abs())
            }
            Step::Rpr { .. } | Step::Attach { .. } => 0.0,
        })
        .fold(0.0, f64::max)
}

/// Positions by Newton's method, `iterations` steps per dyad, each dyad started from where
/// it was at the previous crank angle (`p` holds them). `None` for a kulisa (RPR), which
/// this comparison does not cover.
fn newton(m: &Mechanism, theta: f64, iterations: usize, p: &mut [Vec2]) -> Option<()> {
    for &(id, at) in &m.frame {
        p[id] = at;
    }
    for s in &m.steps {
        match *s {
            Step::Crank { pivot, pin, length, .. } => p[pin] = p[pivot] + from_angle(theta) * length,
            Step::Rrr { p: a, q, b, l_pb, l_qb, .. } => {
                for _ in 0..iterations {
                    let (u, v) = (p[b] - p[a], p[b] - p[q]);
                    let f = (u.hypot2() - l_pb * l_pb, v.hypot2() - l_qb * l_qb);
                    let det = 2.0 * u.cross(v) * 2.0;
                    // J = [2u; 2v]; Δ = −J⁻¹ f.
                    let dx = -(f.0 * 2.0 * v.y - f.1 * 2.0 * u.y) / det;
                    let dy = -(f.1 * 2.0 * u.x - f.0 * 2.0 * v.x) / det;
                    p[b] += Vec2::new(dx, dy);
                }
            }
            Step::Rrp { p: a, d, length, through, dir, .. } => {
                let u = dir / dir.norm();
                let mut t = (p[d] - through).dot(u);
                for _ in 0..iterations {
                    let r = through + u * t - p[a];
                    t -= (r.hypot2() - length * length) / (2.0 * r.dot(u));
                }
                p[d] = through + u * t;
            }
            Step::Rpr { .. } => return None,
            Step::Attach { point, from, toward, distance, angle, ratio, .. } => {
                let d = p[toward] - p[from];
                if toward == from {
                    p[point] = p[from];
                    continue;
                }
                let along = ratio.map_or_else(|| d * (distance / d.norm()), |k| d * k);
                p[point] = p[from] + crate::num::math::rotate(along, angle);
            }
        }
    }
    Some(())
}

/// Closed form (ours) against Newton's method: 360 positions, the largest loop-closure
/// residual over the turn.
fn solver(m: &Mechanism, mu_l: f64, clock: Clock) -> Table {
    let angles: Vec<f64> = (0..360).map(|k| TAU * k as f64 / 360.0).collect();
    let mut turn = Turn::default();
    // The whole turn at once, as the motion's scan solves it (see `Mechanism::solve_turn`).
    let closed = clock.time(|| {
        let _ = m.solve_turn(&angles, &mut turn);
    });
    let exact_worst = angles
        .iter()
        .filter_map(|&a| m.solve(a).ok())
        .map(|st| residual(m, &st.points.iter().map(|k| k.p).collect::<Vec<_>>()))
        .fold(0.0, f64::max);
    let mut rows = vec![vec![
        "closed form, positions + v + a (drawn)".into(),
        micros(closed),
        sci(exact_worst),
        sci(exact_worst / mu_l * 1e3),
    ]];
    let start: Vec<Vec2> = m.solve(angles[359]).map(|s| s.points.iter().map(|k| k.p).collect()).unwrap_or_default();
    for n in [1, 2, 3, 4] {
        let mut p = start.clone();
        let mut worst = 0.0f64;
        let mut ok = !p.is_empty();
        for &a in &angles {
            ok &= newton(m, a, n, &mut p).is_some();
            worst = worst.max(residual(m, &p));
        }
        if !ok {
            continue;
        }
        let time = clock.time(|| {
            let mut p = start.clone();
            for &a in &angles {
                newton(m, a, n, &mut p);
            }
        });
        let label = format!("Newton, {n} step{} a dyad, positions only", if n == 1 { "" } else { "s" });
        rows.push(vec![label, micros(time), sci(worst), sci(worst / mu_l * 1e3)]);
    }
    Table {
        title: "Solver: 360 positions of the worked example's six-bar".into(),
        header: vec!["method", "time", "largest residual, m", "on paper, µm"],
        rows,
        note: "Newton starts each dyad from the previous position (1° before), as an iterative \
               solver tracking the motion would; the closed form has no error to trade."
            .into(),
    }
}

// ---- trajectories ----------------------------------------------------------------------

fn trajectories(lever: &crate::project::LeverProject, mu_l: f64, clock: Clock) -> Result<Table, String> {
    let m = &lever.mechanism;
    let k = analysis::kinematics(m, &lever.settings).map_err(|e| e.to_string())?;
    let drawn = k.trajectories.first().map_or(0.0, |t| t.fitted.tolerance);
    let mut tolerances: Vec<f64> = [0.1, 0.03, 0.01, 0.003, 0.001].iter().map(|t| t * mu_l).collect();
    tolerances.push(drawn);
    tolerances.sort_by(|a, b| b.total_cmp(a));
    tolerances.dedup();
    let mut rows = Vec::new();
    for tol in tolerances {
        let fit_all = || {
            k.trajectories.iter().map(|t| trajectory::fit(m, &k.motion, t.point, tol)).collect::<Result<Vec<_>, _>>()
        };
        let fitted = fit_all().map_err(|e| e.to_string())?;
        let pieces: usize = fitted.iter().map(|f| f.cubics.len()).sum();
        let error = fitted.iter().map(|f| f.error).fold(0.0, f64::max);
        let time = clock.time(fit_all);
        rows.push(vec![
            format!("{:.4} mm", tol / mu_l),
            pieces.to_string(),
            format!("{:.4} mm", error / mu_l),
            millis(time),
            mark(tol == drawn),
        ]);
    }
    Ok(Table {
        title: format!("Trajectories of the centres of mass ({} paths), cubic pieces", k.trajectories.len()),
        header: vec!["asked, on paper", "pieces", "measured error, on paper", "time to fit", ""],
        rows,
        note: format!("The sheet asks for 10⁻⁵ of the motion's extent ({:.4} mm on paper here).", drawn / mu_l),
    })
}

// ---- involute flanks -------------------------------------------------------------------

fn involute(mu_l: f64, clock: Clock) -> Result<Table, String> {
    let spec = PairSpec::standard(0.005, [17, 19]);
    let pair = Pair::new(&spec).map_err(|e| e.to_string())?;
    let o = Outline::new(&spec, &pair.wheels[0]);
    let f = |t: f64| o.involute(t);
    let rows = [1usize, 2, 3, 4, 8]
        .iter()
        .map(|&n| {
            let cubics = bezier::fit(&f, o.t_low, o.t_tip, n);
            let dev = bezier::deviation(&f, o.t_low, o.t_tip, &cubics);
            let time = clock.time(|| bezier::fit(&f, o.t_low, o.t_tip, n).len());
            vec![
                n.to_string(),
                format!("{:.4} µm", dev * 1e6),
                format!("{:.5} mm", dev / mu_l),
                micros(time),
                mark(n == crate::sheets::gears::INVOLUTE_PIECES),
            ]
        })
        .collect();
    Ok(Table {
        title: "Involute flank of the worked example's pinion (m = 5 mm, z = 17), cubic pieces".into(),
        header: vec!["pieces", "deviation, real size", "on paper", "time to fit", ""],
        rows,
        note: format!("On paper at the mesh's scale ({:.0}:1).", 1e-3 / mu_l),
    })
}

// ---- the cam's profile -----------------------------------------------------------------

fn cam_profile(d: &crate::cams::Design, mu_l: f64, clock: Clock) -> Table {
    let exact = |phi: f64| d.profile.working(d.roller, phi);
    let spans: Vec<(f64, f64)> =
        parts(&d.spec.program).into_iter().filter(|(a, b)| b - a > tol::ANGLE_ROUND_OFF).collect();
    let mut rows: Vec<Vec<String>> = [2usize, 4, 8, 16, 32]
        .iter()
        .map(|&n| {
            let fit = || spans.iter().map(|&(a, b)| bezier::fit(&exact, a, b, n)).collect::<Vec<_>>();
            let dev =
                spans.iter().zip(fit()).map(|(&(a, b), c)| bezier::deviation(&exact, a, b, &c)).fold(0.0, f64::max);
            let time = clock.time(fit);
            vec![
                format!("{} ({n} a part)", n * spans.len()),
                format!("{:.3} µm", dev * 1e6),
                format!("{:.4} mm", dev / mu_l),
                micros(time),
                String::new(),
            ]
        })
        .collect();
    let adaptive = || d.profile.cubics(d.roller, tol::PROFILE_FIT, 256);
    let fitted = adaptive();
    let pieces: usize = fitted.iter().map(|f| f.cubics.len()).sum();
    let dev = fitted.iter().map(|f| f.deviation).fold(0.0, f64::max);
    rows.push(vec![
        format!("{pieces} (doubled per part until within 1 µm)"),
        format!("{:.3} µm", dev * 1e6),
        format!("{:.4} mm", dev / mu_l),
        micros(clock.time(adaptive)),
        mark(true),
    ]);
    Table {
        title: "The cam's working profile (the roller's envelope), cubic pieces".into(),
        header: vec!["pieces", "deviation, real size", "on paper", "time to fit", ""],
        rows,
        note: format!("On paper at the profile's scale ({:.0}:1).", 1e-3 / mu_l),
    }
}

// ---- chord integration -----------------------------------------------------------------

fn integration(p: &crate::cams::laws::Program, mu_s: f64, clock: Clock) -> Table {
    let vmax = 2.0 * p.lift / p.rise;
    // The chords a phase the sheet draws: the course's divisions, each in as many chords as
    // keep the displacement within 1 % of the lift.
    let drawn = DIVISIONS * turn_within(p, DIVISIONS)[0].chords;
    let rows = [4usize, 6, 8, 12, 16, 24, 48]
        .iter()
        .map(|&n| {
            let (es, ev) = Phase::BOTH
                .iter()
                .map(|&ph| chords(p, ph, n).error(p))
                .fold((0.0f64, 0.0f64), |m, e| (m.0.max(e.s), m.1.max(e.ds)));
            let time = clock.time(|| Phase::BOTH.iter().map(|&ph| chords(p, ph, n).s.len()).sum::<usize>());
            vec![
                n.to_string(),
                format!("{:.3} %", es / p.lift * 100.0),
                format!("{:.3} mm", es / mu_s),
                format!("{:.3} %", ev / vmax * 100.0),
                micros(time),
                mark(n == drawn),
            ]
        })
        .collect();
    Table {
        title: "The course's graphical integration by chords, divisions per phase".into(),
        header: vec!["divisions", "error of s, % of the lift", "on paper", "error of ds/dφ, % of its peak", "time", ""],
        rows,
        note: "The course prescribes 8 divisions a phase; where they leave the displacement more than 1 % of \
               the lift off the exact law, each division is integrated in more chords (the fewest that keep \
               it within 1 %, up to 4), and the sheet states the error beside the exact law."
            .into(),
    }
}

// ---- whole builds ----------------------------------------------------------------------

/// The process's peak resident memory, MiB, where the system reports it (Linux).
fn peak_memory_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn builds(p: &crate::project::Project, built: &[pipeline::Built], clock: Clock) -> Result<Table, String> {
    let mut rows = Vec::new();
    for b in built {
        let n = b.output.number;
        let svg = clock.time(|| pipeline::build(p, &[n]).map(|b| b.len()));
        let pdf = clock.time(|| pipeline::render(b, Format::Pdf).map(|b| b.len()));
        let png = clock.time(|| pipeline::render(b, Format::Png { dpi: 100.0 }).map(|b| b.len()));
        rows.push(vec![format!("sheet {n}"), millis(svg), millis(pdf), millis(png)]);
    }
    let formats = pipeline::formats(true, Some(100.0), None);
    let all = clock.time(|| pipeline::build(p, &[]).and_then(|b| pipeline::outputs(p, &b, &formats)).map(|f| f.len()));
    let svg_pdf = pipeline::formats(true, None, None);
    let no_png =
        clock.time(|| pipeline::build(p, &[]).and_then(|b| pipeline::outputs(p, &b, &svg_pdf)).map(|f| f.len()));
    rows.push(vec![
        "all three, every file (parallel)".into(),
        format!("{} with the PDF", millis(no_png)),
        "—".into(),
        format!("{} with the PNG", millis(all)),
    ]);
    let memory = peak_memory_mib().map_or("not reported by this system".into(), |m| format!("{m:.0} MiB"));
    Ok(Table {
        title: "Whole builds of the worked example".into(),
        header: vec!["", "scene + SVG", "PDF from the scene", "PNG at 100 dpi"],
        rows,
        note: format!("Peak memory of this whole benchmark: {memory}. Threads: {}.", rayon::current_num_threads()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_table_has_its_rows_and_marks_what_the_sheets_use() {
        let tables = run(Clock { budget: 0.0, min_samples: 1 }).unwrap();
        assert_eq!(tables.len(), 6);
        for t in &tables {
            assert!(!t.rows.is_empty() && t.rows.iter().all(|r| r.len() == t.header.len()), "{}", t.title);
            assert!(t.markdown().contains(&format!("### {}", t.title)));
        }
        for t in &tables[1..5] {
            assert_eq!(t.rows.iter().filter(|r| r.last().is_some_and(|c| c == "← drawn")).count(), 1, "{}", t.title);
        }
        // Newton converges: each step a dyad takes it closer, the closed form is exact.
        let residuals: Vec<f64> = tables[0].rows.iter().map(|r| r[2].parse().unwrap()).collect();
        assert!(residuals[0] < 1e-14 && residuals[1] > residuals[2] && residuals[2] > residuals[3], "{residuals:?}");
    }

    #[test]
    fn newton_converges_to_the_closed_form() {
        let p = pipeline::load(DEFAULT_PROJECT).unwrap();
        let m = &p.lever.unwrap().mechanism;
        let mut pts: Vec<Vec2> = m.solve(0.0).unwrap().points.iter().map(|k| k.p).collect();
        newton(m, 0.02, 4, &mut pts).unwrap();
        let exact = m.solve(0.02).unwrap();
        let worst = exact.points.iter().zip(&pts).map(|(k, q)| (k.p - *q).norm()).fold(0.0, f64::max);
        assert!(worst < 1e-12, "{worst}");
        assert!(residual(m, &pts) < 1e-12);
    }
}
