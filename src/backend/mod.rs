//! Backends: a scene to bytes, one module a format, each reading only the [`Scene`]. SVG
//! is written as text; the PDF (krilla) and the PNG (tiny-skia) draw the same scene
//! themselves, sharing the shapes' outlines ([`shapes`]) and the text's glyph positions
//! ([`text`]) so that the two place every line and letter alike. Another format is one more
//! module and one more [`Format`].
//!
//! **Architecture invariant:** backends compute no geometry and choose no scales.

pub mod dxf;
pub mod pdf;
pub mod png;
pub mod shapes;
pub mod svg;
pub mod text;

use crate::drawing::scene::Scene;

/// An output format of a sheet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Format {
    Svg,
    Pdf,
    /// A raster preview at `dpi` dots per inch.
    Png {
        dpi: f64,
    },
    /// The drawing for CAD programs (AutoCAD, KOMPAS, LibreCAD).
    Dxf(dxf::DxfVersion),
}

impl Format {
    /// The file name extension.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Pdf => "pdf",
            Format::Png { .. } => "png",
            Format::Dxf(_) => "dxf",
        }
    }
}

/// The scene in `format`.
pub fn write(scene: &Scene, format: Format) -> Result<Vec<u8>, BackendError> {
    match format {
        Format::Svg => svg::write(scene).map(String::into_bytes),
        Format::Pdf => pdf::write(scene),
        Format::Png { dpi } => png::write(scene, dpi),
        Format::Dxf(version) => dxf::write(scene, version),
    }
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BackendError {
    #[error("the scene has a non-finite number ({value}) in group '{group}': {item}")]
    NonFinite { group: String, value: f64, item: String },
    #[error("PDF writing failed: {0}")]
    Pdf(String),
    #[error("PNG rendering failed: {0}")]
    Png(String),
}
