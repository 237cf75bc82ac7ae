//! Sheet texts in Uzbek (Latin), Russian or English, from `templates/labels.yaml`.

use std::collections::BTreeMap;

/// The language of a sheet's labels: Uzbek (Latin script, the default), Russian, English.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    #[default]
    Uz,
    Ru,
    En,
}

const SOURCE: &str = include_str!("../../templates/labels.yaml");

#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    uz: String,
    ru: String,
    en: String,
}

/// The label texts of one language.
pub struct Labels {
    lang: Language,
    entries: BTreeMap<String, Entry>,
}

impl Labels {
    pub fn new(lang: Language) -> Labels {
        let entries = serde_saphyr::from_str(SOURCE).expect("templates/labels.yaml is valid (tested)");
        Labels { lang, entries }
    }

    /// The text for `key`. A key missing from the template is a programming error caught
    /// by the tests; it shows as the key itself rather than aborting a sheet.
    pub fn get<'a>(&'a self, key: &'a str) -> &'a str {
        match self.entries.get(key) {
            Some(e) => match self.lang {
                Language::Uz => &e.uz,
                Language::Ru => &e.ru,
                Language::En => &e.en,
            },
            None => {
                debug_assert!(false, "label '{key}' missing from templates/labels.yaml");
                key
            }
        }
    }

    /// Every key of the template (for tests).
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.entries.keys().map(String::as_str)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_label_exists_in_every_language() {
        let l = Labels::new(Language::Uz);
        assert!(l.keys().count() > 20);
        for (k, e) in &l.entries {
            for text in [&e.uz, &e.ru, &e.en] {
                assert!(!text.trim().is_empty(), "label {k} is empty in some language");
                assert!(crate::font::metrics().covers(text), "label {k}: a glyph is missing");
            }
            assert!(!e.uz.contains('\''), "label {k}: Uzbek oʻ/gʻ take U+02BB, not an apostrophe");
        }
    }
}
