//! The rule every sheet applies to the user's assumptions: they are printed in the sheet's
//! notes, and the notes have a room of their own. A sheet measures its notes with the
//! assumptions in them; when they are taller than their room, the assumptions are refused
//! (the field named, at its line) rather than drawn over the drawings or off the page.

use crate::drawing::text::TooLong;

/// The room a sheet keeps for its notes.
pub struct Room {
    /// The field the assumptions are written in (`gears.assumptions`).
    pub field: &'static str,
    /// Where the notes go, in the refusal's words ("notes under the mesh").
    pub place: &'static str,
    /// The notes' width and their greatest height, mm.
    pub size: (f64, f64),
}

impl Room {
    /// Refuses `assumptions` when the notes with them are `height` mm tall, more than the
    /// room holds. Without assumptions there is nothing of the user's to refuse: a sheet's
    /// own notes are sized to fit.
    pub fn check(&self, assumptions: &[String], height: f64) -> Result<(), TooLong> {
        if assumptions.is_empty() || height <= self.size.1 {
            return Ok(());
        }
        Err(TooLong::new(self.field, &assumptions.join(" "), self.place, self.size))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_taller_than_their_room_refuse_the_assumptions() {
        let room = Room { field: "cam.assumptions", place: "notes under the diagrams", size: (300.0, 80.0) };
        let one = vec!["Assumed.".to_string()];
        assert_eq!(room.check(&one, 80.0), Ok(()));
        let e = room.check(&one, 80.5).unwrap_err();
        assert_eq!(
            (e.field.as_str(), e.place.as_str(), e.w, e.h),
            ("cam.assumptions", "notes under the diagrams", 300.0, 80.0)
        );
        assert_eq!(room.check(&[], 500.0), Ok(()), "a sheet's own notes are not the user's to shorten");
    }
}
