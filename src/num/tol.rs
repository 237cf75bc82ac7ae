//! Named tolerances, each with its unit. Where a quantity has a natural size (a mechanism's
//! extent, the largest force of a polygon, a slider's stroke) the tolerance is relative to
//! it, so that the same mechanism drawn in millimetres or in kilometres decides alike.

/// Two course angles closer than this (rad) are the same position: φ1 on a drawn position.
pub const SAME_ANGLE: f64 = 1e-9;

/// An extreme position within this (rad) of a drawn one is that position rather than a
/// separate one ("4′" beside "4"): 1e-7 rad moves a 1 m link by 0.1 µm.
pub const SAME_POSITION: f64 = 1e-7;

/// |sin| of a transmission angle below which a dyad is at a dead point (dimensionless): its
/// velocities would grow beyond 10⁹ times the crank's.
pub const DEAD_POINT_SIN: f64 = 1e-9;

/// Relative to the mechanism's size: distances below this fraction of it are zero (a block on
/// its kulisa's pivot, two coincident points of a link, a slider that does not move).
pub const SAME_POINT: f64 = 1e-9;

/// |sin| of the angle between the two unknown directions of a force polygon below which it
/// has no solution (dimensionless).
pub const PARALLEL_SIN: f64 = 1e-9;

/// Relative to the largest force of a group: a force below this fraction of it is zero (the
/// guide's normal force, whose point of application is then undefined and irrelevant).
pub const ZERO_FORCE: f64 = 1e-12;

/// Relative to √(a·H) (the speed scale of a slider with acceleration a over a stroke H): a
/// speed below this fraction of it is zero, so the slider is at a dead centre and moves next
/// the way its acceleration points.
pub const ZERO_SPEED: f64 = 1e-9;

/// Relative: a scale factor within this fraction of a round value is that value.
pub const ROUND_VALUE: f64 = 1e-12;

/// Paper millimetres: what the SVG can resolve (its numbers have three decimals).
pub const PAPER: f64 = 1e-3;

/// Paper millimetres: a vector shorter than this is not drawn (thinner than a line).
pub const PAPER_INVISIBLE: f64 = 0.05;

/// Square paper millimetres: boxes that share less area than this do not overlap.
pub const PAPER_AREA: f64 = 1e-9;
