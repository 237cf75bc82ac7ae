//! Numbers written for a reader: four significant digits, so that one printed value can be
//! recomputed from others (J_S = 0.001800 and ε = 4467 give M = 8.040, where three fixed
//! decimals printed J_S = 0.002 and M = 8.93).

use super::math;

/// Magnitudes below this print as 0: round-off of a quantity that is zero (a velocity at
/// an extreme position, Δ of two exact computations). The course's smallest real values
/// (moments of inertia of 10⁻⁴ kg·m²) are far above it.
pub const NOISE: f64 = 1e-7;

/// `x` with four significant digits and at most nine decimals, a point and a hyphen-minus.
pub fn significant(x: f64) -> String {
    let a = x.abs();
    // Also catches NaN, which never reaches an output (the writers refuse it).
    if a.is_nan() || a < NOISE {
        return "0".into();
    }
    let magnitude = math::log10(a).floor() as i32;
    let dec = (3 - magnitude).clamp(0, 9) as usize;
    let s = format!("{x:.dec$}");
    // 0.99999 rounds to 1.0000: one digit too many once the rounding reaches the next power.
    let rounded: f64 = s.parse().unwrap_or(x);
    if dec > 0 && rounded.abs() >= 10f64.powi(magnitude + 1) {
        let dec = dec - 1;
        return format!("{x:.dec$}");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_significant_digits_and_no_round_off() {
        assert_eq!(significant(0.0018), "0.001800");
        assert_eq!(significant(0.5254), "0.5254");
        assert_eq!(significant(4466.9), "4467");
        assert_eq!(significant(-3e-14), "0");
        assert_eq!(significant(-46001.0), "-46001");
        assert_eq!(significant(f64::NAN), "0");
        assert_eq!(significant(0.99999), "1.000", "rounding up to the next power keeps four digits");
        assert_eq!(significant(-9.99996), "-10.00");
    }
}
