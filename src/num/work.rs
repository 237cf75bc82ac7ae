//! Counts of the costly steps a build takes, so that a test can prove a build skips what
//! its request does not need: `--sheet 2` analyses no linkage and designs no cam,
//! `--no-png` rasterises nothing, a sheet without a force analysis solves no kinetostatics.
//!
//! Process-wide relaxed atomics: a count costs a few nanoseconds beside a step that takes
//! microseconds to milliseconds, and nothing reads them while building (no output depends
//! on them).

use std::sync::atomic::{AtomicU64, Ordering};

/// A costly step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    /// The linkage's positions, velocities and accelerations over a turn (sheet 1).
    LinkageAnalysis,
    /// The kinetostatic analysis at the assigned position (sheet 1's force drawings).
    ForceAnalysis,
    /// Sheet 1's mechanism drawn at a place (its positions, trajectories and labels).
    MechanismDrawing,
    /// An involute pair's geometry (sheet 2).
    GearPair,
    /// The cam's design: centre, profile, pressure angles (sheet 3).
    CamDesign,
    /// A scene written as SVG, PDF (a document of any number of pages), PNG or DXF.
    Svg,
    Pdf,
    Png,
    Dxf,
}

const STEPS: usize = 9;
static COUNTS: [AtomicU64; STEPS] = [const { AtomicU64::new(0) }; STEPS];

/// Counts one `step` taken.
pub fn count(step: Step) {
    COUNTS[step as usize].fetch_add(1, Ordering::Relaxed);
}

/// How many times `step` was taken in this process so far.
pub fn taken(step: Step) -> u64 {
    COUNTS[step as usize].load(Ordering::Relaxed)
}
