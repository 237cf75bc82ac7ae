//! Backends: a scene to bytes. SVG is written directly; PDF and PNG go through one
//! usvg tree parsed from that SVG, so all three show the same drawing.
//!
//! **Architecture invariant:** backends compute no geometry.

pub mod raster;
pub mod svg;
