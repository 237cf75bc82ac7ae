//! The PNG preview, rasterised from the scene with tiny-skia: black on white, anti-aliased,
//! strokes with round caps and joins and the GOST dashes, text as the embedded font's glyph
//! outlines (read with `skrifa`) placed as the PDF places them.
//!
//! The file is 8-bit grey (the drawing has no colour): a quarter of RGBA's bytes to
//! compress, which is most of the time a preview takes.
//!
//! Paths are given to tiny-skia in paper mm with the page's scale as their transform, as
//! resvg does with an SVG, so stroke widths and dashes scale with the page.

use super::BackendError;
use super::shapes::{self, check_finite};
use super::text;
use crate::drawing::scene::{Item, Pen, Scene, Text};
use crate::font;
use crate::num::work::{self, Step};
use kurbo::{Affine, BezPath, PathEl, Point, Rect};
use skrifa::instance::{LocationRef, Size};
use skrifa::outline::{DrawSettings, OutlineGlyphCollection, OutlinePen};
use skrifa::{GlyphId, MetadataProvider};
use tiny_skia::{Color, FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform};

/// Rows of pixels rasterised at a time: an A1 sheet at 100 dpi is drawn in five strips of
/// 7 MB rather than one 31 MB image, so that the sheets' previews can be drawn in parallel
/// within the program's memory budget (`tmm bench`, README).
const STRIP_ROWS: u32 = 512;

/// Rows each strip is drawn beyond its own, above and below: a thin line cut at a strip's
/// seam came out a pixel thicker near it than drawn whole (sheet 3's 0.25 mm pole ray at
/// 1.9°, against resvg's and poppler's rasters of the same page: 15 pixels unmatched at the
/// seam; 3 with one row more, none with four). Eight: twice that, 3 % more rows drawn.
const STRIP_OVERLAP: u32 = 8;

/// The scene as a PNG at `dpi` dots per inch.
pub fn write(scene: &Scene, dpi: f64) -> Result<Vec<u8>, BackendError> {
    work::count(Step::Png);
    check_finite(scene)?;
    if !(dpi.is_finite() && dpi > 0.0) {
        return Err(BackendError::Png(format!("no raster at {dpi} dpi")));
    }
    let px = |mm: f64| (mm / 25.4 * dpi).round().max(1.0) as u32;
    let (w, h) = (px(scene.width), px(scene.height));
    let no_image = || BackendError::Png(format!("no image of {w} × {h} pixels at {dpi} dpi"));
    let scale = Affine::scale_non_uniform(f64::from(w) / scene.width, f64::from(h) / scene.height);
    let glyphs = font::metrics().font().outline_glyphs();
    // Each item's extent in pixels, found once: a strip draws only the items that reach it.
    let items: Vec<(&Item, Rect)> = scene
        .groups
        .iter()
        .flat_map(|g| &g.items)
        .map(|item| (item, scale.transform_rect_bbox(extent(item))))
        .collect();
    let mut grey = Vec::new();
    grey.try_reserve_exact(w as usize * h as usize).map_err(|_| no_image())?;
    for top in (0..h).step_by(STRIP_ROWS as usize) {
        let rows = STRIP_ROWS.min(h - top);
        // The strip drawn with [`STRIP_OVERLAP`] rows more above and below, kept without them.
        let above = STRIP_OVERLAP.min(top);
        let (first, drawn) = (top - above, rows + above + STRIP_OVERLAP.min(h - top - rows));
        let mut pixmap = Pixmap::new(w, drawn).ok_or_else(no_image)?;
        pixmap.fill(Color::WHITE);
        let page = Page { scale: Affine::translate((0.0, -f64::from(first))) * scale, glyphs: glyphs.clone() };
        let (y0, y1) = (f64::from(first), f64::from(first + drawn));
        for (item, bbox) in &items {
            if bbox.y1 >= y0 && bbox.y0 <= y1 {
                page.draw_item(&mut pixmap, item);
            }
        }
        // Opaque everywhere (the page is filled white first), so premultiplied green is grey.
        let kept = &pixmap.pixels()[(above * w) as usize..((above + rows) * w) as usize];
        grey.extend(kept.iter().map(|p| p.green()));
    }
    encode_grey(&grey, w, h, dpi)
}

/// An item's extent on paper (mm), generously: room for round caps, a text's slanted or
/// accented glyphs (a strip only needs to know which items cannot reach it).
fn extent(item: &Item) -> Rect {
    let margin = match item {
        Item::Text(t) => t.h + 1.0,
        _ => 1.0,
    };
    item.bbox().inflate(margin, margin)
}

/// The page as an 8-bit grey PNG: everything is black on white, so one channel holds it
/// all, and compressing a quarter of the bytes is what makes the preview quick.
fn encode_grey(grey: &[u8], w: u32, h: u32, dpi: f64) -> Result<Vec<u8>, BackendError> {
    let mut out = Vec::new();
    let mut encoder = ::png::Encoder::new(&mut out, w, h);
    encoder.set_color(::png::ColorType::Grayscale);
    encoder.set_depth(::png::BitDepth::Eight);
    // fdeflate's one fast mode (pure Rust, no processor-dependent paths: the same bytes on
    // every machine): the default level was nearly half of the previews' time, for files a
    // third smaller (the worked example's sheet 1: 585 KB against 397 KB; rsvg-convert's
    // RGBA preview of it is 1.17 MB). A whole default run went to 0.68× its wall time.
    encoder.set_compression(::png::Compression::Fast);
    // The resolution, so that the preview prints at the sheet's size.
    let per_metre = (dpi / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(::png::PixelDimensions { xppu: per_metre, yppu: per_metre, unit: ::png::Unit::Meter }));
    let png_error = |e: ::png::EncodingError| BackendError::Png(e.to_string());
    let mut writer = encoder.write_header().map_err(png_error)?;
    writer.write_image_data(grey).map_err(png_error)?;
    writer.finish().map_err(png_error)?;
    Ok(out)
}

/// What every item is drawn with: paper mm to pixels, and the font's outlines.
struct Page<'a> {
    scale: Affine,
    glyphs: OutlineGlyphCollection<'a>,
}

impl Page<'_> {
    fn draw_item(&self, pixmap: &mut Pixmap, item: &Item) {
        match item {
            Item::Path { path, pen } => self.stroke(pixmap, &shapes::bez_path(path), pen),
            Item::Circle { c, r, pen, filled: false } => self.stroke(pixmap, &shapes::circle(*c, *r), pen),
            Item::Circle { c, r, filled: true, .. } => self.fill(pixmap, &shapes::circle(*c, *r)),
            Item::Fill { path } => self.fill(pixmap, &shapes::bez_path(path)),
            Item::Text(t) => self.draw_text(pixmap, t),
        }
    }

    fn transform(&self) -> Transform {
        let [sx, ky, kx, sy, tx, ty] = self.scale.as_coeffs().map(|x| x as f32);
        Transform::from_row(sx, ky, kx, sy, tx, ty)
    }

    fn stroke(&self, pixmap: &mut Pixmap, path: &BezPath, pen: &Pen) {
        let Some(path) = skia_path(path) else { return };
        let dash =
            shapes::dash_array(pen.line).and_then(|a| StrokeDash::new(a.iter().map(|&x| x as f32).collect(), 0.0));
        let stroke = Stroke {
            width: pen.width as f32,
            line_cap: LineCap::Round,
            line_join: LineJoin::Round,
            dash,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &Paint::default(), &stroke, self.transform(), None);
    }

    fn fill(&self, pixmap: &mut Pixmap, path: &BezPath) {
        let Some(path) = skia_path(path) else { return };
        pixmap.fill_path(&path, &Paint::default(), FillRule::Winding, self.transform(), None);
    }

    /// A text's glyph outlines as one path in pixels, filled.
    fn draw_text(&self, pixmap: &mut Pixmap, t: &Text) {
        let set = text::set(t);
        let mut pen = GlyphPen { builder: PathBuilder::new(), to_px: Affine::IDENTITY };
        let em = font::metrics().units_per_em();
        for run in &set.runs {
            let units = run.size / em;
            for g in &run.glyphs {
                let Some(outline) = self.glyphs.get(GlyphId::new(g.id)) else { continue };
                let origin = Point::new(run.origin.x + g.x, run.origin.y);
                // Font units have y up; the text's frame has y down.
                let glyph = Affine::translate(origin.to_vec2()) * Affine::scale_non_uniform(units, -units);
                pen.to_px = self.scale * set.transform * glyph;
                // A glyph the font cannot draw is left blank, as a renderer would.
                let _ = outline.draw(DrawSettings::unhinted(Size::unscaled(), LocationRef::default()), &mut pen);
            }
        }
        if let Some(path) = pen.builder.finish() {
            pixmap.fill_path(&path, &Paint::default(), FillRule::Winding, Transform::identity(), None);
        }
    }
}

/// The path for tiny-skia (paper mm); `None` for one that draws nothing.
fn skia_path(b: &BezPath) -> Option<tiny_skia::Path> {
    let mut p = PathBuilder::new();
    let f = |x: f64| x as f32;
    for el in b.elements() {
        match *el {
            PathEl::MoveTo(q) => p.move_to(f(q.x), f(q.y)),
            PathEl::LineTo(q) => p.line_to(f(q.x), f(q.y)),
            PathEl::QuadTo(a, q) => p.quad_to(f(a.x), f(a.y), f(q.x), f(q.y)),
            PathEl::CurveTo(a, c, q) => p.cubic_to(f(a.x), f(a.y), f(c.x), f(c.y), f(q.x), f(q.y)),
            PathEl::ClosePath => p.close(),
        }
    }
    p.finish()
}

/// Collects glyph outlines into one path, mapping font units to pixels on the way.
struct GlyphPen {
    builder: PathBuilder,
    to_px: Affine,
}

impl GlyphPen {
    fn px(&self, x: f32, y: f32) -> (f32, f32) {
        let p = self.to_px * Point::new(f64::from(x), f64::from(y));
        (p.x as f32, p.y as f32)
    }
}

impl OutlinePen for GlyphPen {
    fn move_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.px(x, y);
        self.builder.move_to(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.px(x, y);
        self.builder.line_to(x, y);
    }

    fn quad_to(&mut self, cx: f32, cy: f32, x: f32, y: f32) {
        let ((cx, cy), (x, y)) = (self.px(cx, cy), self.px(x, y));
        self.builder.quad_to(cx, cy, x, y);
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        let ((cx0, cy0), (cx1, cy1), (x, y)) = (self.px(cx0, cy0), self.px(cx1, cy1), self.px(x, y));
        self.builder.cubic_to(cx0, cy0, cx1, cy1, x, y);
    }

    fn close(&mut self) {
        self.builder.close();
    }
}
