//! Every kind of bad input gets an error that names the input and the reason — with line
//! and column for the project file — and never a panic or a NaN.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture_text, root};
use tmm_sheets::pipeline;

fn example() -> String {
    std::fs::read_to_string(root().join("fixtures/worked-example.yaml")).unwrap()
}

/// Builds sheet 1 of the example with `from` replaced by `to`; returns the error text.
fn error_of(from: &str, to: &str) -> String {
    let text = example();
    assert!(text.contains(from), "the test's pattern {from:?} is not in the example");
    refusal(&text.replacen(from, to, 1))
}

/// Loads `text` and builds sheet 1, expecting a refusal; returns its message.
fn refusal(text: &str) -> String {
    let result = pipeline::load(text).and_then(|p| pipeline::build(&p, &[]).map(|_| ()));
    format!("{:#}", anyhow::Error::from(result.expect_err("the input must be refused")))
}

fn line_of(pattern: &str) -> usize {
    example().lines().position(|l| l.contains(pattern)).unwrap() + 1
}

#[test]
fn misspelt_key_names_line_column_and_the_expected_keys() {
    let e = error_of("rpm: 70", "rmp: 70");
    assert!(e.contains(&format!("line {}, column", line_of("rpm: 70"))), "{e}");
    assert!(e.contains("unknown key `rmp`: did you mean `rpm`?") && e.contains("mechanism.crank.rmp"), "{e}");
}

#[test]
fn missing_value_is_named() {
    let e = error_of("rpm: 70, ", "");
    assert!(
        e.contains("`rpm` (rev/min) or `omega` (1/s)") && e.contains(&format!("line {}", line_of("rpm: 70"))),
        "{e}"
    );
}

#[test]
fn negative_zero_and_nan_lengths_are_refused_where_written() {
    for bad in ["-0.12", "0", ".nan", ".inf"] {
        let e = error_of("length: 0.12,", &format!("length: {bad},"));
        assert!(e.contains("expected a positive number") || e.contains("is not a finite number"), "{bad}: {e}");
        assert!(e.contains(&format!("line {}, column 37: mechanism.crank.length", line_of("rpm: 70"))), "{bad}: {e}");
    }
}

#[test]
fn text_where_a_number_belongs() {
    let e = error_of("length: 0.12,", "length: abc,");
    assert!(e.contains("mechanism.crank.length: expected a number") && e.contains("line"), "{e}");
}

#[test]
fn unknown_enumeration_value_lists_the_choices() {
    let e = error_of("branch: left", "branch: up");
    assert!(e.contains("unknown value `up`") && e.contains("`left`, `right`"), "{e}");
}

#[test]
fn reference_to_an_unknown_point_names_it_and_its_place() {
    let e = error_of("joints: [A, C]", "joints: [A, Q]");
    assert!(e.contains("unknown point 'Q'") && e.contains("mechanism.groups[0].rrr.joints[1]"), "{e}");
    assert!(e.contains(&format!("line {}, column", line_of("joints: [A, C]"))), "{e}");
}

#[test]
fn point_defined_twice() {
    let e = error_of("point: D,", "point: B,");
    assert!(e.contains("point 'B' is defined twice"), "{e}");
}

#[test]
fn link_used_twice_and_link_zero() {
    assert!(error_of("links: [4, 5]", "links: [3, 5]").contains("link 3 is used twice"));
    assert!(error_of("links: [4, 5]", "links: [0, 5]").contains("link 0 is the frame"));
}

#[test]
fn crank_about_a_moving_point() {
    let e = refusal(&example().replacen("pivot: O, pin: A", "pivot: A, pin: A1", 1));
    assert!(e.contains("unknown point 'A'"), "{e}");
}

#[test]
fn mechanism_that_cannot_be_assembled_names_group_angles_and_lengths() {
    let e = error_of("lengths: [0.46, 0.39]", "lengths: [0.16, 0.19]");
    assert!(e.contains("Assur group 1 (RRR, links 2 and 3"), "{e}");
    assert!(e.contains(&format!("line {}", line_of("lengths: [0.46, 0.39]"))), "{e}");
    assert!(e.contains("cannot be assembled for absolute crank angles θ from "), "{e}");
    assert!(e.contains("as the crank turns clockwise"), "{e}");
    assert!(e.contains("the joints are 0.3509 m apart, the links reach only 0.03…0.35 m"), "{e}");
}

#[test]
fn rod_too_short_for_its_guide() {
    let e = error_of("through: [0.0, 0.06]", "through: [0.0, -2.0]");
    assert!(e.contains("Assur group 2 (RRP, links 4 and 5") && e.contains("cannot be assembled"), "{e}");
}

#[test]
fn wrong_number_of_positions_and_bad_plan_positions() {
    assert!(error_of("positions: 8", "positions: 10").contains("8 or 12 crank positions, not 10"));
    let e = error_of("acceleration_plans: [1, 3, 5, 7]", "acceleration_plans: [1, 3, 9]");
    assert!(e.contains("position 9 does not exist: positions are 0…7"), "{e}");
    let e = error_of("acceleration_plans: [1, 3, 5, 7]", "acceleration_plans: [1, 1]");
    assert!(e.contains("listed twice"), "{e}");
    let e = error_of("acceleration_plans: [1, 3, 5, 7]", "acceleration_plans: [0, 1, 2, 3, 4, 5, 6]");
    assert!(e.contains("1 to 6 positions"), "{e}");
}

#[test]
fn assigned_angle_outside_a_turn() {
    let e = error_of("assigned_deg: 45", "assigned_deg: 400");
    assert!(e.contains("φ1 must lie in 0…360°, got 400°"), "{e}");
}

#[test]
fn attached_point_errors() {
    let e = error_of(
        "{name: S2, link: 2, from: A, toward: B, ratio: 0.5,",
        "{name: S2, link: 2, from: A, toward: B, ratio: 0.5, distance: 0.1,",
    );
    assert!(e.contains("exactly one of `ratio` and `distance`"), "{e}");
    let e = error_of("{name: S2, link: 2, from: A,", "{name: S2, link: 9, from: A,");
    assert!(e.contains("link 9 is not formed"), "{e}");
    let e = error_of("{name: S3, link: 3, from: C,", "{name: S3, link: 3, from: A,");
    assert!(e.contains("point 'A' is not on link 3"), "{e}");
}

#[test]
fn output_point_must_be_a_slider() {
    let e = refusal(&example().replacen("  points:\n", "  output_point: B\n  points:\n", 1));
    assert!(e.contains("'B' is not a slider point"), "{e}");
}

#[test]
fn broken_yaml() {
    let e = refusal("project: [\n");
    assert!(e.contains("line 1, column 10") && e.contains("YAML syntax"), "{e}");
    let e = refusal("");
    assert!(!e.is_empty());
}

/// A kulisa whose crank circle passes through the kulisa's pivot: the block would slide
/// over the pivot, where the kulisa's angle is undefined.
#[test]
fn kulisa_block_through_its_pivot_is_an_error_not_nan() {
    let e = refusal(&fixture_text("kulisa").replace("at: [0, -0.8]", "at: [0, -0.4]"));
    assert!(e.contains("Assur group 1 (RPR") && (e.contains("kulisa pivot") || e.contains("dead point")), "{e}");
}

/// A four-bar whose links can all fall into one line (s + l = p + q) passes a change
/// point where its velocities are unbounded: an explicit error, never NaN.
#[test]
fn change_point_four_bar_is_reported() {
    let e = refusal(&fixture_text("four-bar").replace("lengths: [0.18, 0.15]", "lengths: [0.20, 0.05]"));
    assert!(e.contains("Assur group 1 (RRR, links 2 and 3, line 13) passes through a dead point"), "{e}");
}

/// Approaching the change point (rocker 0.05 m, where s + l = p + q) from the Grashof side:
/// every sheet is finite, or the refusal says why; never a panic or NaN.
#[test]
fn near_singular_four_bars_are_finite_or_refused() {
    let base = fixture_text("four-bar");
    for delta in [1e-2, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 0.0] {
        let text = base.replace("lengths: [0.18, 0.15]", &format!("lengths: [0.20, {:.15}]", 0.05 + delta));
        let built = pipeline::load(&text).and_then(|p| pipeline::build(&p, &[]).map(|b| (p, b)));
        match built {
            Ok((p, b)) => {
                assert!(!b[0].svg.contains("NaN") && !b[0].svg.contains("inf"), "δ = {delta}");
                for p in &common::build_lever(&p).kinematics.positions {
                    assert!(p.state.points.iter().all(|k| k.v.is_finite() && k.a.is_finite()), "δ = {delta}");
                }
            }
            Err(e) => {
                let e = format!("{:#}", anyhow::Error::from(e));
                assert!(
                    e.contains("dead point") || e.contains("cannot be assembled") || e.contains("not finite"),
                    "δ = {delta}: {e}"
                );
            }
        }
    }
}

#[test]
fn force_analysis_without_a_mass_names_the_links() {
    let e = error_of("    - {link: 4, mass: 85, inertia: 36}\n", "");
    assert!(
        e.contains("forces.links")
            && e.contains("no mass for link(s) 4")
            && e.contains(&format!("line {}", line_of("forces:") + 1)),
        "{e}"
    );
    let e = error_of("{link: 3, mass: 25, inertia: 1.1}", "{link: 3, inertia: 1.1}");
    assert!(
        e.contains("link 3 needs `mass` (kg) or `q` (kg/m)")
            && e.contains(&format!("line {}", line_of("link: 3, mass: 25"))),
        "{e}"
    );
    let e = error_of("{link: 3, mass: 25, inertia: 1.1}", "{link: 3, mass: 25, q: 20}");
    assert!(e.contains("either `mass` or `q`"), "{e}");
    let e = error_of("{link: 5, mass: 500}", "{link: 5, q: 20}");
    assert!(e.contains("link 5 has no fixed length"), "{e}");
    let e = error_of("{link: 5, mass: 500}", "{link: 7, mass: 500}");
    assert!(e.contains("there is no link 7"), "{e}");
}

#[test]
fn moment_of_inertia_must_be_a_number_or_rod() {
    let e = error_of("inertia: 0.5}", "inertia: stick}");
    assert!(
        e.contains("expected a number or `rod`") && e.contains(&format!("line {}", line_of("inertia: 0.5"))),
        "{e}"
    );
    let e = error_of("inertia: 0.5}", "inertia: -1}");
    assert!(e.contains("moment of inertia from 0 to 1e9 kg·m²"), "{e}");
}

#[test]
fn indicator_table_must_be_monotone_in_stroke() {
    let load = "resistance: {point: D, working: forward, force: 4600, idle_force: 1650}";
    let e = error_of(
        load,
        "resistance: {point: D, working: forward, force: 4600, diagram: [[0, 0], [0.6, 1], [0.5, 1], [1, 0.2]]}",
    );
    assert!(
        e.contains("forces.loads[0].resistance.diagram")
            && e.contains("must increase: row 3 (0.5) does not come after row 2 (0.6)"),
        "{e}"
    );
    assert!(e.contains(&format!("line {}", line_of(load))), "{e}");
    let e = error_of(load, "resistance: {point: D, working: forward, force: 4600, diagram: [[0.1, 0], [1, 1]]}");
    assert!(e.contains("from 0 to 1"), "{e}");
    let gas = "gas: {point: D, force: 1000, indicator: table, table: {toward_head: [[0, 1], [1, 1]], away_from_head: [[0, 1], [1, 1], [0.9, 0]]}}";
    let e = error_of(load, gas);
    assert!(e.contains("table.away_from_head") && e.contains("must increase"), "{e}");
}

#[test]
fn gas_and_resistance_loads_are_checked() {
    let load = "resistance: {point: D, working: forward, force: 4600, idle_force: 1650}";
    let e = error_of(load, "resistance: {point: B, working: forward, force: 4600}");
    assert!(e.contains("'B' is not the slider point of an RRP group"), "{e}");
    let e = error_of(load, "gas: {point: D, bore: 0.1, indicator: engine}");
    assert!(e.contains("give either `force` (N), or `bore` (m) and `pressure` (Pa)"), "{e}");
    let e = error_of(load, "gas: {point: D, force: 100, indicator: engine, revolution: 3}");
    assert!(e.contains("revolutions 1 and 2, not 3"), "{e}");
    let e = error_of(load, "gas: {point: D, force: 100, indicator: table}");
    assert!(e.contains("`indicator: table` needs `table`"), "{e}");
    let e = error_of(load, "gas: {point: D, force: 100, indicator: compressor-stage-3}");
    assert!(e.contains("unknown value `compressor-stage-3`") && e.contains("compressor-stage-1"), "{e}");
    let e = error_of("idle_force: 1650", "idel_force: 1650");
    assert!(e.contains("unknown key `idel_force`") && e.contains(&format!("line {}", line_of("idle_force"))), "{e}");
}

/// A four-bar whose coupler and rocker together fall short of the farthest crank-pin
/// distance by δ = 5·10⁻⁸ m: it locks up over ≈ 0.18° of crank angle, centred between two
/// of the assembly scan's 0.5° samples. The refinement must find it.
#[test]
fn a_lock_up_window_narrower_than_the_scan_step_is_found() {
    let (r, g, delta) = (0.05_f64, 0.20_f64, 5e-8_f64);
    let centre = 180.25_f64; // the crank pin is farthest from O1 at θ = 180.25°, between samples
    let dir = (centre - 180.0).to_radians();
    let l_ab = 0.15;
    let l_bc = r + g - delta - l_ab;
    // The half-width ψ of the window from d² = r² + g² + 2rg·cos ψ = (r + g − δ)², ψ from θ = 180.25°.
    let half = (((r + g - delta).powi(2) - r * r - g * g) / (2.0 * r * g)).acos().to_degrees();
    assert!(half < 0.25, "the window ({half}° each side) fits between samples");
    let text = format!(
        "project: {{title: t}}
mechanism:
  frame: [{{name: O, at: [0, 0]}}, {{name: O1, at: [{:.17}, {:.17}]}}]
  crank: {{pivot: O, pin: A, length: {r}, rpm: 60, sense: ccw}}
  groups:
    - rrr: {{links: [2, 3], joints: [A, O1], point: B, lengths: [{l_ab}, {l_bc:.17}], branch: left}}
",
        g * dir.cos(),
        g * dir.sin()
    );
    let e = refusal(&text);
    assert!(
        e.contains("Assur group 1 (RRR") && e.contains("cannot be assembled for absolute crank angles θ from"),
        "{e}"
    );
    let nums: Vec<f64> = e
        .split("θ from ")
        .nth(1)
        .unwrap()
        .split(" as the crank")
        .next()
        .unwrap()
        .split(" to ")
        .map(|x| x.trim_end_matches('°').parse().unwrap())
        .collect();
    assert!(
        (nums[0] - (centre - half)).abs() < 0.01 && (nums[1] - (centre + half)).abs() < 0.01,
        "{e} (expected {:.2}…{:.2})",
        centre - half,
        centre + half
    );
}

/// A load on a slider that never moves (its rod's crank pin is on the crank's axis): its
/// place in the stroke is undefined, and the refusal names the load's line.
#[test]
fn a_load_on_a_slider_without_stroke_is_refused_with_its_line() {
    let text = fixture_text("two-cylinder-compressor");
    let text = text.replace(
        "{name: D, link: 1, from: O, toward: A, distance: 0.06, angle_deg: 180}",
        "{name: D, link: 1, from: O, toward: A, distance: 0, angle_deg: 180}",
    );
    let line = text.lines().position(|l| l.contains("gas: {point: E")).unwrap() + 1;
    let e = refusal(&text);
    assert!(e.contains("slider E") && e.contains(&format!("line {line}")) && e.contains("does not move"), "{e}");
}

#[test]
fn numbers_too_large_to_compute_with_are_refused_where_written() {
    let e = error_of("{link: 5, mass: 500}", "{link: 5, mass: 1.0e300}");
    assert!(e.contains("too large") && e.contains(&format!("line {}", line_of("{link: 5, mass: 500}"))), "{e}");
    let e = error_of("inertia: 0.5}", "inertia: 1.0e300}");
    assert!(e.contains("moment of inertia from 0 to 1e9"), "{e}");
}

/// Valid but almost surely wrong input builds with a warning that names the field and line.
#[test]
fn implausible_input_is_warned_about() {
    // Without the gears: their stage's ratio follows from the crank's speed, which this makes absurd.
    let lever_only = example().split("\ngears:").next().unwrap().to_string();
    let p =
        pipeline::load(&lever_only.replacen("length: 0.12,", "length: 120,", 1).replacen("rpm: 70,", "rpm: 2.0e5,", 1));
    let w: Vec<String> = p.unwrap().warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        w.iter().any(|w| w.contains("mechanism.crank.length")
            && w.contains("millimetres")
            && w.contains(&format!("line {}", line_of("rpm: 70")))),
        "{w:?}"
    );
    assert!(w.iter().any(|w| w.contains("mechanism.crank.rpm")), "{w:?}");
    let tiny = pipeline::load(&example().replacen("length: 0.12,", "length: 1.0e-9,", 1)).unwrap();
    assert!(tiny.warnings.iter().any(|w| w.message.contains("shorter than 1 mm")), "{:?}", tiny.warnings);
    assert!(pipeline::load(&example()).unwrap().warnings.is_empty());
}

#[test]
fn a_mechanism_that_never_assembles_says_so() {
    let e = refusal(&fixture_text("four-bar").replace("lengths: [0.18, 0.15]", "lengths: [0.01, 0.01]"));
    assert!(e.contains("Assur group 1 (RRR, links 2 and 3, line 13) cannot be assembled at any crank angle"), "{e}");
}

/// With position 0 fixed by `start_deg`, the course angle φ is known and named beside θ.
#[test]
fn assembly_errors_name_the_course_angle_when_position_0_is_fixed() {
    let text = fixture_text("four-bar")
        .replace("lengths: [0.18, 0.15]", "lengths: [0.18, 0.06]")
        .replace("positions: 12", "positions: 12\n  start_deg: 90");
    let e = refusal(&text);
    assert!(e.contains("absolute crank angles θ from") && e.contains("course angles φ = "), "{e}");
}

/// Text that reaches the sheet: control characters, characters the font lacks, line breaks
/// in one-line fields are refused where they are written, naming the field and the character.
#[test]
fn user_text_that_cannot_be_printed_is_refused_with_its_field() {
    let title = "title: {uz: \"Tebranuvchi konveyer mexanizmi\", ru: \"Механизм вибрационного конвейера\", en: \"Vibrating conveyor mechanism\"}";
    let e = error_of(title, "title: \"Tebranuvchi\\u0007 konveyer\"");
    assert!(
        e.contains("project.title") && e.contains("U+0007") && e.contains(&format!("line {}", line_of(title))),
        "{e}"
    );
    let e = error_of("student: \"\"", "student: \"Ли 李\"");
    assert!(e.contains("project.student") && e.contains("'李' (U+674E)") && e.contains("DejaVu Sans Condensed"), "{e}");
    let e = error_of(title, "title: \"two\\nlines\"");
    assert!(e.contains("line break") && e.contains("project.title"), "{e}");
    let e = error_of("{name: C, at: [0.33, 0.06]}", "{name: \"C\\u0000\", at: [0.33, 0.06]}");
    assert!(e.contains("mechanism.frame[1].name") && e.contains("U+0000"), "{e}");
    // Free text may break lines; it is wrapped anyway.
    let text =
        example().replacen("  assumptions:\n    - uz: \"", "  assumptions:\n    - uz: \"first line\\nsecond line ", 1);
    assert!(pipeline::load(&text).is_ok());
}

#[test]
fn text_too_long_for_its_place_on_the_sheet_is_refused_with_its_field() {
    let title = "title: {uz: \"Tebranuvchi konveyer mexanizmi\", ru: \"Механизм вибрационного конвейера\", en: \"Vibrating conveyor mechanism\"}";
    let e = error_of(title, &format!("title: \"{}\"", "Konveyer ".repeat(200)));
    assert!(e.contains("project.title") && e.contains("does not fit the title block's name field"), "{e}");
    let e = error_of("student: \"\"", "student: \"Abdurahmonov Jasurbek Baxtiyorovich\"");
    assert!(e.contains("project.student") && e.contains("title-block cell (23 × 5 mm)"), "{e}");
    // A surname with initials is set condensed on its line, never refused; the letters'
    // box (its stretch applied) stays inside the 23 mm cell.
    let text = example().replacen("student: \"\"", "student: \"Abdurakhmonov A. A.\"", 1);
    let built = pipeline::build(&pipeline::load(&text).unwrap(), &[2]).unwrap();
    let name = built[0].output.scene.texts().find(|t| t.text == "Abdurakhmonov A. A.").expect("the name is drawn");
    assert!(name.stretch < 1.0 && name.stretch >= tmm_sheets::drawing::text::NARROWEST, "{}", name.stretch);
    let cell_x = (651.0 + 17.0, 651.0 + 40.0);
    let b = name.bbox();
    assert!(b.x0 >= cell_x.0 && b.x1 <= cell_x.1, "{b:?} inside {cell_x:?}");
    assert!(built[0].svg.contains("scale(0."), "the SVG condenses it");
    // One word of a million letters: refused (wrapping and measuring are linear).
    let word = "a".repeat(1_000_000);
    let e = refusal(&example().replacen(
        "  assumptions:\n    - uz: \"",
        &format!("  assumptions:\n    - uz: \"{word} "),
        1,
    ));
    assert!(e.contains("mechanism.assumptions") && e.contains("does not fit the notes"), "{}", &e[..e.len().min(300)]);
}

/// A given list of acceleration plans without φ1's position builds, warned: the force
/// analysis there reads its inertia forces off a plan the sheet would not draw; so does a φ1
/// between two positions.
#[test]
fn acceleration_plans_without_phi1s_position_are_warned_about() {
    let text = example().replacen("acceleration_plans: [1, 3, 5, 7]", "acceleration_plans: [2, 4, 6]", 1);
    let w = pipeline::load(&text).unwrap().warnings;
    let line = line_of("acceleration_plans: [1, 3, 5, 7]") as u64;
    assert!(
        w.iter()
            .any(|w| w.field == "analysis.acceleration_plans" && w.line == line && w.message.contains("position 1")),
        "{w:?}"
    );
    // φ1 between two positions: no plan can be drawn there, which is warned about instead.
    let off_grid = text.replacen("assigned_deg: 45", "assigned_deg: 50", 1);
    let w = pipeline::load(&off_grid).unwrap().warnings;
    let line = line_of("assigned_deg: 45") as u64;
    assert!(w.len() == 1 && w[0].field == "analysis.assigned_deg" && w[0].line == line, "{w:?}");
    assert!(w[0].message.contains("φ1 = 50°") && w[0].message.contains("every 45°"), "{w:?}");
    // Without a force analysis there is nothing to read off a plan.
    let lever_only = example().split("\nforces:").next().unwrap().to_string();
    assert!(lever_only.len() < example().len(), "the example has a force analysis");
    let kinematics_only = lever_only.replacen("assigned_deg: 45", "assigned_deg: 50", 1);
    assert!(pipeline::load(&kinematics_only).unwrap().warnings.is_empty());
}
