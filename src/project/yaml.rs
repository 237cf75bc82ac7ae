//! Reading the YAML with serde-saphyr, and its errors in the course's words: each becomes a
//! [`Refusal`] that names the field ([`Places`] finds it from the position) and says what was
//! expected as a student would say it — never a Rust type, a serde or YAML-library term.

use super::places::Places;
use super::refusal::{Kind, Refusal};
use serde::de::DeserializeOwned;
use serde_saphyr::budget::BudgetBreach;
use serde_saphyr::{DuplicateKeyPolicy, Error, Options};

/// The reading options: a key written twice is found by [`Places`], in its own section, so
/// that it blocks that section's sheet only; here the first one is read.
fn options() -> Options {
    let mut o = Options::default();
    o.duplicate_keys = DuplicateKeyPolicy::FirstWins;
    o.with_snippet = false;
    o
}

/// Reads `text` as a `T`; an error names its field through `places`.
pub(crate) fn read<T: DeserializeOwned>(text: &str, places: &Places) -> Result<T, Refusal> {
    serde_saphyr::from_str_with_options(text, options()).map_err(|e| refusal(&e, places))
}

/// The error's own, innermost form (without the snippet and alias wrappers).
fn innermost(e: &Error) -> &Error {
    match e.without_snippet() {
        Error::AliasError { error, .. } => innermost(error),
        other => other,
    }
}

/// A YAML library error as a refusal of the field at its position.
pub(crate) fn refusal(e: &Error, places: &Places) -> Refusal {
    let e = innermost(e);
    let (mut line, mut column) = e.location().map_or((0, 0), |l| (l.line(), l.column()));
    if matches!(e, Error::SerdeMissingField { field: "project", .. }) {
        (line, column) = (1, 1);
    }
    let path = match e {
        _ if line == 0 => String::new(),
        // The top level's one required key: the document is what lacks it.
        Error::SerdeMissingField { field: "project", .. } => String::new(),
        Error::SerdeMissingField { .. } => places.mapping_at(line, column),
        _ => places.path_at(line, column),
    };
    let (mut kind, mut cause) = words(e);
    if path.is_empty() && kind == Kind::Value {
        // The top level itself is not what a project file is.
        kind = Kind::Syntax;
        cause =
            format!("{cause}: a project file is a mapping of sections (`project:`, `mechanism:`, `gears:`, `cam:`)");
    }
    Refusal::new(kind, (line, column), path, cause).placed(places)
}

/// What the error means, in words.
fn words(e: &Error) -> (Kind, String) {
    use Error::*;
    match e {
        Message { msg, .. } => (Kind::Value, msg.clone()),
        InvalidScalar { ty, .. } => (Kind::Value, format!("expected {}", expected(ty))),
        NonFiniteFloat { value, .. } => (Kind::Value, format!("{value} is not a finite number")),
        SerdeInvalidType { unexpected, expected: want, .. } | SerdeInvalidValue { unexpected, expected: want, .. } => {
            (Kind::Value, format!("expected {}, found {}", expected(want), found(unexpected)))
        }
        SerdeInvalidLength { len, expected: want, .. } => {
            (Kind::Value, format!("{len} item(s), expected {}", expected(want)))
        }
        SerdeUnknownVariant { variant, expected, .. } => {
            (Kind::Value, format!("unknown value `{variant}`: {}", choices(variant, expected)))
        }
        SerdeUnknownField { field, expected, .. } => {
            (Kind::Key, format!("unknown key `{field}`: {}", choices(field, expected)))
        }
        SerdeMissingField { field: "project", .. } => (
            Kind::Section,
            "the `project` section (the title and the sheets' language) is missing; `tmm example` prints one".into(),
        ),
        SerdeMissingField { field, .. } => (Kind::Key, format!("the key `{field}` is missing here")),
        DuplicateMappingKey { key, .. } => {
            (Kind::Key, format!("the key `{}` is written twice in one mapping", key.as_deref().unwrap_or("?")))
        }
        MultipleDocuments { .. } => {
            (Kind::Syntax, "a second YAML document starts here (`---`): a project file is one document".to_string())
        }
        Budget { breach, .. } => {
            (Kind::Syntax, format!("the file is too large for a project file: {}", budget(breach)))
        }
        Eof { .. } => (Kind::Syntax, "the file ends in the middle of a value".to_string()),
        InvalidUtf8Input => (Kind::Syntax, "the file is not UTF-8 text".to_string()),
        UnknownAnchor { .. } => {
            (Kind::Syntax, "an alias (`*name`) refers to an anchor that is not defined".to_string())
        }
        AliasReplayCounterOverflow { .. }
        | AliasReplayLimitExceeded { .. }
        | AliasExpansionLimitExceeded { .. }
        | AliasReplayStackDepthExceeded { .. } => {
            (Kind::Syntax, "aliases (`*name`) expand too far for a project file".to_string())
        }
        NullIntoString { .. } => (Kind::Value, "expected a text, found nothing".to_string()),
        InvalidBooleanStrict { .. } => (Kind::Value, "expected true or false".to_string()),
        Unexpected { expected, .. } => (Kind::Value, format!("expected {}", structure(expected))),
        ExternalMessage { msg, .. } => (Kind::Syntax, format!("YAML syntax: {msg}")),
        other => (Kind::Syntax, format!("YAML: {}", other.without_snippet())),
    }
}

/// What serde says was expected, as a reader would: "u32" → "a whole number ≥ 0".
fn expected(want: &str) -> String {
    let w = want.trim();
    let plain = match w {
        "u8" | "u16" | "u32" | "u64" | "u128" | "usize" => "a whole number ≥ 0 (such as 17)",
        "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => "a whole number",
        "f32" | "f64" | "a number" | "floating point" => "a number",
        "bool" | "a boolean" => "true or false",
        "char" | "a character" => "one character",
        "a string" | "string" | "str" | "String" => "a text",
        "a sequence" | "sequence" => "a list ([…])",
        "a map" | "map" => "a mapping of keys ({…})",
        _ => "",
    };
    if !plain.is_empty() {
        return plain.to_string();
    }
    if let Some(n) = w.strip_prefix("an array of length ").or_else(|| w.strip_prefix("a tuple of size ")) {
        return format!("a list of {n} values [x, y, …]");
    }
    if w.starts_with("struct ") || w.starts_with("tuple struct ") {
        return "a mapping of keys ({…})".to_string();
    }
    if w.starts_with("enum ") || w.contains("variant") {
        return "one of the names the format lists".to_string();
    }
    w.to_string()
}

/// A structure the YAML reader expected, in words.
fn structure(what: &str) -> &str {
    match what {
        "mapping start" | "mapping" => "a mapping of keys ({…})",
        "sequence start" | "sequence" => "a list ([…])",
        "scalar" => "a single value",
        other => other,
    }
}

/// What serde says it found: "string \"a\"" → "the text \"a\"".
fn found(what: &str) -> String {
    let w = what.trim();
    for (prefix, word) in [("string ", "the text "), ("integer ", "the number "), ("floating point ", "the number ")] {
        if let Some(rest) = w.strip_prefix(prefix) {
            return format!("{word}{rest}");
        }
    }
    match w {
        "map" => "a mapping ({…})".to_string(),
        "sequence" => "a list ([…])".to_string(),
        "unit value" | "null" => "nothing".to_string(),
        _ => w.to_string(),
    }
}

/// The choices of a key or value, the likeliest first when one is close to what was written.
fn choices(written: &str, expected: &[&str]) -> String {
    if expected.is_empty() {
        return "nothing is expected here".to_string();
    }
    let list = expected.iter().map(|k| format!("`{k}`")).collect::<Vec<_>>().join(", ");
    match closest(written, expected) {
        Some(k) => format!("did you mean `{k}`? (here: {list})"),
        None => format!("here: {list}"),
    }
}

/// The expected name within two edits of `written`, if one is.
pub(crate) fn closest<'a>(written: &str, expected: &[&'a str]) -> Option<&'a str> {
    let w = written.to_lowercase();
    expected
        .iter()
        .map(|&k| (crate::num::edit_distance(&w, &k.to_lowercase()), k))
        .filter(|&(d, k)| d <= 2.min(k.chars().count() / 2 + 1))
        .min_by_key(|&(d, _)| d)
        .map(|(_, k)| k)
}

/// A budget breach in words.
fn budget(b: &BudgetBreach) -> &'static str {
    match b {
        BudgetBreach::Events { .. } | BudgetBreach::Nodes { .. } => "it holds too many values",
        BudgetBreach::Aliases { .. } | BudgetBreach::Anchors { .. } => "it holds too many aliases or anchors",
        BudgetBreach::Depth { .. } => "its values are nested too deeply",
        BudgetBreach::Documents { .. } => "it holds more than one document",
        BudgetBreach::ScalarBytes { .. } => "its texts are too long in all",
        _ => "it is too large or too complex",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn close_names_are_suggested() {
        assert_eq!(closest("rmp", &["rpm", "omega", "length"]), Some("rpm"));
        assert_eq!(closest("modul", &["module", "z", "shift"]), Some("module"));
        assert_eq!(closest("xyz", &["module", "z"]), None);
        assert_eq!(expected("u32"), "a whole number ≥ 0 (such as 17)");
        assert_eq!(found("string \"a\""), "the text \"a\"");
    }
}
