//! Specific sliding of the pair's flanks along the line of action (Artobolevsky): at a
//! contact point K, x from N1 along N1N2 = g, the flanks' radii of curvature are ρ1 = x and
//! ρ2 = g − x, their points move along the flanks at ω1·ρ1 and ω2·ρ2, and the specific
//! sliding of flank 1 is λ1 = 1 − ω2ρ2/(ω1ρ1) = 1 − (g − x)/(u·x), of flank 2
//! λ2 = 1 − u·x/(g − x), u = z2/z1. Both are 0 at the pitch point (ρ2/ρ1 = r_b2/r_b1 = u) and
//! fall without bound towards the other wheel's N: the flank worn most is the one whose
//! contact nears its own base circle. The course's check reads them at the ends of the
//! active line B1B2.

use super::pair::Pair;
use crate::num::math::tan;

/// The line of action as the sliding diagram reads it, metres from N1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sliding {
    /// N1N2.
    pub line: f64,
    /// N1P.
    pub pitch_point: f64,
    /// N1B1 and N1B2: the active line's ends.
    pub active: [f64; 2],
    /// u = z2/z1.
    pub ratio: f64,
}

impl Sliding {
    pub fn of(p: &Pair) -> Sliding {
        let pitch_point = p.wheels[0].base * tan(p.working_pressure_angle);
        let line = p.line_of_action;
        // The active line never runs past N1 or N2 (it stops earlier where an involute begins
        // above its base circle: `Pair::involute_from`).
        let ends = [(pitch_point - p.approach).max(0.0), (pitch_point + p.recess).min(line)];
        Sliding { line, pitch_point, active: ends, ratio: p.ratio }
    }

    /// λ of wheel `i`'s flank (0 or 1) at `x` metres from N1, strictly between N1 and N2.
    pub fn lambda(&self, i: usize, x: f64) -> f64 {
        let (g, u) = (self.line, self.ratio);
        if i == 0 { 1.0 - (g - x) / (u * x) } else { 1.0 - u * x / (g - x) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::math::{cos, sin};

    /// The sliding vanishes at the pitch point and is 1 at the other wheel's N side: λ1 → 1
    /// as x → g (flank 2 rolls on a point of flank 1 that no longer moves along flank 2).
    #[test]
    fn the_sliding_vanishes_at_the_pitch_point() {
        let (r1, r2, a) = (0.024_f64, 0.06_f64, 20f64.to_radians());
        let s =
            Sliding { line: (r1 + r2) / cos(a) * sin(a), pitch_point: r1 * tan(a), active: [0.0, 0.0], ratio: r2 / r1 };
        assert!(s.lambda(0, s.pitch_point).abs() < 1e-12 && s.lambda(1, s.pitch_point).abs() < 1e-12);
        assert!((s.lambda(0, s.line * (1.0 - 1e-9)) - 1.0).abs() < 1e-6);
        assert!(s.lambda(0, s.line * 1e-3) < -100.0 && s.lambda(1, s.line * (1.0 - 1e-3)) < -100.0);
    }
}
