//! The planetary stage's synthesis: every set it returns is re-verified here with the
//! course's formulas written anew (integers where the condition is one of integers), the
//! guide's own set is shown to fail, and bad input gives errors, never a panic.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

use proptest::prelude::*;
use std::f64::consts::PI;
use tmm_sheets::gears::planetary::{Relation, Scheme, Stage, StageError, StageSpec, check, synthesise};

const NAMES: [&str; 7] =
    ["ratio", "coaxiality", "neighbours", "assembly", "no_undercut", "ring_teeth", "ring_planet_difference"];

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

/// The ratio, from the scheme's formula.
fn ratio_of(z: &[u32]) -> f64 {
    match *z {
        [z1, _, z3] => 1.0 + f64::from(z3) / f64::from(z1),
        [z1, z2, z2b, z3] => 1.0 + f64::from(z2) * f64::from(z3) / (f64::from(z1) * f64::from(z2b)),
        _ => panic!("{z:?}"),
    }
}

/// Every condition of the course for the set, independently of the code under test; the
/// first that fails, by name.
fn first_failure(spec: &StageSpec, z: &[u32], k: u32) -> Option<&'static str> {
    let ha = spec.addendum;
    let (z1, z2, z2b, z3) = match *z {
        [z1, z2, z3] => (z1, z2, z2, z3),
        [z1, z2, z2b, z3] => (z1, z2, z2b, z3),
        _ => panic!("{z:?}"),
    };
    let [a, b, c, d, kk] = [z1, z2, z2b, z3, k].map(u64::from);
    let u = ratio_of(z);
    let checks = [
        ((u - spec.ratio_required).abs() <= spec.tolerance * spec.ratio_required * (1.0 + 1e-12), "ratio"),
        (a + b + c == d, "coaxiality"),
        ((PI / f64::from(k)).sin() > (f64::from(z2.max(z2b)) + 2.0 * ha) / f64::from(z1 + z2), "neighbours"),
        ((a * c + b * d) % (kk * gcd(b, c)) == 0, "assembly"),
        (z1 >= 17 && z2 >= 17 && z2b >= 17, "no_undercut"),
        (z3 >= 85, "ring_teeth"),
        (z3 > z2b + 8, "ring_planet_difference"),
    ];
    checks.iter().find(|(ok, _)| !ok).map(|(_, name)| *name)
}

/// The stage is valid by the test's own formulas, and its conditions say so, in order.
fn assert_valid(spec: &StageSpec, stage: &Stage) {
    assert_eq!(stage.z.len(), if spec.scheme == Scheme::SunPlanetRing { 3 } else { 4 });
    assert_eq!(first_failure(spec, &stage.z, stage.planets), None, "{stage:?}");
    assert_eq!(stage.ratio, ratio_of(&stage.z));
    assert!((3..=8).contains(&stage.planets) || spec.planets == Some(stage.planets));
    let names: Vec<&str> = stage.conditions.iter().map(|c| c.name.key()).collect();
    assert_eq!(names, NAMES);
    for c in &stage.conditions {
        assert!(c.ok && c.value.is_finite() && c.limit.is_finite(), "{c:?}");
    }
}

fn condition<'a>(
    conditions: &'a [tmm_sheets::gears::planetary::Condition],
    name: &str,
) -> &'a tmm_sheets::gears::planetary::Condition {
    conditions.iter().find(|c| c.name.key() == name).unwrap()
}

#[test]
fn the_guides_set_17_68_153_with_five_planets_fails_the_neighbour_condition() {
    // u = 1 + 153/17 = 10 exactly.
    let spec = StageSpec::course(Scheme::SunPlanetRing, 10.0);
    let conditions = check(&spec, &[17, 68, 153], 5).unwrap();
    let n = condition(&conditions, "neighbours");
    // The guide says sin 36° = 0.86; it is 0.5878 < (68 + 2)/(17 + 68) = 0.8235.
    assert!(((PI / 5.0).sin() - 0.587_785_252_292_473).abs() < 1e-15);
    assert!((n.value - (PI / 5.0).sin()).abs() < 1e-15, "{n:?}");
    assert!((n.limit - 70.0 / 85.0).abs() < 1e-15, "{n:?}");
    assert_eq!((format!("{:.4}", n.value), format!("{:.4}", n.limit)), ("0.5878".into(), "0.8235".into()));
    assert_eq!(n.relation, Relation::Greater);
    assert!(!n.ok);
    assert_eq!(first_failure(&spec, &[17, 68, 153], 5), Some("neighbours"));
    for c in &conditions {
        assert_eq!(c.ok, c.name.key() != "neighbours", "{c:?}");
    }
    // The integer conditions with their values: 17 + 2·68 = 153, (17 + 153)/5 = 34.
    let coax = condition(&conditions, "coaxiality");
    assert_eq!((coax.value, coax.limit, coax.relation), (153.0, 153.0, Relation::Equal));
    let asm = condition(&conditions, "assembly");
    assert_eq!((asm.value, asm.limit, asm.relation), (34.0, 34.0, Relation::Integer));
    assert_eq!(condition(&conditions, "no_undercut").value, 17.0);
    assert_eq!(condition(&conditions, "ring_planet_difference").value, 85.0);
    // With three planets the same teeth pass neighbours (sin 60° = 0.866) but not assembly (170/3).
    let three = check(&spec, &[17, 68, 153], 3).unwrap();
    assert!(condition(&three, "neighbours").ok && !condition(&three, "assembly").ok);
    // No set the program returns is the guide's: its choice for u = 10 differs.
    let stage = synthesise(&spec).unwrap();
    assert_valid(&spec, &stage);
    assert_ne!((stage.z.as_slice(), stage.planets), (&[17, 68, 153][..], 5));
}

/// Every valid single-row set with the test's formulas, best first by the documented order:
/// the smallest ring, then the closest ratio, more planets, the smallest sun — unless a ring at
/// most 1.25 times that one gives the ratio exactly (to 1e-9): then the best of those.
fn best_single_row_by_brute_force(spec: &StageSpec) -> Option<(Vec<u32>, u32)> {
    let smallest = best_single_row_among(spec, |_| true)?;
    let exact = |z: &[u32]| (ratio_of(z) - spec.ratio_required).abs() <= 1e-9 * spec.ratio_required;
    if exact(&smallest.0) {
        return Some(smallest);
    }
    let allowed = f64::from(smallest.0[2]) * 1.25;
    best_single_row_among(spec, |z| exact(z) && f64::from(z[2]) <= allowed).or(Some(smallest))
}

fn best_single_row_among(spec: &StageSpec, keep: impl Fn(&[u32]) -> bool) -> Option<(Vec<u32>, u32)> {
    let mut best: Option<(u32, f64, i64, u32, Vec<u32>, u32)> = None;
    for z1 in 1..=spec.z_max {
        for z2 in 1..=spec.z_max {
            let z3 = z1 + 2 * z2;
            if z3 > spec.z_max {
                break;
            }
            for k in 3..=8 {
                let z = vec![z1, z2, z3];
                if keep(&z) && first_failure(spec, &z, k).is_none() {
                    let err = (ratio_of(&z) - spec.ratio_required).abs();
                    let key = (z3, err, -i64::from(k), z1, z.clone(), k);
                    let better = best.as_ref().is_none_or(|b| (key.0, key.1, key.2, key.3) < (b.0, b.1, b.2, b.3));
                    if better {
                        best = Some(key);
                    }
                }
            }
        }
    }
    best.map(|b| (b.4, b.5))
}

#[test]
fn the_worked_example_u_9_5865_gets_17_64_145_with_three_planets() {
    let u: f64 = (750.0 / 70.0) / (19.0 / 17.0);
    assert!((u - 9.5865).abs() < 1e-4);
    let spec = StageSpec::course(Scheme::SunPlanetRing, u);
    let stage = synthesise(&spec).unwrap();
    assert_valid(&spec, &stage);
    assert_eq!((stage.z.clone(), stage.planets), (vec![17, 64, 145], 3), "{stage:?}");
    // Independently: 17 + 2·64 = 145, (17 + 145)/3 = 54, sin 60° = 0.866 > 66/81 = 0.815,
    // u = 1 + 145/17 = 9.5294, −0.60 % from 9.5865.
    assert_eq!(17 + 2 * 64, 145);
    assert_eq!((17 + 145) % 3, 0);
    assert!((PI / 3.0).sin() > 66.0 / 81.0);
    assert!((stage.ratio - 9.529_411_764_705_882).abs() < 1e-12);
    assert!(((stage.ratio - u) / u * 100.0 + 0.596).abs() < 1e-3);
    // The smaller ring 143 (z2 = 63) fails assembly with K = 3 (160/3), and K ≥ 4 fails
    // neighbours (sin 45° = 0.707 < 65/80); so 145 is the smallest ring.
    assert_eq!(first_failure(&spec, &[17, 63, 143], 3), Some("assembly"));
    assert_eq!(first_failure(&spec, &[17, 63, 143], 4), Some("neighbours"));
    assert_eq!(best_single_row_by_brute_force(&spec), Some((stage.z.clone(), stage.planets)));
}

/// The undercut fixture's stage: the smallest reducer within ±3 % is 22/32/86 (u = 4.909),
/// but 24/36/96 with K = 4 gives 5 exactly, a ring only 96/86 = 1.12 times larger:
/// 24 + 2·36 = 96, (24 + 96)/4 = 30, sin 45° = 0.7071 > 38/60 = 0.6333.
#[test]
fn an_exact_ratio_a_little_larger_wins_over_the_smallest_reducer() {
    let spec = StageSpec { planets: Some(4), ..StageSpec::course(Scheme::SunPlanetRing, 5.0) };
    let stage = synthesise(&spec).unwrap();
    assert_eq!((stage.z.clone(), stage.planets), (vec![24, 36, 96], 4), "{stage:?}");
    assert_eq!(stage.ratio, 5.0);
    assert_eq!(first_failure(&spec, &[22, 32, 86], 4), None);
    assert!((PI / 4.0).sin() > 38.0 / 60.0);
    // A ratio that only a ring of 373 teeth gives exactly keeps the smallest reducer.
    let spec = StageSpec::course(Scheme::SunPlanetRing, 4.73);
    let stage = synthesise(&spec).unwrap();
    assert!(stage.z[2] < 120 && stage.ratio != 4.73, "{stage:?}");
}

#[test]
fn the_single_row_choice_is_the_brute_force_best_for_several_ratios() {
    for u in [2.6, 4.0, 5.0, 5.5, 7.1, 10.0, 12.5, 16.0, 21.0, 24.0] {
        let spec = StageSpec::course(Scheme::SunPlanetRing, u);
        let brute = best_single_row_by_brute_force(&spec);
        match synthesise(&spec) {
            Ok(stage) => {
                assert_valid(&spec, &stage);
                assert_eq!(Some((stage.z.clone(), stage.planets)), brute, "u = {u}");
            }
            Err(e) => {
                assert!(matches!(e, StageError::NoSet { .. }), "{e:?}");
                assert_eq!(brute, None, "u = {u}: {e}");
            }
        }
    }
}

#[test]
fn the_single_row_refuses_ratios_it_cannot_reach_and_says_what_to_change() {
    for u in [2.0, 30.0, 50.0] {
        let spec = StageSpec::course(Scheme::SunPlanetRing, u);
        assert_eq!(best_single_row_by_brute_force(&spec), None, "u = {u}");
        let e = synthesise(&spec).unwrap_err();
        let StageError::NoSet { scheme, ratio, tolerance, reachable: Some((lo, hi)), .. } = e.clone() else {
            panic!("{e:?}")
        };
        assert_eq!((scheme, ratio, tolerance), (Scheme::SunPlanetRing, u, 0.03));
        assert!(lo > 2.0 && hi < 30.0, "{lo}…{hi}");
        let text = e.to_string();
        for needle in ["sun-planet-ring", &format!("{u:.4}"), "±3 %", "z ≤ 400", "K = 3…8", "the other scheme"] {
            assert!(text.contains(needle), "{needle:?} not in: {text}");
        }
    }
    // Inside the reachable span but with no tolerance: the message says to widen it.
    let spec = StageSpec { tolerance: 0.0, planets: Some(3), ..StageSpec::course(Scheme::SunPlanetRing, 9.5865) };
    let text = synthesise(&spec).unwrap_err().to_string();
    assert!(
        text.contains("widen the tolerance") && text.contains("K = 3 ") && text.contains("number of planets"),
        "{text}"
    );
}

#[test]
fn the_double_planet_finds_sets_for_20_and_40_and_the_smallest_reducer() {
    for u in [20.0, 40.0] {
        let spec = StageSpec::course(Scheme::DoublePlanet, u);
        let stage = synthesise(&spec).unwrap_or_else(|e| panic!("u = {u}: {e}"));
        assert_valid(&spec, &stage);
        // Brute force over every set whose outer size, max(z3, z1 + 2·z2) in modules, is
        // smaller: no valid set makes a smaller reducer, unless the one chosen gives u exactly
        // and is at most 1.25 times the smallest; then no exact set is smaller.
        let size = |z: &[u32]| z[3].max(z[0] + 2 * z[1]);
        let exact = |z: &[u32]| (ratio_of(z) - u).abs() <= 1e-9 * u;
        let best = size(&stage.z);
        let mut smallest = best;
        for z1 in 17..best {
            for z2 in 17..best {
                for z2b in 17..best {
                    let z = [z1, z2, z2b, z1 + z2 + z2b];
                    if size(&z) >= best || !(3..=8).any(|k| first_failure(&spec, &z, k).is_none()) {
                        continue;
                    }
                    assert!(exact(&stage.z) && !exact(&z), "u = {u}: {z:?} beats {stage:?}");
                    smallest = smallest.min(size(&z));
                }
            }
        }
        assert!(f64::from(best) <= 1.25 * f64::from(smallest), "u = {u}: {stage:?} against size {smallest}");
        println!("u = {u}: z = {:?}, K = {}, u found = {:.4}", stage.z, stage.planets, stage.ratio);
    }
}

#[test]
fn bad_input_gives_errors_not_panics() {
    for r in [1.0, 0.5, -3.0, 0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e6] {
        for scheme in Scheme::ALL {
            let spec = StageSpec::course(scheme, r);
            assert!(matches!(synthesise(&spec), Err(StageError::BadRatio { .. })), "{r}");
            let z: &[u32] = if scheme == Scheme::SunPlanetRing { &[17, 64, 145] } else { &[17, 20, 20, 57] };
            assert!(matches!(check(&spec, z, 3), Err(StageError::BadRatio { .. })), "{r}");
        }
    }
    let spec = StageSpec::course(Scheme::SunPlanetRing, 9.5);
    for k in [0, 1, 13, u32::MAX] {
        assert_eq!(
            synthesise(&StageSpec { planets: Some(k), ..spec.clone() }),
            Err(StageError::BadPlanets { planets: k })
        );
        assert_eq!(check(&spec, &[17, 64, 145], k), Err(StageError::BadPlanets { planets: k }));
    }
    for z in [&[][..], &[17, 64], &[17, 64, 64, 145], &[0, 64, 145], &[17, 0, 145]] {
        assert!(matches!(check(&spec, z, 3), Err(StageError::BadTeeth { .. })), "{z:?}");
        assert_eq!(Scheme::SunPlanetRing.ratio(z), 0.0);
    }
    let double = StageSpec::course(Scheme::DoublePlanet, 9.5);
    assert!(matches!(check(&double, &[17, 64, 145], 3), Err(StageError::BadTeeth { expected: 4, .. })));
    for bad in [
        StageSpec { tolerance: f64::NAN, ..spec.clone() },
        StageSpec { tolerance: -0.01, ..spec.clone() },
        StageSpec { addendum: 0.0, ..spec.clone() },
        StageSpec { z_min: 0, ..spec.clone() },
        StageSpec { z_max: 100_000, ..spec.clone() },
        StageSpec { z_max: 10, ..spec.clone() },
    ] {
        assert!(matches!(synthesise(&bad), Err(StageError::BadParameter { .. })), "{bad:?}");
    }
    // Limits that leave nothing to find: a refusal, not a panic.
    let e = synthesise(&StageSpec { ring_min: 500, ..spec.clone() }).unwrap_err();
    assert!(matches!(e, StageError::NoSet { reachable: None, .. }), "{e:?}");
    assert!(e.to_string().contains("meets the conditions at all"), "{e}");
}

#[test]
fn errors_read_as_plain_english_naming_what_was_asked() {
    let e = synthesise(&StageSpec::course(Scheme::DoublePlanet, f64::NAN)).unwrap_err();
    assert!(e.to_string().contains("NaN"), "{e}");
    let e = check(&StageSpec::course(Scheme::DoublePlanet, 5.0), &[17, 20, 57], 3).unwrap_err();
    assert!(e.to_string().contains("double-planet") && e.to_string().contains("4 tooth numbers"), "{e}");
    let e = synthesise(&StageSpec { planets: Some(1), ..StageSpec::course(Scheme::DoublePlanet, 5.0) }).unwrap_err();
    assert!(e.to_string().contains("K = 1"), "{e}");
}

/// How long the search takes over ratios 2–50, with K searched or fixed, a tight tolerance
/// and the largest z_max accepted (refusals included): `cargo test --release --test
/// planetary search_time -- --ignored --nocapture --test-threads=1`.
#[test]
#[ignore]
fn search_time() {
    let mut variants: Vec<(Option<u32>, f64, u32)> = vec![(None, 0.03, 400), (None, 0.01, 400)];
    variants.extend((3..=8).map(|k| (Some(k), 0.03, 400)));
    variants.extend([(None, 0.03, 1000), (Some(8), 0.03, 1000)]);
    for scheme in Scheme::ALL {
        for &(planets, tolerance, z_max) in &variants {
            let (mut worst, mut total, mut found, mut n, mut worst_u) = (0.0_f64, 0.0, 0, 0, 0.0);
            for i in 0..=480 {
                let u = 2.0 + f64::from(i) * 0.1;
                let spec = StageSpec { planets, tolerance, z_max, ..StageSpec::course(scheme, u) };
                let t = std::time::Instant::now();
                let r = synthesise(&spec);
                let dt = t.elapsed().as_secs_f64() * 1e3;
                found += usize::from(r.is_ok());
                n += 1;
                total += dt;
                if dt > worst {
                    (worst, worst_u) = (dt, u);
                }
            }
            println!(
                "{scheme}, K {planets:?}, ±{tolerance}, z ≤ {z_max}: {found}/{n} found, mean {:.3} ms, worst {worst:.3} ms at u = {worst_u:.1}",
                total / f64::from(n)
            );
        }
    }
}

fn scheme() -> impl Strategy<Value = Scheme> {
    prop_oneof![Just(Scheme::SunPlanetRing), Just(Scheme::DoublePlanet)]
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::with_cases(256) })]

    #[test]
    fn every_set_returned_meets_every_condition(
        u in 2.0..50.0f64,
        scheme in scheme(),
        tolerance in prop_oneof![Just(0.03), 0.0..0.06f64],
        planets in prop_oneof![Just(None), (2u32..=12).prop_map(Some)],
    ) {
        let spec = StageSpec { tolerance, planets, ..StageSpec::course(scheme, u) };
        match synthesise(&spec) {
            Ok(stage) => assert_valid(&spec, &stage),
            Err(StageError::NoSet { reachable, .. }) => {
                if let Some((lo, hi)) = reachable {
                    prop_assert!(lo.is_finite() && hi.is_finite() && 1.0 < lo && lo <= hi);
                }
            }
            Err(e) => prop_assert!(false, "{e:?}"),
        }
    }

    #[test]
    fn check_never_panics_and_says_only_finite_numbers(
        scheme in scheme(),
        z in prop::collection::vec(prop_oneof![0u32..300, Just(u32::MAX), any::<u32>()], 0..6),
        k in prop_oneof![0u32..14, any::<u32>()],
        u in prop_oneof![1.0..60.0f64, any::<f64>()],
    ) {
        let spec = StageSpec::course(scheme, u);
        if let Ok(conditions) = check(&spec, &z, k) {
            prop_assert_eq!(conditions.len(), 7);
            for c in &conditions {
                prop_assert!(c.value.is_finite() && c.limit.is_finite(), "{:?}", c);
            }
            if z.iter().all(|&t| t < 100_000) {
                let ok = conditions.iter().all(|c| c.ok);
                prop_assert_eq!(ok, first_failure(&spec, &z, k).is_none());
            }
        }
        let _ = scheme.ratio(&z);
    }
}

/// The README's rule, on the case that tells "the smallest ring" from "the smallest reducer":
/// 17/46/22/85 and 22/46/17/85 have the same ring and the same ratio, but the first one's
/// planet z2 reaches to z1 + 2·z2 = 109 modules and the second one's to 114, so the first is
/// the smaller reducer and is chosen, though the second would take more planets.
#[test]
fn the_double_planet_prefers_the_smaller_outer_size_over_a_same_ring() {
    let u = ratio_of(&[17, 46, 22, 85]);
    assert_eq!(u, ratio_of(&[22, 46, 17, 85]));
    let spec = StageSpec::course(Scheme::DoublePlanet, u);
    let stage = synthesise(&spec).unwrap();
    assert_valid(&spec, &stage);
    assert_eq!((stage.z.as_slice(), stage.planets), (&[17, 46, 22, 85][..], 3));
    // The other set is valid too, with four planets, and has the same ring.
    assert_eq!(first_failure(&spec, &[22, 46, 17, 85], 4), None);
}
