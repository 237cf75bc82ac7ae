//! A task's template with a variant's numbers in place: each `${expression}` evaluated in
//! floating point (exmex), and above each line that used a value, a comment per value naming
//! where it came from — the file a student edits says which table each number is from.

use exmex::prelude::*;
use std::collections::BTreeMap;

/// A value an expression may use: its number (`None`: lost) and the comment naming it.
#[derive(Debug, Clone)]
pub struct Known {
    pub value: Option<f64>,
    pub note: String,
}

/// Why a template cannot be filled.
#[derive(Debug, Clone, PartialEq)]
pub enum Unfilled {
    /// Values the variant lacks (the guide lost them), by key, in order of use.
    Missing(Vec<String>),
    /// A template fault: an expression that does not parse, names an unknown key or gives
    /// no finite number (line of the template, the expression, the reason).
    Invalid { line: usize, expression: String, reason: String },
}

/// The `${…}` expressions of a line, with their byte ranges (including `${` and `}`).
fn expressions(line: &str) -> Vec<(usize, usize, &str)> {
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(i) = line[from..].find("${") {
        let start = from + i;
        let Some(j) = line[start..].find('}') else { break };
        let end = start + j + 1;
        out.push((start, end, &line[start + 2..end - 1]));
        from = end;
    }
    out
}

/// The keys an expression names, or why it does not parse.
pub fn keys_of(expression: &str) -> Result<Vec<String>, String> {
    let e = exmex::parse::<f64>(expression).map_err(|e| e.to_string())?;
    Ok(e.var_names().to_vec())
}

/// Every expression of a template with its line (1-based), for checking a catalogue.
pub fn all_expressions(template: &str) -> Vec<(usize, String)> {
    template
        .lines()
        .enumerate()
        .flat_map(|(i, l)| expressions(l).into_iter().map(move |(_, _, e)| (i + 1, e.to_string())))
        .collect()
}

/// Evaluates one expression over `known`: `Ok(None)` when a value it uses is lost.
pub fn evaluate(
    expression: &str,
    known: &BTreeMap<String, Known>,
    missing: &mut Vec<String>,
) -> Result<Option<(f64, Vec<String>)>, String> {
    let e = exmex::parse::<f64>(expression).map_err(|e| e.to_string())?;
    let mut values = Vec::new();
    let mut lacking = false;
    for name in e.var_names() {
        match known.get(name) {
            None => return Err(format!("`{name}` is neither a column nor a constant of the task")),
            Some(Known { value: Some(v), .. }) => values.push(*v),
            Some(Known { value: None, .. }) => {
                lacking = true;
                if !missing.contains(name) {
                    missing.push(name.clone());
                }
                values.push(0.0);
            }
        }
    }
    if lacking {
        return Ok(None);
    }
    let x = e.eval(&values).map_err(|e| e.to_string())?;
    if !x.is_finite() {
        return Err(format!("gives {x}, not a finite number"));
    }
    Ok(Some((x, e.var_names().to_vec())))
}

/// A number as the project file gets it: ten significant digits, trailing zeros dropped,
/// never an exponent for the course's magnitudes, never `-0`.
pub fn number(x: f64) -> String {
    crate::num::digits::sig(x, 10)
}

/// A top-level section of the filled template: its key (`mechanism`; empty for the opening
/// comments), its text, or the keys it lacks.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    pub key: String,
    pub filled: Result<String, Vec<String>>,
}

/// The sections the project file's sheets are drawn from; a file keeps at least one.
const SHEET_SECTIONS: [&str; 3] = ["mechanism", "gears", "cam"];

/// Sections that mean nothing without the mechanism.
const NEED_MECHANISM: [&str; 2] = ["analysis", "forces"];

/// The template with `known`'s values in place, section by section: a section whose values
/// the variant lacks is left out (`filled` holds the keys it lacks), and so are the analysis
/// and forces of a mechanism left out. `computed(expression, value)` words a derived value's
/// comment. When no section a sheet is drawn from is left, the variant is
/// [`Unfilled::Missing`] every key it lacks.
pub fn fill(
    template: &str,
    known: &BTreeMap<String, Known>,
    computed: &dyn Fn(&str, &str) -> String,
) -> Result<Vec<Section>, Unfilled> {
    let mut sections: Vec<Section> = Vec::new();
    for (i, line) in template.lines().enumerate() {
        if let Some(key) = top_level_key(line) {
            sections.push(Section { key: key.to_string(), filled: Ok(String::new()) });
        } else if sections.is_empty() {
            sections.push(Section { key: String::new(), filled: Ok(String::new()) });
        }
        let section = sections.last_mut().expect("a section was pushed");
        let mut missing = Vec::new();
        let text = fill_line(line, i + 1, known, computed, &mut missing)?;
        section.filled = match std::mem::replace(&mut section.filled, Ok(String::new())) {
            Ok(mut t) if missing.is_empty() => {
                t.push_str(&text);
                Ok(t)
            }
            Ok(_) => Err(missing),
            Err(mut lacking) => {
                for m in missing {
                    if !lacking.contains(&m) {
                        lacking.push(m);
                    }
                }
                Err(lacking)
            }
        };
    }
    let mechanism_lost = sections.iter().any(|s| s.key == "mechanism" && s.filled.is_err());
    for s in &mut sections {
        if mechanism_lost && NEED_MECHANISM.contains(&s.key.as_str()) && s.filled.is_ok() {
            s.filled = Err(Vec::new());
        }
    }
    if !sections.iter().any(|s| SHEET_SECTIONS.contains(&s.key.as_str()) && s.filled.is_ok()) {
        let mut all: Vec<String> = Vec::new();
        for m in sections.iter().filter_map(|s| s.filled.as_ref().err()).flatten() {
            if !all.contains(m) {
                all.push(m.clone());
            }
        }
        return Err(Unfilled::Missing(all));
    }
    Ok(sections)
}

/// The key of a line that opens a top-level section (`cam:`), if it is one.
fn top_level_key(line: &str) -> Option<&str> {
    if line.starts_with([' ', '\t', '#', '-']) || line.trim().is_empty() {
        return None;
    }
    line.split_once(':').map(|(k, _)| k.trim())
}

/// One line with its values in place and, above it, the comments naming them; the keys it
/// lacks go to `missing`.
fn fill_line(
    line: &str,
    number_of_line: usize,
    known: &BTreeMap<String, Known>,
    computed: &dyn Fn(&str, &str) -> String,
    missing: &mut Vec<String>,
) -> Result<String, Unfilled> {
    let found = expressions(line);
    if found.is_empty() {
        return Ok(format!("{line}\n"));
    }
    let indent = &line[..line.len() - line.trim_start().len()];
    let (mut text, mut notes, mut last) = (String::new(), Vec::<String>::new(), 0);
    for (start, end, expression) in found {
        let invalid =
            |reason: String| Unfilled::Invalid { line: number_of_line, expression: expression.into(), reason };
        let evaluated = evaluate(expression, known, missing).map_err(invalid)?;
        text.push_str(&line[last..start]);
        last = end;
        let Some((x, names)) = evaluated else { continue };
        text.push_str(&number(x));
        for n in &names {
            for note in known[n].note.lines() {
                if !notes.iter().any(|x| x == note) {
                    notes.push(note.to_string());
                }
            }
        }
        let note = computed(expression.trim(), &number(x));
        if (names.len() != 1 || expression.trim() != names[0]) && !notes.contains(&note) {
            notes.push(note);
        }
    }
    text.push_str(&line[last..]);
    let mut out: String = notes.into_iter().map(|n| format!("{indent}# {n}\n")).collect();
    out.push_str(&text);
    out.push('\n');
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn known(pairs: &[(&str, Option<f64>)]) -> BTreeMap<String, Known> {
        pairs.iter().map(|(k, v)| (k.to_string(), Known { value: *v, note: format!("{k} note") })).collect()
    }

    #[test]
    fn fills_numbers_and_names_their_sources_above_the_line() {
        let k = known(&[("l_ab", Some(0.55)), ("m_2", Some(40.0))]);
        let t = "cam:\n  - {link: 2, mass: ${m_2}, inertia: ${m_2*l_ab^2/12}}\n";
        let out = text(fill(t, &k, &|e, v| format!("{e} = {v}")).unwrap());
        assert_eq!(
            out,
            "cam:\n  # m_2 note\n  # l_ab note\n  # m_2*l_ab^2/12 = 1.008333333\n  - {link: 2, mass: 40, inertia: 1.008333333}\n"
        );
    }

    #[test]
    fn division_is_in_floating_point() {
        let out = text(fill("cam: ${1/2}\n", &known(&[]), &|_, _| String::new()).unwrap());
        assert!(out.ends_with("cam: 0.5\n"), "{out}");
    }

    #[test]
    fn a_lost_value_is_missing_and_an_unknown_key_is_invalid() {
        let k = known(&[("a", None), ("b", Some(1.0))]);
        let none = |_: &str, _: &str| String::new();
        assert_eq!(fill("cam: ${a+b}\ngears: ${a}\n", &k, &none), Err(Unfilled::Missing(vec!["a".into()])));
        assert!(matches!(fill("cam: ${c}\n", &k, &none), Err(Unfilled::Invalid { line: 1, .. })));
        assert!(matches!(fill("cam: ${b/0}\n", &k, &none), Err(Unfilled::Invalid { .. })));
    }

    #[test]
    fn a_section_lacking_values_is_left_out_with_what_needs_the_mechanism() {
        let k = known(&[("a", None), ("b", Some(1.0))]);
        let t = "# opening\nproject:\n  x: 1\nmechanism:\n  l: ${a}\nforces:\n  m: ${b}\ncam:\n  h: ${b}\n";
        let s = fill(t, &k, &|_, _| String::new()).unwrap();
        let keys: Vec<(&str, bool)> = s.iter().map(|s| (s.key.as_str(), s.filled.is_ok())).collect();
        assert_eq!(keys, [("", true), ("project", true), ("mechanism", false), ("forces", false), ("cam", true)]);
        assert_eq!(s[2].filled, Err(vec!["a".to_string()]));
    }

    fn text(sections: Vec<Section>) -> String {
        sections.into_iter().map(|s| s.filled.unwrap()).collect()
    }
}
