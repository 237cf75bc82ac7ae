//! Numbers as the sheets print them: decimal comma in Uzbek and Russian, point in English.

use crate::model::Language;

/// A value with about four significant digits (three decimals below 10).
pub fn value(x: f64, lang: Language) -> String {
    let a = x.abs();
    let dec = if a < 10.0 { 3 } else if a < 100.0 { 2 } else if a < 1000.0 { 1 } else { 0 };
    let s = format!("{x:.dec$}");
    let s = if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { s.trim_start_matches('-').to_string() } else { s };
    localise(&s, lang)
}

/// Replaces the decimal point for the language.
pub fn localise(s: &str, lang: Language) -> String {
    match lang {
        Language::En => s.to_string(),
        Language::Uz | Language::Ru => s.replace('.', ","),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_comma_and_significant_digits() {
        assert_eq!(value(0.5254, Language::Uz), "0,525");
        assert_eq!(value(18.149, Language::Ru), "18,15");
        assert_eq!(value(18.149, Language::En), "18.15");
        assert_eq!(value(-0.0001, Language::En), "0.000");
        assert_eq!(value(1234.6, Language::En), "1235");
    }
}
