//! The lever mechanism of sheet 1, exact and in SI units: closed-form dyads, the motion over
//! a turn, structure, vector plans, kinetostatics with the Zhukovsky lever and the power
//! balance, and [`analysis`], which computes once what the sheet needs.
//!
//! **Architecture invariant:** this module is pure. It does no I/O, knows nothing about
//! paper, scales or SVG (it imports nothing from `drawing`, `sheets` or `backend`), and never
//! returns NaN: a configuration it cannot solve is an error.

pub mod analysis;
mod batch;
pub mod dyads;
pub mod indicators;
pub mod kin;
pub mod kinetostatics;
pub mod lanes;
pub mod linkage;
pub mod load;
pub mod motion;
pub mod plans;
pub mod structure;
pub mod trajectory;
pub mod turn;

pub use analysis::Settings;
pub use kin::{Kin, LinkKin};
pub use linkage::{DyadKind, Group, Link, LinkId, LinkKind, Mechanism, Output, PointId, Solution, State, Step};
pub use motion::{Motion, MotionError, Start};
pub use turn::Turn;
