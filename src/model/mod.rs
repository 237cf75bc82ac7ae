//! The input model: the project file (YAML) and its translation into a mechanism.

mod build;
mod forces;
mod indicators;
pub mod spec;

pub use build::{build, Settings};
pub use spec::{Language, ProjectFile, ProjectInfo};

/// An error in the user's project file, always with where it is.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The YAML does not parse or does not fit the schema (the message has line and column).
    #[error("{0}")]
    Yaml(String),
    #[error("line {line}, column {column}: {field}: {message}")]
    Invalid { line: u64, column: u64, field: String, message: String },
}

/// Parses a project file from YAML text.
pub fn parse(text: &str) -> Result<ProjectFile, ModelError> {
    serde_saphyr::from_str(text).map_err(|e| {
        let msg = e.to_string();
        ModelError::Yaml(msg.strip_prefix("error: ").unwrap_or(&msg).to_string())
    })
}
