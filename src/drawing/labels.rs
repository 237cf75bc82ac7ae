//! Every word and unit a sheet prints, in Uzbek (Latin), Russian or English, from one YAML
//! file per label set under `templates/labels/`: `common.yaml` for what every sheet shares
//! (title block, units), one file per sheet for the rest.
//!
//! A label set is declared with [`crate::label_set!`]: its keys become typed accessors, so a
//! misspelt key does not compile; a key with parameters, e.g. `position(k)`, takes them by
//! name and fills the text's `{k}`. Loading checks that the file has exactly the declared
//! keys, each in all three languages, with exactly the declared placeholders (tested for
//! every set, so the `expect` on loading cannot fire in a release).

use std::collections::BTreeSet;

/// The language of a sheet's labels: Uzbek (Latin script, the default), Russian, English.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    #[default]
    Uz,
    Ru,
    En,
}

impl Language {
    pub const ALL: [Language; 3] = [Language::Uz, Language::Ru, Language::En];

    /// The key a project file writes it by.
    pub fn key(self) -> &'static str {
        match self {
            Language::Uz => "uz",
            Language::Ru => "ru",
            Language::En => "en",
        }
    }
}

/// A label set declared with [`crate::label_set!`]: the set for a language, loaded once.
pub trait LabelSet: 'static {
    fn get(lang: Language) -> &'static Self;
}

/// A sheet's language with the words every sheet shares and the sheet's own: what a function
/// that writes a word, a unit or a number needs, passed as one reference rather than three
/// parameters.
#[derive(Debug)]
pub struct Wording<S: 'static> {
    pub lang: Language,
    /// Units, table corners, the title block.
    pub common: &'static Common,
    /// The sheet's own label set.
    pub sheet: &'static S,
}

impl<S: LabelSet> Wording<S> {
    pub fn new(lang: Language) -> Wording<S> {
        Wording { lang, common: Common::get(lang), sheet: S::get(lang) }
    }
}

impl<S: 'static> Clone for Wording<S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S: 'static> Copy for Wording<S> {}

/// One label in the three languages, as written in a template.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub uz: String,
    pub ru: String,
    pub en: String,
}

impl Entry {
    pub fn pick(&self, lang: Language) -> &str {
        match lang {
            Language::Uz => &self.uz,
            Language::Ru => &self.ru,
            Language::En => &self.en,
        }
    }
}

/// The `{name}` placeholders of a text.
pub fn placeholders(text: &str) -> BTreeSet<&str> {
    let mut out = BTreeSet::new();
    let mut rest = text;
    while let Some(i) = rest.find('{') {
        let Some(j) = rest[i..].find('}') else { break };
        out.insert(&rest[i + 1..i + j]);
        rest = &rest[i + j + 1..];
    }
    out
}

/// Checks one entry: non-empty in every language, the declared placeholders exactly, every
/// glyph in the font, Uzbek oʻ/gʻ with U+02BB rather than an apostrophe.
pub fn check_entry(key: &str, e: &Entry, params: &[&str]) -> Result<(), String> {
    let want: BTreeSet<&str> = params.iter().copied().collect();
    for lang in Language::ALL {
        let text = e.pick(lang);
        if text.trim().is_empty() {
            return Err(format!("label `{key}` is empty in {lang:?}"));
        }
        if placeholders(text) != want {
            return Err(format!(
                "label `{key}` in {lang:?} has placeholders {:?}, declared {want:?}",
                placeholders(text)
            ));
        }
        if !crate::font::metrics().covers(text) {
            return Err(format!("label `{key}` in {lang:?} has a character the font lacks"));
        }
    }
    if e.uz.contains('\'') {
        return Err(format!("label `{key}`: Uzbek oʻ/gʻ take U+02BB (ʻ), not an apostrophe"));
    }
    Ok(())
}

/// Fills `{name}` placeholders; linear in the text's length.
pub fn fill(text: &str, args: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    let mut rest = text;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        let Some(j) = rest[i..].find('}') else { break };
        let name = &rest[i + 1..i + j];
        match args.iter().find(|(n, _)| *n == name) {
            Some((_, v)) => out.push_str(v),
            None => out.push_str(&rest[i..i + j + 1]),
        }
        rest = &rest[i + j + 1..];
    }
    out.push_str(rest);
    out
}

/// Declares a label set: a struct with one accessor per key, loaded from a YAML template.
///
/// ```ignore
/// label_set! {
///     /// Sheet 1's texts.
///     pub struct LeverLabels = "lever.yaml" {
///         velocity_plans,
///         position(k),
///     }
/// }
/// let l = LeverLabels::get(Language::Ru);
/// l.velocity_plans();   // "Планы скоростей"
/// l.position("3");      // "Положение 3"
/// ```
#[macro_export]
macro_rules! label_set {
    ($(#[$doc:meta])* pub struct $name:ident = $file:literal { $($key:ident $(($($param:ident),+))?),+ $(,)? }) => {
        $(#[$doc])*
        #[derive(Debug)]
        pub struct $name {
            $($key: String,)+
        }

        impl $name {
            /// Every key with its declared parameters.
            pub const KEYS: &'static [(&'static str, &'static [&'static str])] =
                &[$((stringify!($key), &[$($(stringify!($param)),+)?])),+];

            /// The template's text (embedded at build time).
            pub const SOURCE: &'static str = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/templates/labels/", $file));

            /// Parses and checks the template, and picks `lang`.
            pub fn load(lang: $crate::drawing::labels::Language) -> Result<$name, String> {
                #[derive(serde::Deserialize)]
                #[serde(deny_unknown_fields)]
                struct Source {
                    $($key: $crate::drawing::labels::Entry,)+
                }
                let s: Source = serde_saphyr::from_str(Self::SOURCE).map_err(|e| format!("templates/labels/{}: {e}", $file))?;
                $($crate::drawing::labels::check_entry(stringify!($key), &s.$key, &[$($(stringify!($param)),+)?])
                    .map_err(|e| format!("templates/labels/{}: {e}", $file))?;)+
                Ok($name { $($key: s.$key.pick(lang).to_string(),)+ })
            }

            /// The set for `lang`, loaded once.
            pub fn get(lang: $crate::drawing::labels::Language) -> &'static $name {
                static SETS: [std::sync::OnceLock<$name>; 3] = [const { std::sync::OnceLock::new() }; 3];
                let i = lang as usize;
                SETS[i].get_or_init(|| $name::load(lang).expect("label templates are checked by the tests"))
            }

            $($crate::label_set!(@accessor $key $(($($param),+))?);)+
        }

        impl $crate::drawing::labels::LabelSet for $name {
            fn get(lang: $crate::drawing::labels::Language) -> &'static $name {
                $name::get(lang)
            }
        }
    };
    (@accessor $key:ident) => {
        pub fn $key(&self) -> &str {
            &self.$key
        }
    };
    (@accessor $key:ident ($($param:ident),+)) => {
        pub fn $key(&self, $($param: &str),+) -> String {
            $crate::drawing::labels::fill(&self.$key, &[$((stringify!($param), $param)),+])
        }
    };
}

label_set! {
    /// Texts every sheet shares: the title block, units, common words.
    pub struct Common = "common.yaml" {
        tb_drawn,
        tb_checked,
        tb_tech_control,
        tb_std_control,
        tb_approved,
        tb_change,
        tb_sheet_no,
        tb_doc,
        tb_sign,
        tb_date,
        tb_lit,
        tb_lit_letter,
        tb_mass,
        tb_scale,
        tb_sheets,
        tb_course,
        unit_m_per_mm,
        unit_v_per_mm,
        unit_a_per_mm,
        unit_n_per_mm,
        unit_n,
        unit_m_per_s,
        unit_m_per_s2,
        unit_per_s,
        unit_per_s2,
        unit_kg,
        unit_kg_m2,
        unit_mm,
        unit_n_m,
        quantity,
        unit,
        assumed,
        link_col,
        position_col,
        value,
    }
}

impl Common {
    /// An SI unit as the note's tables write it ("kg", "m/s²", "N·m" …), in this language;
    /// a unit without a translation ("%", "") as it is.
    pub fn si_unit<'a>(&'a self, si: &'a str) -> &'a str {
        match si {
            "m/s" => self.unit_m_per_s(),
            "m/s²" => self.unit_m_per_s2(),
            "1/s" => self.unit_per_s(),
            "1/s²" => self.unit_per_s2(),
            "kg" => self.unit_kg(),
            "kg·m²" => self.unit_kg_m2(),
            "mm" => self.unit_mm(),
            "N" => self.unit_n(),
            "N·m" => self.unit_n_m(),
            other => other,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_common_set_loads_in_every_language() {
        for lang in Language::ALL {
            Common::load(lang).unwrap();
        }
        assert_eq!(Common::get(Language::Ru).unit_n_per_mm(), "Н/мм");
        assert_eq!(Common::get(Language::Ru).si_unit("kg·m²"), "кг·м²");
    }

    #[test]
    fn placeholders_are_filled_by_name() {
        assert_eq!(fill("{k}-holat", &[("k", "4′")]), "4′-holat");
        assert_eq!(fill("a {x} b {y}", &[("y", "2"), ("x", "1")]), "a 1 b 2");
        assert_eq!(placeholders("φ₁ = {phi}° {g}").into_iter().collect::<Vec<_>>(), ["g", "phi"]);
        let e = Entry { uz: "{k}-holat".into(), ru: "Положение {k}".into(), en: "Position {n}".into() };
        assert!(check_entry("position", &e, &["k"]).unwrap_err().contains("En"));
    }
}
