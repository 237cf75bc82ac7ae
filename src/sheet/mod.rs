//! Sheet composition: results of the mechanics laid out as a scene of paper-millimetre
//! primitives (lines with GOST line types, arrows, text, tables).
//!
//! **Architecture invariant:** composition reads mechanics results and never changes
//! them; it writes no bytes (that is the backends' job).

pub mod draw;
pub mod fmt;
pub mod forces_view;
pub mod frame;
pub mod labels;
pub mod mechanism_view;
pub mod place;
pub mod plans_view;
pub mod scale;
pub mod scene;
pub mod sheet1;
pub mod table;
pub mod text;
