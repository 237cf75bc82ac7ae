//! The drawing kit every sheet composes with: the scene (paper-millimetre primitives owned
//! by neither the sheets nor the backends), drafting symbols, text with subscripts, tables,
//! label placement, GOST scales, the world-to-paper view, the A1 frame and title block,
//! labels in three languages and number formatting.
//!
//! **Architecture invariant:** the kit writes no bytes (that is the backends' job) and
//! knows no domain: it draws whatever geometry a sheet hands it.

pub mod along;
pub mod columns;
pub mod fmt;
pub mod frame;
pub mod grid;
pub mod labels;
pub mod layout;
pub mod obstacles;
pub mod path;
pub mod phrases;
pub mod place;
pub mod plot;
pub mod scale;
pub mod scene;
pub mod symbols;
pub mod table;
pub mod text;
pub mod view;
