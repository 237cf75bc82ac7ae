//! The units a student may write a value in, for each unit the answers have: the factor
//! from the student's unit to the answer's. Written the usual ways in Latin, Cyrillic and
//! ASCII ("m/s^2", "м/с²", "rad/s", "об/мин", "kN", "Н·м").

use std::f64::consts::PI;

/// The answers' units (as `report::Unit::si` writes them) and the spellings each accepts.
const TABLE: &[(&str, &[(&str, f64)])] = &[
    ("m/s", &[("m/s", 1.0), ("м/с", 1.0), ("mm/s", 1e-3), ("мм/с", 1e-3), ("cm/s", 1e-2), ("см/с", 1e-2)]),
    ("m/s²", &[("m/s2", 1.0), ("м/с2", 1.0), ("mm/s2", 1e-3), ("мм/с2", 1e-3)]),
    (
        "1/s",
        &[
            ("1/s", 1.0),
            ("rad/s", 1.0),
            ("s-1", 1.0),
            ("1/с", 1.0),
            ("рад/с", 1.0),
            ("с-1", 1.0),
            ("rpm", PI / 30.0),
            ("rev/min", PI / 30.0),
            ("min-1", PI / 30.0),
            ("об/мин", PI / 30.0),
            ("айл/мин", PI / 30.0),
            ("ayl/min", PI / 30.0),
        ],
    ),
    ("1/s²", &[("1/s2", 1.0), ("rad/s2", 1.0), ("s-2", 1.0), ("1/с2", 1.0), ("рад/с2", 1.0), ("с-2", 1.0)]),
    ("mm", &[("mm", 1.0), ("мм", 1.0), ("m", 1e3), ("м", 1e3), ("cm", 10.0), ("см", 10.0)]),
    ("°", &[("°", 1.0), ("deg", 1.0), ("град", 1.0), ("daraja", 1.0), ("rad", 180.0 / PI), ("рад", 180.0 / PI)]),
    ("N", &[("n", 1.0), ("н", 1.0), ("kn", 1e3), ("кн", 1e3)]),
    ("N·m", &[("n·m", 1.0), ("nm", 1.0), ("н·м", 1.0), ("нм", 1.0), ("kn·m", 1e3), ("кн·м", 1e3)]),
    ("kg", &[("kg", 1.0), ("кг", 1.0), ("g", 1e-3), ("г", 1e-3)]),
    ("kg·m²", &[("kg·m2", 1.0), ("кг·м2", 1.0)]),
    ("%", &[("%", 1.0)]),
    ("", &[("", 1.0), ("-", 1.0)]),
];

/// The unit written the one way the table spells it: no spaces, lower case (so "N" and
/// "n" are one), "²" and "^2" as "2", "⁻¹" and "^-1" as "-1", "*" and "." as "·".
fn normal(unit: &str) -> String {
    let mut u: String = unit.chars().filter(|c| !c.is_whitespace()).flat_map(char::to_lowercase).collect();
    for (from, to) in
        [("^-1", "-1"), ("⁻¹", "-1"), ("^-2", "-2"), ("⁻²", "-2"), ("^2", "2"), ("²", "2"), ("*", "·"), (".", "·")]
    {
        u = u.replace(from, to);
    }
    u
}

/// The factor from `given` (empty: the answer's own unit) to the answer's `unit`, or `None`
/// when `given` is not a unit of that quantity.
pub fn factor(given: &str, unit: &str) -> Option<f64> {
    if given.trim().is_empty() {
        return Some(1.0);
    }
    let (_, spellings) = TABLE.iter().find(|(u, _)| *u == unit)?;
    let g = normal(given);
    spellings.iter().find(|(s, _)| normal(s) == g).map(|&(_, f)| f)
}

/// The unit as a message names it ("m/s", "no unit").
pub fn spelled(unit: &str) -> String {
    if unit.is_empty() { "no unit".into() } else { unit.into() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_usual_spellings_convert_and_others_are_refused() {
        assert_eq!(factor("m/s^2", "m/s²"), Some(1.0));
        assert_eq!(factor("м/с²", "m/s²"), Some(1.0));
        assert_eq!(factor("mm/s", "m/s"), Some(1e-3));
        assert_eq!(factor("kN", "N"), Some(1e3));
        assert_eq!(factor("Н·м", "N·m"), Some(1.0));
        assert_eq!(factor("N*m", "N·m"), Some(1.0));
        assert!((factor("rpm", "1/s").unwrap() * 60.0 - 2.0 * PI).abs() < 1e-15);
        assert!((factor("rad", "°").unwrap() - 57.29577951308232).abs() < 1e-12);
        assert_eq!(factor("", "m/s"), Some(1.0));
        assert_eq!(factor("N", "m/s"), None);
        assert_eq!(factor("furlongs", "mm"), None);
    }
}
