//! Round scale factors in the spirit of GOST 2.302: {1, 1.5, 2, 2.5, 4, 5, 7.5}·10ⁿ.

const MANTISSAS: [f64; 7] = [1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5];

/// The smallest round value ≥ `x` (for x > 0). A scale factor μ (units per mm) chosen
/// this way makes a drawing as large as possible without leaving its region.
pub fn round_up(x: f64) -> f64 {
    assert!(x.is_finite() && x > 0.0, "scale of a non-positive extent");
    let mut e = x.log10().floor() as i32 - 1;
    loop {
        let p = 10f64.powi(e);
        for m in MANTISSAS {
            // Tolerance so that an exact round value is kept, not bumped to the next one.
            if m * p >= x * (1.0 - 1e-12) {
                return m * p;
            }
        }
        e += 1;
    }
}

/// Formats a scale factor with as many significant digits as it has.
pub fn format(mu: f64) -> String {
    let s = format!("{mu:.10}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}
