//! No value's statement runs into a name or a number on its line, on the catalogue's
//! variants where one did: a teacher reads «φ₁ = 150,0° 1» as one phrase.

mod common;

use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline;

/// The sheet `sheet` of the catalogue's `task`, `variant` in Russian: the layout measure's
/// pairs of texts read as one phrase, and the faults of every kind.
fn run_together(task: &str, variant: u32, sheet: u32) -> (u64, serde_json::Value) {
    let text = common::catalogue_text(task, variant, Language::Ru);
    let built = pipeline::build(&pipeline::load_for(&text, &[sheet]).unwrap(), &[sheet]).unwrap();
    let layout = built[0].output.results["layout"].clone();
    (layout["texts_run_together"].as_u64().expect("counted"), layout)
}

/// Each of these ran together before statements kept off their line: the analysed
/// position's «φ₁ = 150,0°» and the load diagram's S/H value «1» (task 1 variant 5), the
/// idle stroke's name and «φ₁ = 240,0°» (task 15 variant 3), the stroke's «H = 383,4 mm» and
/// position number 10 (task 15 variant 9), the nomogram's «α_п = 40°» and point 2 (task 6
/// variant 21, sheet 3).
#[test]
fn no_values_statement_runs_into_a_name_on_its_line() {
    for (task, variant, sheet) in [("1", 5, 1), ("15", 3, 1), ("15", 9, 1), ("6", 21, 3)] {
        let (n, layout) = run_together(task, variant, sheet);
        assert_eq!(n, 0, "task {task} variant {variant} sheet {sheet}: {}", layout["problems"]);
        for fault in tmm_sheets::drawing::layout::FAULTS {
            assert_eq!(layout[fault], 0, "task {task} variant {variant}: {fault}: {}", layout["problems"]);
        }
    }
}

/// Random mechanisms of the stress tests (tests/stress.rs, seed 2026) whose position number
/// ran into the stroke's value: «5» set 3.5 mm high 4.2 mm before «H = 2178 mm» (the
/// statement's room was sized for the batch's smaller numbers), «H = 1279 mm 8» 1.1 mm apart
/// and «H = 551.0 mm» with «4» 3.2 mm after it (numbers set on the position plan's
/// breakable lines, where the statement's room was not asked).
#[test]
fn no_position_number_runs_into_the_strokes_value_on_the_stress_cases() {
    for text in [STRESS_CRANK_SLIDER, STRESS_CRANK_SLIDER_ON_LINES, STRESS_SIX_BAR] {
        let built = pipeline::build(&pipeline::load(text).unwrap(), &[1]).unwrap();
        let layout = &built[0].output.results["layout"];
        for fault in tmm_sheets::drawing::layout::FAULTS {
            assert_eq!(layout[fault], 0, "{fault}: {}", layout["problems"]);
        }
    }
}

const STRESS_CRANK_SLIDER: &str = "project:\n  title: {uz: \"Sinov\", ru: \"Проба\", en: \"Stress\"}\n  designation: {uz: \"MMN KL 00.00.00\", ru: \"ТММ КП 00.00.00\", en: \"TMM CP 00.00.00\"}\n  language: en\n\nmechanism:\n  frame:\n    - {name: O, at: [0.0, 0.0]}\n  crank: {pivot: O, pin: A, length: 1.076826, rpm: 1.0, sense: ccw}\n  groups:\n    - rrp: {links: [2, 3], joint: A, point: B, length: 1.201431, guide: {through: [0.0, 0.076257], angle_deg: 0}, branch: forward}\n  points:\n    - {name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}\n    - {name: S3, link: 3, from: B, mass_centre: true}\n";
const STRESS_CRANK_SLIDER_ON_LINES: &str = "project:\n  title: {uz: \"Sinov\", ru: \"Проба\", en: \"Stress\"}\n  designation: {uz: \"MMN KL 00.00.00\", ru: \"ТММ КП 00.00.00\", en: \"TMM CP 00.00.00\"}\n  language: en\n\nmechanism:\n  frame:\n    - {name: O, at: [0.0, 0.0]}\n  crank: {pivot: O, pin: A, length: 0.639367, rpm: 1.0, sense: ccw}\n  groups:\n    - rrp: {links: [2, 3], joint: A, point: B, length: 1.065659, guide: {through: [0.0, -0.010195], angle_deg: 0}, branch: forward}\n  points:\n    - {name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}\n    - {name: S3, link: 3, from: B, mass_centre: true}\n";
const STRESS_SIX_BAR: &str = "project:\n  title: {uz: \"Sinov\", ru: \"Проба\", en: \"Stress\"}\n  designation: {uz: \"MMN KL 00.00.00\", ru: \"ТММ КП 00.00.00\", en: \"TMM CP 00.00.00\"}\n  language: en\n\nmechanism:\n  frame:\n    - {name: O, at: [0, 0]}\n    - {name: C, at: [1.658145, 0]}\n  crank: {pivot: O, pin: A, length: 0.221082, rpm: 90, sense: cw}\n  groups:\n    - rrr: {links: [2, 3], joints: [A, C], point: B, lengths: [2.236169, 1.236027], branch: left}\n    - rrp: {links: [4, 5], joint: B, point: D, length: 2.209881, guide: {through: [0, 0.383570], angle_deg: 0}, branch: backward}\n  points:\n    - {name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}\n    - {name: S3, link: 3, from: C, toward: B, ratio: 0.5, mass_centre: true}\n    - {name: S4, link: 4, from: B, toward: D, ratio: 0.5, mass_centre: true}\n    - {name: S5, link: 5, from: D, mass_centre: true}\n";
