//! Numerical ground rules shared by every domain: the limits of accepted input, named
//! tolerances with their units, and the one root finder.

pub mod limits;
pub mod roots;
pub mod tol;
