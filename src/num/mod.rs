//! Numerical ground rules shared by every domain: the limits of accepted input, named
//! tolerances with their units (and [`Near`] with `assert_near!` for the tests), the one
//! root finder, the sense of rotation, and the mathematical functions whose results reach an output
//! (platform-independent).

pub mod bezier;
pub mod digits;
pub mod limits;
pub mod math;
pub mod near;
pub mod roots;
pub mod sense;
pub mod tol;
pub mod units;

pub use near::Near;
pub use sense::Sense;
