//! Where each field of a project file is written: every node's path (`gears.pair.z[1]`) with
//! its line and column, read from the YAML parser's events. It names the field of an error
//! the YAML library reports only by position, and gives the line of a field that a later
//! step (a mechanism that cannot turn, a name too long for its cell) refuses by path. It also
//! finds keys written twice in one mapping, each in its own section.

use serde_saphyr::granit_parser::{Event, Parser, Span};

/// A node of the file: its path, where it starts and ends (1-based line and column), and
/// whether it is a mapping.
#[derive(Debug, Clone, PartialEq)]
struct Node {
    path: String,
    line: u64,
    column: u64,
    end: (u64, u64),
    mapping: bool,
}

/// A key written twice in one mapping: the second one's path and place.
#[derive(Debug, Clone, PartialEq)]
pub struct Duplicate {
    pub path: String,
    pub key: String,
    pub line: u64,
    pub column: u64,
}

/// Every node of a project file, in the file's order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Places {
    nodes: Vec<Node>,
    /// Where the first document ends: an error beyond it is about the file, not a field.
    end: Option<(u64, u64)>,
    /// Keys written twice in one mapping.
    pub duplicates: Vec<Duplicate>,
}

/// A container being walked: a mapping waiting for a key or a value, or a sequence and the
/// index of its next item.
enum Frame {
    Mapping { path: String, key: Option<String>, keys: Vec<String>, node: usize },
    Sequence { path: String, next: usize, node: usize },
}

fn child(parent: &str, key: &str) -> String {
    if parent.is_empty() { key.to_string() } else { format!("{parent}.{key}") }
}

/// The place of a span's start, 1-based.
fn place(span: &Span) -> (u64, u64) {
    (span.start.line() as u64, span.start.col() as u64 + 1)
}

/// The place of a span's end, 1-based.
fn end_of(span: &Span) -> (u64, u64) {
    (span.end.line() as u64, span.end.col() as u64 + 1)
}

impl Places {
    /// Walks `text`'s first document; a syntax error ends the walk (the YAML library
    /// reports it).
    pub fn of(text: &str) -> Places {
        let mut out = Places::default();
        let mut stack: Vec<Frame> = Vec::new();
        for event in Parser::new_from_str(text) {
            let Ok((event, span)) = event else { break };
            match event {
                Event::DocumentEnd => {
                    out.end = Some(place(&span));
                    break;
                }
                Event::Scalar(value, ..) => out.scalar(&mut stack, value.as_ref(), &span),
                Event::Alias(_) => {
                    out.value(&mut stack, &span);
                }
                Event::MappingStart(..) => {
                    let path = out.value(&mut stack, &span);
                    let node = out.nodes.len() - 1;
                    out.nodes[node].mapping = true;
                    stack.push(Frame::Mapping { path, key: None, keys: Vec::new(), node });
                }
                Event::SequenceStart(..) => {
                    let path = out.value(&mut stack, &span);
                    stack.push(Frame::Sequence { path, next: 0, node: out.nodes.len() - 1 });
                }
                Event::MappingEnd | Event::SequenceEnd => {
                    if let Some(Frame::Mapping { node, .. } | Frame::Sequence { node, .. }) = stack.pop() {
                        out.nodes[node].end = end_of(&span);
                    }
                }
                _ => {}
            }
        }
        out
    }

    /// A scalar: a mapping's key (recorded at its own place, so that an error at a key
    /// names it), or a value.
    fn scalar(&mut self, stack: &mut [Frame], value: &str, span: &Span) {
        if let Some(Frame::Mapping { path, key: key @ None, keys, .. }) = stack.last_mut() {
            let (line, column) = place(span);
            let full = child(path, value);
            if keys.iter().any(|k| k == value) {
                self.duplicates.push(Duplicate { path: full.clone(), key: value.to_string(), line, column });
            } else {
                keys.push(value.to_string());
            }
            self.nodes.push(Node { path: full, line, column, end: end_of(span), mapping: false });
            *key = Some(value.to_string());
            return;
        }
        self.value(stack, span);
    }

    /// A value at `span`: its path, recorded with its place.
    fn value(&mut self, stack: &mut [Frame], span: &Span) -> String {
        let path = match stack.last_mut() {
            None => String::new(),
            Some(Frame::Mapping { path, key, .. }) => child(path, &key.take().unwrap_or_default()),
            Some(Frame::Sequence { path, next, .. }) => {
                *next += 1;
                format!("{path}[{}]", *next - 1)
            }
        };
        let (line, column) = place(span);
        self.nodes.push(Node { path: path.clone(), line, column, end: end_of(span), mapping: false });
        path
    }

    /// Whether the file holds no value at all (empty, or comments only).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The path of the field written at `(line, column)` (the innermost one there), else the
    /// one written last before it: the field an error reported there is about (empty: the
    /// document itself).
    pub fn path_at(&self, line: u64, column: u64) -> String {
        if self.end.is_some_and(|end| (line, column) >= end) {
            return String::new();
        }
        let at = (line, column);
        let i = self.nodes.partition_point(|n| (n.line, n.column) <= at);
        let before = &self.nodes[..i];
        let inside = before.iter().rev().find(|n| n.end >= at);
        inside.or(before.last()).map(|n| n.path.clone()).unwrap_or_default()
    }

    /// The path of the innermost mapping written around `(line, column)`: where a key is
    /// missing.
    pub fn mapping_at(&self, line: u64, column: u64) -> String {
        let at = (line, column);
        let i = self.nodes.partition_point(|n| (n.line, n.column) <= at);
        let inside = self.nodes[..i].iter().rev().find(|n| n.mapping && n.end >= at);
        inside.map(|n| n.path.clone()).unwrap_or_else(|| self.path_at(line, column))
    }

    /// Whether `path` itself is written in the file.
    pub fn has(&self, path: &str) -> bool {
        self.nodes.iter().any(|n| n.path == path)
    }

    /// Where `path` is written (its first node), else where its nearest written ancestor is.
    pub fn place_of(&self, path: &str) -> Option<(u64, u64)> {
        let mut p = path;
        loop {
            if let Some(n) = self.nodes.iter().find(|n| n.path == p) {
                return Some((n.line, n.column));
            }
            let cut = p.rfind(['.', '['])?;
            p = &p[..cut];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str =
        "project:\n  title: T\ngears:\n  pair: {module: 5, z: [17, 19]}\n  assumptions:\n    - a\n    - b\n";

    #[test]
    fn paths_are_found_by_place_and_places_by_path() {
        let p = Places::of(TEXT);
        assert_eq!(p.path_at(4, 29), "gears.pair.z[1]");
        assert_eq!(p.path_at(4, 27), "gears.pair.z[0]");
        assert_eq!(p.path_at(4, 12), "gears.pair.module");
        assert_eq!(p.path_at(7, 7), "gears.assumptions[1]");
        assert_eq!(p.place_of("gears.pair.z[1]"), Some((4, 29)));
        assert_eq!(p.place_of("gears.pair.shift"), Some((4, 3)), "a field not written: its mapping's key");
        assert_eq!(p.place_of("cam"), None);
        assert!(p.has("gears.pair.module") && !p.has("gears.pair.shift"));
        assert_eq!(p.mapping_at(4, 33), "gears.pair", "the pair's closing brace");
        assert_eq!(p.path_at(4, 33), "gears.pair");
        assert!(p.duplicates.is_empty());
    }

    #[test]
    fn a_key_written_twice_is_found_in_its_mapping() {
        let p = Places::of("project: {title: T}\ncam:\n  law: sine\n  law: cosine\ngears: {law: x}\n");
        assert_eq!(p.duplicates.len(), 1, "{:?}", p.duplicates);
        let d = &p.duplicates[0];
        assert_eq!((d.path.as_str(), d.line, d.column), ("cam.law", 4, 3));
    }
}
