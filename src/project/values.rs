//! Numbers and names as the project file writes them, checked where they are written.
//!
//! Every number must be finite and within [`crate::num::limits::INPUT_MAX`] (SI units), so no
//! product of a few inputs can overflow on the way to a sheet: a `mass: 1.0e300` is refused
//! at its line instead of ending as `inf` in an output.

use crate::drawing::labels::Language;
use crate::num::digits::{sig, written};
use crate::num::limits::INPUT_MAX;
use serde::{Deserialize, Deserializer};
use serde_saphyr::Spanned;

/// A point name as written, with where it was written.
pub type Name = Spanned<String>;

/// Text as written, with where it was written (checked by [`super::text::check`]).
pub type UserText = Spanned<String>;

fn number<'de, D: Deserializer<'de>>(d: D, ok: impl Fn(f64) -> bool, what: &str) -> Result<f64, D::Error> {
    let x = f64::deserialize(d)?;
    if !x.is_finite() {
        return Err(serde::de::Error::custom(format!("expected {what}, got {}", written(x))));
    }
    if x.abs() > INPUT_MAX {
        return Err(serde::de::Error::custom(format!(
            "{} is too large: numbers in a project file are SI units and must lie within ±{}",
            written(x),
            sig(INPUT_MAX, 3)
        )));
    }
    if !ok(x) {
        return Err(serde::de::Error::custom(format!("expected {what}, got {}", written(x))));
    }
    Ok(x)
}

/// A finite number (YAML's .nan and .inf are refused where they are written).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finite(pub f64);

impl<'de> Deserialize<'de> for Finite {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |_| true, "a finite number").map(Finite)
    }
}

/// A finite number ≥ 0 (masses, forces that may vanish).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonNegative(pub f64);

impl<'de> Deserialize<'de> for NonNegative {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |x| x >= 0.0, "a number ≥ 0").map(NonNegative)
    }
}

/// A strictly positive finite number (lengths, speeds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Positive(pub f64);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d, |x| x > 0.0, "a positive number").map(Positive)
    }
}

/// Text a user writes for the sheets: one text for every language, or one per language
/// (`{uz: …, ru: …, en: …}`, any of them; a language not given takes the first one written).
#[derive(Debug, Clone, PartialEq)]
pub enum LocalText {
    All(String),
    Each(Vec<(Language, String)>),
}

impl LocalText {
    /// The text for a sheet in `lang`.
    pub fn get(&self, lang: Language) -> &str {
        match self {
            LocalText::All(t) => t,
            LocalText::Each(each) => {
                each.iter().find(|(l, _)| *l == lang).or(each.first()).map_or("", |(_, t)| t.as_str())
            }
        }
    }

    /// Every text written, with its language (none for [`LocalText::All`]).
    pub fn texts(&self) -> Vec<(Option<Language>, &str)> {
        match self {
            LocalText::All(t) => vec![(None, t.as_str())],
            LocalText::Each(each) => each.iter().map(|(l, t)| (Some(*l), t.as_str())).collect(),
        }
    }
}

impl Default for LocalText {
    fn default() -> LocalText {
        LocalText::All(String::new())
    }
}

impl From<String> for LocalText {
    fn from(t: String) -> LocalText {
        LocalText::All(t)
    }
}

impl From<&str> for LocalText {
    fn from(t: &str) -> LocalText {
        LocalText::All(t.to_string())
    }
}

struct LocalTextVisitor;

impl<'de> serde::de::Visitor<'de> for LocalTextVisitor {
    type Value = LocalText;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a text, or one per language: `{uz: …, ru: …, en: …}`")
    }

    fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<LocalText, E> {
        Ok(LocalText::All(s.to_owned()))
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<LocalText, A::Error> {
        let mut each: Vec<(Language, String)> = Vec::new();
        while let Some(lang) = map.next_key::<Language>()? {
            if each.iter().any(|(l, _)| *l == lang) {
                return Err(serde::de::Error::custom(format!("the language `{}` is given twice", lang.key())));
            }
            each.push((lang, map.next_value::<String>()?));
        }
        if each.is_empty() {
            return Err(serde::de::Error::custom("no text: give `uz`, `ru` or `en` (or one text for all)"));
        }
        Ok(LocalText::Each(each))
    }
}

impl<'de> Deserialize<'de> for LocalText {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(LocalTextVisitor)
    }
}
