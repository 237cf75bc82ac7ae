//! Drawings a sheet's compositions share. Sheet 1 composes up to dozens of layouts and
//! keeps one (the kulisa: 51), and most of them draw the mechanism, or a region of plans,
//! at the very same place and scale: each such drawing is a function of that place alone
//! (the project, its kinematics and its words are the sheet's), so it is drawn once and
//! cloned for the others.

use std::sync::Mutex;

/// The drawings made so far, each with what it was drawn from.
pub(super) struct DrawnOnce<K, V>(Mutex<Vec<(K, V)>>);

impl<K, V> Default for DrawnOnce<K, V> {
    fn default() -> Self {
        DrawnOnce(Mutex::new(Vec::new()))
    }
}

impl<K: PartialEq, V: Clone> DrawnOnce<K, V> {
    /// The drawing from `key`: drawn before, else `draw` now and kept. Two compositions on
    /// rayon's pool side by side may both draw one key (alike); the lock is not held while
    /// drawing.
    pub(super) fn get(&self, key: K, draw: impl FnOnce() -> V) -> V {
        let found = self.with(|kept| kept.iter().find(|(k, _)| *k == key).map(|(_, v)| v.clone()));
        if let Some(drawn) = found {
            return drawn;
        }
        let drawn = draw();
        self.with(|kept| kept.push((key, drawn.clone())));
        drawn
    }

    /// `f` on the kept drawings (a lock poisoned by a panic elsewhere still holds whole
    /// drawings: each is pushed complete).
    fn with<R>(&self, f: impl FnOnce(&mut Vec<(K, V)>) -> R) -> R {
        match self.0.lock() {
            Ok(mut kept) => f(&mut kept),
            Err(poisoned) => f(&mut poisoned.into_inner()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_key_is_drawn_once_and_each_key_its_own() {
        let memo: DrawnOnce<u32, String> = DrawnOnce::default();
        let mut draws = 0;
        for key in [1, 2, 1, 1, 2] {
            let drawn = memo.get(key, || {
                draws += 1;
                format!("drawing {key}")
            });
            assert_eq!(drawn, format!("drawing {key}"));
        }
        assert_eq!(draws, 2);
    }
}
