//! The force analysis: every link in equilibrium, Newton's third law, the balancing force
//! three ways (kinetostatics, Zhukovsky lever, power balance), and a closed-form case.
// Tests compute their references with the platform's math; only src/ must not (clippy.toml).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{fixture_names, lever, lever_of};
use proptest::prelude::*;
use tmm_sheets::assert_near;
use tmm_sheets::lever::analysis;
use tmm_sheets::lever::kinetostatics::{self, FRAME, Forces, Kind};
use tmm_sheets::lever::motion;
use tmm_sheets::num::Near;

fn largest_force(f: &Forces) -> f64 {
    f.applied.iter().map(|a| a.force.hypot()).fold(0.0, f64::max)
}

fn analysed(name: &str) -> (tmm_sheets::project::LeverProject, Forces) {
    let p = lever(name);
    let k = analysis::kinematics(&p.mechanism, &p.settings).expect("kinematics");
    let model = p.forces.as_ref().unwrap_or_else(|| panic!("{name} has a force analysis"));
    let fa = analysis::forces(&p.mechanism, &k, model).unwrap_or_else(|e| panic!("{name}: {e}"));
    (p, fa.forces)
}

#[test]
fn every_link_of_every_fixture_is_in_equilibrium() {
    for name in fixture_names() {
        let (p, f) = analysed(&name);
        let scale = largest_force(&f);
        assert!(scale > 0.0, "{name}: no forces at all");
        for link in 0..p.mechanism.links.len() {
            let (r, m) = f.residual(link);
            let arm = 1.0 + f.on(link).map(|a| a.at.hypot()).fold(0.0, f64::max);
            assert!(
                r.hypot() <= 1e-9 * scale,
                "{name}: link {} force residual {r:?} (largest force {scale})",
                p.mechanism.links[link].number
            );
            assert!(
                m.abs() <= 1e-9 * scale * arm,
                "{name}: link {} moment residual {m}",
                p.mechanism.links[link].number
            );
        }
    }
}

#[test]
fn reactions_obey_newtons_third_law() {
    for name in fixture_names() {
        let (p, f) = analysed(&name);
        let mut pairs = 0;
        for a in &f.applied {
            let Kind::Reaction { from, .. } = a.kind else { continue };
            if from == FRAME {
                continue;
            }
            let back = f.applied.iter().find(|b| {
                b.on == from
                    && matches!(b.kind, Kind::Reaction { from: x, .. } if x == a.on)
                    && (b.at - a.at).hypot() < 1e-12
            });
            let b = back.unwrap_or_else(|| {
                panic!(
                    "{name}: no reaction of link {} on {}",
                    p.mechanism.links[a.on].number, p.mechanism.links[from].number
                )
            });
            assert!(
                (a.force + b.force).hypot() <= 1e-12 * a.force.hypot().max(1.0),
                "{name}: R_ij + R_ji = {:?}",
                a.force + b.force
            );
            pairs += 1;
        }
        // Every group has an inner pair and joins something moving or the crank.
        assert!(pairs >= 2 * p.mechanism.groups.len(), "{name}: only {pairs} reactions between links");
    }
}

#[test]
fn every_polygon_closes() {
    for name in fixture_names() {
        let (_, f) = analysed(&name);
        let scale = largest_force(&f);
        for poly in &f.polygons {
            let sum = poly.terms.iter().fold(kurbo::Vec2::ZERO, |s, t| s + t.force);
            assert!(sum.hypot() <= 1e-9 * scale, "{name}: polygon of group {:?} leaves {sum:?}", poly.group);
            if let Some(inner) = poly.inner {
                let first = poly.terms[..poly.split].iter().fold(inner.force, |s, t| s + t.force);
                assert!(
                    first.hypot() <= 1e-9 * scale,
                    "{name}: the first link's part of group {:?} does not close with the inner reaction",
                    poly.group
                );
            }
        }
    }
}

#[test]
fn balancing_force_agrees_three_ways_on_every_fixture() {
    for name in fixture_names() {
        let (_, f) = analysed(&name);
        let tol = Near::rel(1e-9).floor(1e-9);
        assert_near!(f.p_m, f.p_m_lever, tol, "{name}: kinetostatics against the lever");
        assert_near!(f.p_m, f.p_m_power, tol, "{name}: kinetostatics against the power balance");
    }
}

/// P_m at course angle `phi` with the fixture's masses and loads.
fn p_m_at(p: &tmm_sheets::project::LeverProject, k: &analysis::Kinematics, phi: f64) -> Forces {
    let model =
        analysis::place_loads(&p.mechanism, &k.motion, p.forces.as_ref().expect("forces")).expect("loads placed");
    let s = motion::sample_at(&p.mechanism, &k.motion, phi).expect("assembles");
    kinetostatics::analyse(&p.mechanism, &s, &model).expect("solvable")
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::with_cases(64) })]
    #[test]
    fn kinetostatic_p_m_is_the_power_balance_at_any_angle(which in 0usize..8, phi in 0.0f64..std::f64::consts::TAU) {
        let names = fixture_names();
        let name = &names[which % names.len()];
        let p = lever(name);
        let k = analysis::kinematics(&p.mechanism, &p.settings).expect("kinematics");
        let f = p_m_at(&p, &k, phi);
        let tol = Near::rel(1e-9).floor(1e-9 * largest_force(&f));
        prop_assert!(tol.holds(f.p_m, f.p_m_power), "{} at φ = {}: {} vs {}", name, phi, f.p_m, f.p_m_power);
        prop_assert!(tol.holds(f.p_m, f.p_m_lever));
    }
}

/// An axial crank-slider, massless, under a constant gas force F on the piston: the
/// textbook balancing force is P_m = F·sin(θ + β)/cos β, with θ the crank angle from the
/// dead centre beyond which the piston lies and sin β = (r/l)·sin θ.
#[test]
fn massless_crank_slider_under_a_constant_force_matches_the_closed_form() {
    let (r, l, force) = (0.05, 0.2, 1000.0);
    let text = format!(
        "project: {{title: t}}
mechanism:
  frame: [{{name: O, at: [0, 0]}}]
  crank: {{pivot: O, pin: A, length: {r}, rpm: 100, sense: ccw}}
  groups:
    - rrp: {{links: [2, 3], joint: A, point: B, length: {l}, guide: {{through: [0, 0], angle_deg: 0}}, branch: forward}}
analysis: {{positions: 12, start: max}}
forces:
  links: [{{link: 2, mass: 0}}, {{link: 3, mass: 0}}]
  loads:
    - gas: {{point: B, force: {force}, indicator: table, table: {{toward_head: [[0, 1], [1, 1]], away_from_head: [[0, 1], [1, 1]]}}}}
"
    );
    let p = lever_of(&text);
    let k = analysis::kinematics(&p.mechanism, &p.settings).expect("kinematics");
    for deg in [10.0, 45.0, 90.0, 135.0, 200.0, 300.0] {
        let phi = f64::to_radians(deg);
        let f = p_m_at(&p, &k, phi);
        // Position 0 is the outer dead centre (start: max), so θ = φ measured from +x.
        let beta = (r / l * phi.sin()).asin();
        let expected = force * (phi + beta).sin() / beta.cos();
        // The gas pushes the piston towards the crank (−x); at θ in (0, 180°) the piston moves
        // towards the crank, so the gas drives and the balancing force opposes the motion.
        assert_near!(f.p_m, -expected, Near::rel(1e-12).floor(1e-9), "θ = {deg}°: P_m against the closed form");
    }
}

/// A kulisa's block with a moment of inertia (`fixtures/kulisa.yaml` with J = 0.01 kg·m² on
/// link 2): on the lever its couple stands at the images of the kulisa's joints, which the
/// block turns with — the lever takes the same moment M·ω, computed here from the velocity
/// plan. At a point a metre along the block, its second arrow stood 120 mm off the lever,
/// alone. The balancing force still agrees three ways.
#[test]
fn a_blocks_inertia_couple_stands_on_its_kulisas_image() {
    let text = std::fs::read_to_string(common::root().join("fixtures/kulisa.yaml"))
        .unwrap()
        .replace("- {link: 2, mass: 2}", "- {link: 2, mass: 2, inertia: 0.01}");
    let p = lever_of(&text);
    let k = analysis::kinematics(&p.mechanism, &p.settings).expect("kinematics");
    let fa = analysis::forces(&p.mechanism, &k, p.forces.as_ref().unwrap()).unwrap();
    let (m, f) = (&p.mechanism, &fa.forces);
    let block = m.links.iter().position(|l| l.number == 2).unwrap();
    let kulisa = m.links.iter().position(|l| l.number == 3).unwrap();
    let state = &k.assigned.state;
    let sense = if m.sense().sign() > 0.0 { 1.0 } else { -1.0 };
    let images: Vec<_> = m.links[kulisa].points.iter().map(|&q| state.points[q].v.turn_90() * sense).collect();
    let couple: Vec<_> = f.lever.iter().filter(|l| l.couple && l.on == block).collect();
    assert_eq!(couple.len(), 2, "the block's couple");
    for c in &couple {
        let on_kulisa = images.iter().any(|&i| (i - c.image).hypot() < 1e-12);
        assert!(on_kulisa, "a couple force at {:?}, not at a kulisa joint's image {images:?}", c.image);
    }
    // The couple's moment on the lever is its power M·ω turned into a moment about the pole:
    // the images are the velocities turned 90° in ω1's sense, (v0 − v1) = ω·(p0 − p1)⊥,
    // so Σ image × F = −sense·ω·M.
    let inertia = f.inertia.iter().find(|i| i.link == block).unwrap();
    let moment: f64 = couple.iter().map(|c| c.image.cross(c.force)).sum();
    let power = inertia.moment * state.links[block].omega;
    assert!((moment + power * sense).abs() < 1e-9 * power.abs().max(1e-9), "{moment} vs −M·ω = {}", -power * sense);
    let tol = 1e-9 * largest_force(f);
    assert_near!(f.p_m, f.p_m_lever, tol, "kinetostatics against the lever");
}

/// The crank's polygon is drawn without crossing itself on every fixture: its equation may
/// list the known forces in any order, and G₁ + R₂₁ + P_m + R₀₁ = 0 of the offset
/// crank-slider crossed R₂₁ with R₀₁, both labelled at the crossing. Its sides (the forces
/// head to tail) are checked pairwise here, and the polygon must still close.
#[test]
fn every_crank_polygon_is_drawn_without_crossing_itself() {
    let mut checked = 0;
    for name in fixture_names() {
        if lever(&name).forces.is_none() {
            continue;
        }
        let (_, f) = analysed(&name);
        let crank = f.polygons.iter().find(|p| p.group.is_none()).expect("the crank's polygon");
        let mut pts = vec![kurbo::Vec2::ZERO];
        for t in &crank.terms {
            pts.push(*pts.last().unwrap() + t.force);
        }
        let scale = crank.terms.iter().map(|t| t.force.hypot()).fold(0.0, f64::max);
        assert!(pts.last().unwrap().hypot() < 1e-9 * scale, "{name}: the polygon does not close");
        if let Some((i, j)) = crossing_sides(&pts).first() {
            panic!("{name}: sides {i} and {j} of the crank's polygon cross");
        }
        checked += 1;
    }
    assert!(checked >= 6, "{checked} fixtures");
}

/// A group polygon's faults, from the forces head to tail: sides that turn back over the
/// side before them (within 12°, the last side before the first), and pairs of sides that
/// cross (strictly, sharing no vertex).
fn faults(forces: &[kurbo::Vec2]) -> usize {
    let sides: Vec<kurbo::Vec2> = forces.iter().copied().filter(|v| v.hypot() > 0.0).collect();
    let folds = (0..sides.len())
        .filter(|&k| {
            let (a, b) = (sides[k], sides[(k + 1) % sides.len()]);
            let turn = (-a.dot(b) / (a.hypot() * b.hypot())).clamp(-1.0, 1.0).acos().to_degrees();
            sides.len() > 1 && turn < 12.0
        })
        .count();
    let mut pts = vec![kurbo::Vec2::ZERO];
    for f in forces {
        pts.push(*pts.last().unwrap() + *f);
    }
    folds + crossing_sides(&pts).len()
}

/// The pairs of sides of the closed chain `pts` (the forces head to tail) that cross
/// strictly, sides sharing a vertex left out.
fn crossing_sides(pts: &[kurbo::Vec2]) -> Vec<(usize, usize)> {
    let n = pts.len() - 1;
    let cross = |p: kurbo::Vec2, q: kurbo::Vec2, r: kurbo::Vec2| (q - p).cross(r - p);
    (0..n)
        .flat_map(|i| (i + 2..n).filter(move |&j| !(i == 0 && j == n - 1)).map(move |j| (i, j)))
        .filter(|&(i, j)| {
            let (a, b, c, d) = (pts[i], pts[i + 1], pts[j], pts[j + 1]);
            cross(c, d, a) * cross(c, d, b) < 0.0 && cross(a, b, c) * cross(a, b, d) < 0.0
        })
        .collect()
}

/// A group's polygon lists each link's own loads (G and P_i) in the order that draws no side
/// back over the one before and no two sides crossing, where one does: the worked example's
/// II(2,3) drew P_i3 and then Rᵗ03 across it (their arrows one over the other in the
/// enlargement T). On every fixture each group's polygon closes, starts and ends with its
/// reactions, and has no more faults than the course's order (each link's G before its P_i,
/// rebuilt here); the worked example's II(2,3) fewer.
#[test]
fn group_polygons_list_g_and_p_i_so_that_no_side_runs_back_over_the_last() {
    let mut checked = 0;
    for name in fixture_names() {
        if lever(&name).forces.is_none() {
            continue;
        }
        let (_, f) = analysed(&name);
        for poly in f.polygons.iter().filter(|p| p.group.is_some()) {
            let scale = poly.terms.iter().map(|t| t.force.hypot()).fold(0.0, f64::max);
            let sum = poly.terms.iter().fold(kurbo::Vec2::ZERO, |s, t| s + t.force);
            assert!(sum.hypot() < 1e-9 * scale, "{name}: a polygon does not close");
            for t in [&poly.terms[0], poly.terms.last().unwrap()] {
                assert!(matches!(t.kind, Kind::Reaction { .. }), "{name}: {:?} at an end", t.kind);
            }
            // The course's order: each link's own loads in their places, G first.
            let own = |k: &Kind| matches!(k, Kind::Weight | Kind::Inertia);
            let mut course = poly.terms.clone();
            let places: Vec<usize> = (0..course.len()).filter(|&k| own(&course[k].kind)).collect();
            let mut loads: Vec<_> = places.iter().map(|&k| poly.terms[k]).collect();
            loads.sort_by_key(|t| (t.on, matches!(t.kind, Kind::Inertia)));
            for (&k, t) in places.iter().zip(loads) {
                course[k] = t;
            }
            let forces = |terms: &[kinetostatics::Applied]| terms.iter().map(|t| t.force).collect::<Vec<_>>();
            let (drawn, listed) = (faults(&forces(&poly.terms)), faults(&forces(&course)));
            assert!(drawn <= listed, "{name} group {:?}: {drawn} faults, the course's order {listed}", poly.group);
            if name == "worked-example" && poly.terms.iter().any(|t| t.on == 2) {
                assert!(drawn < listed, "the worked example's II(2,3): {drawn} faults, the course's order {listed}");
                checked += 1;
            }
        }
    }
    // Link 3 (its forces' `on` is 2) is in II(2,3) only.
    assert_eq!(checked, 1, "the worked example's II(2,3) checked");
}

/// Table 5's values are signed ("+": the balancing force drives the crank, along the pin's
/// velocity), while the initial link's drawing writes the force's magnitude with its arrow's
/// true sense: wherever a printed balancing value is negative, the table's title says what
/// the sign means, in the sheet's language; where none is, the title is the plain one. Both
/// occur on the fixtures (crank-slider-axial brakes at its φ1, in the expansion stroke).
#[test]
fn the_balancing_table_says_what_a_negative_sign_means() {
    use tmm_sheets::drawing::labels::Language;
    let mut seen = [false; 2];
    for name in fixture_names() {
        let mut p = common::fixture(&name);
        if p.lever.as_ref().is_none_or(|l| l.forces.is_none()) {
            continue;
        }
        for (lang, words) in
            [(Language::Uz, "harakatlantiruvchi"), (Language::Ru, "движущая"), (Language::En, "driving")]
        {
            p.info.language = lang;
            let b = common::build_lever(&p);
            let table = &b.notes[4];
            let negative = table
                .table
                .rows
                .iter()
                .filter(|r| !["S_H", "delta"].iter().any(|k| r.key.starts_with(k)))
                .flat_map(|r| r.printed(false))
                .any(|v| v.starts_with('-'));
            let said = table.title.contains(words);
            assert_eq!(said, negative, "{name} {lang:?}: “{}”, a negative value: {negative}", table.title);
            seen[usize::from(negative)] = true;
        }
    }
    assert_eq!(seen, [true, true], "both a driving and a braking balancing force among the fixtures");
}

/// Under the Zhukovsky lever, table 5's third balancing force is written with its source:
/// P″ₘ from the balance of powers, in the sheet's language, agreeing with the lever's P′ₘ
/// (two independent methods: virtual powers on the turned plan, and Σ P·v + M·ω = 0) to
/// the four figures written. A teacher found P″ in the table and nowhere on the sheet.
#[test]
fn the_lever_says_where_the_third_balancing_force_comes_from() {
    use tmm_sheets::drawing::labels::Language;
    let source = |lang: Language| match lang {
        Language::Uz => "(quvvatlar balansidan)",
        Language::Ru => "(из баланса мощностей)",
        Language::En => "(from the power balance)",
    };
    for lang in Language::ALL {
        let mut p = common::fixture("worked-example");
        p.info.language = lang;
        let b = &tmm_sheets::pipeline::build(&p, &[1]).unwrap()[0];
        let texts: Vec<_> = b.output.scene.texts().collect();
        let value = |main: &str| -> f64 {
            let t = texts
                .iter()
                .find(|t| t.text == main && t.tail.starts_with(" = "))
                .unwrap_or_else(|| panic!("{lang:?}: no {main} = …"));
            let number = t.tail[3..].split(' ').next().unwrap();
            number.replace(',', ".").replace('\u{2212}', "-").parse().unwrap_or_else(|_| panic!("{}", t.tail))
        };
        let p2 = texts.iter().find(|t| t.text == "P″" && t.tail.starts_with(" = ")).expect("P″ under the lever");
        assert!(p2.tail.ends_with(source(lang)), "{lang:?}: {:?}", p2.tail);
        let (lever, power) = (value("P′"), value("P″"));
        assert!((lever - power).abs() <= 5e-4 * lever.abs(), "{lang:?}: P′ = {lever}, P″ = {power}");
    }
}
