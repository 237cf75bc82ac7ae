//! The segments a student draws or measures on a sheet: each with its stable identifier
//! (`sheet1.plan.v.3.pb`), its name as the course writes it (`pb`), its length on the paper,
//! the quantity it stands for (an answer key, when the note's tables have it), that
//! quantity's value and unit, and the scale between them — so that a teacher can check a
//! student's measurements, and a test can check a drawing against the numbers.

use std::collections::BTreeSet;

/// One drawn segment.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Segment {
    /// Within its sheet ("plan.v.3.pb"); the files write it after the sheet's name.
    #[serde(skip)]
    pub id: String,
    /// As the course writes it: "pb", "ab", "πb", "an_BA".
    pub name: String,
    /// On the paper, mm.
    pub length_mm: f64,
    /// The answer key of the quantity it stands for ("sheet1.velocities.v_B.3"), if the
    /// note's tables have it.
    pub quantity: Option<String>,
    /// The quantity's magnitude, in `unit`.
    pub value: f64,
    pub unit: &'static str,
    /// `unit` per paper mm: value = length_mm × scale.
    pub scale: f64,
}

impl Segment {
    /// A segment standing for `value` (in `unit`) drawn at `scale` (`unit` per mm), tied to
    /// no answer yet. A length has no sign: an ordinate below its axis is measured as it is
    /// above (the answer may be signed).
    pub fn new(id: impl Into<String>, name: impl Into<String>, value: f64, unit: &'static str, scale: f64) -> Segment {
        let value = value.abs();
        Segment { id: id.into(), name: name.into(), length_mm: value / scale, quantity: None, value, unit, scale }
    }

    /// Tied to the answer `key` of its sheet ("velocities.v_B.3"), when the note's tables
    /// have it.
    pub fn answering(self, key: &str, answers: &AnswerKeys) -> Segment {
        let full = answers.key(key);
        Segment { quantity: answers.has(&full).then_some(full), ..self }
    }
}

/// The answer keys a sheet's note tables give (`sheet1.velocities.v_B.3`), to tie segments to.
#[derive(Debug, Clone, Default)]
pub struct AnswerKeys {
    /// The sheet's name in ids: "sheet1".
    pub sheet: String,
    ids: BTreeSet<String>,
}

impl AnswerKeys {
    pub fn of(sheet: &str, tables: &[super::NoteTable]) -> AnswerKeys {
        AnswerKeys {
            sheet: sheet.to_string(),
            ids: tables.iter().flat_map(|n| n.answers(sheet)).map(|a| a.id).collect(),
        }
    }

    /// The full key of `key` within the sheet ("velocities.v_B.3" → "sheet1.velocities.v_B.3").
    pub fn key(&self, key: &str) -> String {
        format!("{}.{key}", self.sheet)
    }

    pub fn has(&self, key: &str) -> bool {
        self.ids.contains(key)
    }
}

/// The segments as CSV: one row each, full precision (9 decimals).
pub fn segments_csv(segments: &[Segment], prefix: &str) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["id", "name", "length_mm", "quantity", "value", "unit", "scale"]).expect("writing to memory");
    for s in segments {
        let record = [
            format!("{prefix}.{}", s.id),
            s.name.clone(),
            super::csv_number(s.length_mm),
            s.quantity.clone().unwrap_or_default(),
            super::csv_number(s.value),
            s.unit.to_string(),
            super::csv_number(s.scale),
        ];
        w.write_record(&record).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("flushing to memory")).expect("UTF-8 in, UTF-8 out")
}
