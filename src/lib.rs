//! tmm-sheets: the graphical part of the course project in Theory of Machines and
//! Mechanisms, computed exactly and drawn the way the course requires.
//!
//! Layers, each depending only on the ones before it:
//! [`project`] (the project file, refused as data: [`project::Refusal`]) → pure SI domains
//! ([`lever`] for sheet 1, [`gears`] for sheet 2, [`cams`] for sheet 3; [`num`] under them
//! all) → [`sheets`] (each sheet's composition into a [`drawing`] scene of paper
//! millimetres, finished by one scaffold) → [`backend`] (SVG, PDF, PNG bytes, each read from
//! the scene) and [`report`] (typed tables under their answer keys); [`pipeline`] runs the
//! sheets a project has, [`cli`] writes their files safely. [`font`] is the one embedded font.
//!
//! ```
//! use tmm_sheets::pipeline;
//!
//! // The guide's worked example: a six-bar vibrating conveyor.
//! let project = pipeline::load(pipeline::DEFAULT_PROJECT)?;
//! let lever = project.lever.as_ref().expect("the example has a mechanism");
//! let s = lever.mechanism.solve(0.3)?; // absolute crank angle, radians
//! let d = lever.mechanism.point_id("D").unwrap();
//! assert!(s.points[d].v.x.is_finite());
//!
//! let sheets = pipeline::build(&project, &[])?;
//! assert!(sheets[0].svg.starts_with("<svg"));
//! assert_eq!(sheets[0].output.results["structure"]["formula"], "I(0,1) → II(2,3) → II(4,5)");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod backend;
pub mod bench;
pub mod cams;
pub mod catalogue;
pub mod check;
pub mod cli;
pub mod drawing;
pub mod font;
pub mod gears;
pub mod lever;
pub mod num;
pub mod pipeline;
pub mod project;
pub mod report;
pub mod session;
pub mod sheets;
