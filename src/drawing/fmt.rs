//! Numbers as the sheets print them: decimal comma in Uzbek and Russian, point in English,
//! and the minus sign (−, U+2212) rather than a hyphen.

use crate::drawing::labels::Language;
use crate::num::{digits, math};

/// A value with four significant digits (at most nine decimals), so that a reader can
/// recompute one printed value from others: J_S = 0,001800, ε = 4467, M = 8,040; round-off
/// of a zero prints as 0 (see [`crate::num::digits`]).
pub fn value(x: f64, lang: Language) -> String {
    localise(&digits::significant(x), lang)
}

/// Two values written as [`value`] does, with more digits where that writes them alike: a
/// shift just under its limit read "x = 0,2941 < x_min = 0,2941".
pub fn values_apart(a: f64, b: f64, lang: Language) -> (String, String) {
    let (sa, sb) = (value(a, lang), value(b, lang));
    if sa != sb || a == b {
        return (sa, sb);
    }
    let at = |d: usize| (localise(&digits::sig(a, d), lang), localise(&digits::sig(b, d), lang));
    (5..=15).map(at).find(|(x, y)| x != y).unwrap_or((sa, sb))
}

/// Values of one quantity written alike, as a table's row prints them: whole numbers
/// without decimals when every one is whole (u = 5, required 5), else every one with the
/// decimals of the largest's four significant digits (u = 4,909, required 5,000).
pub fn values_alike(values: &[f64], lang: Language) -> Vec<String> {
    let whole = values.iter().all(|&v| digits::nearly_whole(v));
    let decimals = if whole { 0 } else { digits::row_decimals(values) };
    values.iter().map(|&v| localise(&digits::at_decimals(v, decimals), lang)).collect()
}

/// A value with four significant digits, trailing zeros dropped (a module of 5 mm is "5", a
/// scale of 0,001000 m/mm is "0,001").
pub fn trimmed(x: f64, lang: Language) -> String {
    let s = value(x, lang);
    if s.contains([',', '.']) && !s.contains(['e', '·']) {
        s.trim_end_matches('0').trim_end_matches([',', '.']).to_string()
    } else {
        s
    }
}

/// A dimension's value, mm: with the fewest decimals (up to two) that write it exactly —
/// h_a = 5, h_f = 6,25, a_w = 90, as the course's drawings dimension them — else to 0,01 mm
/// (p = 15,71, h_a = 4,42), as the course writes a gear's lengths and the wheels' table its
/// radii: one drawing's dimensions at one precision, not h_a = 4,420 beside h_f = 1,95.
pub fn dimension(x: f64, lang: Language) -> String {
    let decimals = digits::exact_decimals(&[x]).filter(|&d| d <= DIMENSION_DECIMALS);
    localise(&digits::at_decimals(x, decimals.unwrap_or(DIMENSION_DECIMALS)), lang)
}

/// The decimals of a dimension that is not exact at fewer: 0,01 mm.
const DIMENSION_DECIMALS: usize = 2;

/// A tiny number in the form 1,6·10⁻¹³ (zero as 0), as the sheets show a residual.
pub fn scientific(x: f64, lang: Language) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let e = math::log10(x.abs()).floor() as i32;
    let mantissa = x / 10f64.powi(e);
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let exp: String = e.abs().to_string().chars().map(|c| SUP[c.to_digit(10).expect("a digit") as usize]).collect();
    let sign = if e < 0 { "⁻" } else { "" };
    format!("{}·10{sign}{exp}", localise(&format!("{mantissa:.1}"), lang))
}

/// The least of 1, 2, 5 times a power of ten above `x` (> 0): a bound a reader takes in at
/// a glance, where the measured value's digits say nothing a drawing can show ("within
/// 0,5 µm", not "0,3357 µm").
pub fn bound_above(x: f64, lang: Language) -> String {
    let x = x.abs().max(f64::MIN_POSITIVE);
    let e = math::log10(x).floor() as i32;
    let bound =
        [1.0, 2.0, 5.0, 10.0].into_iter().map(|m| m * 10f64.powi(e)).find(|&b| b > x).unwrap_or(10.0 * 10f64.powi(e));
    value(bound, lang).trim_end_matches('0').trim_end_matches([',', '.']).to_string()
}

/// A relative difference in per cent as a drawing reports it: two decimals, or "< 0,01"
/// where it is smaller (a drawing is read to 0,1 mm; 1,1·10⁻⁴ % says nothing more).
pub fn percent_difference(d: f64, lang: Language) -> String {
    if d.abs() < 0.01 { localise("< 0.01", lang) } else { localise(&format!("{d:.2}"), lang) }
}

/// A number written by Rust, as the sheet prints it: the decimal point for the language and
/// a true minus sign.
pub fn localise(s: &str, lang: Language) -> String {
    let s = s.replace('-', "−");
    match lang {
        Language::En => s,
        Language::Uz | Language::Ru => s.replace('.', ","),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dimension_is_written_exactly_where_few_decimals_do() {
        assert_eq!(dimension(5.0, Language::Uz), "5");
        assert_eq!(dimension(6.25, Language::Uz), "6,25");
        assert_eq!(dimension(90.0 + 1e-12, Language::En), "90", "round-off of an exact value");
        assert_eq!(dimension(15.707963267948966, Language::Ru), "15,71");
        assert_eq!(dimension(-1.8, Language::En), "−1.8");
        // Not exact at two decimals: to 0,01 mm, as every other dimension of the drawing.
        assert_eq!(dimension(4.419_98, Language::Ru), "4,42", "not 4,420 beside h_f = 1,95");
        assert_eq!(dimension(1.5625, Language::Ru), "1,56");
        assert_eq!(dimension(0.625, Language::En), "0.63");
        assert_eq!(dimension(287.433_6, Language::En), "287.43");
    }

    #[test]
    fn decimal_comma_and_significant_digits() {
        assert_eq!(value(0.5254, Language::Uz), "0,5254");
        assert_eq!(value(0.0018, Language::Uz), "0,001800", "four significant figures, not three decimals");
        assert_eq!(value(18.149, Language::Ru), "18,15");
        assert_eq!(value(18.149, Language::En), "18.15");
        assert_eq!(value(-0.0001, Language::En), "−0.0001000");
        assert_eq!(value(-3e-14, Language::En), "0", "round-off of a zero");
        assert_eq!(value(1234.6, Language::En), "1235");
        assert_eq!(value(-46001.0, Language::En), "−46001");
        assert_eq!(scientific(1.63e-13, Language::Uz), "1,6·10⁻¹³");
        assert_eq!(scientific(-250.0, Language::En), "−2.5·10²");
        assert_eq!(value(-4600.0, Language::Ru), "−4600");
        assert_eq!(scientific(0.0, Language::En), "0");
    }

    /// A shift just under the course's limit 5/17 = 0.294118 is written apart from it.
    #[test]
    fn values_written_alike_get_the_digits_that_tell_them_apart() {
        assert_eq!(values_apart(0.2940, 5.0 / 17.0, Language::Ru), ("0,2940".into(), "0,2941".into()));
        assert_eq!(values_apart(0.29410, 5.0 / 17.0, Language::En), ("0.2941".into(), "0.29412".into()));
        assert_eq!(values_apart(0.2, 0.3, Language::En), ("0.2000".into(), "0.3000".into()));
        assert_eq!(values_apart(0.25, 0.25, Language::En), ("0.2500".into(), "0.2500".into()));
    }
}

#[cfg(test)]
mod bound_tests {
    use super::*;

    #[test]
    fn a_bound_above_is_the_next_one_two_or_five() {
        let en = Language::En;
        assert_eq!(bound_above(0.3357, en), "0.5");
        assert_eq!(bound_above(0.5115, en), "1");
        assert_eq!(bound_above(0.5, en), "1");
        assert_eq!(bound_above(0.12, en), "0.2");
        assert_eq!(bound_above(3.0, Language::Ru), "5");
        assert_eq!(bound_above(0.0004, Language::Uz), "0,0005");
    }

    #[test]
    fn a_tiny_difference_is_under_a_hundredth_of_a_percent() {
        assert_eq!(percent_difference(1.1e-4, Language::Ru), "< 0,01");
        assert_eq!(percent_difference(-0.384, Language::En), "-0.38".replace('-', "−"));
    }
}
