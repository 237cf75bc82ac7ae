//! The PDF, drawn from the scene with krilla: one vector page exactly the sheet's size,
//! the text real text in the embedded font (subset by krilla), so that it can be selected
//! and searched. krilla's page has its origin at the top left with y down, as the scene
//! does; one transform scales millimetres to points, so every coordinate is written in
//! paper mm, rounded to 1 µm as the SVG writes them.
//!
//! Deterministic: krilla writes the same bytes for the same drawing with one font, and the
//! document carries no date.

use super::BackendError;
use super::shapes::{self, check_finite};
use super::text::{self, SetRun};
use crate::drawing::scene::{Item, Pen, Scene, Text};
use crate::font;
use crate::num::work::{self, Step};
use krilla::color::rgb;
use krilla::geom::{Path as PdfPath, PathBuilder, Point as PdfPoint, Size, Transform};
use krilla::metadata::Metadata;
use krilla::page::PageSettings;
use krilla::paint::{Fill, LineCap, LineJoin, Paint, Stroke, StrokeDash};
use krilla::surface::Surface;
use krilla::text::{Font, GlyphId, KrillaGlyph};
use krilla::{Data, Document};
use kurbo::{Affine, BezPath, PathEl};

/// Points per millimetre.
const PT_PER_MM: f32 = (72.0 / 25.4) as f32;

/// The scene as a one-page PDF.
pub fn write(scene: &Scene) -> Result<Vec<u8>, BackendError> {
    write_pages(std::slice::from_ref(scene))
}

/// The scenes as the pages of one PDF, each page its scene's size; the document takes the
/// first scene's title.
pub fn write_pages(scenes: &[Scene]) -> Result<Vec<u8>, BackendError> {
    work::count(Step::Pdf);
    let font = Font::new(Data::from(font::BYTES), 0).ok_or_else(|| BackendError::Pdf("the font".into()))?;
    let mut doc = Document::new();
    doc.set_metadata(Metadata::new().title(scenes.first().map(|s| s.title.clone()).unwrap_or_default()));
    for scene in scenes {
        check_finite(scene)?;
        let size = Size::from_wh(scene.width as f32 * PT_PER_MM, scene.height as f32 * PT_PER_MM)
            .ok_or_else(|| BackendError::Pdf(format!("no page of {} × {} mm", scene.width, scene.height)))?;
        let mut page = doc.start_page_with(PageSettings::new(size));
        let mut surface = page.surface();
        surface.push_transform(&Transform::from_scale(PT_PER_MM, PT_PER_MM));
        let [r, g, b] = scene.ink.rgb();
        let ink = Ink { font: font.clone(), paint: rgb::Color::new(r, g, b).into() };
        draw_items(&mut surface, scene.groups.iter().flat_map(|g| &g.items), &ink);
        surface.pop();
        surface.finish();
        page.finish();
    }
    doc.finish().map_err(|e| BackendError::Pdf(format!("{e:?}")))
}

/// What every mark is drawn with: the font and the scene's ink.
struct Ink {
    font: Font,
    paint: Paint,
}

impl Ink {
    fn fill(&self) -> Fill {
        Fill { paint: self.paint.clone(), ..Fill::default() }
    }
}

/// Draws the items in order, consecutive strokes of one pen as one path: one operation
/// instead of one each (krilla writes a graphics state and a transform per operation, and
/// compressing them was most of the PDF's time). The marks are the same: PDF restarts the
/// dash pattern at each subpath, and every stroke is one opaque ink. Fills are not joined:
/// overlapping outlines of opposite turn would cancel under the non-zero rule.
fn draw_items<'a>(surface: &mut Surface, items: impl Iterator<Item = &'a Item>, ink: &Ink) {
    let mut pending: Option<(Pen, BezPath)> = None;
    for item in items {
        match stroke_of(item) {
            Some((pen, path)) => match &mut pending {
                Some((same, joined)) if *same == pen => joined.extend(path),
                _ => {
                    flush(surface, pending.replace((pen, path)), ink);
                }
            },
            None => {
                flush(surface, pending.take(), ink);
                draw_item(surface, item, ink);
            }
        }
    }
    flush(surface, pending.take(), ink);
}

/// A stroked item's pen and outline.
fn stroke_of(item: &Item) -> Option<(Pen, BezPath)> {
    match item {
        Item::Path { path, pen } => Some((*pen, shapes::bez_path(path))),
        Item::Circle { c, r, pen, filled: false } => Some((*pen, shapes::circle(*c, *r))),
        _ => None,
    }
}

fn flush(surface: &mut Surface, pending: Option<(Pen, BezPath)>, ink: &Ink) {
    if let Some((pen, path)) = pending {
        stroke(surface, &path, &pen, ink);
    }
}

/// One item by itself.
fn draw_item(surface: &mut Surface, item: &Item, ink: &Ink) {
    match item {
        Item::Path { path, pen } => stroke(surface, &shapes::bez_path(path), pen, ink),
        Item::Circle { c, r, pen, filled: false } => stroke(surface, &shapes::circle(*c, *r), pen, ink),
        Item::Circle { c, r, filled: true, .. } => fill(surface, &shapes::circle(*c, *r), ink),
        Item::Fill { path } => fill(surface, &shapes::bez_path(path), ink),
        Item::Text(t) => draw_text(surface, t, ink),
    }
}

fn stroke(surface: &mut Surface, path: &BezPath, pen: &Pen, ink: &Ink) {
    let Some(path) = pdf_path(path) else { return };
    let dash =
        shapes::dash_array(pen.line).map(|a| StrokeDash { array: a.iter().map(|&x| x as f32).collect(), offset: 0.0 });
    let stroke = Stroke {
        paint: ink.paint.clone(),
        width: pen.width as f32,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        dash,
        ..Stroke::default()
    };
    surface.set_fill(None);
    surface.set_stroke(Some(stroke));
    surface.draw_path(&path);
}

fn fill(surface: &mut Surface, path: &BezPath, ink: &Ink) {
    let Some(path) = pdf_path(path) else { return };
    surface.set_stroke(None);
    surface.set_fill(Some(ink.fill()));
    surface.draw_path(&path);
}

/// Paper mm rounded to 1 µm, the SVG's resolution: the content stream stays as short.
fn mm(x: f64) -> f32 {
    ((x * 1000.0).round() / 1000.0) as f32
}

/// The path for krilla; `None` for one that draws nothing (a lone point).
fn pdf_path(b: &BezPath) -> Option<PdfPath> {
    let mut p = PathBuilder::new();
    for el in b.elements() {
        match *el {
            PathEl::MoveTo(q) => p.move_to(mm(q.x), mm(q.y)),
            PathEl::LineTo(q) => p.line_to(mm(q.x), mm(q.y)),
            PathEl::QuadTo(a, q) => p.quad_to(mm(a.x), mm(a.y), mm(q.x), mm(q.y)),
            PathEl::CurveTo(a, c, q) => p.cubic_to(mm(a.x), mm(a.y), mm(c.x), mm(c.y), mm(q.x), mm(q.y)),
            PathEl::ClosePath => p.close(),
        }
    }
    p.finish()
}

/// A text in its frame (rotated, sloped), each run as real text in the embedded font.
fn draw_text(surface: &mut Surface, t: &Text, ink: &Ink) {
    let set = text::set(t);
    surface.set_stroke(None);
    surface.set_fill(Some(ink.fill()));
    surface.push_transform(&transform(set.transform));
    for run in &set.runs {
        draw_run(surface, run, &ink.font);
    }
    surface.pop();
}

fn draw_run(surface: &mut Surface, run: &SetRun, font: &Font) {
    let em = |mm: f64| (mm / run.size) as f32;
    let glyphs: Vec<KrillaGlyph> = run
        .glyphs
        .iter()
        .map(|g| KrillaGlyph::new(GlyphId::new(g.id), em(g.advance), 0.0, 0.0, 0.0, g.chars.clone(), None))
        .collect();
    let start = PdfPoint::from_xy(run.origin.x as f32, run.origin.y as f32);
    surface.draw_glyphs(start, &glyphs, font.clone(), run.text, run.size as f32, false);
}

fn transform(a: Affine) -> Transform {
    let [sx, ky, kx, sy, tx, ty] = a.as_coeffs().map(|x| x as f32);
    Transform::from_row(sx, ky, kx, sy, tx, ty)
}
