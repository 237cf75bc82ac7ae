//! Numbers written for a reader: four significant digits, so that one printed value can be
//! recomputed from others (J_S = 0.001800 and ε = 4467 give M = 8.040, where three fixed
//! decimals printed J_S = 0.002 and M = 8.93).

use super::{math, tol};

/// Between one cell's two values where its quantity jumps at the cell's position: the value
/// just before, then just after ("1.169→−1.169": from one to the other; a slash read as a
/// fraction), as a diagram draws the jump.
pub const JUMP: char = '→';

/// `x` with four significant digits and at most nine decimals, a point and a hyphen-minus.
pub fn significant(x: f64) -> String {
    let a = x.abs();
    // Also catches NaN, which never reaches an output (the writers refuse it).
    if a.is_nan() || a < tol::PRINTED_ZERO {
        return "0".into();
    }
    // Rounded first to 12 significant digits: a value that is a tie in decimals (−0.21875)
    // but computed a few ulps off it (−0.2187499999999999) printed one digit apart from its
    // exact twin elsewhere in the same table. Then a tie is moved off by 1e-14 of itself,
    // away from zero: rounded half up, as the course rounds (0.0028125 → 0.002813), where
    // the formatter would take the binary value's side. Only a tie is that near a boundary:
    // any other 12-digit value is at least 1e-12 of itself from one.
    let x = tie_moved(x);
    let a = x.abs();
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

/// Whole to rounding: a planet's radius of 2 mm·36/2 computed in metres and written in mm is
/// 36.00000000000001.
pub fn nearly_whole(v: f64) -> bool {
    (v - v.round()).abs() <= 1e-9 * v.abs().max(1.0)
}

/// The fewest decimals (at most three) that write every one of `values` exactly — the
/// positions' angles of a phase divided into eight (80; 88,75; 97,5 … print with two, so
/// 106,25 is not cut to 106,2) — or `None` when some value needs more.
pub fn exact_decimals(values: &[f64]) -> Option<usize> {
    (0..=3).find(|&d| {
        let scale = 10f64.powi(d as i32);
        values.iter().all(|&v| {
            let x = v * scale;
            (x - x.round()).abs() <= 1e-6 * x.abs().max(1.0)
        })
    })
}

/// The decimals of one row of a table: those that give its largest value four significant
/// digits (as [`significant`] writes it), so that every value of the row has as many (GOST
/// 2.105: the values of one quantity in a table have the same number of decimals; "116,2"
/// beside "96,21" and "0" beside "12,31" read as different precisions).
pub fn row_decimals(values: &[f64]) -> usize {
    let largest = values.iter().map(|v| v.abs()).filter(|a| a.is_finite()).fold(0.0, f64::max);
    significant(largest).split_once('.').map_or(0, |(_, d)| d.len())
}

/// `x` with `decimals` fixed decimals, rounded as [`significant`] rounds (half up, after
/// rounding to 12 significant digits), a value that rounds to zero without its sign.
pub fn at_decimals(x: f64, decimals: usize) -> String {
    if x.is_nan() || x.abs() < tol::PRINTED_ZERO {
        return fixed(0.0, decimals);
    }
    fixed(tie_moved(x), decimals)
}

/// `x` rounded to 12 significant digits and, a tie there, moved 1e-14 of itself away from
/// zero, so that formatting it rounds half up (see [`significant`]).
fn tie_moved(x: f64) -> f64 {
    let x: f64 = format!("{x:.11e}").parse().unwrap_or(x);
    x + x * 1e-14
}

/// `x` to `digits` significant digits (at least one), trailing zeros dropped, for a message:
/// plain between 10⁻⁴ and 10⁶, else in scientific notation (`-2e-9`, `1.23e9`), so that neither
/// a tiny imbalance nor a huge size prints as a row of zeros or of hundreds of digits.
pub fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = digits.max(1);
    // The exponent after rounding (9.996e5 to three digits is 1.00e6).
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if (-4..6).contains(&exponent) {
        let rounded: f64 = sci.parse().unwrap_or(x);
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        let s = trim_zeros(format!("{rounded:.decimals$}"));
        // A value that rounds to zero at these digits has no sign ("-0.00°" read as a bug).
        if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { "0".into() } else { s }
    } else {
        format!("{}e{exponent}", trim_zeros(mantissa.to_string()))
    }
}

/// A number of the project file as it was written, for a message: [`sig`] to nine digits, so
/// that a value written with up to nine digits (or a degree's round trip through radians)
/// reads back as written, and 1e-300 as `1e-300`.
pub fn written(x: f64) -> String {
    sig(x, 9)
}

/// `x` with `decimals` fixed decimals for a message, a value that rounds to zero without its
/// sign (`0.00°`, never `-0.00°`).
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') { s[1..].to_string() } else { s }
}

/// A decimal's trailing zeros (and a point left bare) dropped.
fn trim_zeros(s: String) -> String {
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row's decimals are its largest value's at four significant digits, and every value
    /// of the row is written with them, rounded half up, zero unsigned.
    #[test]
    fn a_rows_values_share_the_decimals_of_its_largest() {
        let row = [0.0, 12.31, 96.21, -0.004];
        assert_eq!(row_decimals(&row), 2);
        let printed: Vec<String> = row.iter().map(|&v| at_decimals(v, row_decimals(&row))).collect();
        assert_eq!(printed, ["0.00", "12.31", "96.21", "0.00"]);
        assert_eq!(row_decimals(&[116.2, 200.0]), 1);
        assert_eq!(row_decimals(&[0.0018, 0.0000005]), 6);
        assert_eq!(row_decimals(&[0.0, 0.0]), 0);
        // 9.99995 is 10.00 at four significant digits: two decimals, not three.
        assert_eq!(row_decimals(&[9.99995]), 2);
        assert_eq!(at_decimals(0.0028125, 6), "0.002813", "half up");
        assert_eq!(at_decimals(-0.21875, 4), "-0.2188");
    }

    #[test]
    fn exact_decimals_are_the_fewest_that_write_every_value() {
        assert_eq!(exact_decimals(&[80.0, 88.75, 97.5, 106.25]), Some(2));
        assert_eq!(exact_decimals(&[0.0, 15.0, 30.0]), Some(0));
        assert_eq!(exact_decimals(&[(106.25f64).to_radians().to_degrees()]), Some(2), "a degree's round trip");
        assert_eq!(exact_decimals(&[0.0, 13.0 / 3.0]), None);
        assert_eq!(exact_decimals(&[]), Some(0));
    }

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
        // A tie computed a few ulps off prints as its exact twin (7/32 = 0.21875 exactly).
        assert_eq!(significant(-0.21875), significant(-0.21875 + 3e-17));
        assert_eq!(significant(-0.21875 + 3e-17), "-0.2188");
        assert_eq!(significant(0.0028125), "0.002813", "half up, as the course rounds");
        assert_eq!(significant(0.0028125 - 4e-19), "0.002813");
        assert_eq!(significant(-1.0625), "-1.063");
    }

    #[test]
    fn significant_digits_in_plain_or_scientific_notation() {
        assert_eq!(sig(4580.123456789, 3), "4580");
        assert_eq!(sig(4586.0, 3), "4590");
        assert_eq!(sig(-2.0e-9, 2), "-2e-9");
        assert_eq!(sig(1.2e9, 3), "1.2e9");
        assert_eq!(sig(0.6, 6), "0.6");
        assert_eq!(sig(-0.000123456, 3), "-0.000123");
        assert_eq!(sig(999_960.0, 3), "1e6", "rounding up to the next power changes the notation");
        assert_eq!(sig(1e300, 3), "1e300");
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig(5.0, 0), "5");
    }

    #[test]
    fn written_numbers_read_back_as_written_and_short() {
        assert_eq!(written(0.123456789), "0.123456789");
        assert_eq!(written(1e-300), "1e-300");
        assert_eq!(written(1.0000000000000002e-9), "1e-9");
        assert_eq!(written(25f64.to_radians().to_degrees()), "25");
        assert_eq!(written(-0.0), "0");
    }
}
