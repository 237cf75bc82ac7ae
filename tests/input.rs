//! Input semantics a student trips on: ω1 in 1/s, `q` on a link with three joints, an
//! output with more than two extreme positions per turn.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::fixture_text;
use tmm_sheets::pipeline;

/// Loads `text` and builds its sheets, expecting a refusal; returns its message.
fn refusal(text: &str) -> String {
    let result = pipeline::load(text).and_then(|p| pipeline::build(&p, &[]).map(|_| ()));
    format!("{:#}", anyhow::Error::from(result.expect_err("the input must be refused")))
}

fn omega1(text: &str) -> f64 {
    let p = pipeline::load(text).expect("loads");
    p.lever.as_ref().expect("a mechanism").mechanism.omega1
}

#[test]
fn omega_in_per_second_is_the_same_crank_as_rpm() {
    let text = fixture_text("worked-example");
    // n = 70 rev/min is ω = 70·π/30 = 7.330 1/s, clockwise (negative).
    let by_omega = text.replace("rpm: 70", "omega: 7.330382858376184");
    assert!((omega1(&text) - omega1(&by_omega)).abs() < 1e-12);
    assert!((omega1(&by_omega) + 70.0 * std::f64::consts::PI / 30.0).abs() < 1e-12);
    let both = text.replace("rpm: 70", "rpm: 70, omega: 7.33");
    let e = refusal(&both);
    assert!(e.contains("once") && e.contains("line 18"), "{e}");
    let neither = text.replace("rpm: 70, ", "");
    let e = refusal(&neither);
    assert!(e.contains("`rpm` (rev/min) or `omega` (1/s)") && e.contains("line 18"), "{e}");
}

/// The jaw crusher with the second rod pinned at E on link 3, beyond B (O2E = 1.2·O2B):
/// link 3 then has three joints, and q·l takes O2E = 0.48 m, not O2B = 0.40 m.
#[test]
fn q_takes_the_full_length_of_a_link_with_three_joints_and_says_which() {
    let text = fixture_text("jaw-crusher")
        .replace("joints: [B, O3], point: C", "joints: [E, O3], point: C")
        .replacen("  points:\n", "  points:\n    - {name: E, link: 3, from: O2, toward: B, ratio: 1.2}\n", 1)
        .replace("from: B, toward: C, ratio: 0.5", "from: E, toward: C, ratio: 0.5");
    let p = pipeline::load(&text).expect("loads");
    let lever = p.lever.as_ref().unwrap();
    let m3 = lever.forces.as_ref().unwrap().masses.iter().find(|m| lever.mechanism.links[m.link].number == 3).unwrap();
    let l = 1.2 * 0.40;
    assert!((m3.mass - 20.0 * l).abs() < 1e-12, "m3 = {}", m3.mass);
    assert!((m3.j - 20.0 * l * l * l / 12.0).abs() < 1e-12, "J3 = {}", m3.j);
    let w: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
    assert!(w.iter().any(|w| w.contains("link 3 has 3 joints") && w.contains("O2E = 0.4800 m")), "{w:?}");
    // A two-joint link is not mentioned.
    assert!(!w.iter().any(|w| w.contains("link 2 has")), "{w:?}");
}

/// A rocker swinging through the vertical drives a slider on a vertical guide through the
/// rocker's pivot: the slider rises and falls twice per swing, four extremes per turn.
#[test]
fn an_output_with_four_extreme_positions_per_turn_is_warned_about_with_its_angles() {
    let text = r#"
project: {title: "Four extremes"}
mechanism:
  frame:
    - {name: O, at: [0.15, 0.1]}
    - {name: O1, at: [0, 0]}
  crank: {pivot: O, pin: A, length: 0.03, omega: 20, sense: ccw}
  groups:
    - rrr: {links: [2, 3], joints: [A, O1], point: B, lengths: [0.15, 0.1], branch: right}
    - rrp: {links: [4, 5], joint: B, point: D, length: 0.12, guide: {through: [0, 0], angle_deg: 90}, branch: forward}
  output_point: D
"#;
    let p = pipeline::load(text).expect("loads");
    let built = pipeline::build(&p, &[]).expect("builds");
    let d = &built[0].output.diagnostics;
    assert!(
        d.iter().any(|d| d.contains("4 extreme positions per crank turn") && d.matches("θ = ").count() == 4),
        "{d:?}"
    );
    // The usual crank-slider says nothing of the kind.
    let usual = pipeline::build(&common::fixture("crank-slider-axial"), &[]).expect("builds");
    assert!(!usual[0].output.diagnostics.iter().any(|d| d.contains("extreme positions")));
}

/// Every warning and refusal of `text`, as printed.
fn messages(text: &str) -> Vec<String> {
    match tmm_sheets::project::load_sections(text) {
        Ok((p, refused)) => {
            p.warnings.iter().map(|w| w.to_string()).chain(refused.iter().map(|r| r.to_string())).collect()
        }
        Err(r) => vec![r.to_string()],
    }
}

/// The longest run of digits in `s`.
fn longest_digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0)
}

/// A hostile length (10⁻³⁰⁰ m, or 10⁻⁹ m written with its last bit) is printed short in every
/// message about it, in metres and in millimetres (not as hundreds of digits, nor as
/// 0.0000010000000000000002 mm), and no message prints a negative zero.
#[test]
fn hostile_tiny_lengths_print_as_short_numbers() {
    let lever = fixture_text("worked-example");
    let translating = fixture_text("cams/translating-offset-auto");
    let rocker = fixture_text("cams/knife-rocker");
    let mut cases = Vec::new();
    for tiny in ["1e-300", "1.0000000000000002e-9"] {
        cases.push(lever.replace("length: 0.12, rpm: 70", &format!("length: {tiny}, rpm: 70")));
        cases.push(lever.replace("lengths: [0.46, 0.39]", &format!("lengths: [{tiny}, 0.39]")));
        cases.push(translating.replace("stroke: 0.04, offset: auto", &format!("stroke: {tiny}, offset: auto")));
        cases.push(translating.replace("stroke: 0.04, offset: auto", &format!("stroke: 0.04, offset: {tiny}")));
        cases.push(translating.replace("roller: 0.008", &format!("roller: {tiny}")));
        cases.push(rocker.replace("length: 0.12, swing_deg: 20", &format!("length: {tiny}, swing_deg: 20")));
    }
    for text in &cases {
        assert_ne!(text, &lever, "the substitution must change the file");
        let all = messages(text);
        assert!(!all.is_empty(), "a hostile length gives a warning or a refusal:\n{text}");
        for m in all {
            assert!(longest_digit_run(&m) <= 8, "a number of more than 8 digits in: {m}");
            assert!(!m.contains("-0"), "a negative zero in: {m}");
        }
    }
}
