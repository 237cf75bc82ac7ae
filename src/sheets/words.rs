//! The note tables' keys in the sheet's language: units, subscript words, force letters and
//! condition names. Every match is exhaustive, so a key without a word does not compile,
//! and the label sets' loading checks that every word exists in every language.

use super::cam::labels::CamLabels;
use super::gears::labels::GearLabels;
use super::lever::labels::LeverLabels;
use crate::drawing::labels::{Common, Language};
use crate::gears::planetary::ConditionKind;
use crate::report::{Quantity, Sub, SubWord, Unit};

/// A unit as the sheet's language writes it.
pub fn unit(lang: Language, u: Unit) -> &'static str {
    let c = Common::get(lang);
    match u {
        Unit::None => "",
        Unit::Mm => c.unit_mm(),
        Unit::MPerS => c.unit_m_per_s(),
        Unit::MPerS2 => c.unit_m_per_s2(),
        Unit::PerS => c.unit_per_s(),
        Unit::PerS2 => c.unit_per_s2(),
        Unit::Kg => c.unit_kg(),
        Unit::KgM2 => c.unit_kg_m2(),
        Unit::N => c.unit_n(),
        Unit::NM => c.unit_n_m(),
        Unit::Deg => "°",
        Unit::Percent => "%",
    }
}

/// A subscript word in the sheet's language.
fn word(lang: Language, w: SubWord) -> &'static str {
    let (g, c) = (GearLabels::get(lang), CamLabels::get(lang));
    match w {
        SubWord::Drawn => g.sub_drawn(),
        SubWord::Required => g.sub_required(),
        SubWord::Pitch => c.sub_pitch(),
        SubWord::Work => c.sub_work(),
        SubWord::Roller => c.sub_roller(),
        SubWord::AllowedRise => c.sub_allowed_rise(),
        SubWord::AllowedReturn => c.sub_allowed_return(),
        SubWord::MaxRise => c.sub_max_rise(),
        SubWord::MaxReturn => c.sub_max_return(),
    }
}

/// A subscript as the sheet prints it.
pub fn sub(lang: Language, s: &Sub) -> String {
    match s {
        Sub::None => String::new(),
        Sub::Name(n) => n.clone(),
        Sub::Word(w) => word(lang, *w).to_string(),
        Sub::Force(kind, link) => LeverLabels::get(lang).force(*kind, link),
    }
}

/// A planetary condition's name in the sheet's language.
pub fn condition(lang: Language, k: ConditionKind) -> &'static str {
    let g = GearLabels::get(lang);
    match k {
        ConditionKind::Ratio => g.cond_ratio(),
        ConditionKind::Coaxiality => g.cond_coaxiality(),
        ConditionKind::Neighbours => g.cond_neighbours(),
        ConditionKind::Assembly => g.cond_assembly(),
        ConditionKind::NoUndercut => g.cond_no_undercut(),
        ConditionKind::RingTeeth => g.cond_ring_teeth(),
        ConditionKind::RingPlanetDifference => g.cond_ring_planet_difference(),
    }
}

/// A row's quantity as printed: its symbol and subscript, or a condition's name alone.
pub fn quantity(lang: Language, q: &Quantity) -> (String, String) {
    match q {
        Quantity::Symbol(symbol, s) => (symbol.to_string(), sub(lang, s)),
        Quantity::Condition(k) => (condition(lang, *k).to_string(), String::new()),
    }
}
