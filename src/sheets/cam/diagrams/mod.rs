//! The law's three diagrams as the course draws them, stacked: s(φ) on top, ds/dφ, then
//! d²s/dφ² at the bottom, over the working angle at μ_φ. The acceleration analog is the given
//! law; the velocity analog and the displacement are drawn as the chord integration builds them
//! (thick), each with its pole at H to the left of its origin and the rays to the mid-ordinates,
//! the exact curves thin over them. Every scale is written to the left of its graph.

mod axes;
mod plan;
mod pole;

use plan::velocity_range;
pub use plan::{Plan, Scales, plan, squeezed};

use super::labels::CamWords;
use crate::cams::Design;
use crate::cams::follower::Follower;
use crate::cams::integrate::Integrated;
use crate::cams::laws::Program;
use crate::drawing::fmt;
use crate::drawing::labels::Language;
use crate::drawing::phrases;
use crate::drawing::place::{Labels, label_size};
use crate::drawing::plot::{Axis, Plot};
use crate::drawing::scene::{Anchor, DASHED, Group, MAIN, THIN};
use crate::drawing::symbols::dimension;
use crate::drawing::text::LabelText;
use crate::num::tol;
use axes::{analog_ticks, axis_values, lift_ticks, ordinates, unlabelled};
use kurbo::{Point, Rect, Vec2};
use plan::peaks;
use pole::{Pole, SCALE_GAP, SCALE_TEXT, clear_of_rays, pole, scale_line, scale_text, top_ray};

/// What the diagrams measured.
pub struct Drawn {
    pub scales: Scales,
    /// The bottom of the last diagram, mm.
    pub bottom: f64,
}

/// Vertical room of one diagram besides its data: the title above, the axis values below.
const GAP: f64 = 14.0;
/// The most height added between two diagrams where their area is taller than their plan, mm.
const SPREAD_MAX: f64 = 20.0;

/// Draws the three diagrams of `plan` from the top left of `area`; the poles take the room
/// at its left.
pub fn draw(
    g: &mut Group,
    area: Rect,
    plan: &Plan,
    d: &Design,
    integrated: &[Integrated; 2],
    words: &CamWords,
) -> Drawn {
    let sc = plan.scales;
    let p = &d.spec.program;
    let (vmax, amax) = peaks(d);
    let rocker = matches!(d.spec.follower, Follower::Rocker { .. });
    let names = if rocker { ["β", "dβ/dφ", "d²β/dφ²"] } else { ["s", "ds/dφ", "d²s/dφ²"] };
    let stack = Stack {
        sc,
        p,
        integrated,
        // Room left of the poles for their names.
        x0: area.x0 + sc.h1.max(sc.h2) + POLE_NAME,
        left: area.x0,
        work: p.rise + p.far_dwell + p.ret,
        peaks: (vmax, amax),
        v_range: velocity_range(d),
        rocker,
        names,
        words,
    };
    let mut labels = Labels::new();
    let start = g.mark();
    // The height the area has beyond the plan's, shared between the diagrams (a band left
    // under the last read as a gap in the column).
    let spread = ((area.height() - plan.height) / 3.0).clamp(0.0, SPREAD_MAX);
    let top = stack.displacement(g, &mut labels, area.y0) + spread;
    g.part_from("diagram.s", start);
    let start = g.mark();
    let top = stack.velocity(g, top) + spread;
    g.part_from("diagram.v", start);
    let start = g.mark();
    let bottom = stack.acceleration(g, top);
    g.part_from("diagram.a", start);
    labels.place(g, area);
    Drawn { scales: sc, bottom }
}

/// What the three stacked diagrams share: the scales, the law, the integration, the x of
/// their origins and of the scales' texts, the working angle, the peaks of ds/dφ and
/// d²s/dφ², and the names of the quantities (β for a rocker).
struct Stack<'a> {
    sc: Scales,
    p: &'a Program,
    integrated: &'a [Integrated; 2],
    x0: f64,
    left: f64,
    work: f64,
    peaks: (f64, f64),
    /// The velocity analog's range, (lowest, highest).
    v_range: (f64, f64),
    rocker: bool,
    names: [&'static str; 3],
    words: &'a CamWords,
}

impl Stack<'_> {
    fn x_axis(&self) -> Axis {
        Axis {
            lo: 0.0,
            hi: self.work.to_degrees(),
            mu: self.sc.mu_phi_deg,
            name: "φ".into(),
            ticks: division_ticks(self.integrated),
        }
    }

    /// An exact curve over the working angle, four points a degree.
    fn exact(&self, f: &dyn Fn(f64) -> f64) -> Vec<(f64, f64)> {
        let work = self.work;
        let n = (work.to_degrees() * 4.0).ceil() as usize;
        (0..=n)
            .map(|k| {
                // Just inside the working angle at its end, where `at` belongs to the near dwell.
                let phi = (work * k as f64 / n as f64).min(work - tol::INSIDE_PHASE);
                (phi.to_degrees(), f(phi))
            })
            .collect()
    }

    /// An analog's axis name: a translating follower's in mm, as its tables give it (a
    /// rocker's has no unit).
    fn analog_name(&self, name: &str) -> String {
        if self.rocker { name.into() } else { format!("{name}, {}", self.words.common.unit_mm()) }
    }

    /// A translating follower's scales are all m/mm; a rocker's analogs have no unit.
    fn unit(&self) -> &str {
        if self.rocker { self.words.sheet.unit_per_mm() } else { self.words.common.unit_m_per_mm() }
    }

    /// s(φ): the lift above the axis, from `top`; returns the next diagram's top.
    fn displacement(&self, g: &mut Group, labels: &mut Labels, top: f64) -> f64 {
        let (sc, p, w) = (self.sc, self.p, self.words);
        let (l, lang) = (w.sheet, w.lang);
        let s_plot = Plot {
            origin: Point::new(self.x0, top + GAP + p.lift / sc.mu_s),
            x: self.x_axis(),
            y: Axis {
                lo: 0.0,
                hi: p.lift,
                mu: sc.mu_s,
                name: format!("{}, {}", self.names[0], if self.rocker { l.unit_deg() } else { w.common.unit_mm() }),
                ticks: lift_ticks(p.lift, sc.mu_s, self.rocker, lang),
            },
            x_above: None,
        };
        s_plot.draw_axes(g);
        s_plot.line(g, &self.exact(&|phi| p.at(phi).s), THIN);
        let s_drawn = integrated_curve(self.integrated, |i| &i.s);
        s_plot.line(g, &s_drawn, MAIN);
        ordinates(g, &s_plot, &at_positions(self.integrated, |i| &i.s));
        number_divisions(&s_plot, self.integrated, labels);
        phase_dimensions(g, &s_plot, p, labels, w);
        let lines = if self.rocker {
            let deg = format!("({} {})", fmt::trimmed(sc.mu_s.to_degrees(), lang), l.unit_deg_per_mm());
            vec![mu("β", sc.mu_s, l.unit_rad_per_mm(), lang), LabelText::new(deg, "")]
        } else {
            vec![mu("s", sc.mu_s, self.unit(), lang)]
        };
        // Beside the axis's values, not at the column's left edge: that room is the poles'
        // of the diagrams below, and this one has none (its μ stood 95 mm from its axis).
        // Its first line shares the top value's row: twice the poles' gap keeps them apart
        // («μ_β = 0,0075 рад/мм 20» read as one at 4 mm).
        let widest = lines.iter().map(|t| t.width(SCALE_TEXT)).fold(0.0, f64::max);
        let x = (s_plot.y_labels_left() - 2.0 * SCALE_GAP - widest).max(self.left);
        let at = Point::new(x, s_plot.origin.y - p.lift / sc.mu_s);
        scale_text(g, off_value_rows(at, &lines, &s_plot), &lines);
        s_plot.origin.y + PHASES + GAP
    }

    /// ds/dφ, both signs, with the displacement's pole: rays to the mean ordinates of the
    /// velocity's chords; returns the next diagram's top.
    fn velocity(&self, g: &mut Group, top: f64) -> f64 {
        let (sc, p, lang) = (self.sc, self.p, self.words.lang);
        let (vmax, name) = (self.peaks.0, self.names[1]);
        let (lo, hi) = self.v_range;
        let start = g.mark();
        let v_plot = Plot {
            origin: Point::new(self.x0, top + hi / sc.mu_ds + 4.0),
            x: self.x_axis(),
            y: Axis {
                lo,
                hi,
                mu: sc.mu_ds,
                name: self.analog_name(name),
                ticks: unlabelled(within(analog_ticks(vmax, sc.mu_ds, self.rocker, lang), (lo, hi))),
            },
            x_above: None,
        };
        v_plot.draw_axes(g);
        v_plot.line(g, &self.exact(&|phi| p.at(phi).ds), THIN);
        let v_drawn = integrated_curve(self.integrated, |i| &i.ds);
        v_plot.line(g, &v_drawn, MAIN);
        ordinates(g, &v_plot, &at_positions(self.integrated, |i| &i.ds));
        let means: Vec<f64> =
            self.integrated.iter().flat_map(|i| i.ds.windows(2).map(|w| (w[0] + w[1]) / 2.0)).collect();
        let lines = [mu(name, sc.mu_ds, self.unit(), lang)];
        let top = v_plot.origin.y - hi / sc.mu_ds;
        let (at, lines) =
            clear_of_rays(&lines, (self.left, top, v_plot.origin.y), top_ray(&v_plot, sc.h1, &means, sc.mu_ds));
        scale_text(g, at, &lines);
        let rays = pole(g, &v_plot, Pole { h: sc.h1, index: "1" }, &means, sc.mu_ds, self.words);
        axis_values(g, &v_plot, &within(analog_ticks(vmax, sc.mu_ds, self.rocker, lang), (lo, hi)), start, &rays);
        v_plot.origin.y - lo / sc.mu_ds + GAP
    }

    /// d²s/dφ²: the given law, with its mid-ordinates and its pole; returns the bottom.
    fn acceleration(&self, g: &mut Group, top: f64) -> f64 {
        let (sc, p, lang) = (self.sc, self.p, self.words.lang);
        let l = self.words.sheet;
        let (amax, name) = (self.peaks.1, self.names[2]);
        let start = g.mark();
        let a_plot = Plot {
            origin: Point::new(self.x0, top + amax / sc.mu_dds + 4.0),
            x: self.x_axis(),
            y: Axis {
                lo: -amax,
                hi: amax,
                mu: sc.mu_dds,
                name: self.analog_name(name),
                ticks: unlabelled(analog_ticks(amax, sc.mu_dds, self.rocker, lang)),
            },
            x_above: None,
        };
        a_plot.draw_axes(g);
        // From the axis and back to it: the near dwell's s″ = 0 on both sides of the working
        // angle (a law that starts or ends with a jump shows it).
        let mut a_exact = self.exact(&|phi| p.at(phi).dds);
        a_exact.insert(0, (0.0, 0.0));
        a_exact.push((self.work.to_degrees(), 0.0));
        a_plot.line(g, &a_exact, MAIN);
        for i in self.integrated {
            for (k, &a) in i.mid_dds.iter().enumerate() {
                let mid = (i.phi[k] + i.phi[k + 1]) / 2.0;
                g.line(a_plot.at(mid.to_degrees(), 0.0), a_plot.at(mid.to_degrees(), a), DASHED);
            }
        }
        // The radians as the degrees' gloss in brackets, as μ_β's degrees above.
        let phi_rad = LabelText::new(format!("({} {})", fmt::value(sc.mu_phi_rad, lang), l.unit_rad_per_mm()), "");
        let lines =
            [mu(name, sc.mu_dds, self.unit(), lang), mu("φ", sc.mu_phi_deg, l.unit_deg_per_mm(), lang), phi_rad];
        let mids: Vec<f64> = self.integrated.iter().flat_map(|i| i.mid_dds.iter().copied()).collect();
        let top = a_plot.origin.y - amax / sc.mu_dds;
        let (at, lines) =
            clear_of_rays(&lines, (self.left, top, a_plot.origin.y), top_ray(&a_plot, sc.h2, &mids, sc.mu_dds));
        scale_text(g, at, &lines);
        let rays = pole(g, &a_plot, Pole { h: sc.h2, index: "2" }, &mids, sc.mu_dds, self.words);
        axis_values(g, &a_plot, &analog_ticks(amax, sc.mu_dds, self.rocker, lang), start, &rays);
        a_plot.origin.y + amax / sc.mu_dds + GAP
    }
}

/// `at`, or lower by as little as keeps each of the scale `lines` off the rows of `plot`'s
/// y values where the column's edge holds it nearer them than a phrase's gap (a 12.8°
/// swing's «μ_β = 0,006 рад/мм» stood 2.4 mm before «12,5», on its row, read as one).
fn off_value_rows(at: Point, lines: &[LabelText], plot: &Plot) -> Point {
    let left = plot.y_labels_left();
    let rows: Vec<f64> = plot.y_value_baselines().collect();
    let near = |at: Point| {
        lines.iter().enumerate().any(|(k, t)| {
            let base = scale_line(at, k);
            let apart = left - (base.x + t.width(SCALE_TEXT)) >= phrases::APART * SCALE_TEXT;
            !apart && rows.iter().any(|&y| (y - base.y).abs() < ROW_CLEAR * SCALE_TEXT)
        })
    };
    (0..=16).map(|k| at + Vec2::new(0.0, 0.5 * f64::from(k))).find(|&p| !near(p)).unwrap_or(at)
}

/// A scale line this many heights above or below a value's row is on a row of its own (the
/// layout measure's one line is 0.4).
const ROW_CLEAR: f64 = 0.6;

/// The ticks within the range `(lo, hi)`.
fn within(ticks: Vec<(f64, String)>, (lo, hi): (f64, f64)) -> Vec<(f64, String)> {
    ticks.into_iter().filter(|(v, _)| *v >= lo * (1.0 + 1e-9) && *v <= hi * (1.0 + 1e-9)).collect()
}

/// The division points along the x axis; their numbers are placed as labels, clear of the
/// curves (the integrated displacement may end a little below the axis).
fn division_ticks(integrated: &[Integrated; 2]) -> Vec<(f64, String)> {
    integrated.iter().flat_map(|i| i.positions().map(|k| (i.phi[k].to_degrees(), String::new()))).collect()
}

/// Divisions closer than this on paper are not numbered one by one, mm: a 2.5 mm number
/// is ~1.6 mm wide, and a row of them touching reads as one number.
const NUMBERED_STEP_MM: f64 = 3.0;

/// The positions' numbers under the displacement's axis (0 at the start of the rise); a
/// phase whose divisions are closer than [`NUMBERED_STEP_MM`] (a 4° return beside a 300°
/// rise) has only its first and last position numbered — its dimension below names it.
fn number_divisions(plot: &Plot, integrated: &[Integrated; 2], labels: &mut Labels) {
    let phis: Vec<f64> = integrated.iter().flat_map(|i| i.positions().map(|k| i.phi[k])).collect();
    let numbered = integrated.iter().flat_map(|i| {
        let n = i.positions().count();
        let step = (i.phi[(n - 1).min(1) * i.chords] - i.phi[0]).to_degrees() / plot.x.mu;
        (0..n).map(move |k| step >= NUMBERED_STEP_MM || k == 0 || k + 1 == n)
    });
    for ((&phi, name), numbered) in phis.iter().zip(super::nomogram::position_labels(&phis)).zip(numbered) {
        if let (Some(name), true) = (name, numbered) {
            labels.add_text(
                plot.at(phi.to_degrees(), 0.0) + kurbo::Vec2::new(0.0, 1.5),
                kurbo::Vec2::new(0.0, 1.0),
                &name,
                2.5,
            );
        }
    }
}

/// Under the displacement's axis: the position numbers, then the phases' dimensions, then the
/// working angle's, mm below the axis.
const NUMBERS: f64 = 5.5;
const PHASE_ROW: f64 = 12.5;
/// Low enough that a short phase's value on its shelf (see [`SHELF_DROP`]) stands clear above
/// the working angle's.
const WORK_ROW: f64 = 26.5;
/// The room the phases' dimensions add under the displacement, mm.
const PHASES: f64 = 18.5;
/// How far below its dimension line a short phase's value stands on its leader's shelf, mm.
const SHELF_DROP: f64 = 7.0;

/// The phase angles as the course dimensions them under the displacement's axis (rise, far
/// dwell, return), and the working angle under those; extension lines start below the
/// position numbers that stand at the phases' ends.
fn phase_dimensions(g: &mut Group, plot: &Plot, p: &Program, labels: &mut Labels, words: &CamWords) {
    let (l, lang) = (words.sheet, words.lang);
    let (rise, dwell, work) = (p.rise, p.rise + p.far_dwell, p.rise + p.far_dwell + p.ret);
    let rows = [
        (0.0, rise, l.sub_rise(), PHASE_ROW),
        (rise, dwell, l.sub_far_dwell(), PHASE_ROW),
        (dwell, work, l.sub_return(), PHASE_ROW),
        (0.0, work, l.sub_working_angle(), WORK_ROW),
    ];
    let below = Vec2::new(0.0, NUMBERS);
    // The shelves so far (x from, x to), and how far a shelf may reach: from the
    // axis' origin less the room under its scale to the axis' arrow.
    let mut shelved: Vec<(f64, f64)> = Vec::new();
    let (left, right) = (plot.origin.x - POLE_NAME, plot.at(work.to_degrees(), 0.0).x + RIGHT_ROOM);
    for (a, b, sub, row) in rows {
        if b - a <= 0.0 {
            continue;
        }
        let (pa, pb) = (plot.at(a.to_degrees(), 0.0) + below, plot.at(b.to_degrees(), 0.0) + below);
        let mid = dimension(g, pa, pb, Vec2::new(0.0, row - NUMBERS));
        let text = LabelText::new("φ", sub).with_tail(format!(" = {}°", fmt::trimmed((b - a).to_degrees(), lang)));
        let (w, _, depth) = label_size(&text, 2.5);
        // Too short to write between its extension lines, and a value written under the line
        // would read as the working angle's: on a leader's shelf (GOST 2.307), towards the
        // axis' middle, else the other way, clear of the other shelves' values.
        let short = w + 2.0 > pb.x - pa.x && row == PHASE_ROW;
        let inward = if mid.x > (left + right) / 2.0 { -1.0 } else { 1.0 };
        let reach = |side: f64| side * ((pb.x - pa.x) / 2.0 + 2.0);
        let spot = short.then(|| {
            [inward, -inward].into_iter().map(reach).map(|r| (r, shelf_span(mid.x, r, w))).find(|&(_, (x0, x1))| {
                x0 >= left && x1 <= right && shelved.iter().all(|&(a, b)| x1 + 1.5 < a || x0 > b + 1.5)
            })
        });
        match spot.flatten() {
            Some((r, span)) => {
                shelved.push(span);
                shelf(g, mid, r, text, (w, depth));
            }
            None => labels.add(mid, Vec2::new(0.0, -1.0), text, 2.5),
        }
    }
}

/// Room right of the displacement's axis end that a shelf may take, mm (its arrow and "φ"
/// stand above the axis).
const RIGHT_ROOM: f64 = 10.0;

/// What a shelf takes across (x from, x to), its leader and its value, when the leader starts
/// at `x` and runs `reach` across (see [`shelf`]) and the value is `w` wide.
fn shelf_span(x: f64, reach: f64, w: f64) -> (f64, f64) {
    let far = x + reach + reach.signum() * (0.5 + w);
    (x.min(far), x.max(far))
}

/// A value on a leader's shelf below `from` (a dimension line's middle): the leader runs `reach`
/// across (negative: to the left; past the extension line), the shelf on to that side as long
/// as the value is wide, its subscript clear of it (`size`: the value's width and depth below
/// its baseline).
fn shelf(g: &mut Group, from: Point, reach: f64, text: LabelText, (w, depth): (f64, f64)) {
    let side = reach.signum();
    let knee = from + Vec2::new(reach, SHELF_DROP);
    let end = knee + Vec2::new(side * (w + 1.0), 0.0);
    g.line(from, knee, THIN);
    g.line(knee, end, THIN);
    let anchor = if side < 0.0 { Anchor::End } else { Anchor::Start };
    text.draw(g, Point::new(knee.x + side * 0.5, knee.y - depth - 0.5), 2.5, anchor);
}

/// "μ_q = value unit", with q as a subscript.
fn mu(q: &str, value: f64, unit: &str, lang: Language) -> LabelText {
    LabelText::new("μ", q).with_tail(format!(" = {} {unit}", fmt::trimmed(value, lang)))
}

/// Room left of a pole for its name, mm.
const POLE_NAME: f64 = 26.0;

/// An integrated quantity over the working angle: the rise's division points, the dwell,
/// the return's.
fn integrated_curve(integrated: &[Integrated; 2], f: impl Fn(&Integrated) -> &Vec<f64>) -> Vec<(f64, f64)> {
    integrated.iter().flat_map(|i| i.phi.iter().zip(f(i)).map(|(&p, &v)| (p.to_degrees(), v))).collect()
}

/// [`integrated_curve`] at the positions only (a division integrated in several chords has
/// its ends' ordinates drawn, as the course measures them).
fn at_positions(integrated: &[Integrated; 2], f: impl Fn(&Integrated) -> &Vec<f64>) -> Vec<(f64, f64)> {
    integrated
        .iter()
        .flat_map(|i| {
            let values = f(i);
            i.positions().map(move |k| (i.phi[k].to_degrees(), values[k]))
        })
        .collect()
}

/// The integration's error on this sheet, in percent of the lift (s) and of the largest
/// |ds/dφ|, over both phases.
pub fn error_percent(d: &Design, integrated: &[Integrated; 2]) -> (f64, f64) {
    let (vmax, _) = peaks(d);
    let e = integrated
        .iter()
        .map(|i| i.error(&d.spec.program))
        .fold((0.0f64, 0.0f64), |m, e| (m.0.max(e.s), m.1.max(e.ds)));
    (e.0 / d.spec.program.lift * 100.0, e.1 / vmax * 100.0)
}
