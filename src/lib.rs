//! tmm-sheets: the graphical part of the course project in Theory of Machines and
//! Mechanisms, computed exactly and drawn the way the course requires.
//!
//! Layers, each depending only on the ones before it:
//! [`model`] (project file) → [`mechanics`] (pure SI computation) → [`analysis`]
//! (what a sheet needs, computed once) → [`sheet`] (paper-millimetre scene) →
//! [`backend`] (SVG, PDF, PNG bytes) and [`report`] (tables, JSON).
//!
//! ```
//! use tmm_sheets::pipeline;
//!
//! // The guide's worked example: a six-bar vibrating conveyor.
//! let project = pipeline::load(pipeline::DEFAULT_PROJECT)?;
//! let s = project.mechanism.solve(0.3)?; // absolute crank angle, radians
//! let d = project.mechanism.point_id("D").unwrap();
//! assert!(s.points[d].v.x.is_finite());
//!
//! let sheet = pipeline::sheet1(&project)?;
//! assert!(sheet.svg.starts_with("<svg"));
//! assert_eq!(sheet.kinematics.structure.formula, "I(0,1) → II(2,3) → II(4,5)");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

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
