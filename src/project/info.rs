//! The `project` section: what the title block says and the sheets' language.

use super::values::UserText;
use crate::drawing::labels::Language;
use serde::Deserialize;
use serde_saphyr::{Location, Spanned};

fn blank() -> UserText {
    Spanned::new(String::new(), Location::UNKNOWN, Location::UNKNOWN)
}

/// The section as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InfoSpec {
    pub title: UserText,
    #[serde(default = "blank")]
    pub designation: UserText,
    #[serde(default = "blank")]
    pub student: UserText,
    #[serde(default = "blank")]
    pub group: UserText,
    #[serde(default = "blank")]
    pub supervisor: UserText,
    #[serde(default = "blank")]
    pub institution: UserText,
    #[serde(default)]
    pub language: Language,
}

/// What every sheet's title block and title say, checked.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ProjectInfo {
    pub title: String,
    pub designation: String,
    pub student: String,
    pub group: String,
    pub supervisor: String,
    pub institution: String,
    pub language: Language,
}

impl InfoSpec {
    /// Every text field with its name, for the checks of [`super::text`].
    pub fn texts(&self) -> [(&'static str, &UserText); 6] {
        [
            ("project.title", &self.title),
            ("project.designation", &self.designation),
            ("project.student", &self.student),
            ("project.group", &self.group),
            ("project.supervisor", &self.supervisor),
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
    /// The title block's organisation field: the institution and the group, as given.
    pub fn organisation(&self) -> String {
        [self.institution.as_str(), self.group.as_str()]
            .iter()
            .filter(|s| !s.is_empty())
            .copied()
            .collect::<Vec<_>>()
            .join(", ")
    }
}
