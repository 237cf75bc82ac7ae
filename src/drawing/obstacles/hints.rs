//! The segments an index last found, asked first by its next question (see [`Hints`]).

use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// The segments that last answered a question, asked first next time: a label's spots come
/// round its anchor, and the line that blocked one spot mostly blocks the next (most spots
/// tried are blocked, and a blocked box's cells were read up to the line that blocks it).
/// Only the order in which segments are tested changes: every answer is the same.
#[derive(Debug)]
pub(super) struct Hints {
    pub(super) met: AtomicU32,
    pub(super) crossed: AtomicU32,
    /// The segment that last met a box asked in each slot ([`super::Obstacles::is_clear_in`]).
    pub(super) slots: [AtomicU32; SLOTS],
    /// The segment that last crossed one asked in each slot
    /// ([`super::Obstacles::segment_crosses_stroke_in`]).
    pub(super) crossed_slots: [AtomicU32; SLOTS],
}

/// How many slots of hints [`super::Obstacles::is_clear_in`] keeps: one for each of a label's
/// directions.
pub const SLOTS: usize = 24;

impl Default for Hints {
    fn default() -> Hints {
        Hints {
            met: AtomicU32::new(u32::MAX),
            crossed: AtomicU32::new(u32::MAX),
            slots: std::array::from_fn(|_| AtomicU32::new(u32::MAX)),
            crossed_slots: std::array::from_fn(|_| AtomicU32::new(u32::MAX)),
        }
    }
}

impl Clone for Hints {
    fn clone(&self) -> Hints {
        Hints::default()
    }
}

impl Hints {
    /// Remembers piece `id` in `hint`; true, to end the search that found it.
    pub(super) fn remember(&self, hint: &AtomicU32, id: u32) -> bool {
        hint.store(id, Relaxed);
        true
    }
}
