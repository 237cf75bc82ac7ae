//! SVG text → usvg tree (with only the embedded font), → PDF (krilla-svg) or PNG (resvg).

pub use super::BackendError;
use crate::font;
use std::sync::Arc;

/// usvg options that know exactly one font: the embedded one.
pub fn options() -> usvg::Options<'static> {
    let mut db = usvg::fontdb::Database::new();
    db.load_font_data(font::BYTES.to_vec());
    db.set_sans_serif_family(font::FAMILY);
    usvg::Options { fontdb: Arc::new(db), font_family: font::FAMILY.into(), ..Default::default() }
}

pub fn parse(svg: &str) -> Result<usvg::Tree, BackendError> {
    usvg::Tree::from_str(svg, &options()).map_err(|e| BackendError::Parse(e.to_string()))
}

/// Points per millimetre.
const PT_PER_MM: f32 = 72.0 / 25.4;

/// A vector PDF of one page exactly the sheet's size, text embedded as subset fonts.
pub fn pdf(tree: &usvg::Tree, width_mm: f64, height_mm: f64) -> Result<Vec<u8>, BackendError> {
    use krilla::Document;
    use krilla::geom::Size;
    use krilla::page::PageSettings;
    use krilla_svg::{SurfaceExt, SvgSettings};
    let size = Size::from_wh(width_mm as f32 * PT_PER_MM, height_mm as f32 * PT_PER_MM)
        .ok_or_else(|| BackendError::Pdf("empty page".into()))?;
    let mut doc = Document::new();
    let mut page = doc.start_page_with(PageSettings::new(size));
    let mut surface = page.surface();
    surface
        .draw_svg(tree, size, SvgSettings::default())
        .ok_or_else(|| BackendError::Pdf("drawing the SVG failed".into()))?;
    surface.finish();
    page.finish();
    doc.finish().map_err(|e| BackendError::Pdf(format!("{e:?}")))
}

/// A PNG preview at `dpi` dots per inch.
pub fn png(tree: &usvg::Tree, width_mm: f64, height_mm: f64, dpi: f64) -> Result<Vec<u8>, BackendError> {
    let px = |mm: f64| (mm / 25.4 * dpi).round().max(1.0) as u32;
    let (w, h) = (px(width_mm), px(height_mm));
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).ok_or_else(|| BackendError::Png("bad size".into()))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let sx = w as f32 / tree.size().width();
    let sy = h as f32 / tree.size().height();
    resvg::render(tree, resvg::tiny_skia::Transform::from_scale(sx, sy), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| BackendError::Png(e.to_string()))
}
