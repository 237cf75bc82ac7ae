//! The overlay: a sheet's constructions alone, in one colour, exactly where the sheet has
//! them — every line of the overlay is a line of the sheet, and every line of a drawing is on
//! the overlay.

mod common;

use common::{fixture, fixture_names};
use std::collections::BTreeMap;
use tmm_sheets::backend::svg;
use tmm_sheets::drawing::frame::DESIGNATION_BOX;
use tmm_sheets::drawing::scene::{Ink, Item};
use tmm_sheets::pipeline::{self, Built};
use tmm_sheets::sheets::scaffold;

/// The drawn elements of an SVG (paths and circles), each counted, with the colour left out.
fn marks(text: &str, colour: &str) -> BTreeMap<String, usize> {
    let mut out = BTreeMap::new();
    for line in text.lines().filter(|l| l.starts_with("<path ") || l.starts_with("<circle ")) {
        *out.entry(line.replace(colour, "INK")).or_insert(0) += 1;
    }
    out
}

fn sheets(name: &str) -> Vec<Built> {
    pipeline::build(&fixture(name), &[]).unwrap()
}

#[test]
fn every_mark_of_the_overlay_is_a_mark_of_the_sheet_at_the_same_place() {
    for name in fixture_names() {
        for b in sheets(&name) {
            let over = scaffold::overlay(&b.output.scene);
            assert_eq!(over.ink, Ink::Overlay);
            let text = svg::write(&over).unwrap();
            let (o, s) = (marks(&text, "#e60000"), marks(&b.svg, "#000"));
            for (mark, n) in &o {
                let on_sheet = s.get(mark).copied().unwrap_or(0);
                assert!(on_sheet >= *n, "{name} sheet {}: overlay mark not on the sheet: {mark}", b.output.number);
            }
            assert!(!text.contains("<text") && !text.contains("#000") && !text.contains("fill=\"#fff\""));
            assert!(!text.contains("title-block") && !text.contains(".table."), "{name}: a table on the overlay");
            assert!(!text.contains(DESIGNATION_BOX), "{name}: box 26 (the title block's) on the overlay");
        }
    }
}

#[test]
fn every_line_of_every_drawing_is_on_the_overlay() {
    let b = &sheets("worked-example")[0];
    let over = scaffold::overlay(&b.output.scene);
    for g in b.output.scene.groups.iter().filter(|g| g.id != scaffold::TITLE_BLOCK && g.id != DESIGNATION_BOX) {
        let og = over.groups.iter().find(|o| o.id == g.id).expect("the group is on the overlay");
        let in_tables: usize = g
            .parts
            .iter()
            .filter(|p| p.id.starts_with("table."))
            .map(|p| p.items.clone().filter(|&i| !matches!(g.items[i], Item::Text(_))).count())
            .sum();
        let drawn = g.items.iter().filter(|i| !matches!(i, Item::Text(_))).count();
        // A label's leader and a legend's sample line are writing, not constructions.
        let writing = g.writing.len();
        assert!(g.writing.iter().all(|&i| matches!(g.items[i], Item::Path { .. })), "{}: writing is lines", g.id);
        assert_eq!(og.items.len(), drawn - in_tables - writing, "{}: lines lost or added", g.id);
        // The plans keep their ids on the overlay.
        for p in g.parts.iter().filter(|p| p.id.starts_with("plan.")) {
            assert!(og.parts.iter().any(|o| o.id == p.id), "{}: {} lost", g.id, p.id);
        }
    }
    let mechanism = b.output.scene.groups.iter().find(|g| g.id == "mechanism").unwrap();
    assert!(!mechanism.writing.is_empty(), "the trajectories' legend sample is writing");
    // The overlay's plan 3 is the sheet's plan 3 without its letters and their leaders.
    let plan = |g: &tmm_sheets::drawing::scene::Group| -> Vec<Item> {
        let range = g.parts.iter().find(|p| p.id == "plan.v.3").unwrap().items.clone();
        range
            .filter(|i| !matches!(g.items[*i], Item::Text(_)) && !g.writing.contains(i))
            .map(|i| g.items[i].clone())
            .collect()
    };
    let group =
        |s: &tmm_sheets::drawing::scene::Scene| s.groups.iter().find(|g| g.id == "velocity-plans").unwrap().clone();
    assert_eq!(plan(&group(&b.output.scene)), plan(&group(&over)));
}

#[test]
fn the_overlay_pdf_is_an_a1_page_in_red() {
    let b = &sheets("worked-example")[2];
    let files = pipeline::overlays(std::slice::from_ref(b)).unwrap();
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["sheet3-overlay.svg", "sheet3-overlay.pdf"]);
    let pdf = &files[1].1;
    assert!(pdf.starts_with(b"%PDF"));
    // 841 × 594 mm in points, and the red of the ink as the stroke colour.
    let text = String::from_utf8_lossy(pdf);
    assert!(text.contains("2383.937") && text.contains("1683.7795"), "not A1");
    // Rasterised by poppler (when installed): red marks, none black.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("o.pdf"), pdf).unwrap();
    let Ok(out) = std::process::Command::new("pdftoppm").args(["-r", "30"]).arg(dir.path().join("o.pdf")).output()
    else {
        eprintln!("skipped: pdftoppm not installed");
        return;
    };
    let ppm = out.stdout;
    // P6 header: four whitespace-separated fields, then RGB bytes.
    let mut fields = 0;
    let mut at = 0;
    while fields < 4 {
        while ppm[at].is_ascii_whitespace() {
            at += 1;
        }
        while !ppm[at].is_ascii_whitespace() {
            at += 1;
        }
        fields += 1;
    }
    let px: Vec<&[u8]> = ppm[at + 1..].chunks(3).collect();
    let red = px.iter().filter(|p| p[0] > 150 && p[1] < 120 && p[2] < 120).count();
    let dark = px.iter().filter(|p| p[0] < 100 && p[1] < 100 && p[2] < 100).count();
    assert!(red > 1000 && dark == 0, "red {red}, dark {dark}");
}
