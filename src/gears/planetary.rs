//! Planetary stage (being written).
