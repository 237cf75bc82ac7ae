//! Backends: a scene to bytes. SVG is written directly; PDF and PNG go through one
//! usvg tree parsed from that SVG, so all three show the same drawing.
//!
//! **Architecture invariant:** backends compute no geometry and choose no scales.

pub mod raster;
pub mod svg;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BackendError {
    #[error("the scene has a non-finite number ({value}) in group '{group}': {item}")]
    NonFinite { group: String, value: f64, item: String },
    #[error("the generated SVG does not parse: {0}")]
    Parse(String),
    #[error("PDF conversion failed: {0}")]
    Pdf(String),
    #[error("PNG rendering failed: {0}")]
    Png(String),
}
