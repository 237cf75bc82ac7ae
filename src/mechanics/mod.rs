//! Exact mechanics of planar lever mechanisms, in SI units.
//!
//! **Architecture invariant:** this module is pure. It does no I/O, knows nothing about
//! paper, scales or SVG, and never returns NaN: a configuration it cannot solve is an error.

pub mod dyads;
pub mod kin;
pub mod kinetostatics;
pub mod linkage;
pub mod load;
pub mod motion;
pub mod plans;
pub mod structure;

pub use kin::{Kin, LinkKin};
pub use linkage::{DyadKind, Group, Link, LinkId, LinkKind, Mechanism, Output, PointId, State, Step};
pub use motion::{Motion, MotionError, Start};
