//! Errors as data: a refusal of the project file says what kind of problem it is, which field
//! (`gears.pair.z[1]`), where (line and column), why in the course's words, and which section
//! it belongs to — so that the other sections' sheets can still be built and a batch can
//! count refusals by kind. A [`Warning`] is input that builds but is almost surely a mistake.

use super::places::Places;
use serde_saphyr::Location;

/// What kind of problem a refusal is, for a batch to count them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Not a YAML document this program reads: its syntax, its encoding, its size, a second
    /// document, an alias that expands too far.
    Syntax,
    /// A key the format does not have, a key missing, a key written twice.
    Key,
    /// A value of the wrong type, out of its range, or not finite.
    Value,
    /// A name that refers to nothing, or a name or number given twice.
    Reference,
    /// Text the sheets cannot print, or too long for its place.
    Text,
    /// What the numbers describe cannot be built by the course's method: a mechanism that
    /// cannot be assembled or passes a dead point, a gear pair without a working angle, a cam
    /// too large to draw, a planetary ratio no tooth numbers give.
    Design,
    /// A section a sheet needs is missing, or the file has nothing to draw.
    Section,
}

impl Kind {
    /// The kind's name as `results.json`, a batch summary and the tests write it.
    pub fn key(self) -> &'static str {
        match self {
            Kind::Syntax => "syntax",
            Kind::Key => "key",
            Kind::Value => "value",
            Kind::Reference => "reference",
            Kind::Text => "text",
            Kind::Design => "design",
            Kind::Section => "section",
        }
    }
}

/// A refusal of the project file, always with the field and where it is written.
#[derive(Debug, Clone, PartialEq, serde::Serialize, thiserror::Error)]
#[error("line {line}, column {column}: {}{cause}", field_prefix(path))]
pub struct Refusal {
    pub kind: Kind,
    /// The field's path (`gears.pair.z[1]`); empty for the document as a whole.
    pub path: String,
    /// 1-based; the document's start when the problem is the whole file's.
    pub line: u64,
    pub column: u64,
    /// Why, in the course's words.
    pub cause: String,
    /// The section the field belongs to (`mechanism`, `gears`, `cam`): its sheet cannot be
    /// built, the others can. `None`: the whole project is refused.
    pub section: Option<&'static str>,
}

fn field_prefix(path: &str) -> String {
    if path.is_empty() { String::new() } else { format!("{path}: ") }
}

impl Refusal {
    pub fn new(kind: Kind, (line, column): (u64, u64), path: impl Into<String>, cause: impl Into<String>) -> Refusal {
        Refusal { kind, path: path.into(), line, column, cause: cause.into(), section: None }
    }

    /// The same refusal with a place: its own, else where its field (or the field's nearest
    /// written ancestor) is written, else the document's start.
    pub fn placed(mut self, places: &Places) -> Refusal {
        if self.line == 0 {
            (self.line, self.column) = places.place_of(&self.path).unwrap_or((1, 1));
        }
        self.column = self.column.max(1);
        self
    }

    /// The same refusal as another kind.
    pub fn kind(mut self, kind: Kind) -> Refusal {
        self.kind = kind;
        self
    }

    /// The same refusal, belonging to `section`.
    pub fn in_section(mut self, section: &'static str) -> Refusal {
        self.section = Some(section);
        self
    }
}

/// Input that builds but is almost surely a mistake (printed; the build continues).
#[derive(Debug, Clone, PartialEq, serde::Serialize, thiserror::Error)]
#[error("line {line}, column {column}: {field}: {message}")]
pub struct Warning {
    pub line: u64,
    pub column: u64,
    pub field: String,
    pub message: String,
}

/// A value out of its range (or otherwise wrong) where it was written.
pub(crate) fn invalid(loc: Location, field: impl Into<String>, message: impl Into<String>) -> Refusal {
    Refusal::new(Kind::Value, (loc.line(), loc.column()), field, message)
}

pub(crate) fn warning(loc: Location, field: impl Into<String>, message: impl Into<String>) -> Warning {
    Warning { line: loc.line(), column: loc.column(), field: field.into(), message: message.into() }
}
