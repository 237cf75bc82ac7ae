//! Numbers and names as the project file writes them, checked where they are written.
//!
//! Every number must be finite and within [`crate::num::limits::INPUT_MAX`] (SI units), so no
//! product of a few inputs can overflow on the way to a sheet: a `mass: 1.0e300` is refused
//! at its line instead of ending as `inf` in an output.

use crate::num::limits::INPUT_MAX;
use serde::{Deserialize, Deserializer};
use serde_saphyr::Spanned;

/// A point name as written, with where it was written.
pub type Name = Spanned<String>;

/// Text as written, with where it was written (checked by [`super::text::check`]).
pub type UserText = Spanned<String>;

fn number<'de, D: Deserializer<'de>>(d: D, ok: impl Fn(f64) -> bool, what: &str) -> Result<f64, D::Error> {
    let x = f64::deserialize(d)?;
    if !x.is_finite() {
        return Err(serde::de::Error::custom(format!("expected {what}, got {x}")));
    }
    if x.abs() > INPUT_MAX {
        return Err(serde::de::Error::custom(format!(
            "{x:e} is too large: numbers in a project file are SI units and must lie within ±{INPUT_MAX:e}"
        )));
    }
    if !ok(x) {
        return Err(serde::de::Error::custom(format!("expected {what}, got {x}")));
    }
    Ok(x)
}

/// A finite number (YAML's .nan and .inf are refused where they are written).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finite(pub f64);

impl<'de> Deserialize<'de> for Finite {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |_| true, "a finite number").map(Finite)
    }
}

/// A finite number ≥ 0 (masses, forces that may vanish).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonNegative(pub f64);

impl<'de> Deserialize<'de> for NonNegative {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |x| x >= 0.0, "a number ≥ 0").map(NonNegative)
    }
}

/// A strictly positive finite number (lengths, speeds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Positive(pub f64);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |x| x > 0.0, "a positive number").map(Positive)
    }
}
