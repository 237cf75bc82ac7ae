//! Stress: random projects across the ranges the course can meet and beyond — gear pairs of
//! 5 to 400 teeth with shifts and planetary ratios 2 to 50, cams with strokes from 1 mm to
//! 1 m and phases from 1° to 300° with and without dwells, crank-sliders with λ close to 1 and
//! offsets close to their limit, four-bars (Grashof and not) and six-bars (a crank-rocker
//! driving a slider) with frames from 1 mm to 10 m, kulisas swinging and turning with their
//! forces. Each either builds, with every number it writes finite, nothing drawn off the A1
//! page, its layout measure clean (no text crossed or overlapping, no drawing leaving its
//! region: issue 22's "done when") and no plan under 20 mm, or is refused with a
//! field, a place and a reason — never a panic.
//!
//! `STRESS_CASES` (default 300 of each kind; the suite is kept to a few minutes) sets the
//! number of cases of each kind, `STRESS_SEED` (default a fixed 2026, so that a run is
//! repeatable; `random` for new cases each run) the cases drawn;
//! `STRESS_CASES=3000 STRESS_SEED=random cargo test --release --test stress` is the sweep. A
//! failure prints its project file: it becomes a fixture or a bad-input file with the refusal
//! it must give.

mod common;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};
use tmm_sheets::num::math;
use tmm_sheets::pipeline;

fn cases() -> u32 {
    common::env_cases("STRESS_CASES", 300)
}

/// The cases' seed: fixed, so that a run is repeatable and its layout verdict is the same on
/// every machine; `STRESS_SEED=N` draws other cases, `STRESS_SEED=random` new ones each run.
fn seed() -> RngSeed {
    common::env_seed("STRESS_SEED")
}

const HEADER: &str = "project:\n  title: {uz: \"Sinov\", ru: \"Проба\", en: \"Stress\"}\n  designation: {uz: \"MMN KL 00.00.00\", ru: \"ТММ КП 00.00.00\", en: \"TMM CP 00.00.00\"}\n  language: en\n\n";

/// A crank-slider with its rod's and slider's masses and a load on the slider, as the
/// mechanism sweep writes it: the crank (length m, rpm, clockwise), the rod's length (m),
/// the guide (its height through x = 0, m; its angle, °), φ₁ analysed (°), the masses
/// (kg) and the load (the stroke it works on, its force and its idle force, N).
fn loaded_crank_slider(
    (crank, rpm): (f64, f64),
    rod: f64,
    (guide_y, guide_deg): (f64, f64),
    assigned_deg: f64,
    (m2, m3): (f64, f64),
    (working, force, idle): (&str, f64, f64),
) -> String {
    format!(
        "{HEADER}mechanism:
  frame:
    - {{name: O, at: [0.0, 0.0]}}
  crank: {{pivot: O, pin: A, length: {crank}, rpm: {rpm}, sense: cw}}
  groups:
    - rrp: {{links: [2, 3], joint: A, point: B, length: {rod}, guide: {{through: [0.0, {guide_y}], angle_deg: {guide_deg}}}, branch: forward}}
  points:
    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.32, mass_centre: true}}
    - {{name: S3, link: 3, from: B, mass_centre: true}}
analysis:
  positions: 12
  assigned_deg: {assigned_deg}
forces:
  links:
    - {{link: 2, mass: {m2}, inertia: rod}}
    - {{link: 3, mass: {m3}}}
  loads:
    - resistance: {{point: B, working: {working}, force: {force}, idle_force: {idle}}}
"
    )
}

/// How a case ended.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Outcome {
    /// Built, its layout measure clean: no drawing leaving its region, no text crossed by a
    /// line or overlapping another.
    Built,
    Refused,
}

/// A refusal says which field, where and why.
fn names_field_and_line(r: &tmm_sheets::project::Refusal) -> bool {
    !r.cause.is_empty() && !r.path.is_empty() && r.line > 0
}

/// What a build must be: refused with a reason, or finished with finite numbers, on the page.
fn verdict(text: &str) -> Result<Outcome, String> {
    let p = match pipeline::load(text) {
        Ok(p) => p,
        Err(pipeline::Error::Refused(r)) if names_field_and_line(&r.refusal) => {
            return Ok(Outcome::Refused);
        }
        Err(e) => return Err(format!("refused without a place or reason: {e:?}")),
    };
    let built = match pipeline::build(&p, &[]) {
        Ok(b) => b,
        Err(pipeline::Error::Refused(r)) if names_field_and_line(&r.refusal) => {
            return Ok(Outcome::Refused);
        }
        Err(e) => return Err(format!("refused without a place or reason: {e:?}")),
    };
    for b in &built {
        let n = b.output.number;
        for bad in ["NaN", "inf"] {
            if b.svg.contains(bad) {
                return Err(format!("sheet {n}: the SVG holds {bad}"));
            }
        }
        let page = kurbo::Rect::new(0.0, 0.0, b.output.scene.width, b.output.scene.height);
        for g in &b.output.scene.groups {
            for item in &g.items {
                let bb = item.bbox();
                if bb.x0 < page.x0 - 0.01 || bb.y0 < page.y0 - 0.01 || bb.x1 > page.x1 + 0.01 || bb.y1 > page.y1 + 0.01
                {
                    return Err(format!("sheet {n}: '{}' draws off the page at {bb:?}", g.id));
                }
            }
        }
        for t in &b.output.tables {
            for a in t.answers(&format!("sheet{n}")) {
                if !a.value.is_finite() {
                    return Err(format!("sheet {n}: {} = {}", a.id, a.value));
                }
            }
        }
    }
    let json = pipeline::results_json(&p, &built);
    if serde_json::from_str::<serde_json::Value>(&json).is_err() {
        return Err("results.json does not parse".into());
    }
    let count = |keys: &[&str]| -> u64 {
        built.iter().flat_map(|b| keys.iter().map(|k| b.output.results["layout"][k].as_u64().unwrap_or(0))).sum()
    };
    if count(&tmm_sheets::drawing::layout::FAULTS) > 0 {
        let problems: Vec<String> = built
            .iter()
            .flat_map(|b| {
                let n = b.output.number;
                let listed = b.output.results["layout"]["problems"].as_array().cloned().unwrap_or_default();
                listed.into_iter().map(move |p| format!("sheet {n}: {}", p.as_str().unwrap_or_default()))
            })
            .collect();
        return Err(format!("the layout measure reports {}", problems.join("; ")));
    }
    // Issue 22: no plan too small to measure (the sheet enlarges one at a scale of its own
    // rather than draw it under 20 mm).
    for b in &built {
        if let Some(mm) = b.output.results["layout"]["smallest_plan_mm"].as_f64()
            && mm < 20.0
        {
            return Err(format!("sheet {}: a plan is drawn {mm:.1} mm across, too small to measure", b.output.number));
        }
    }
    Ok(Outcome::Built)
}

/// Sheet `n`'s SVG of a project that builds.
fn sheet_svg(text: &str, n: u32) -> String {
    let built = pipeline::build(&pipeline::load(text).expect("loads"), &[]).expect("builds");
    built.into_iter().find(|b| b.output.number == n).expect("the sheet").svg
}

/// Runs the cases; at least `min_built` of every hundred must build (the ranges are the
/// course's, mostly: a generator that only made refusals would test nothing).
fn run(name: &str, min_built: u32, strategy: impl Strategy<Value = String>) {
    run_n(name, min_built, cases(), strategy);
}

/// As [`run`], `n` cases.
fn run_n(name: &str, min_built: u32, n: u32, strategy: impl Strategy<Value = String>) {
    run_checked(name, min_built, n, strategy, |_| None);
}

/// As [`run_n`], each built case's project text also asked of `wrong`: what is wrong with
/// its sheets beyond the verdict's checks, if anything.
fn run_checked(
    name: &str,
    min_built: u32,
    n: u32,
    strategy: impl Strategy<Value = String>,
    wrong: impl Fn(&str) -> Option<String>,
) {
    let config = Config { cases: n, failure_persistence: None, rng_seed: seed(), ..Config::default() };
    let mut runner = TestRunner::new(config);
    let built = std::cell::Cell::new(0u32);
    let result = runner.run(&strategy, |text| {
        let outcome = std::panic::catch_unwind(|| verdict(&text)).unwrap_or_else(|_| Err("panicked".into()));
        prop_assert!(outcome.is_ok(), "{}:\n{text}", outcome.as_ref().unwrap_err());
        if let Ok(Outcome::Built) = outcome {
            built.set(built.get() + 1);
            let wrong = wrong(&text);
            prop_assert!(wrong.is_none(), "{}:\n{text}", wrong.unwrap_or_default());
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    eprintln!(
        "{name}: {} of {n} built, each with its layout measure clean; the others refused with field, line and reason",
        built.get(),
    );
    assert!(built.get() * 100 >= min_built * n, "{name}: only {} of {n} built", built.get());
}

#[test]
fn gear_pairs_and_planetary_stages() {
    let shift = prop_oneof![
        Just(String::new()),
        Just(", shift: auto".to_string()),
        (-0.5f64..1.0, -0.5f64..1.0).prop_map(|(a, b)| format!(", shift: [{a:.3}, {b:.3}]")),
    ];
    let planetary = prop_oneof![
        Just(String::new()),
        (2.0f64..50.0, 0.5f64..6.0)
            .prop_map(|(u, m)| format!("\n  planetary: {{scheme: sun-planet-ring, module: {m:.1}, ratio: {u:.2}}}")),
        (2.0f64..50.0, 0.5f64..6.0)
            .prop_map(|(u, m)| format!("\n  planetary: {{scheme: double-planet, module: {m:.1}, ratio: {u:.2}}}")),
    ];
    let strategy =
        (5u32..=400, 5u32..=400, 0.5f64..20.0, shift, planetary).prop_map(|(z1, z2, m, shift, planetary)| {
            format!("{HEADER}gears:\n  pair: {{module: {m:.2}, z: [{z1}, {z2}]{shift}}}{planetary}\n")
        });
    run("gears", 50, strategy);
}

#[test]
fn cams_of_every_size_and_phase() {
    let laws = [
        "sine",
        "cosine",
        "polynomial-345",
        "uniform-acceleration",
        "linearly-decreasing",
        "trapezoid",
        "modified-sine",
    ];
    let law = proptest::sample::select(laws.to_vec());
    let strategy = (0.001f64..1.0, 1.0f64..300.0, 0.0f64..1.0, 1.0f64..300.0, law, 10.0f64..60.0, any::<bool>())
        .prop_map(|(stroke, rise, dwell_share, ret, law, alpha, rocker)| {
            // The three phases share at most 360°.
            let scale = (359.0 / (rise + ret)).min(1.0);
            let (rise, ret) = (rise * scale, ret * scale);
            let dwell = (360.0 - rise - ret) * dwell_share * 0.9;
            let follower = if rocker {
                format!("{{rocker: {{length: {:.4}, swing_deg: {:.1}}}}}", stroke.max(0.02), 5.0 + 40.0 * stroke)
            } else {
                format!("{{translating: {{stroke: {stroke:.4}, offset: auto}}}}")
            };
            format!(
                "{HEADER}cam:\n  follower: {follower}\n  roller: auto\n  phases_deg: {{rise: {rise:.2}, far_dwell: {dwell:.2}, return: {ret:.2}}}\n  law: {law}\n  pressure_angle_deg: {alpha:.1}\n  sense: cw\n"
            )
        });
    run("cams", 30, strategy);
}

#[test]
fn crank_sliders_near_their_limits() {
    // λ = r/l up to 0.99, the offset up to 99 % of what still lets the crank turn.
    let strategy = (0.001f64..2.0, 0.05f64..0.99, -0.99f64..0.99, 1.0f64..3000.0).prop_map(|(r, lam, off, rpm)| {
        let l = r / lam;
        let e = off * (l - r);
        format!(
            "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0.0, 0.0]}}\n  crank: {{pivot: O, pin: A, length: {r:.6}, rpm: {rpm:.1}, sense: ccw}}\n  groups:\n    - rrp: {{links: [2, 3], joint: A, point: B, length: {l:.6}, guide: {{through: [0.0, {e:.6}], angle_deg: 0}}, branch: forward}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: S3, link: 3, from: B, mass_centre: true}}\n"
        )
    });
    run("crank-sliders", 50, strategy);
}

/// Crank-sliders with a force analysis and a load: a guide at any angle, any φ1, a working
/// force from 100 N to 50 kN and an idle one from a thousandth of it to all of it (an audit's
/// 120 random ones found the idle line through the S/H values where it was under 7 %). A
/// third of the cases (a sheet with forces takes longest).
#[test]
fn crank_sliders_with_loads_small_idle_forces_included() {
    let geometry = (0.05f64..0.5, 0.15f64..0.4, -0.3f64..0.3, 0.0f64..360.0, 0.0f64..360.0);
    let load = (100.0f64..50_000.0, 0.001f64..1.0, any::<bool>(), 1.0f64..50.0, 60.0f64..1500.0);
    let strategy = (geometry, load).prop_map(|((r, lam, off, guide, phi), (force, idle, forward, mass, rpm))| {
        let l = r / lam;
        let e = off * (l - r);
        let working = if forward { "forward" } else { "backward" };
        let idle = force * idle;
        let m3 = mass * 0.6;
        format!(
            "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0.0, 0.0]}}\n  crank: {{pivot: O, pin: A, length: {r:.6}, rpm: {rpm:.1}, sense: cw}}\n  groups:\n    - rrp: {{links: [2, 3], joint: A, point: B, length: {l:.6}, guide: {{through: [0.0, {e:.6}], angle_deg: {guide:.3}}}, branch: forward}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.32, mass_centre: true}}\n    - {{name: S3, link: 3, from: B, mass_centre: true}}\nanalysis:\n  positions: 12\n  assigned_deg: {phi:.3}\nforces:\n  links:\n    - {{link: 2, mass: {mass:.2}, inertia: rod}}\n    - {{link: 3, mass: {m3:.2}}}\n  loads:\n    - resistance: {{point: B, working: {working}, force: {force:.1}, idle_force: {idle:.1}}}\n"
        )
    });
    run_n("crank-sliders with loads", 80, cases() / 3, strategy);
}

/// A crank-slider a random seed's sweep found (stop 93): analysed at φ₁ = 356.5°, S/H = 0,
/// its idle level 1078 N (against a 17346 N working one) 5 mm over the S/H axis. The mark of
/// the position stood on the axis's «0» and the idle line ran over «0,5» and «1»: the value
/// under the mark is left out, and a line within a millimetre of the values' tops sends them
/// under the axis.
#[test]
fn a_load_diagrams_small_idle_level_keeps_off_the_stroke_values() {
    let text = format!(
        "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0.0, 0.0]}}\n  crank: {{pivot: O, pin: A, length: 0.050000, rpm: 708.1, sense: cw}}\n  groups:\n    - rrp: {{links: [2, 3], joint: A, point: B, length: 0.333333, guide: {{through: [0.0, -0.073908], angle_deg: 0.000}}, branch: forward}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.32, mass_centre: true}}\n    - {{name: S3, link: 3, from: B, mass_centre: true}}\nanalysis:\n  positions: 12\n  assigned_deg: 356.545\nforces:\n  links:\n    - {{link: 2, mass: 13.06, inertia: rod}}\n    - {{link: 3, mass: 7.84}}\n  loads:\n    - resistance: {{point: B, working: forward, force: 17345.8, idle_force: 1077.8}}\n"
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A pair the sweep found (a random seed, 1500 cases) whose diagram of specific sliding
/// wrote its two values under its title exactly two lettering heights apart, where the
/// layout measure reads them as one phrase: «λ₁ (B₁) → −∞» ran into «λ₂ (B₂) = −2.610».
/// They now stand further apart, in every language.
#[test]
fn a_pair_the_sweep_found_keeps_its_two_sliding_values_apart() {
    for lang in ["uz", "ru", "en"] {
        let text = HEADER.replace("language: en", &format!("language: {lang}"))
            + "gears:\n  pair: {module: 0.50, z: [21, 15], shift: [-0.245, -0.343]}\n  planetary: {scheme: double-planet, module: 0.5, ratio: 2.00}\n";
        assert_eq!(verdict(&text), Ok(Outcome::Built), "{lang}");
    }
}

/// Pairs the sweep found drawing teeth off the page (their three teeth wider than the
/// region at the course's tooth height): now drawn at a scale at which they fit.
#[test]
fn pairs_the_sweep_found_off_the_page_fit_their_region() {
    for pair in [
        // Unshifted, the 7-tooth pinion was undercut so deep that the involute left meshes
        // less than one pitch (ε = 0.8, refused): shifted as a designer would.
        "{module: 4.39, z: [7, 70], shift: [0.45, 0]}",
        "{module: 1.01, z: [48, 75], shift: [0.231, 0.957]}",
        // At x1 = −0.362 (ε = 0.8 on the involute left by the undercut, refused) as x1 = 0.
        "{module: 4.40, z: [10, 25], shift: [0, 0.805]}",
        // A circle's part inside the region had no sweep: boxed at (0, 0), "off the page".
        "{module: 5.31, z: [318, 155], shift: [0.522, 0.281]}",
        // A pair alone, its mesh as wide as the tables leave: the region ran over the title
        // block and the circles' arcs through its lines (now the region ends above it).
        "{module: 5.50, z: [18, 17]}",
        // A random seed's find (stop 92): its notes under the mesh sized with stand-in
        // numbers in three columns, set with its own in one, 22 mm taller: in English their
        // last lines ran 8.2 mm off the page (the mesh is now drawn again above them).
        "{module: 0.50, z: [133, 133], shift: [-0.478, -0.461]}",
    ] {
        let text = format!("{HEADER}gears:\n  pair: {pair}\n");
        assert_eq!(verdict(&text), Ok(Outcome::Built), "{pair}");
    }
    // A random seed's find (stop 93): p_b's value set along its line over the end of α_w's
    // arc, where α_w's name is anchored; α_w stood on a leader across «p_b = 57.09». The
    // dimensions' values now keep off α_w's anchor.
    let text = format!(
        "{HEADER}gears:\n  pair: {{module: 19.34, z: [64, 258], shift: [0.941, 0.106]}}\n  planetary: {{scheme: double-planet, module: 0.5, ratio: 2.00}}\n"
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
    // A 363-tooth wheel's arc ended on its region's edge, its stroke 0.4 mm over it.
    let text = format!(
        "{HEADER}gears:\n  pair: {{module: 1.76, z: [363, 132], shift: [0.993, -0.062]}}\n  planetary: {{scheme: double-planet, module: 0.5, ratio: 2.00}}\n"
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A 5-tooth pinion the sweep found (stop 71) with p's value, set along the line of centres
/// in its small body, across the sense arrow ω₁ drawn after it: the arrows are now drawn
/// before the dimensions' values, which keep clear of them. At x = 0.349 that pinion is
/// undercut (x_min = 0.71) so deep that the involute left meshes less than one pitch, and
/// any shift that mends it points its teeth: it is refused, and a 6-tooth pinion is drawn.
#[test]
fn a_five_tooth_pinions_pitch_value_stands_clear_of_its_sense_arrow() {
    let text = format!("{HEADER}gears:\n  pair: {{module: 7.15, z: [6, 84], shift: [0.45, 0.708]}}\n");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
    let text = format!("{HEADER}gears:\n  pair: {{module: 7.15, z: [5, 84], shift: [0.349, 0.708]}}\n");
    assert_eq!(verdict(&text), Ok(Outcome::Refused));
}

/// A slider the sweep found (stop 71) on a guide 8° off the vertical: G3 down, P_i3 its twin
/// pushed into the block from above, and the load P_c3 slid past P_i3's tail up into the
/// group's title. A twin no longer pushes into the side a force still to come leaves by.
#[test]
fn a_slider_pushed_into_from_above_keeps_its_load_arrow_under_the_group_title() {
    let text = loaded_crank_slider(
        (0.206268, 339.0),
        0.559253,
        (0.000000, 81.754),
        288.228,
        (37.20, 22.32),
        ("forward", 44731.5, 18332.2),
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A six-bar the random sweep found at stop 71: a 30 µm crank in a 1 mm frame, drawn at
/// 100:1, had its detail at 100:1 too — a 3 mm circle with a line across "O" and "10". Its
/// detail is now at 1000:1, the (100·n):1 GOST 2.302 allows beyond 100:1.
#[test]
fn a_six_bar_with_a_30_micrometre_crank_keeps_its_letters_clear() {
    let text = common::six_bar(HEADER, 0.001, 0.00003, (0.001402, 0.000478), 0.0, 0.000502, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
    // The detail draws the crank 30 mm long, ten times the mechanism's 3 mm.
    assert!(sheet_svg(&text, 1).contains(" = 0.000001 m/mm)"), "no 1000:1 detail");
}

/// A six-bar the sweep found at stop 80: its stroke's value, written along its dimension
/// line across two of the other positions' thin lines (interrupted for it), was then
/// crossed by ω₁'s arc, drawn after it and turned to cross the fewest lines only. A turn
/// arrow now counts a text it would cross as many lines.
#[test]
fn a_turn_arrow_keeps_off_a_strokes_value_written_before_it() {
    let text = common::six_bar(HEADER, 0.004494, 0.000882, (0.005105, 0.002019), 0.000364, 0.005151, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A crank-slider the sweep found at stop 72, its guide at 201°: the stroke H dimensioned
/// under a 376 mm stroke, its extension line's 2 mm past the dimension line across the
/// trajectories' legend (the offsets were tried without that overshoot). An offset whose
/// lines cross a text now comes after every one whose lines do not.
#[test]
fn a_slider_strokes_dimension_keeps_off_the_trajectories_legend() {
    let text = loaded_crank_slider(
        (0.187398, 60.0),
        0.502822,
        (-0.040406, 201.292),
        0.000,
        (1.00, 0.60),
        ("backward", 100.0, 61.3),
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A crank-slider a random sweep found at stop 93, its guide at 214°: no offset of its
/// stroke's dimension left the extension line clear of the trajectories' legend in the
/// region's bottom left corner. The legend moves to a corner the drawing leaves free.
#[test]
fn a_legend_crossed_by_the_drawing_moves_to_a_free_corner() {
    let text = loaded_crank_slider(
        (0.05, 60.0),
        0.333333,
        (0.075834, 214.109),
        66.105,
        (1.00, 0.60),
        ("backward", 100.0, 0.1),
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A six-bar the sweep found at stop 72: its slider barely moves round the dead centre,
/// positions 9, 10, 10′, 11, 0 and 1 within 1.5 mm on paper, and "11" found no spot off the
/// stroke's dimension line. Slider positions that near share one number, "0 ≡ 1 ≡ 9 ≡ …".
#[test]
fn a_six_bars_slider_numbers_round_its_dead_centre_share_a_label() {
    let text = common::six_bar(HEADER, 3.855486, 1.612974, (1.922098, 3.780710), 0.737682, 4.873080, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
    assert!(sheet_svg(&text, 1).contains(">0 ≡ 1 ≡ 9 ≡ 10 ≡ 10′ ≡ 11<"), "no shared slider number");
}

/// A pair the sweep found at stop 72 (m = 12.4 mm, z = 22 and 21), wheel 1's centre at
/// the mesh drawing's foot: ω₁'s arc, meant to turn over the centre, started 20° under it
/// and ran into the notes below. It now turns from 35° to 145° above the horizontal.
#[test]
fn a_pinions_sense_arrow_at_the_drawings_foot_stays_over_the_notes() {
    let text = format!(
        "{HEADER}{}",
        "gears:\n  pair: {module: 12.40, z: [22, 21]}\n  planetary: {scheme: sun-planet-ring, module: 0.5, ratio: 10.85}\n"
    );
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// A six-bar a third sweep found at stop 72: its crank 9.3 mm on paper, just over the
/// detail's 9 mm, its numbers crowded by the rods' lines and ω₁ but none on a leader 20 mm
/// long, "10" left on a line. The crowded crank's detail is now tried for a label left
/// without a clean spot too, and a free spot taken with the tight margin where the full one
/// finds none: the detail at 1:5 beside the 1:10 mechanism.
#[test]
fn a_six_bar_with_a_crank_just_over_the_details_size_keeps_its_numbers_clear() {
    let text = common::six_bar(HEADER, 0.990438, 0.092463, (0.488958, 1.129854), 0.451429, 1.977995, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
    assert!(sheet_svg(&text, 1).contains(" = 0.005 m/mm)"), "no 1:5 detail");
}

/// Cams the sweep found with texts crossed, each now clean: a 3.5° return after a 283° rise
/// (its ds/dφ ~80 times the rise's: the diagram a sliver, its scale text on the pole's name);
/// a nomogram in a narrow region beside the profile (r_min's label across the wedge); a 3.7°
/// return's nine division numbers in 0.2 mm. The first also warns that its lift is drawn
/// lower than the course's scales want. Two short phases side by side (18.4° and 3.53°, 1° and
/// 20.26°) and a 1° phase at either end of the axis: their values' shelves stay clear of each
/// other and inside the column (the first shelves went off the column's right edge and across
/// each other); a 1° rise's tables.
/// A cam the sweeps found: its follower (YAML), phases in degrees, law and allowed angle.
fn cam(follower: &str, (rise, dwell, ret): (f64, f64, f64), law: &str, alpha: f64) -> String {
    format!(
        "{HEADER}cam:\n  follower: {follower}\n  roller: auto\n  phases_deg: {{rise: {rise}, far_dwell: {dwell}, return: {ret}}}\n  law: {law}\n  pressure_angle_deg: {alpha}\n  sense: cw\n"
    )
}

#[test]
fn cams_the_sweep_found_with_texts_crossed_are_clean() {
    let squeezed = cam("{translating: {stroke: 0.87, offset: auto}}", (283.27, 18.4, 3.53), "trapezoid", 31.8);
    for text in [
        squeezed.clone(),
        cam("{translating: {stroke: 0.4913, offset: auto}}", (77.03, 115.23, 49.78), "uniform-acceleration", 13.2),
        cam("{translating: {stroke: 0.2394, offset: auto}}", (178.96, 0.19, 180.04), "sine", 16.9),
        cam("{translating: {stroke: 0.5999, offset: auto}}", (61.54, 120.5, 3.74), "linearly-decreasing", 13.5),
        cam("{translating: {stroke: 0.0010, offset: auto}}", (169.78, 102.76, 1.0), "sine", 10.0),
        cam("{translating: {stroke: 0.0010, offset: auto}}", (1.0, 20.26, 207.04), "sine", 10.0),
        // A 1° rise: its analogs' values are eight digits long, and the tables lettered 3.5 mm
        // for the views' sake were wider than their strip (now 2.5 mm where 3.5 does not fit).
        cam("{translating: {stroke: 0.4181, offset: auto}}", (1.0, 0.0, 8.35), "trapezoid", 41.6),
        // "e = 405.1 mm" set against its region's left edge: the measure boxed a lone label's
        // slant half to the left (0.47 mm out) where the labeller, rightly, puts it all right.
        cam("{translating: {stroke: 0.7603, offset: auto}}", (63.69, 0.0, 158.73), "trapezoid", 21.5),
        // A 20 mm rocker's return of 1°: pivots A₈…A₁₇ and rollers 8…17 within 3 mm of each
        // other, their names knotted across the arms; positions drawn less than 1.5 mm apart
        // now share a name ("8≡9≡…≡14").
        cam("{rocker: {length: 0.0200, swing_deg: 5.0}}", (172.04, 0.0, 1.0), "linearly-decreasing", 10.0),
        // A 6.7 mm stroke over a 236° return: H2 = 16 mm, and "μ_d²s/dφ² = 0.0005968 m/mm"
        // reached into the pole's rays; a scale line the highest ray would cross is broken
        // after its "=".
        cam("{translating: {stroke: 0.0067, offset: auto}}", (55.09, 27.95, 235.73), "uniform-acceleration", 58.0),
        // A random seed's find (stop 93): a 375 mm stroke over a 20° rise, ds/dφ's top value
        // «2000» set left of its axis 2.7 mm after «μ_ds/dφ = 0.04 m/mm», read as one phrase;
        // a value left of the axis now keeps a phrase's gap from a text level with it.
        cam("{translating: {stroke: 0.3752, offset: auto}}", (20.38, 48.87, 35.21), "sine", 19.0),
        // The same seed's: a 12.8° swing, «μ_β = 0.006 rad/mm» held by the column's edge
        // 2.4 mm before the top value «12.5», on its row; the scale now steps off the row.
        cam("{rocker: {length: 0.1947, swing_deg: 12.8}}", (32.54, 221.40, 65.14), "uniform-acceleration", 28.2),
    ] {
        assert_eq!(verdict(&text), Ok(Outcome::Built), "{text}");
    }
    let p = pipeline::load(&squeezed).unwrap();
    let built = pipeline::build(&p, &[]).unwrap();
    let warned =
        built[0].output.diagnostics.iter().any(|d| d.contains("the lift is drawn") && d.contains("return of 3.53°"));
    assert!(warned, "{:?}", built[0].output.diagnostics);
}

/// An open find of a 2000-case sweep (stop 42), kept so that it is fixed and then held: a
/// modified-sine cam offset 11.18 mm (extension lines 1.1 mm apart on its nomogram), its value and r_min's
/// competing for the one clean spot under the offset's close extension lines. Whichever is
/// placed second is set across a line (r_min first: "e = 11.18 mm" across an extension line;
/// e first: r_min across a limiting line). Found clean on 2026-11-29 (the change that cleaned
/// it was not bisected): no longer ignored, so that it stays clean.
#[test]
fn cams_the_sweep_found_open_a_narrow_offset_and_r_min() {
    let text = cam("{translating: {stroke: 0.1599, offset: auto}}", (156.90, 0.0, 202.10), "modified-sine", 15.4);
    assert_eq!(verdict(&text), Ok(Outcome::Built), "{text}");
}

/// A find of a 1000-case sweep (a random seed, stop 62), right after the cam's follower
/// positions became lines a label may interrupt: a 20 mm rocker swinging 5.4° with a cam
/// about 2 mm across. Its position numbers took spots beside their points on the broken
/// rocker lines, and r_min, placed after them, found no clean spot left ("r_min = 0.9109
/// mm" across a rocker line). Where breaking leaves a label without a clean spot, the
/// placement without it is kept if it leaves fewer.
#[test]
fn cams_the_sweep_found_a_tiny_rockers_r_min_crowded_out_by_numbers_on_broken_lines() {
    let text = cam("{rocker: {length: 0.0200, swing_deg: 5.4}}", (160.33, 0.0, 188.05), "cosine", 31.6);
    assert_eq!(verdict(&text), Ok(Outcome::Built), "{text}");
}

/// A find of a 5000-case sweep (seed 20261129): a 20 mm rocker swinging 5.1° (a_w =
/// 20.49 mm, r_min = 0.86 mm) had its nomogram in a strip 51 mm tall at 10:1, the pivot A
/// 200 mm right of a B′ curve 25 mm across. The zone's name found no clean spot and its
/// leader crossed the position number "2". The pivot, seven times the picture's size away
/// from the curve and O, is now left off the nomogram (an arrow to it at the picture's edge):
/// the nomogram is drawn at 50:1.
#[test]
fn cams_the_sweep_found_a_rockers_zone_name_across_a_position_number() {
    let text = cam("{rocker: {length: 0.0200, swing_deg: 5.1}}", (246.37, 0.0, 100.98), "polynomial-345", 45.2);
    assert_eq!(verdict(&text), Ok(Outcome::Built), "{text}");
}

/// The same family, found by a 4000-case sweep (seed 31): a 20 mm rocker swinging 5.7°
/// drawn at 2:1, its B′ curve 6 mm across with the pivot 40 mm to its right. Every position
/// merged into five names ("0≡1≡15≡16≡17"), and the labels of the angles, the zone and r_min,
/// 3.5 mm letters beside a picture a few mm tall, found no clean spot: the return's limiting
/// line crossed "α_ret = 56.5°", "admissible zone" and "r_min = 0.4136 mm". With the far
/// pivot left off, the nomogram is drawn at 50:1, every position named apart.
#[test]
fn cams_the_sweep_found_a_small_rockers_labels_across_its_limiting_line() {
    let text = cam("{rocker: {length: 0.0200, swing_deg: 5.7}}", (117.17, 0.0, 212.22), "modified-sine", 56.5);
    assert_eq!(verdict(&text), Ok(Outcome::Built), "{text}");
}

#[test]
fn four_bars_grashof_and_not_from_a_millimetre_to_ten_metres() {
    // The frame d from 1 mm to 10 m; three in four are crank-rockers by construction
    // (the crank shortest, s + l ≤ p + q), the rest any four lengths (most refused: the
    // crank cannot turn), the branch either way.
    let grashof = (0.001f64..10.0, 0.05f64..0.45, 0.3f64..1.6, 0.3f64..1.6).prop_filter_map(
        "a crank-rocker",
        |(d, rs, l2s, l3s)| {
            let (r, l2, l3) = (rs * d, l2s * d, l3s * d);
            let longest = d.max(l2).max(l3);
            let (p, q) = (d + l2 + l3 - longest, r);
            (r < l2.min(l3).min(d) && q + longest <= p).then_some((d, r, l2, l3))
        },
    );
    let any_four = (0.001f64..10.0, 0.05f64..2.0, 0.05f64..2.0, 0.05f64..2.0)
        .prop_map(|(d, rs, l2s, l3s)| (d, rs * d, l2s * d, l3s * d));
    let lengths = prop_oneof![3 => grashof, 1 => any_four];
    let strategy = (lengths, any::<bool>(), 1.0f64..3000.0).prop_map(|((d, r, l2, l3), left, rpm)| {
        let branch = if left { "left" } else { "right" };
        format!(
            "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0, 0]}}\n    - {{name: C, at: [{d:.6}, 0]}}\n  crank: {{pivot: O, pin: A, length: {r:.6}, rpm: {rpm:.1}, sense: ccw}}\n  groups:\n    - rrr: {{links: [2, 3], joints: [A, C], point: B, lengths: [{l2:.6}, {l3:.6}], branch: {branch}}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: S3, link: 3, from: C, toward: B, ratio: 0.5, mass_centre: true}}\n"
        )
    });
    run("four-bars", 40, strategy);
}

/// Kulisas (a block on the crank's pin sliding along a link that turns about O1) with their
/// force analysis: a crank of 1 cm to 1.5 m, O1 in any direction from O at 1.02–4 cranks
/// (a swinging kulisa; the pin passes as close as 2 % of the crank to O1, where the velocity
/// plans of a few positions are many times smaller than the others) or at 0.3–0.9 of one (a
/// turning kulisa), the kulisa 1–1.3 times the pin's farthest reach, the block with a moment
/// of inertia or without. A third of the cases (a sheet with forces takes longest).
#[test]
fn kulisas_swinging_and_turning_with_their_forces() {
    let swinging = prop_oneof![3 => 1.02f64..4.0, 1 => 0.3f64..0.9];
    let geometry = (0.01f64..1.5, swinging, 0.0f64..360.0, 1.0f64..1.3, 0.5f64..1.0, 0.0f64..360.0);
    let masses = (0.5f64..20.0, 2.0f64..60.0, 0.5f64..1.5, prop_oneof![Just(0.0), 0.001f64..0.05], 10.0f64..500.0);
    let strategy = (geometry, masses).prop_map(|((r, dr, at, k, f, phi), (m2, m3, j, j2, rpm))| {
        let d = r * dr;
        let (x1, y1) = (d * math::cos(at.to_radians()), d * math::sin(at.to_radians()));
        let length = (d + r) * k;
        let (b, s3) = (length * f, length * f / 2.0);
        let j3 = j * m3 * length * length / 12.0;
        let block = if j2 > 0.0 { format!(", inertia: {j2:.4}") } else { String::new() };
        // A turning kulisa has no extreme position to start from: position 0 is given.
        let start = if dr < 1.0 { format!("  start_deg: {at:.3}\n") } else { String::new() };
        format!(
            "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0, 0]}}\n    - {{name: O1, at: [{x1:.6}, {y1:.6}]}}\n  crank: {{pivot: O, pin: A, length: {r:.6}, rpm: {rpm:.1}, sense: ccw}}\n  groups:\n    - rpr: {{links: [2, 3], block_at: A, pivot: O1, length: {length:.6}}}\n  points:\n    - {{name: B, link: 3, from: O1, toward: A3, distance: {b:.6}}}\n    - {{name: S3, link: 3, from: O1, toward: A3, distance: {s3:.6}, mass_centre: true}}\n  output_link: 3\nanalysis:\n  positions: 12\n{start}  assigned_deg: {phi:.3}\nforces:\n  links:\n    - {{link: 2, mass: {m2:.2}{block}}}\n    - {{link: 3, mass: {m3:.2}, inertia: {j3:.6}}}\n"
        )
    });
    run_n("kulisas with forces", 90, cases() / 3, strategy);
}

/// Six-bars of the worked example's kind: a crank-rocker (frame d from 1 mm to 10 m, its crank
/// `crank` of it) whose rocker's joint B drives a slider on a horizontal guide by a rod
/// `rod` times the rocker and the guide's offset; the rod always reaches the guide.
fn six_bars(crank: std::ops::Range<f64>, rod: std::ops::Range<f64>) -> impl Strategy<Value = String> {
    (0.001f64..10.0, crank, 0.3f64..1.6, 0.3f64..1.6, -0.5f64..0.5, rod, any::<bool>())
        .prop_filter_map("a crank-rocker", |(d, rs, l2s, l3s, es, k, forward)| {
            let (r, l2, l3) = (rs * d, l2s * d, l3s * d);
            let longest = d.max(l2).max(l3);
            let crank_rocker = r < l2.min(l3).min(d) && r + longest <= d + l2 + l3 - longest;
            let (e, l4) = (es * d, (es.abs() * d + l3) * k);
            // Every length within the README's range (a longer one is warned of as a likely
            // slip of units).
            (crank_rocker && l4.max(longest) <= 10.0).then_some((d, r, l2, l3, e, l4, forward))
        })
        .prop_map(|(d, r, l2, l3, e, l4, forward)| {
            common::six_bar(HEADER, d, r, (l2, l3), e, l4, if forward { "forward" } else { "backward" })
        })
}

#[test]
fn six_bars_a_crank_rocker_driving_a_slider() {
    run("six-bars", 40, six_bars(0.15..0.45, 1.05..4.0));
}

/// Cranks a thirtieth to a seventh of their frame beside rods up to six times the rocker: a
/// crank a few mm on paper, whose numbers, letters and ω₁ go to its enlarged detail (beside
/// the drawing, under it or in a free spot of its region) or, where none has room, stay
/// round it — clean either way.
#[test]
fn six_bars_with_cranks_a_few_millimetres_on_paper() {
    run("six-bars with small cranks", 40, six_bars(0.03..0.15, 1.05..6.0));
}

/// Found by the six-bar sweep before its crank was kept to at least 0.15 of the frame: a
/// crank of 33 mm in a 0.46 m frame with a 2.4 m rod is ~3 mm on paper, and its twelve
/// position numbers, ω₁ and the letters crowded round it (a line crossed "ω₁"). The crank
/// now has its enlarged detail beside the mechanism, where they stand clear.
#[test]
fn a_six_bar_with_a_crank_a_fourteenth_of_its_frame_has_its_labels_clear() {
    let text = common::six_bar(HEADER, 0.461563, 0.033111, (0.271366, 0.529799), -0.183497, 2.425637, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// Found by a 4000-case sweep (seed 31), within the generator's range (the crank 0.19 of
/// its frame): a 78 mm crank beside a 2.47 m rod is a circle 12 mm across on paper, and its
/// position numbers set off on leaders round it ("10", "11" below it) leave "8" crossed by a
/// line ("a line crossed “8”"). The same crowding as the six-bar above with a crank 3 mm on
/// paper, a size larger: its numbers too are in the crank's enlarged detail now.
#[test]
fn a_six_bar_with_a_crank_a_fifth_of_its_frame_and_a_long_rod_has_its_numbers_clear() {
    let text = common::six_bar(HEADER, 0.401235, 0.077826, (0.238488, 0.485740), 0.169785, 2.468025, "forward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// Found by the small-crank sweep (1500 cases, a random seed): a 71 mm crank beside an
/// 8.2 m rod is 2.8 mm on paper at 1:25 in a band 50 mm tall that the rod crosses; its
/// detail, 60 mm tall, found no free box there and was left out, and a line crossed “11”.
/// A detail that would fill more than half of its band now goes under the drawing.
#[test]
fn a_six_bar_with_a_crank_under_3_mm_and_an_8_m_rod_has_its_numbers_clear() {
    let text = common::six_bar(HEADER, 0.754295, 0.070594, (0.913781, 1.147984), 0.239350, 8.234664, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// Found by the six-bar sweep (a random seed, about 1 in 12,000 cases): position 1's
/// acceleration plan is about 40 × 8 mm at the sheet's one μ_a, and n_BA's spots near its
/// point are all taken by "d=s5", "b=n_DB", s2 and s4, placed before it in every round; it
/// hung on a leader through "d=s5" ("a line crosses “d=s5”"). It now takes a spot that
/// only "d=s5" blocked, and "d=s5" moves to a clean one of its own.
#[test]
fn a_flat_acceleration_plans_boxed_in_label_takes_a_spot_another_label_gives_up() {
    let text = common::six_bar(HEADER, 2.948469, 0.764900, (3.765320, 1.612518), 0.0, 4.084237, "backward");
    assert_eq!(verdict(&text), Ok(Outcome::Built));
}

/// The force analysis at the dead centres and toggles themselves and a nanoradian either side:
/// every fixture with a force analysis, its assigned position put at position 0 (an extreme of
/// the output link: a slider's dead centre, a rocker's toggle) and at the other extreme, each
/// exactly and 1e-9 rad before and after. Where the output link stands still the Zhukovsky
/// lever and the groups' equilibrium meet a zero velocity and a zero-length side: each case
/// builds with every number finite and its layout clean, or is refused with a reason.
#[test]
fn forces_at_and_a_nanoradian_beside_the_dead_centres_build_or_refuse_cleanly() {
    let with_assigned = |text: &str, deg: f64| -> String {
        let kept: Vec<&str> = text.lines().filter(|l| !l.trim_start().starts_with("assigned_deg:")).collect();
        kept.join("\n").replace("\nanalysis:\n", &format!("\nanalysis:\n  assigned_deg: {deg:.12}\n"))
    };
    let nano = 1e-9f64.to_degrees();
    let mut built = 0;
    for name in ["crank-slider-axial", "crank-slider-offset-vertical", "four-bar", "worked-example", "kulisa"] {
        let text = common::fixture_text(name);
        let p = pipeline::load(&text).unwrap();
        let sheets = pipeline::build(&p, &[]).unwrap();
        let other = sheets[0].output.results["other_extreme_phi_deg"].as_f64().unwrap_or(180.0);
        for at in [0.0, other] {
            for d in [0.0, nano, -nano] {
                let deg = (at + d).rem_euclid(360.0);
                let case = with_assigned(&text, deg);
                assert!(case.contains(&format!("assigned_deg: {deg:.12}")), "{name}: the angle was not set");
                match verdict(&case) {
                    Ok(Outcome::Built) => built += 1,
                    Ok(Outcome::Refused) => {}
                    Err(e) => panic!("{name} at φ1 = {deg}°: {e}"),
                }
            }
        }
    }
    assert!(built >= 20, "only {built} of 30 built");
}

/// Crank-rockers (Grashof by construction) with a resistance on the rocker's point K: K
/// anywhere from a fifth of the rocker to its end, the working stroke either sense, a
/// force from 100 N to 200 kN with an idle force or a diagram, any φ₁. Each either builds
/// with its layout measure clean and its physics right — the force square to K's radius
/// from the pivot and never helping K along, P_m the same from the groups, the lever and
/// the power balance — or is refused naming its field and line. A third of the cases.
#[test]
fn crank_rockers_with_a_load_on_the_rockers_point() {
    let lengths =
        (0.05f64..2.0, 0.1f64..0.4, 0.5f64..1.5, 0.5f64..1.5).prop_filter_map("a crank-rocker", |(d, rs, l2s, l3s)| {
            let (r, l2, l3) = (rs * d, l2s * d, l3s * d);
            let longest = d.max(l2).max(l3);
            (r < l2.min(l3).min(d) && r + longest <= d + l2 + l3 - longest).then_some((d, r, l2, l3))
        });
    let load = (0.2f64..1.0, any::<bool>(), 100.0f64..200_000.0, prop_oneof![Just(None), (0.0f64..0.5).prop_map(Some)]);
    let strategy = (lengths, any::<bool>(), 0.0f64..360.0, load).prop_map(
        |((d, r, l2, l3), left, phi, (at, cw, force, idle))| {
            let branch = if left { "left" } else { "right" };
            let working = if cw { "cw" } else { "ccw" };
            let rest = match idle {
                Some(share) => format!("idle_force: {:.1}", force * share),
                None => "diagram: [[0, 0], [0.5, 0.8], [1, 1]]".to_string(),
            };
            format!(
                "{HEADER}mechanism:\n  frame:\n    - {{name: O, at: [0, 0]}}\n    - {{name: C, at: [{d:.6}, 0]}}\n  crank: {{pivot: O, pin: A, length: {r:.6}, rpm: 120.0, sense: ccw}}\n  groups:\n    - rrr: {{links: [2, 3], joints: [A, C], point: B, lengths: [{l2:.6}, {l3:.6}], branch: {branch}}}\n  points:\n    - {{name: S2, link: 2, from: A, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: S3, link: 3, from: C, toward: B, ratio: 0.5, mass_centre: true}}\n    - {{name: K, link: 3, from: C, toward: B, ratio: {at:.3}}}\n  output_link: 3\nanalysis:\n  positions: 12\n  assigned_deg: {phi:.3}\nforces:\n  links:\n    - {{link: 2, q: 20}}\n    - {{link: 3, q: 20}}\n  loads:\n    - resistance: {{point: K, working: {working}, force: {force:.1}, {rest}}}\n"
            )
        },
    );
    let physics = |text: &str| {
        let p = pipeline::load(text).unwrap();
        rocker_load_wrong(&pipeline::build(&p, &[1]).unwrap().remove(0).output.results)
    };
    run_checked("crank-rockers with loads", 60, cases() / 3, strategy, physics);
}

/// What is wrong with the load on the rocker's point K (pivot C) in a sheet's results, if
/// anything: its force not square to CK, helping K along, or P_m not the same three ways.
fn rocker_load_wrong(r: &serde_json::Value) -> Option<String> {
    let xy = |v: &serde_json::Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
    let at = &r["assigned"]["points"];
    let (c, k, v) = (xy(&at["C"]["p"]), xy(&at["K"]["p"]), xy(&at["K"]["v"]));
    let f = xy(&r["forces"]["loads"][0]["force"]);
    let radius = [k[0] - c[0], k[1] - c[1]];
    let (fr, fv) = (f[0] * radius[0] + f[1] * radius[1], f[0] * v[0] + f[1] * v[1]);
    let norm = |a: [f64; 2]| (a[0] * a[0] + a[1] * a[1]).sqrt();
    if fr.abs() > 1e-9 * norm(f) * norm(radius) {
        return Some(format!("F·CK = {fr}"));
    }
    if fv > 1e-9 * norm(f) * norm(v) {
        return Some(format!("the resistance helps K along: F·v_K = {fv}"));
    }
    let forces = &r["forces"];
    let p_m = forces["balancing_force"].as_f64().unwrap();
    for other in ["balancing_force_lever", "balancing_force_power"] {
        let x = forces[other].as_f64().unwrap();
        if (x - p_m).abs() > 1e-6 * p_m.abs().max(1.0) {
            return Some(format!("{other} {x} against P_m {p_m}"));
        }
    }
    None
}
