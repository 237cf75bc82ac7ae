//! Checks of the text a user writes that ends up on a sheet: no control characters (they
//! make an SVG invalid) and no character the embedded font lacks (it would print as an
//! empty box, or vanish). Each refusal names the field, the character and where it is.

use super::values::{LocalText, UserText};
use super::{Kind, Refusal, invalid};
use crate::font;
use serde_saphyr::{Location, Spanned};

/// Whether a line break may stand in the field (free text that is wrapped anyway).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lines {
    One,
    Many,
}

fn describe(c: char) -> String {
    if c.is_control() {
        format!("the control character U+{:04X}", c as u32)
    } else {
        format!("the character '{c}' (U+{:04X})", c as u32)
    }
}

/// Refuses control characters (but line breaks and tabs in [`Lines::Many`] fields) and
/// characters without a glyph in the sheets' font. Linear in the text's length.
pub fn check(field: &str, t: &UserText, lines: Lines) -> Result<(), Refusal> {
    check_str(field, &t.value, t.referenced, lines)
}

/// [`check`] for each language's text (the field named with the language's key).
pub fn check_local(field: &str, t: &Spanned<LocalText>, lines: Lines) -> Result<(), Refusal> {
    for (lang, text) in t.value.texts() {
        let field = match lang {
            Some(l) => format!("{field}.{}", l.key()),
            None => field.to_string(),
        };
        check_str(&field, text, t.referenced, lines)?;
    }
    Ok(())
}

/// A section's `assumptions`, each checked as free text (`<section>.assumptions[i]`).
pub fn assumptions(section: &str, texts: &[Spanned<LocalText>]) -> Result<Vec<LocalText>, Refusal> {
    texts
        .iter()
        .enumerate()
        .map(|(i, a)| check_local(&format!("{section}.assumptions[{i}]"), a, Lines::Many).map(|()| a.value.clone()))
        .collect()
}

fn check_str(field: &str, text: &str, at: Location, lines: Lines) -> Result<(), Refusal> {
    let metrics = font::metrics();
    for (i, c) in text.chars().enumerate() {
        let breaks = matches!(c, '\n' | '\t' | '\r');
        let why = if breaks && lines == Lines::Many {
            continue;
        } else if breaks {
            format!("{} (a line break or tab) is not allowed in this field", describe(c))
        } else if c.is_control() {
            format!("{} is not allowed in text", describe(c))
        } else if !metrics.has_glyph(c) {
            format!("{} is not in the sheets' font ({}), so it cannot be printed", describe(c), font::NAME)
        } else {
            continue;
        };
        return Err(invalid(at, field, format!("{why} (character {} of the text)", i + 1)).kind(Kind::Text));
    }
    Ok(())
}
