//! Tests only: our SVG read back with usvg (knowing only the embedded font) and rasterised
//! with resvg, to count what a renderer sees and to compare with the PDF and PNG backends.
#![allow(dead_code)]

use std::sync::Arc;
use tmm_sheets::font;

/// usvg options that know exactly one font: the embedded one.
pub fn options() -> usvg::Options<'static> {
    let mut db = usvg::fontdb::Database::new();
    db.load_font_data(font::BYTES.to_vec());
    db.set_sans_serif_family(font::FAMILY);
    usvg::Options { fontdb: Arc::new(db), font_family: font::FAMILY.into(), ..Default::default() }
}

pub fn parse(svg: &str) -> usvg::Tree {
    usvg::Tree::from_str(svg, &options()).unwrap_or_else(|e| panic!("the SVG does not parse: {e}"))
}

/// The SVG as a PNG at `dpi`, sized as the PNG backend sizes it.
pub fn png(svg: &str, width_mm: f64, height_mm: f64, dpi: f64) -> Vec<u8> {
    let tree = parse(svg);
    let px = |mm: f64| (mm / 25.4 * dpi).round().max(1.0) as u32;
    let (w, h) = (px(width_mm), px(height_mm));
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).expect("a raster size");
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let sx = w as f32 / tree.size().width();
    let sy = h as f32 / tree.size().height();
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(sx, sy), &mut pixmap.as_mut());
    pixmap.encode_png().expect("PNG encoding")
}
