//! tmm-sheets in the browser: the library's `session` calls, for JavaScript through
//! wasm-bindgen. Everything crosses as JSON text or bytes; nothing here computes or draws —
//! the files are the command line's own (the browser test compares them byte for byte).
//!
//! A build goes step by step so that the page's worker can report progress:
//! `new Job(text, options)`, `job.sheets()`, `job.build_sheet(n)` for each, `job.finish()`,
//! then `job.count()`, `job.name(i)`, `job.bytes(i)` and `job.zip()`.

use std::io::Write as _;
use tmm_sheets::drawing::labels::Language;
use tmm_sheets::pipeline::DxfVersion;
use tmm_sheets::session::{self, Files, Problem, Request, Session};
use wasm_bindgen::prelude::*;

/// A language by its key (`uz`, `ru`, `en`); empty for the project file's own.
fn language(key: &str) -> Result<Option<Language>, String> {
    match key {
        "" => Ok(None),
        _ => Language::ALL
            .into_iter()
            .find(|l| l.key() == key)
            .map(Some)
            .ok_or_else(|| format!("no language '{key}': uz, ru or en")),
    }
}

/// A problem that is not the project's (a bad option from the page) as a [`Problem`].
fn usage(message: String) -> Box<Problem> {
    Box::new(Problem::unplaced("usage", message))
}

fn json(p: &Problem) -> JsValue {
    JsValue::from_str(&serde_json::to_string(p).expect("a problem serialises"))
}

/// The page's options, as JSON: `{"sheets": [1, 3], "lang": "ru", "pdf": true, "dxf":
/// "r2000", "overlay": false}`; every key may be left out (the command line's defaults,
/// but no DXF).
pub fn request(options: &str) -> Result<Request, Box<Problem>> {
    let v: serde_json::Value = serde_json::from_str(if options.trim().is_empty() { "{}" } else { options })
        .map_err(|e| usage(e.to_string()))?;
    let sheets = match v.get("sheets") {
        None | Some(serde_json::Value::Null) => Vec::new(),
        Some(s) => serde_json::from_value::<Vec<u32>>(s.clone()).map_err(|e| usage(format!("sheets: {e}")))?,
    };
    let lang = language(v.get("lang").and_then(|l| l.as_str()).unwrap_or("")).map_err(usage)?;
    let dxf = match v.get("dxf").and_then(|d| d.as_str()) {
        None | Some("") => None,
        Some("r2000") => Some(DxfVersion::R2000),
        Some("r12") => Some(DxfVersion::R12),
        Some(other) => return Err(usage(format!("no DXF version '{other}': r2000 or r12"))),
    };
    let flag = |k: &str, default: bool| v.get(k).and_then(|b| b.as_bool()).unwrap_or(default);
    Ok(Request { sheets, lang, pdf: flag("pdf", true), dxf, overlay: flag("overlay", false) })
}

/// Files as one zip, deflated, every entry dated 1980-01-01 (the same bytes every time).
pub fn zip_files(files: &Files) -> Result<Vec<u8>, String> {
    let mut zip = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .last_modified_time(zip::DateTime::default());
    for (name, bytes) in files {
        zip.start_file(name.as_str(), options).map_err(|e| e.to_string())?;
        zip.write_all(bytes).map_err(|e| e.to_string())?;
    }
    Ok(zip.finish().map_err(|e| e.to_string())?.into_inner())
}

/// The guide's worked example's project file (the program's default project).
#[wasm_bindgen]
pub fn example() -> String {
    tmm_sheets::pipeline::DEFAULT_PROJECT.to_string()
}

/// The catalogue's tasks and variants named in `lang`, as JSON (`session::TaskEntry`).
#[wasm_bindgen]
pub fn catalogue(lang: &str) -> Result<String, JsValue> {
    let lang = language(lang)?.unwrap_or_default();
    let tasks = session::catalogue(lang)?;
    Ok(serde_json::to_string(&tasks).expect("the catalogue serialises"))
}

/// A catalogue variant's project file, its comments in `lang`.
#[wasm_bindgen]
pub fn variant(task: &str, variant: u32, lang: &str) -> Result<String, JsValue> {
    Ok(session::variant(task, variant, language(lang)?.unwrap_or_default())?)
}

/// Reads a project for the options without building it: `{"ok": true, "sheets": […],
/// "notes": […]}` or `{"ok": false, "problem": {…}}`, for the editor to mark as it is typed.
#[wasm_bindgen]
pub fn validate(text: &str, options: &str) -> String {
    let value = request(options).and_then(|r| Session::open(text, &r)).map_or_else(
        |p| serde_json::json!({ "ok": false, "problem": p }),
        |s| serde_json::json!({ "ok": true, "sheets": s.sheets(), "notes": s.notes(), "title": s.title() }),
    );
    value.to_string()
}

/// One build, sheet by sheet; its files kept for the page to show and download.
#[wasm_bindgen]
pub struct Job {
    session: Session,
    files: Files,
}

#[wasm_bindgen]
impl Job {
    /// Reads the project; a refusal is thrown as the JSON of a `session::Problem`.
    #[wasm_bindgen(constructor)]
    pub fn new(text: &str, options: &str) -> Result<Job, JsValue> {
        let session = request(options).and_then(|r| Session::open(text, &r)).map_err(|p| json(&p))?;
        Ok(Job { session, files: Vec::new() })
    }

    /// The sheets to build, in order.
    pub fn sheets(&self) -> Vec<u32> {
        self.session.sheets().to_vec()
    }

    /// Builds sheet `n` and keeps its files.
    pub fn build_sheet(&mut self, n: u32) -> Result<(), JsValue> {
        let files = self.session.build_sheet(n).map_err(|p| json(&p))?;
        self.files.extend(files);
        Ok(())
    }

    /// Adds `results.json` (and the overlays when asked for) after the sheets' files.
    pub fn finish(&mut self) -> Result<(), JsValue> {
        let files = self.session.finish().map_err(|p| json(&p))?;
        self.files.extend(files);
        Ok(())
    }

    /// The warnings so far, as JSON (`session::Note`).
    pub fn notes(&self) -> String {
        serde_json::to_string(self.session.notes()).expect("notes serialise")
    }

    pub fn title(&self) -> String {
        self.session.title().to_string()
    }

    pub fn count(&self) -> usize {
        self.files.len()
    }

    pub fn name(&self, i: usize) -> String {
        self.files.get(i).map(|f| f.0.clone()).unwrap_or_default()
    }

    pub fn bytes(&self, i: usize) -> Vec<u8> {
        self.files.get(i).map(|f| f.1.clone()).unwrap_or_default()
    }

    /// Every file kept, as one zip.
    pub fn zip(&self) -> Result<Vec<u8>, JsValue> {
        Ok(zip_files(&self.files)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_read_as_the_command_lines() {
        let r = request(r#"{"sheets":[1,3],"lang":"ru","pdf":false,"dxf":"r12","overlay":true}"#).unwrap();
        assert_eq!(
            (r.sheets, r.lang, r.pdf, r.dxf, r.overlay),
            (vec![1, 3], Some(Language::Ru), false, Some(DxfVersion::R12), true)
        );
        let d = request("").unwrap();
        assert_eq!((d.sheets.len(), d.lang, d.pdf, d.dxf, d.overlay), (0, None, true, None, false));
        assert_eq!(request(r#"{"lang":"de"}"#).unwrap_err().kind, "usage");
    }

    #[test]
    fn the_zip_is_the_same_bytes_every_time() {
        let files: Files = vec![("a.svg".into(), b"<svg/>".repeat(100)), ("b.csv".into(), b"x,y\n".to_vec())];
        let z = zip_files(&files).unwrap();
        assert_eq!(z, zip_files(&files).unwrap());
        assert!(z.starts_with(b"PK\x03\x04") && z.len() < 600, "{}", z.len());
    }
}
