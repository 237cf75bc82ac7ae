//! Hostile cam input: a cam kilometres across (a tiny phase, a stroke in the wrong unit, an
//! allowed angle of a billionth of a degree, a custom law with a huge velocity peak) is
//! refused before anything is sampled, naming the field most responsible and its line, with
//! its numbers in significant digits; a custom law written to 6–8 significant digits is
//! accepted; a custom law's key is checked like every text that reaches the sheet; and random
//! input is either refused with a field or designs a cam under 1 km whose sheet stays small.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

use tmm_sheets::cams::size::{self, SIZE_MAX};
use tmm_sheets::num::math::Norm;
use tmm_sheets::pipeline;
use tmm_sheets::project::{self, Project, Refusal};

/// A translating follower with a given offset (the case the old bound did not cover); the
/// cam section starts on line 6, one key a line.
const BASE: &str = "project:
  title: \"Cam\"
  designation: \"MMN KL 09.00.00\"
  language: en

cam:
  follower: {translating: {stroke: 0.04, offset: 0}}
  roller: auto
  phases_deg: {rise: 120, far_dwell: 30, return: 90}
  law: sine
  pressure_angle_deg: 30
  sense: cw
";

/// BASE with each `(from, to)` replaced (every pattern must be there).
fn with(edits: &[(&str, &str)]) -> String {
    edits.iter().fold(BASE.to_string(), |text, (from, to)| {
        assert!(text.contains(from), "the test's pattern {from:?} is not in the text");
        text.replacen(from, to, 1)
    })
}

/// The 1-based line of `text` that contains `pattern`.
fn line_of(text: &str, pattern: &str) -> u64 {
    text.lines().position(|l| l.contains(pattern)).unwrap_or_else(|| panic!("{pattern:?} not in the text")) as u64 + 1
}

/// Loads `text`, expecting a refusal at `field` on the line holding `at`; returns the message.
fn refused_at(text: &str, field: &str, at: &str) -> String {
    match project::load(text) {
        Ok(p) => panic!("must be refused (r_min = {:?} m):\n{text}", p.cam.map(|c| c.design.centre.r_min)),
        Err(Refusal { line, path, cause, .. }) => {
            assert_eq!(path, field, "{cause}\n{text}");
            assert_eq!(line, line_of(text, at), "{field}: {cause}");
            cause
        }
    }
}

/// No number in a message is a long row of digits (4580.123456789, 300-digit decimals).
fn assert_short_numbers(message: &str) {
    let longest = message.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0);
    assert!(longest <= 6, "a number of {longest} digits: {message}");
}

/// A too-large cam's refusal: the field, its line, why, and numbers a reader can take in.
fn too_large(edits: &[(&str, &str)], field: &str, at: &str, says: &str) {
    let text = with(edits);
    let e = refused_at(&text, field, at);
    assert!(e.contains("too large to draw") && e.contains("m across") && e.contains(says), "{field}: {e}");
    assert_short_numbers(&e);
}

#[test]
fn a_given_offset_is_bounded_like_auto() {
    // 4 cm over a ten-thousandth of a degree: the old build allocated 6.5 GB and aborted.
    let tiny = "phases_deg: {rise: 0.0001, far_dwell: 30, return: 90}";
    too_large(&[("phases_deg: {rise: 120, far_dwell: 30, return: 90}", tiny)], "cam.phases_deg.rise", tiny, "0.0001°");
    // A thousandth of a degree on both phases: the old build wrote a 205 MB sheet (r_min 4.6 km).
    let both = "phases_deg: {rise: 0.001, return: 0.001}";
    too_large(&[("phases_deg: {rise: 120, far_dwell: 30, return: 90}", both)], "cam.phases_deg.rise", both, "ds/dφ");
    let stroke = "{translating: {stroke: 1.0e9, offset: 0}}";
    too_large(
        &[("{translating: {stroke: 0.04, offset: 0}}", stroke)],
        "cam.follower.translating.stroke",
        stroke,
        "1e9 m",
    );
    let angle = "pressure_angle_deg: 1.0e-9";
    too_large(&[("pressure_angle_deg: 30", angle)], "cam.pressure_angle_deg", angle, "1e-9°");
    let offset = "{translating: {stroke: 0.04, offset: 1.0e9}}";
    too_large(
        &[("{translating: {stroke: 0.04, offset: 0}}", offset)],
        "cam.follower.translating.offset",
        offset,
        "offset",
    );
    let auto = "{translating: {stroke: 0.04, offset: auto}}";
    let tiny = "phases_deg: {rise: 120, far_dwell: 30, return: 1.0e-6}";
    too_large(
        &[
            ("{translating: {stroke: 0.04, offset: 0}}", auto),
            ("phases_deg: {rise: 120, far_dwell: 30, return: 90}", tiny),
        ],
        "cam.phases_deg.return",
        tiny,
        "return",
    );
}

#[test]
fn a_per_phase_allowed_angle_is_named_by_its_phase() {
    let each = "pressure_angle_deg:\n    rise: 30\n    return: 1.0e-7";
    too_large(&[("pressure_angle_deg: 30", each)], "cam.pressure_angle_deg.return", "return: 1.0e-7", "1e-7°");
}

#[test]
fn a_rocker_is_bounded_by_its_length_its_phases_and_its_swing() {
    let rocker = |length: &str, swing: &str| format!("{{rocker: {{length: {length}, swing_deg: {swing}}}}}");
    let from = "{translating: {stroke: 0.04, offset: 0}}";
    let long = rocker("1.0e6", "25");
    too_large(&[(from, &long)], "cam.follower.rocker.length", &long, "1e6 m long");
    let normal = rocker("0.105", "25");
    let phases = "phases_deg: {rise: 70, return: 0.0002}";
    too_large(
        &[(from, &normal), ("phases_deg: {rise: 120, far_dwell: 30, return: 90}", phases)],
        "cam.phases_deg.return",
        phases,
        "l·dβ/dφ",
    );
    // Half the swing a hair below the allowed 30°: the wedges turn nearly onto their sides.
    let wide = rocker("0.105", "59.99999");
    too_large(&[(from, &wide)], "cam.follower.rocker.swing_deg", &wide, "leaves only");
}

#[test]
fn a_custom_law_with_a_huge_velocity_peak_is_named_at_the_law() {
    // A velocity spike 2⁻²⁰ wide, then rest: normalised to s(1) = 1 its peak is ~10⁶.
    let (a, b) = (2f64.powi(-20), 2f64.powi(-19));
    let laws = format!(
        "law: spike\n  laws:\n    spike:\n      acceleration: [[0, 1], [{a:e}, 1], [{a:e}, -1], [{b:e}, -1], [{b:e}, 0], [1, 0]]"
    );
    too_large(&[("law: sine", &laws)], "cam.law", "law: spike", "`spike`");
}

#[test]
fn the_bound_is_checked_before_the_region_is_sampled() {
    // Straight from the domain: the refusal names its cause without designing anything.
    use tmm_sheets::cams::follower::Follower;
    use tmm_sheets::cams::laws::{Program, Standard};
    use tmm_sheets::cams::radius::{Allowed, Phase, Placement};
    let p = Program::new(1e-9f64.to_radians(), 0.0, 1.0, (Standard::Sine, Standard::Sine), 0.04).unwrap();
    let a = Allowed { rise: 0.5, ret: 0.5 };
    let e = size::check(Follower::Translating, &p, a, Placement::Offset(0.0)).unwrap_err();
    assert_eq!(e.cause, size::Cause::Phase(Phase::Rise));
    assert!(e.size.reach > SIZE_MAX, "{e}");
    let message = e.to_string();
    assert!(message.contains("a rise of only 1e-9°"), "{message}");
    assert_short_numbers(&message);
}

// --- custom laws: the area balance's tolerance and its numbers -----------------------------

/// BASE with its return drawn by `corners` in the `laws` table (the rise stays sine).
fn two_rectangles(corners: &str) -> String {
    let laws = format!("law: {{rise: sine, return: steps}}\n  laws:\n    steps:\n      acceleration: {corners}");
    with(&[("law: sine", &laws)])
}

#[test]
fn a_law_written_to_8_or_6_significant_digits_is_accepted_and_drawn() {
    // −3/7 to 8 digits: the net area is −1e-9 of 0.6 (refused by the old tolerance of 1e-9).
    for corners in [
        "[[0, 1], [0.3, 1], [0.3, -0.42857143], [1, -0.42857143]]",
        "[[0, 1], [0.3, 1], [0.3, -0.428571], [1, -0.428571]]",
    ] {
        let text = two_rectangles(corners);
        let p: Project = project::load(&text).unwrap_or_else(|e| panic!("{corners}: {e}"));
        let built = pipeline::build(&p, &[3]).unwrap_or_else(|e| panic!("{corners}: {e:#}"));
        assert!(built[0].svg.contains("<svg"), "{corners}");
    }
    // The worst rounding of 6 digits: the net area is 5e-6 of the total.
    let worst = two_rectangles("[[0, 1.00001], [0.5, 1.00001], [0.5, -1], [1, -1]]");
    assert!(project::load(&worst).is_ok());
}

#[test]
fn an_imbalance_is_printed_in_significant_digits() {
    // −3/7 to 4 digits: the net area is −2e-5, 3.4e-5 of the total 0.6.
    let text = two_rectangles("[[0, 1], [0.3, 1], [0.3, -0.4286], [1, -0.4286]]");
    let e = refused_at(&text, "cam.laws.steps.acceleration", "acceleration:");
    assert!(e.contains("net area is -2e-5") && e.contains("total area 0.60002") && e.contains("-3.3e-5"), "{e}");
    assert!(!e.contains("0.000000") && !e.contains("-0.00002"), "{e}");
}

// --- the law's key and name reach the sheet: the font's check ------------------------------

#[test]
fn a_laws_key_the_font_cannot_print_is_refused_at_the_key() {
    let laws = "law: 漢字\n  laws:\n    漢字:\n      acceleration: [[0, 1], [0.5, 1], [0.5, -1], [1, -1]]";
    let text = with(&[("law: sine", laws)]);
    let e = refused_at(&text, "cam.laws.漢字", "漢字:");
    assert!(e.contains("U+6F22") && e.contains("font"), "{e}");
    // A key the font has, with a name it lacks: the name's field and line.
    let laws = "law: steps\n  laws:\n    steps:\n      name: \"漢字\"\n      acceleration: [[0, 1], [0.5, 1], [0.5, -1], [1, -1]]";
    let e = refused_at(&with(&[("law: sine", laws)]), "cam.laws.steps.name", "name:");
    assert!(e.contains("U+6F22"), "{e}");
}

// --- random input: refused with a field, or a cam under 1 km and a small sheet -------------

/// A small deterministic generator (xorshift64*), so that a failure is reproducible.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Log-uniform in [lo, hi].
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.unit())
    }

    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[((self.unit() * xs.len() as f64) as usize).min(xs.len() - 1)]
    }
}

/// One random cam section: phases of 0.001°–360° in total, strokes and rocker lengths of
/// 1e-6–1e9 m, allowed angles of 1e-9°–89°, every follower and roller kind.
fn random_project(rng: &mut Rng) -> String {
    let total = rng.log(1e-3, 360.0);
    let (r, d) = (rng.unit().max(1e-3), rng.unit() * 0.5);
    let rise = total * r / (1.0 + r + d);
    let (dwell, ret) = (total * d / (1.0 + r + d), total / (1.0 + r + d));
    let length = rng.log(1e-6, 1e9);
    let follower = match rng.pick(&["given", "auto", "rocker"]) {
        "given" => format!("{{translating: {{stroke: {length:e}, offset: {:e}}}}}", length * (rng.unit() - 0.5)),
        "auto" => format!("{{translating: {{stroke: {length:e}, offset: auto}}}}"),
        _ => format!("{{rocker: {{length: {length:e}, swing_deg: {:e}}}}}", 1.0 + rng.unit() * 88.0),
    };
    let angle = |rng: &mut Rng| rng.log(1e-9, 89.0);
    let allowed = if rng.unit() < 0.5 {
        format!("{:e}", angle(rng))
    } else {
        format!("{{rise: {:e}, return: {:e}}}", angle(rng), angle(rng))
    };
    let law = rng.pick(&["sine", "cosine", "1", "polynomial-345", "modified-sine"]);
    let roller = rng.pick(&["auto", "knife"]);
    format!(
        "project:\n  title: \"Cam\"\n  designation: \"X\"\n  language: en\n\ncam:\n  follower: {follower}\n  roller: {roller}\n  phases_deg: {{rise: {rise:e}, far_dwell: {dwell:e}, return: {ret:e}}}\n  law: {law}\n  pressure_angle_deg: {allowed}\n"
    )
}

/// Loads a random project: a refusal names a `cam` field; a design is under 1 km, within its
/// closed-form bound (the bound is sound), and is returned.
fn check_random(text: &str) -> Option<Project> {
    match project::load(text) {
        Err(Refusal { path, .. }) => {
            assert!(path.starts_with("cam"), "{path}:\n{text}");
            None
        }
        Ok(p) => {
            let d = &p.cam.as_ref().expect("a cam").design;
            let s = &d.spec;
            let b = size::bound(s.follower, &s.program, s.allowed, s.placement).expect("a designed cam has a bound");
            assert!(
                d.centre.r_min < SIZE_MAX && d.centre.r_min <= b.r_min * (1.0 + 1e-9),
                "{}:\n{text}",
                d.centre.r_min
            );
            let far = (0..360).map(|k| d.profile.pitch((k as f64).to_radians()).p.norm()).fold(0.0, f64::max);
            assert!(far <= b.reach * (1.0 + 1e-9), "{far} > {}:\n{text}", b.reach);
            Some(p)
        }
    }
}

/// A sheet that fell back to drawing a large cam at 1:1 (the old 1.5 GB) would be huge.
const SHEET_SVG_MAX: usize = 4 << 20;

#[test]
fn random_input_is_refused_with_a_field_or_designs_a_cam_under_a_kilometre() {
    let mut rng = Rng(0x5eed_cafe_f00d_0001);
    let mut built = 0;
    for _ in 0..300 {
        let text = random_project(&mut rng);
        if let Some(p) = check_random(&text)
            && built < 4
        {
            let b = pipeline::build(&p, &[3]).unwrap_or_else(|e| panic!("{e:#}:\n{text}"));
            assert!(b[0].svg.len() < SHEET_SVG_MAX, "{} bytes:\n{text}", b[0].svg.len());
            built += 1;
        }
    }
}

/// The near-limit cams of each follower: just under the bound, the sheet still finds a GOST
/// scale (at most 1:10 000) and stays small.
#[test]
fn cams_just_under_the_bound_draw_a_small_sheet() {
    for (follower, phases) in [
        ("{translating: {stroke: 0.0055, offset: 0}}", "{rise: 0.004, return: 0.004}"),
        ("{translating: {stroke: 0.005, offset: auto}}", "{rise: 0.002, return: 0.002}"),
        ("{rocker: {length: 0.1, swing_deg: 20}}", "{rise: 0.025, return: 0.025}"),
    ] {
        let text = with(&[
            ("{translating: {stroke: 0.04, offset: 0}}", follower),
            ("{rise: 120, far_dwell: 30, return: 90}", phases),
        ]);
        let p = check_random(&text).unwrap_or_else(|| panic!("must design: {}", project::load(&text).unwrap_err()));
        let r_min = p.cam.as_ref().unwrap().design.centre.r_min;
        assert!(r_min > 0.05 * SIZE_MAX, "not near the bound: {r_min} m");
        let b = pipeline::build(&p, &[3]).unwrap_or_else(|e| panic!("{e:#}"));
        assert!(b[0].svg.len() < SHEET_SVG_MAX, "{follower}: {} bytes", b[0].svg.len());
    }
}

/// The heavier sweep: more random projects, every design built to a sheet.
#[test]
#[ignore = "about two minutes at the test profile; run with --ignored"]
fn random_input_sweep() {
    let mut rng = Rng(0x0dd_ba11_2024);
    for _ in 0..3000 {
        let text = random_project(&mut rng);
        if let Some(p) = check_random(&text) {
            let b = pipeline::build(&p, &[3]).unwrap_or_else(|e| panic!("{e:#}:\n{text}"));
            assert!(b[0].svg.len() < SHEET_SVG_MAX, "{} bytes:\n{text}", b[0].svg.len());
        }
    }
}
