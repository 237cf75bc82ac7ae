//! The `project` section: what the title block says and the sheets' language.

use super::values::{LocalText, UserText};
use crate::drawing::labels::Language;
use serde::Deserialize;
use serde_saphyr::{Location, Spanned};

fn blank() -> UserText {
    Spanned::new(String::new(), Location::UNKNOWN, Location::UNKNOWN)
}

fn blank_local() -> Spanned<LocalText> {
    Spanned::new(LocalText::default(), Location::UNKNOWN, Location::UNKNOWN)
}

/// The section as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InfoSpec {
    /// One text, or one per language (`{uz: …, ru: …, en: …}`).
    pub title: Spanned<LocalText>,
    /// One text, or one per language (the course's letters differ: MMN, ТММ, TMM).
    #[serde(default = "blank_local")]
    pub designation: Spanned<LocalText>,
    #[serde(default = "blank")]
    pub student: UserText,
    #[serde(default = "blank")]
    pub group: UserText,
    #[serde(default = "blank")]
    pub supervisor: UserText,
    /// One text, or one per language.
    #[serde(default = "blank_local")]
    pub institution: Spanned<LocalText>,
    #[serde(default)]
    pub language: Language,
}

/// What every sheet's title block and title say, checked.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ProjectInfo {
    /// Per language: read it with [`ProjectInfo::title`].
    pub title: LocalText,
    /// Per language: read it with [`ProjectInfo::designation`].
    pub designation: LocalText,
    pub student: String,
    pub group: String,
    pub supervisor: String,
    /// Per language: read it with [`ProjectInfo::institution`].
    pub institution: LocalText,
    pub language: Language,
}

impl InfoSpec {
    /// Every one-language text field with its name, for the checks of [`super::text`].
    pub fn texts(&self) -> [(&'static str, &UserText); 3] {
        [("project.student", &self.student), ("project.group", &self.group), ("project.supervisor", &self.supervisor)]
    }

    /// The fields that may be written per language.
    pub fn local_texts(&self) -> [(&'static str, &Spanned<LocalText>); 3] {
        [
            ("project.title", &self.title),
            ("project.designation", &self.designation),
            ("project.institution", &self.institution),
        ]
    }

    pub fn resolve(&self) -> ProjectInfo {
        ProjectInfo {
            title: self.title.value.clone(),
            designation: self.designation.value.clone(),
            student: self.student.value.clone(),
            group: self.group.value.clone(),
            supervisor: self.supervisor.value.clone(),
            institution: self.institution.value.clone(),
            language: self.language,
        }
    }
}

impl ProjectInfo {
    /// The project's title in the sheets' language.
    pub fn title(&self) -> &str {
        self.title.get(self.language)
    }

    /// The designation in the sheets' language.
    pub fn designation(&self) -> &str {
        self.designation.get(self.language)
    }

    /// The institution in the sheets' language.
    pub fn institution(&self) -> &str {
        self.institution.get(self.language)
    }

    /// The title block's organisation field: the institution and the group, as given.
    pub fn organisation(&self) -> String {
        [self.institution(), self.group.as_str()]
            .iter()
            .filter(|s| !s.is_empty())
            .copied()
            .collect::<Vec<_>>()
            .join(", ")
    }
}
