//! A force polygon's short sides enlarged: where weights and inertia forces of tens of
//! newtons stand between reactions of thousands, their sides at the polygon's μ_P are
//! fractions of a millimetre and their labels knotted at one vertex (the worked example's
//! II(2,3): G₂, P_i2, G₃, P_i3, R^t03 and R^t12 within 1.2 mm). Each run of sides under
//! 5 mm is drawn again, ringed and lettered, at its own μ_P in the room the sheet leaves.

mod common;

use common::fixture;
use tmm_sheets::drawing::scene::Item;
use tmm_sheets::pipeline;

/// Sides a ruler measures and a 3.5 mm label stands beside, mm (the sheet's `SIDE_MIN`).
const SIDE_MIN: f64 = 5.0;

#[test]
fn the_worked_examples_polygons_label_no_side_under_5_mm_and_enlarge_the_short_ones() {
    for name in ["worked-example", "two-cylinder-compressor", "crank-slider-axial"] {
        let built = pipeline::build(&fixture(name), &[1]).unwrap();
        let scales = &built[0].output.results["forces"]["scales"];
        let on_polygon = scales["smallest_polygon_side_mm"].as_f64().unwrap();
        assert!(on_polygon >= SIDE_MIN, "{name}: a side of {on_polygon} mm labelled on its polygon");
        assert!(scales["smallest_enlarged_side_mm"].as_f64().is_some(), "{name}: nothing enlarged");
    }
    // The worked example's II(2,3) polygon (μ_P = 200 N/mm) rings its two runs and draws
    // each at a μ_P at least twice as fine, titled with its letter and scale.
    let built = pipeline::build(&fixture("worked-example"), &[1]).unwrap();
    let scene = &built[0].output.scene;
    let (group, part) = scene
        .groups
        .iter()
        .find_map(|g| g.parts.iter().find(|p| p.id == "forces.group.2-3").map(|p| (g, p)))
        .expect("the II(2,3) cell");
    let items = &group.items[part.items.clone()];
    let rings = items.iter().filter(|i| matches!(i, Item::Circle { r, filled: false, .. } if *r > 3.0)).count();
    assert_eq!(rings, 2, "rings round the short sides");
    let titles: Vec<f64> = items
        .iter()
        .filter_map(|i| match i {
            Item::Text(t) if t.text == "μ" && t.sub == "P" && t.tail.ends_with(')') => {
                let value = t.tail.trim_start_matches(" = ").split(' ').next()?.replace(',', ".");
                value.parse().ok()
            }
            _ => None,
        })
        .collect();
    assert_eq!(titles.len(), 2, "{titles:?}");
    assert!(titles.iter().all(|&mu| mu * 2.0 <= 200.0), "{titles:?}");
}
