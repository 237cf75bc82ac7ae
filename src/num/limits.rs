//! What the project file accepts, and what it accepts only with a warning.

/// Largest magnitude of any number in a project file (SI units). Products of a few inputs
/// (m·ω²·l, p·d²) then stay far from overflow, so no output can become infinite.
pub const INPUT_MAX: f64 = 1e9;

/// A length above this (m) is almost surely written in millimetres.
pub const LENGTH_LOOKS_LIKE_MM: f64 = 10.0;

/// A link length below this (m) is almost surely a mistake.
pub const LENGTH_TINY: f64 = 1e-3;

/// A crank speed above this (rev/min) is almost surely a mistake.
pub const RPM_PLAUSIBLE_MAX: f64 = 1e5;

/// A link mass above this (kg) is almost surely a mistake.
pub const MASS_PLAUSIBLE_MAX: f64 = 1e5;
