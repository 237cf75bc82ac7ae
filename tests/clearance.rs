//! Labels stand clear of the lines: a letter that touches a line reads as crowded, and at
//! 150 dpi as a label on a line, even where the sheet's layout measure (which counts a line
//! that enters the letters' box) finds nothing. Placed labels keep 0.5 mm from any stroke;
//! this holds every fixture's every sheet, in the three languages, to 0.4 mm.

mod common;

use common::{fixture, fixture_names};
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::drawing::layout::texts_near_lines;
use tmm_sheets::drawing::scene::{Group, Item};
use tmm_sheets::pipeline;

/// From a label's letters' box to the nearest line's centre, mm, at least.
const CLEARANCE: f64 = 0.4;

/// A table's texts stand in its cells by the table's own rule, not by the label placer.
fn in_a_table(g: &Group, item: usize) -> bool {
    g.id == "tables" || g.parts.iter().any(|p| p.id.contains("table") && p.items.contains(&item))
}

#[test]
fn every_label_stands_clear_of_the_lines_on_every_fixture_in_every_language() {
    let mut near = Vec::new();
    let mut checked = 0;
    for name in fixture_names() {
        for lang in [Language::Uz, Language::Ru, Language::En] {
            let mut p = fixture(&name);
            p.info.language = lang;
            for b in pipeline::build(&p, &[]).unwrap() {
                let scene = &b.output.scene;
                checked += scene.texts().count();
                for (gi, ii) in texts_near_lines(scene, CLEARANCE) {
                    let g = &scene.groups[gi];
                    let Item::Text(t) = &g.items[ii] else { continue };
                    if !in_a_table(g, ii) {
                        near.push(format!(
                            "{name} {lang:?} '{}': “{}” at ({:.1}, {:.1})",
                            g.id,
                            t.plain(),
                            t.at.x,
                            t.at.y
                        ));
                    }
                }
            }
        }
    }
    assert!(checked > 10_000, "only {checked} texts");
    assert!(near.is_empty(), "{} labels within {CLEARANCE} mm of a line:\n{}", near.len(), near.join("\n"));
}
