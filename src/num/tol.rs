//! Named tolerances, each with its unit. Where a quantity has a natural size (a mechanism's
//! extent, the largest force of a polygon, a slider's stroke) the tolerance is relative to
//! it, so that the same mechanism drawn in millimetres or in kilometres decides alike.

use super::Near;

/// Relative: what `assert_near!` allows when no tolerance is given, the round-off of a few
/// dozen operations on doubles (2.2·10⁻¹⁶ each).
pub const NEAR: Near = Near::rel(1e-12);

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

/// Relative to the largest over a turn: a sampled speed below this fraction of it is zero,
/// the sample itself an extreme position (round-off alone gives it a sign, which a bisection
/// towards it would not find again: an output's stroke end exactly at position 0).
pub const EXTREME_SPEED: f64 = 1e-12;

/// Relative to the larger: two speeds within this fraction of each other are one (sheet 2's
/// n1 as written and the crank's, which may come from ω1 in 1/s through π/30).
pub const SAME_SPEED: f64 = 1e-9;

/// Relative: a scale factor within this fraction of a round value is that value.
pub const ROUND_VALUE: f64 = 1e-12;

/// Magnitudes below this print as 0: round-off of a quantity that is zero (a velocity at an
/// extreme position, Δ of two exact computations). The course's smallest real values
/// (moments of inertia of 10⁻⁴ kg·m²) are far above it.
pub const PRINTED_ZERO: f64 = 1e-7;

/// Paper millimetres: what the SVG can resolve (its numbers have three decimals).
pub const PAPER: f64 = 1e-3;

/// Paper millimetres: a vector shorter than this is not drawn (thinner than a line).
pub const PAPER_INVISIBLE: f64 = 0.05;

/// Square paper millimetres: boxes that share less area than this do not overlap.
pub const PAPER_AREA: f64 = 1e-9;

/// Square paper millimetres: texts that share less area than this only touch (a
/// thousandth of a millimetre by a thousandth); more is an overlap the layout reports.
pub const TEXT_OVERLAP_AREA: f64 = 1e-6;

/// Paper millimetres: how far the Bézier form of an arc may stray from the arc when a path
/// is measured (arcs are written exact; only the measurement approximates them).
pub const ARC_MEASURE: f64 = 1e-4;

/// Relative to the mechanism's motion: how closely the drawn trajectories follow the exact
/// paths. On a sheet, where that extent is at most ~450 mm, 10⁻⁵ of it is at most 0.0045 mm
/// (the sheet states the measured value).
pub const TRAJECTORY_FIT: f64 = 1e-5;

/// Radians: where a search for a crank angle stops (an extreme position, the edge of a
/// lock-up window).
pub const ANGLE_RESOLUTION: f64 = 1e-12;

/// Radians: angles of at most a few turns that differ by less than this differ by round-off
/// only (their spacing of doubles is below 10⁻¹⁵): two cam positions that are one, an arc
/// or a part of the cam without sweep, phases that make up exactly a turn.
pub const ANGLE_ROUND_OFF: f64 = 1e-12;

/// Radians: how far inside a phase's end a cam angle is taken to read the phase's own value;
/// at the end itself the law belongs to the next part (the dwell, or a jump's other side).
pub const INSIDE_PHASE: f64 = 1e-12;

/// Relative: a law's value that differs across a position (taken [`INSIDE_PHASE`] either
/// side) by more than this part of its row's largest value jumps there. A smooth law moves
/// by ~10⁻¹¹ of its peak across those 2·10⁻¹² rad; a jump the tables print moves by at
/// least a digit of four.
pub const JUMP_RELATIVE: f64 = 1e-6;

/// Radians: where the cam's searches over φ stop. A smooth maximum's value is then exact to
/// ~10⁻²² of its curvature, and the step stays above the spacing of doubles near φ, which a
/// golden section cannot shrink past.
pub const CAM_ANGLE_SEARCH: f64 = 1e-11;

/// Radians: where a drawing's search for a maximum over the cam's φ stops (the nomogram's
/// zone boundary at its 241 columns). The value found is then within 10⁻¹⁴ of its
/// curvature, far below a thousandth of a millimetre on paper; [`CAM_ANGLE_SEARCH`] costs
/// half as many steps again for digits no drawing shows.
pub const CAM_ANGLE_DRAWN: f64 = 1e-7;

/// Metres: where the search for the cam's centre along its column stops, and what pads the
/// column's bound so that the bracket is never empty.
pub const CENTRE_SEARCH: f64 = 1e-12;

/// Relative to the column's bound: the finest step of the centre's search, above the
/// spacing of doubles near the bound (2.2·10⁻¹⁶ of it).
pub const CENTRE_SEARCH_RELATIVE: f64 = 1e-14;

/// Relative: the column's bound is widened by this fraction, so that a centre on it is
/// inside the bracket.
pub const BRACKET_MARGIN: f64 = 1e-9;

/// Relative to the allowed angle: a rocker's half swing counts as below it only when below by
/// this fraction. The viewing direction must lie strictly inside every wedge; at the limit
/// the admissible region degenerates.
pub const STRICTLY_INSIDE: f64 = 1e-9;

/// Dimensionless: a unit direction's component below this is zero, so a ray along a box's
/// side never leaves through it.
pub const ALONG_SIDE: f64 = 1e-12;

/// Metres: the translating follower's offset below this (1 nm) is none; the nomogram
/// dimensions e only above it.
pub const ZERO_OFFSET: f64 = 1e-9;

/// Millimetres: the profile draws the circle of the offset e only above this (10⁻¹² m).
/// Kept apart from [`ZERO_OFFSET`]: an offset between the two is drawn as a circle of no
/// size but not dimensioned.
pub const OFFSET_CIRCLE_MM: f64 = 1e-9;

/// Metres: a working pitch circle within this (1 nm) of the pitch circle is the pitch
/// circle, drawn and named once.
pub const SAME_CIRCLE: f64 = 1e-9;

/// Metres: the fillet of a drawn tooth is fitted to this (0.1 µm), far below any drawn line:
/// a thousandth of a millimetre on paper even at 10:1.
pub const FILLET_FIT: f64 = 1e-7;

/// Metres: the cam's profiles as drawn and as given in the tables are fitted to this.
pub const PROFILE_FIT: f64 = 1e-6;

/// Relative to a law's total area (the integral of |s″|): a teacher's corners copied from a
/// figure to 6 significant digits. Each a written to 6 digits is off by at most half a unit
/// of its 6th digit, 5·10⁻⁶ of |a|; the net area, the integral of a, is then off by at most
/// 5·10⁻⁶ of the total area; twice that leaves room for the x's rounding (multiples of 1/8
/// are exact). A law that speeds up once and slows down once (its total area twice its peak
/// velocity) is then left with at most 5·10⁻⁶ of its peak velocity at the phase's end, which
/// the law sets to zero: nothing a sheet can show.
pub const CUSTOM_LAW_AREA: f64 = 1e-5;

/// Dimensionless: a ratio within this of an end of the course's range is inside it (the
/// roller's share of r_min, 0.25 written as 2.5 mm over 10 mm).
pub const RANGE_EDGE: f64 = 1e-9;

/// Steps: a value within this of a whole number of steps is that number, not one less
/// (a roller of 3 mm computed as 2.9999999999 mm).
pub const WHOLE_STEP: f64 = 1e-9;

/// Relative: a round scale below μ by less than this fraction is μ itself.
pub const SAME_SCALE: f64 = 1e-9;

/// Relative to the larger diagonal entry: a least-squares 2×2 system whose determinant (or
/// entry) is below this fraction of its square (or of it) is singular in that unknown.
pub const SINGULAR: f64 = 1e-12;

/// In the curve's units: the accuracy of kurbo's nearest-point search when a fit
/// re-parameterises its samples or checks a trajectory (metres, far below every fit's
/// tolerance).
pub const NEAREST: f64 = 1e-12;

/// Of a Bézier piece's parameter (0 to 1): where Newton's search for the point nearest a
/// sample stops. A piece is at most metres long, so the point is then found to well below
/// [`NEAREST_MEASURE`] (and the distance, at a minimum, to its square).
pub const NEWTON_PARAMETER: f64 = 1e-13;

/// In the curve's units: the accuracy of the nearest-point search when a fit's deviation is
/// measured, a tenth of [`NEAREST`], so that the measured deviation is the fit's and not the
/// search's.
pub const NEAREST_MEASURE: f64 = 1e-13;

/// Relative: a bisection whose bracket is within this fraction of its value has reached its
/// last bit; at zero, within this fraction of [`LAST_BIT_FLOOR`].
pub const LAST_BIT: f64 = f64::EPSILON;

/// The magnitude below which [`LAST_BIT`] is taken of this instead (a normal number, so the
/// product never underflows to zero).
pub const LAST_BIT_FLOOR: f64 = 1e-300;
