//! The segments a student draws or measures on a sheet: each with its stable identifier
//! (`sheet1.plan.v.3.pb`), its name as the course writes it (`pb`), its length on the paper,
//! the quantity it stands for (an answer key, when the note's tables have it), that
//! quantity's value and unit, and the scale between them — so that a teacher can check a
//! student's measurements, and a test can check a drawing against the numbers.

use std::fmt::Write;

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

/// The segments as CSV: one row each, full precision (9 decimals).
pub fn segments_csv(segments: &[Segment], prefix: &str) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["id", "name", "length_mm", "quantity", "value", "unit", "scale"]).expect("writing to memory");
    for s in segments {
        let record = [
            format!("{prefix}.{}", s.id),
            s.name.clone(),
            nine(s.length_mm),
            s.quantity.clone().unwrap_or_default(),
            nine(s.value),
            s.unit.to_string(),
            nine(s.scale),
        ];
        w.write_record(&record).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("flushing to memory")).expect("UTF-8 in, UTF-8 out")
}

fn nine(v: f64) -> String {
    let mut s = String::new();
    write!(s, "{v:.9}").expect("writing to a string");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') { s[1..].to_string() } else { s }
}
