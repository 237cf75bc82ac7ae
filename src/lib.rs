//! tmm-sheets: the graphical part of the course project in Theory of Machines and
//! Mechanisms, computed exactly and drawn the way the course requires.
//!
//! Layers, each depending only on the ones before it:
//! [`model`] (project file) → [`mechanics`] (pure SI computation) → [`analysis`]
//! (what a sheet needs, computed once) → [`sheet`] (paper-millimetre scene) →
//! [`backend`] (SVG, PDF, PNG bytes) and [`report`] (tables, JSON).

pub mod mechanics;
pub mod model;
pub mod analysis;
pub mod backend;
pub mod font;
pub mod report;
pub mod sheet;
pub mod pipeline;
pub mod results;
pub mod cli;
